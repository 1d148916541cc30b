// What the monitor proposes for a test cell (docs/protocol.md, "Proposals, swaps and the
// monitor"): the model the diagnosis (`gearcoupling diagnose`'s, analysis/model_diagnosis.h)
// finds on the cell's rolling window, with what it adds, the fitted parameters, the held-out error
// before and after and the verdict's words. No DDS here (live/proposal_wire.h writes it).
#pragma once

#include <chrono>
#include <memory>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "diagnosis/diagnose.h"
#include "core/recorded_sample.h"
#include "live/cell_model.h"

namespace gc::live {

enum class ProposalState { standing, applied, withdrawn };

struct ProposalParameter {
  std::string effect, name, unit;   ///< unit: SI, "-" for none
  double value = 0.0;
  double standard_error = 0.0;      ///< 0 when held
  bool held = false, plausible = true;
  std::string note;
};

/// An effect the data cannot tell from the proposed one (the round's "alike").
struct ProposalAlternative {
  std::string effect;
  double held_out_rmse_nm = 0.0;    ///< [N·m]
  double correlation = 0.0;
  std::string experiment;           ///< one sentence, "" when no recorded input separates them
};

struct Proposal {
  std::string test_cell;
  std::uint64_t id = 0;             ///< random, never 0
  ProposalState state = ProposalState::standing;
  std::string state_reason;
  std::string kind;                 ///< addition | refinement | formula (the first claim's)
  std::string effects;              ///< comma-separated
  std::string outcome;              ///< the last claiming round's
  std::vector<ProposalParameter> parameters;
  std::string base_model, model_name, model_text;
  std::shared_ptr<const CouplingModel> model;   ///< model_text's model (not on the wire)
  double window_begin_s = 0.0, window_end_s = 0.0;   ///< measurement time [s]
  std::uint64_t window_samples = 0;
  double before_rmse_nm = 0.0;      ///< the base model on the search rows, pooled [N·m]
  double after_rmse_nm = 0.0;       ///< held out, with what it adds [N·m]
  double noise_nm = 0.0;            ///< pooled noise estimate [N·m]
  std::string verdict;              ///< one line per claiming round
  std::chrono::system_clock::time_point proposed_at{};
  double onset_to_proposal_s = 0.0; ///< [s]
  double diagnosis_cpu_s = 0.0;     ///< [s]
  std::vector<ProposalAlternative> alternatives;   ///< of the first claiming round

  /// The share of the error it removes: 1 - after / before.
  double reduction() const;
};

/// The proposal a diagnosis of `window` against `base` makes for `test_cell` (id, times and CPU
/// left for the caller): the base model with every effect the diagnosis added, as the text a
/// ModelSwap carries. nullopt when the diagnosis added nothing (noise, or unexplained).
std::optional<Proposal> proposal_from(const Diagnosis& diagnosis, const CellModel& base,
                                      const std::string& test_cell,
                                      std::span<const RecordedSample> window);

/// Whether `candidate` should replace `standing` (same test cell): `standing` is not in force
/// any more (withdrawn or applied), or `candidate` removes a larger share of the error.
bool replaces(const Proposal& candidate, const Proposal& standing);

/// The pooled RMSE of `model` on `samples` (both channels) [N·m]; samples it refuses are skipped.
/// nullopt when it predicts none.
std::optional<double> pooled_rmse(const CouplingModel& model, std::span<const RecordedSample> samples);

const char* to_string(ProposalState state);

}  // namespace gc::live
