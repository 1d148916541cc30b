// Runs `gearcoupling diagnose --data F --model M --json` on a draw as a user runs it (a child
// process) and reads what it claimed. A false claim: any round whose outcome is not "noise"
// (effect_found, indistinguishable, partly_explained, formula_proposed and unexplained all count),
// or a non-empty add_flags. A run that fails (exit code not 0) is counted apart, as an error.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/diagnosis/zoo/zoo.h"

namespace gc::zoo {

struct DiagnoseOutcome {
  int exit_code = -1;
  double wall_s = 0.0;               ///< diagnose's wall time [s]
  bool claim = false;                ///< a false claim (see above)
  bool error = false;                ///< exit code not 0, or JSON that does not parse
  std::string outcomes;              ///< the rounds' outcomes, "noise" or e.g. "effect_found; noise"
  std::vector<std::string> claimed;  ///< names claimed: effects, formula terms, add_flags
  std::vector<std::string> first_claim;  ///< the names of the first claiming round (power mode's "named first")
  std::string numbers;               ///< held-out figures of the claiming rounds, as text
  std::string stderr_tail;           ///< the end of its standard error (errors)
};

/// Runs `gearcoupling` (path) diagnose on csv and model; `threads` > 0 adds -j threads.
DiagnoseOutcome run_diagnose(const std::string& gearcoupling, const std::filesystem::path& csv,
                             const std::filesystem::path& model, int threads = 0);

/// Reads diagnose's --json output (idl/diagnosis.proto) into an outcome (claim, names, numbers).
void read_diagnosis_json(const std::string& json, DiagnoseOutcome& out);

/// Clopper-Pearson upper bound of a binomial proportion, k of n, at one-sided level alpha/2
/// (two-sided 1 - alpha interval), by bisection on the regularised incomplete beta function.
double clopper_pearson_upper(std::size_t k, std::size_t n, double alpha = 0.05);

}  // namespace gc::zoo
