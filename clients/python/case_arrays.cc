// The in-process vectorised calls: every core on the cases, the GIL released, each thread a
// contiguous share (parallel/thread_parallel_for.h), results written straight into numpy arrays.
#include "clients/python/case_arrays.h"

#include <cstring>

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

CaseInputs::CaseInputs(const std::vector<const char*>& names, const std::vector<py::handle>& values) {
  for (std::size_t k = 0; k < values.size(); ++k) {
    auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values[k]);
    if (!array || array.ndim() > 1) {
      throw InvalidInput(names[k], "must be a number or a 1-D array of numbers");
    }
    const std::size_t length = array.ndim() == 0 ? 1 : static_cast<std::size_t>(array.shape(0));
    if (length == 0) throw InvalidInput(names[k], "is empty: no load cases");
    if (length != 1) {
      if (size_ != 1 && length != size_) {
        throw InvalidInput(names[k], "has " + std::to_string(length) + " cases, the other arrays " +
                                         std::to_string(size_));
      }
      size_ = length;
    }
    data_.push_back(array.data());
    lengths_.push_back(length);
    arrays_.push_back(std::move(array));
  }
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
CaseArrays<Result>::CaseArrays(const std::vector<Column<Result>>& columns, std::size_t count)
    : columns_(columns), errors_(count) {
  const auto n = static_cast<py::ssize_t>(count);
  for (const Column<Result>& column : columns_) {
    switch (column.kind) {
      case Kind<Result>::real: arrays_.push_back(py::array_t<double>(n)); break;
      case Kind<Result>::integer: arrays_.push_back(py::array_t<std::int32_t>(n)); break;
      case Kind<Result>::flag: arrays_.push_back(py::array_t<bool>(n)); break;
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
      case Kind<Result>::integer: static_cast<std::int32_t*>(data_[k])[i] = static_cast<std::int32_t>(value); break;
      case Kind<Result>::flag: static_cast<bool*>(data_[k])[i] = value != 0.0; break;
    }
  }
}

template <typename Result>
py::dict CaseArrays<Result>::finish(FailedCases failed) {
  if (failed == FailedCases::raise) {
    for (std::size_t i = 0; i < errors_.size(); ++i) {
      if (errors_[i]) {
        set_python_error(errors_[i], i);
        throw py::error_already_set();
      }
    }
  }
  py::dict out;
  for (std::size_t k = 0; k < columns_.size(); ++k) out[columns_[k].name] = arrays_[k];
  if (failed == FailedCases::mask) {
    py::array_t<bool> ok(static_cast<py::ssize_t>(errors_.size()));
    py::list messages;
    bool* flags = ok.mutable_data();
    for (std::size_t i = 0; i < errors_.size(); ++i) {
      flags[i] = !errors_[i];
      std::string message;
      if (errors_[i]) {
        for (std::size_t k = 0; k < columns_.size(); ++k) {  // zeros, never stale numbers
          const auto size = static_cast<std::size_t>(arrays_[k].itemsize());
          std::memset(static_cast<char*>(data_[k]) + i * size, 0, size);
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
    out["error"] = py::array(messages);
  }
  return out;
}

template class CaseArrays<ToothContact>;
template class CaseArrays<LoadCase>;
template class CaseArrays<FrictionEstimate>;

// ---- the in-process calls ---------------------------------------------------------------------

namespace {

// Runs `compute(i)` for every case on `threads` threads (0: all cores) with the GIL released;
// a case that throws is recorded as failed, the others still run.
template <typename Result, typename Compute>
py::dict run_cases(const std::vector<Column<Result>>& columns, std::size_t count, unsigned threads,
                   FailedCases failed, const Compute& compute) {
  CaseArrays<Result> arrays(columns, count);
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
  return arrays.finish(failed);
}

py::dict tooth_contact_many(py::handle coupling, py::handle torque_nm, py::handle misalignment_rad,
                            py::handle direction_rad, int slices, double tolerance,
                            int max_iterations, unsigned threads, const std::string& errors) {
  const auto c = coupling_argument(coupling);
  const CaseInputs in({"torque_nm", "misalignment_rad", "direction_rad"},
                      {torque_nm, misalignment_rad, direction_rad});
  const ContactOptions options = contact_options(slices, tolerance, max_iterations);
  return run_cases(tooth_contact_columns(), in.size(), threads, failed_cases_argument(errors),
                   [&](std::size_t i) {
                     return gc::tooth_contact(*c->geometry, {in(0, i), in(1, i), in(2, i), 0.0}, options);
                   });
}

py::dict induced_moments_many(py::handle coupling, py::handle torque_nm, py::handle misalignment_rad,
                              py::handle direction_rad, py::handle mu, int slices, double tolerance,
                              int max_iterations, unsigned threads, const std::string& errors) {
  const auto c = coupling_argument(coupling);
  const CaseInputs in({"torque_nm", "misalignment_rad", "direction_rad", "mu"},
                      {torque_nm, misalignment_rad, direction_rad, mu});
  const ContactOptions options = contact_options(slices, tolerance, max_iterations);
  return run_cases(load_case_columns(), in.size(), threads, failed_cases_argument(errors),
                   [&](std::size_t i) {
                     const OperatingPoint point{in(0, i), in(1, i), in(2, i), in(3, i)};
                     LoadCase result{gc::tooth_contact(*c->geometry, point, options), {}};
                     result.moments = gc::induced_moments(*c->geometry, point, result.contact);
                     return result;
                   });
}

py::dict estimate_friction_many(py::handle coupling, py::handle torque_nm, py::handle misalignment_rad,
                                py::handle direction_rad, py::handle sensor_moment_y_nm,
                                py::handle sensor_moment_z_nm, unsigned threads, const std::string& errors) {
  const auto c = coupling_argument(coupling);
  const CaseInputs in({"torque_nm", "misalignment_rad", "direction_rad", "sensor_moment_y_nm",
                       "sensor_moment_z_nm"},
                      {torque_nm, misalignment_rad, direction_rad, sensor_moment_y_nm, sensor_moment_z_nm});
  return run_cases(friction_estimate_columns(), in.size(), threads, failed_cases_argument(errors),
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
        "torque_nm [N·m], misalignment_rad, direction_rad [rad]: 1-D arrays of one length, or "
        "scalars for every case. Returns a dict of numpy arrays: q, iterations, teeth_in_contact, "
        "max_tooth_load_n, total_normal_load_n, offset_alpha_rad, edge_loaded, contact_stress_pa, "
        "bending_stress_pa, contact_safety_factor, bending_safety_factor. errors='raise': the "
        "first failed case's exception, with .index; 'mask': also 'ok' and 'error' columns.");
  m.def("induced_moments_many", &induced_moments_many, py::arg("coupling"), py::arg("torque_nm"),
        py::arg("misalignment_rad"), py::arg("direction_rad") = 0.0, py::kw_only(), py::arg("mu"),
        GC_PYTHON_CONTACT_OPTION_ARGS, py::arg("threads") = 0u, py::arg("errors") = "raise",
        "Contact and induced moments (eqs 5-48) over many load cases on all cores, as "
        "gearcoupling batch: arrays or scalars of torque_nm [N·m], misalignment_rad, "
        "direction_rad [rad], mu [-]. Returns a dict of numpy arrays: q, teeth_in_contact, "
        "max_tooth_load_n, moment_y_dd_nm, moment_z_dd_nm, moment_y_nm, moment_z_nm, "
        "sensor_moment_y_nm, sensor_moment_z_nm, magnitude_nm, moment_direction_rad, "
        "contact_stress_pa, bending_stress_pa, contact_safety_factor, bending_safety_factor. "
        "errors as tooth_contact_many.");
  m.def("estimate_friction_many", &estimate_friction_many, py::arg("coupling"), py::arg("torque_nm"),
        py::arg("misalignment_rad"), py::arg("direction_rad"), py::arg("sensor_moment_y_nm"),
        py::arg("sensor_moment_z_nm"), py::kw_only(), py::arg("threads") = 0u,
        py::arg("errors") = "raise",
        "estimate_friction over many measurements on all cores: arrays or scalars. Returns a dict "
        "of numpy arrays friction_coefficient [-] and moment_z_dd_nm [N·m]; errors as "
        "tooth_contact_many.");
}

}  // namespace gc::python
