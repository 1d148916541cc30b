// Vectorised calls: load cases as numpy arrays in, one numpy array per result column out (a dict
// of column name -> array, names with their units as in the batch CSV, ready for
// pandas.DataFrame). Shared by the in-process calls (case_arrays.cc) and the remote ones
// (remote_client.cc).
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "analysis/load_case.h"
#include "core/friction_estimate.h"
#include "core/tooth_contact.h"

namespace gc::python {

/// The inputs of a vectorised call: each a 1-D array or a scalar (used for every case); the
/// arrays must have one length, the number of cases. Throws InvalidInput naming the argument.
class CaseInputs {
 public:
  /// `names` and `values` in the same order. Needs the GIL.
  CaseInputs(const std::vector<const char*>& names, const std::vector<pybind11::handle>& values);
  std::size_t size() const { return size_; }
  /// Input `k` of case `i` (no GIL needed).
  double operator()(std::size_t k, std::size_t i) const {
    return lengths_[k] == 1 ? data_[k][0] : data_[k][i];
  }

 private:
  std::vector<pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>> arrays_;
  std::vector<const double*> data_;
  std::vector<std::size_t> lengths_;
  std::size_t size_ = 1;
};

/// One output column: its name and how it is read from a case's result.
template <typename Result>
struct Column {
  enum class Kind { real, integer, flag };
  const char* name;
  Kind kind;
  double (*value)(const Result&);
};

/// tooth_contact_many's columns.
const std::vector<Column<ToothContact>>& tooth_contact_columns();
/// induced_moments_many's: the batch CSV's (analysis/batch_csv.h) and the rest of eqs 42-48.
const std::vector<Column<analysis::LoadCase>>& load_case_columns();
/// estimate_friction_many's.
const std::vector<Column<FrictionEstimate>>& friction_estimate_columns();

/// What a vectorised call does with the cases that fail: "raise" the first (by case index) as
/// its gearcoupling exception with .index, or "mask": return every case, with the columns
/// "ok" (bool) and "error" (the message, "" where ok), and zeros in the failed cases' numbers.
enum class FailedCases { raise, mask };
FailedCases failed_cases_argument(const std::string& errors);

/// The output arrays of `count` cases, allocated with the GIL held and filled without it (each
/// case by one thread), then handed to Python.
template <typename Result>
class CaseArrays {
 public:
  CaseArrays(const std::vector<Column<Result>>& columns, std::size_t count);
  void set(std::size_t i, const Result& result);
  void fail(std::size_t i, std::exception_ptr error) { errors_[i] = std::move(error); }
  /// The dict of arrays; with FailedCases::raise, raises the first failed case's error instead.
  /// Needs the GIL.
  pybind11::dict finish(FailedCases failed);

 private:
  const std::vector<Column<Result>>& columns_;
  std::vector<pybind11::array> arrays_;
  std::vector<void*> data_;
  std::vector<std::exception_ptr> errors_;
};

}  // namespace gc::python
