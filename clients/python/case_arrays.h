// Vectorised calls: load cases as numpy arrays in (broadcast together), one numpy array per
// result column out, of the inputs' broadcast shape (a CaseTable: a dict of column name -> array,
// names with their units as in the batch CSV, .to_frame() for pandas). Shared by the in-process calls (case_arrays.cc) and the remote ones
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
#include "clients/python/typed_objects.h"
#include "core/friction_estimate.h"
#include "core/tooth_contact.h"

namespace gc::python {

/// The inputs of a vectorised call, broadcast together by numpy's rules: each a number or an
/// array of any shape; the shapes, aligned on their last axes, must agree where neither is 1.
/// The cases are the broadcast shape's elements in C order. Throws InvalidInput naming the
/// argument that does not broadcast, is empty, or is not numbers.
class CaseInputs {
 public:
  /// `names` and `values` in the same order. Needs the GIL.
  CaseInputs(const std::vector<const char*>& names, const std::vector<pybind11::handle>& values);
  /// Cases: the product of shape() (1 for numbers alone).
  std::size_t size() const { return size_; }
  /// The broadcast shape: () for numbers alone, as numpy gives for scalars.
  const std::vector<pybind11::ssize_t>& shape() const { return shape_; }
  /// Input `k` of case `i` (no GIL needed).
  double operator()(std::size_t k, std::size_t i) const { return data_[k][i]; }
  /// Every input broadcast to shape(), by name: the CaseTable's inputs. Needs the GIL.
  pybind11::dict arrays() const;
  /// The index of the first input that is a pandas Series, when the cases are one axis of its
  /// length (the Series against numbers or arrays of its length); else None. CaseTable.to_frame()
  /// keeps it, so the rows line up with the user's own frame.
  const pybind11::object& index() const { return index_; }

 private:
  std::vector<const char*> names_;
  std::vector<pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>> arrays_;
  std::vector<const double*> data_;
  std::vector<pybind11::ssize_t> shape_;
  std::size_t size_ = 1;
  pybind11::object index_ = pybind11::none();
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
/// "ok" (bool) and "error" (the message, "" where ok), and NaN in the failed cases' numbers
/// (integer columns are then float64, as pandas makes an integer column with missing values;
/// flags are False where a case failed).
enum class FailedCases { raise, mask };
FailedCases failed_cases_argument(const std::string& errors);

/// The output arrays of the cases of `inputs` (its broadcast shape), allocated with the GIL
/// held and filled without it (each case by one thread), then handed to Python as a CaseTable.
template <typename Result>
class CaseArrays {
 public:
  CaseArrays(const std::vector<Column<Result>>& columns, const CaseInputs& inputs, FailedCases failed);
  void set(std::size_t i, const Result& result);
  void fail(std::size_t i, std::exception_ptr error) { errors_[i] = std::move(error); }
  /// gearcoupling.CaseTable: the columns as arrays of the inputs' shape, with the inputs; under
  /// FailedCases::raise, raises the first failed case's error instead. Needs the GIL.
  CaseTableObject finish();

 private:
  const std::vector<Column<Result>>& columns_;
  const CaseInputs& inputs_;
  FailedCases failed_;
  std::vector<pybind11::array> arrays_;
  std::vector<void*> data_;
  std::vector<std::exception_ptr> errors_;
};

}  // namespace gc::python
