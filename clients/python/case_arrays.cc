// The in-process vectorised calls: every core on the cases, the GIL released, each thread a
// contiguous share (parallel/thread_parallel_for.h), results written straight into numpy arrays.
#include "clients/python/case_arrays.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "clients/python/bindings.h"
#include "clients/python/coupling_argument.h"
#include "clients/python/errors.h"
#include "clients/python/result_object.h"
#include "core/induced_moments.h"
#include "core/model_error.h"
#include "parallel/thread_parallel_for.h"

namespace py = pybind11;

namespace gc::python {

// ---- inputs -----------------------------------------------------------------------------------

namespace {

std::string shape_text(const std::vector<py::ssize_t>& shape) {
  std::string text = "(";
  for (std::size_t d = 0; d < shape.size(); ++d) {
    text += std::to_string(shape[d]) + (shape.size() == 1 ? "," : d + 1 < shape.size() ? ", " : "");
  }
  return text + ")";
}

py::tuple shape_tuple(const std::vector<py::ssize_t>& shape) {
  py::tuple out(shape.size());
  for (std::size_t d = 0; d < shape.size(); ++d) out[d] = shape[d];
  return out;
}

}  // namespace

CaseInputs::CaseInputs(const std::vector<const char*>& names, const std::vector<py::handle>& values)
    : names_(names) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  std::vector<Array> given;
  for (std::size_t k = 0; k < values.size(); ++k) {
    // A pandas Series (not an Index, which has no .index): its index, the first one given.
    if (index_.is_none() && py::hasattr(values[k], "index") && py::hasattr(values[k], "to_numpy") &&
        !py::isinstance<py::array>(values[k])) {
      index_ = values[k].attr("index");
    }
    Array array = Array::ensure(values[k]);
    if (!array) {
      PyErr_Clear();
      throw InvalidInput(names[k], "must be a number or an array of numbers");
    }
    if (array.size() == 0) throw InvalidInput(names[k], "is empty: no load cases");
    // numpy's rule: align the last axes; each pair equal, or one of them 1.
    std::vector<py::ssize_t> shape(array.shape(), array.shape() + array.ndim());
    std::vector<py::ssize_t> merged(std::max(shape.size(), shape_.size()), 1);
    for (std::size_t d = 0; d < merged.size(); ++d) {
      const std::size_t from_end = merged.size() - 1 - d;
      const py::ssize_t a = from_end < shape_.size() ? shape_[shape_.size() - 1 - from_end] : 1;
      const py::ssize_t b = from_end < shape.size() ? shape[shape.size() - 1 - from_end] : 1;
      if (a != b && a != 1 && b != 1) {
        throw InvalidInput(names[k], "has shape " + shape_text(shape) +
                                         ", which does not broadcast with the shape " +
                                         shape_text(shape_) +
                                         " of the arguments before it (numpy's broadcasting rules)");
      }
      merged[d] = a == 1 ? b : a;
    }
    shape_ = std::move(merged);
    given.push_back(std::move(array));
  }
  size_ = 1;
  for (py::ssize_t n : shape_) size_ *= static_cast<std::size_t>(n);
  if (!index_.is_none() && !(shape_.size() == 1 && py::len(index_) == size_)) index_ = py::none();
  // Each input at the full shape, C-contiguous: a view where it already is, else a copy.
  const py::object broadcast_to = py::module_::import("numpy").attr("broadcast_to");
  for (Array& array : given) {
    Array full = Array::ensure(broadcast_to(array, shape_tuple(shape_)));
    data_.push_back(full.data());
    arrays_.push_back(std::move(full));
  }
}

py::dict CaseInputs::arrays() const {
  py::dict out;
  for (std::size_t k = 0; k < arrays_.size(); ++k) out[names_[k]] = arrays_[k];
  return out;
}

// ---- columns ----------------------------------------------------------------------------------

using analysis::LoadCase;
template <typename R> using Kind = typename Column<R>::Kind;

const std::vector<Column<ToothContact>>& tooth_contact_columns() {
  using C = ToothContact;
  static const std::vector<Column<C>> columns = {
      {"q", Kind<C>::real, [](const C& c) { return c.load_sharing.q; }},
      {"iterations", Kind<C>::integer, [](const C& c) { return double(c.load_sharing.iterations); }},
      {"teeth_in_contact", Kind<C>::integer, [](const C& c) { return double(c.teeth_in_contact); }},
      {"max_tooth_load_n", Kind<C>::real, [](const C& c) { return c.max_tooth_load_n; }},
      {"total_normal_load_n", Kind<C>::real, [](const C& c) { return c.total_normal_load_n; }},
      {"offset_alpha_rad", Kind<C>::real, [](const C& c) { return c.offset_alpha_rad; }},
      {"edge_loaded", Kind<C>::flag, [](const C& c) { return double(c.edge_loaded); }},
      {"contact_stress_pa", Kind<C>::real, [](const C& c) { return c.max_stress.contact_stress_pa; }},
      {"bending_stress_pa", Kind<C>::real, [](const C& c) { return c.max_stress.bending_stress_pa; }},
      {"contact_safety_factor", Kind<C>::real, [](const C& c) { return c.max_stress.contact_safety_factor; }},
      {"bending_safety_factor", Kind<C>::real, [](const C& c) { return c.max_stress.bending_safety_factor; }},
  };
  return columns;
}

const std::vector<Column<LoadCase>>& load_case_columns() {
  using C = LoadCase;
  static const std::vector<Column<C>> columns = {
      {"q", Kind<C>::real, [](const C& c) { return c.contact.load_sharing.q; }},
      {"teeth_in_contact", Kind<C>::integer, [](const C& c) { return double(c.contact.teeth_in_contact); }},
      {"max_tooth_load_n", Kind<C>::real, [](const C& c) { return c.contact.max_tooth_load_n; }},
      {"moment_y_dd_nm", Kind<C>::real, [](const C& c) { return c.moments.moment_y_dd_nm; }},
      {"moment_z_dd_nm", Kind<C>::real, [](const C& c) { return c.moments.moment_z_dd_nm; }},
      {"moment_y_nm", Kind<C>::real, [](const C& c) { return c.moments.moment_y_nm; }},
      {"moment_z_nm", Kind<C>::real, [](const C& c) { return c.moments.moment_z_nm; }},
      {"sensor_moment_y_nm", Kind<C>::real, [](const C& c) { return c.moments.sensor_moment_y_nm; }},
      {"sensor_moment_z_nm", Kind<C>::real, [](const C& c) { return c.moments.sensor_moment_z_nm; }},
      {"magnitude_nm", Kind<C>::real, [](const C& c) { return c.moments.magnitude_nm; }},
      {"moment_direction_rad", Kind<C>::real, [](const C& c) { return c.moments.direction_rad; }},
      {"contact_stress_pa", Kind<C>::real, [](const C& c) { return c.contact.max_stress.contact_stress_pa; }},
      {"bending_stress_pa", Kind<C>::real, [](const C& c) { return c.contact.max_stress.bending_stress_pa; }},
      {"contact_safety_factor", Kind<C>::real, [](const C& c) { return c.contact.max_stress.contact_safety_factor; }},
      {"bending_safety_factor", Kind<C>::real, [](const C& c) { return c.contact.max_stress.bending_safety_factor; }},
  };
  return columns;
}

const std::vector<Column<FrictionEstimate>>& friction_estimate_columns() {
  using C = FrictionEstimate;
  static const std::vector<Column<C>> columns = {
      {"friction_coefficient", Kind<C>::real, [](const C& c) { return c.friction_coefficient; }},
      {"moment_z_dd_nm", Kind<C>::real, [](const C& c) { return c.moment_z_dd_nm; }},
  };
  return columns;
}

FailedCases failed_cases_argument(const std::string& errors) {
  if (errors == "raise") return FailedCases::raise;
  if (errors == "mask") return FailedCases::mask;
  throw InvalidInput("errors", "\"" + errors + "\" is not one of \"raise\", \"mask\"");
}

// ---- outputs ----------------------------------------------------------------------------------

template <typename Result>
CaseArrays<Result>::CaseArrays(const std::vector<Column<Result>>& columns, const CaseInputs& inputs,
                               FailedCases failed)
    : columns_(columns), inputs_(inputs), failed_(failed), errors_(inputs.size()) {
  const std::vector<py::ssize_t>& shape = inputs.shape();
  for (const Column<Result>& column : columns_) {
    // Under "mask" an integer column holds NaN for a failed case, so it is float64.
    const bool real = column.kind == Kind<Result>::real ||
                      (column.kind == Kind<Result>::integer && failed_ == FailedCases::mask);
    if (real) {
      arrays_.push_back(py::array_t<double>(shape));
    } else if (column.kind == Kind<Result>::integer) {
      arrays_.push_back(py::array_t<std::int32_t>(shape));
    } else {
      arrays_.push_back(py::array_t<bool>(shape));
    }
    data_.push_back(arrays_.back().mutable_data());
  }
}

template <typename Result>
void CaseArrays<Result>::set(std::size_t i, const Result& result) {
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    const double value = columns_[k].value(result);
    switch (columns_[k].kind) {
      case Kind<Result>::real: static_cast<double*>(data_[k])[i] = value; break;
      case Kind<Result>::integer:
        if (failed_ == FailedCases::mask) {
          static_cast<double*>(data_[k])[i] = value;
        } else {
          static_cast<std::int32_t*>(data_[k])[i] = static_cast<std::int32_t>(value);
        }
        break;
      case Kind<Result>::flag: static_cast<bool*>(data_[k])[i] = value != 0.0; break;
    }
  }
}

template <typename Result>
CaseTableObject CaseArrays<Result>::finish() {
  if (failed_ == FailedCases::raise) {
    for (std::size_t i = 0; i < errors_.size(); ++i) {
      if (errors_[i]) {
        set_python_error(errors_[i], i);
        throw py::error_already_set();
      }
    }
  }
  py::dict out;
  for (std::size_t k = 0; k < columns_.size(); ++k) out[columns_[k].name] = arrays_[k];
  if (failed_ == FailedCases::mask) {
    py::array_t<bool> ok(inputs_.shape());
    py::list messages;
    bool* flags = ok.mutable_data();
    for (std::size_t i = 0; i < errors_.size(); ++i) {
      flags[i] = !errors_[i];
      std::string message;
      if (errors_[i]) {
        for (std::size_t k = 0; k < columns_.size(); ++k) {  // NaN (False for a flag), never stale
          if (arrays_[k].dtype().kind() == 'b') {
            static_cast<bool*>(data_[k])[i] = false;
          } else {
            static_cast<double*>(data_[k])[i] = std::numeric_limits<double>::quiet_NaN();
          }
        }
        try {
          std::rethrow_exception(errors_[i]);
        } catch (const std::exception& e) {
          message = e.what();
        }
      }
      messages.append(message);
    }
    out["ok"] = ok;
    out["error"] = py::array(messages).attr("reshape")(shape_tuple(inputs_.shape()));
  }
  return py::module_::import("gearcoupling._results").attr("CaseTable")(out, inputs_.arrays(),
                                                                       inputs_.index());
}

template class CaseArrays<ToothContact>;
template class CaseArrays<LoadCase>;
template class CaseArrays<FrictionEstimate>;

// ---- the in-process calls ---------------------------------------------------------------------

namespace {

// Runs `compute(i)` for every case on `threads` threads (0: all cores) with the GIL released;
// a case that throws is recorded as failed, the others still run.
template <typename Result, typename Compute>
CaseTableObject run_cases(const std::vector<Column<Result>>& columns, const CaseInputs& inputs,
                          unsigned threads, FailedCases failed, const Compute& compute) {
  CaseArrays<Result> arrays(columns, inputs, failed);
  const std::size_t count = inputs.size();
  {
    py::gil_scoped_release release;
    thread_parallel_for(threads)(count, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        try {
          arrays.set(i, compute(i));
        } catch (const std::exception&) {
          arrays.fail(i, std::current_exception());
        }
      }
    });
  }
  return arrays.finish();
}

CaseTableObject tooth_contact_many(const CouplingArgument& coupling, const ArrayArgument& torque_nm,
                                   const ArrayArgument& misalignment_rad,
                                   const ArrayArgument& direction_rad, int slices, double tolerance,
                            int max_iterations, unsigned threads, const std::string& errors) {
  const auto c = coupling_argument(coupling);
  const CaseInputs in({"torque_nm", "misalignment_rad", "direction_rad"},
                      {torque_nm, misalignment_rad, direction_rad});
  const ContactOptions options = contact_options(slices, tolerance, max_iterations);
  return run_cases(tooth_contact_columns(), in, threads, failed_cases_argument(errors),
                   [&](std::size_t i) {
                     return gc::tooth_contact(*c->geometry, {in(0, i), in(1, i), in(2, i), 0.0}, options);
                   });
}

CaseTableObject induced_moments_many(const CouplingArgument& coupling, const ArrayArgument& torque_nm,
                                     const ArrayArgument& misalignment_rad,
                                     const ArrayArgument& direction_rad, const ArrayArgument& mu,
                                     int slices, double tolerance,
                              int max_iterations, unsigned threads, const std::string& errors) {
  const auto c = coupling_argument(coupling);
  const CaseInputs in({"torque_nm", "misalignment_rad", "direction_rad", "mu"},
                      {torque_nm, misalignment_rad, direction_rad, mu});
  const ContactOptions options = contact_options(slices, tolerance, max_iterations);
  return run_cases(load_case_columns(), in, threads, failed_cases_argument(errors),
                   [&](std::size_t i) {
                     const OperatingPoint point{in(0, i), in(1, i), in(2, i), in(3, i)};
                     // The load case without the table of teeth, which its columns do not read.
                     LoadCase result;
                     result.moments = gc::induced_moments(*c->geometry, point, options, result.contact);
                     return result;
                   });
}

CaseTableObject estimate_friction_many(const CouplingArgument& coupling,
                                       const ArrayArgument& torque_nm,
                                       const ArrayArgument& misalignment_rad,
                                       const ArrayArgument& direction_rad,
                                       const ArrayArgument& sensor_moment_y_nm,
                                       const ArrayArgument& sensor_moment_z_nm, unsigned threads, const std::string& errors) {
  const auto c = coupling_argument(coupling);
  const CaseInputs in({"torque_nm", "misalignment_rad", "direction_rad", "sensor_moment_y_nm",
                       "sensor_moment_z_nm"},
                      {torque_nm, misalignment_rad, direction_rad, sensor_moment_y_nm, sensor_moment_z_nm});
  return run_cases(friction_estimate_columns(), in, threads, failed_cases_argument(errors),
                   [&](std::size_t i) {
                     return gc::estimate_friction(*c->geometry,
                                                  {in(0, i), in(1, i), in(2, i), in(3, i), in(4, i)});
                   });
}

}  // namespace

void bind_case_arrays(py::module_& m) {
  m.def("tooth_contact_many", &tooth_contact_many, py::arg("coupling"), py::arg("torque_nm"),
        py::arg("misalignment_rad"), py::arg("direction_rad") = 0.0, py::kw_only(),
        GC_PYTHON_CONTACT_OPTION_ARGS, py::arg("threads") = 0u, py::arg("errors") = "raise",
        "tooth_contact over many load cases on all cores (threads=0) with the GIL released. "
        "torque_nm [N·m], misalignment_rad, direction_rad [rad]: numbers or numpy arrays of any "
        "shape, broadcast together as numpy does (a scalar against an array, a column against a "
        "row for a grid). Returns a CaseTable (a dict of numpy arrays of the broadcast shape; "
        ".to_frame() for pandas): q, iterations, teeth_in_contact, max_tooth_load_n, "
        "total_normal_load_n, offset_alpha_rad, edge_loaded, contact_stress_pa, "
        "bending_stress_pa, contact_safety_factor, bending_safety_factor. errors='raise': the "
        "first failed case's exception, with .index (flat, C order); 'mask': also 'ok' and "
        "'error' columns, NaN in a failed case's numbers.");
  m.def("induced_moments_many", &induced_moments_many, py::arg("coupling"), py::arg("torque_nm"),
        py::arg("misalignment_rad"), py::arg("direction_rad") = 0.0, py::kw_only(), py::arg("mu"),
        GC_PYTHON_CONTACT_OPTION_ARGS, py::arg("threads") = 0u, py::arg("errors") = "raise",
        "Contact and induced moments (eqs 5-48) over many load cases on all cores, as "
        "gearcoupling batch: torque_nm [N·m], misalignment_rad, direction_rad [rad], mu [-], "
        "broadcast together as numpy does. Returns a CaseTable of the broadcast shape: q, "
        "teeth_in_contact, max_tooth_load_n, moment_y_dd_nm, moment_z_dd_nm, moment_y_nm, "
        "moment_z_nm, sensor_moment_y_nm, sensor_moment_z_nm, magnitude_nm, "
        "moment_direction_rad, contact_stress_pa, bending_stress_pa, contact_safety_factor, "
        "bending_safety_factor. errors as tooth_contact_many.");
  m.def("estimate_friction_many", &estimate_friction_many, py::arg("coupling"), py::arg("torque_nm"),
        py::arg("misalignment_rad"), py::arg("direction_rad"), py::arg("sensor_moment_y_nm"),
        py::arg("sensor_moment_z_nm"), py::kw_only(), py::arg("threads") = 0u,
        py::arg("errors") = "raise",
        "estimate_friction over many measurements on all cores, the arguments broadcast together "
        "as numpy does. Returns a CaseTable: friction_coefficient [-] and moment_z_dd_nm [N·m]; "
        "errors as tooth_contact_many.");
}

}  // namespace gc::python
