#include "clients/python/predictions.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "core/coupling_model.h"
#include "parallel/thread_parallel_for.h"

namespace py = pybind11;

namespace gc::python {

CaseTableObject predict_recording(const Model& model, const Recording& recording, unsigned threads) {
  const std::vector<RecordedSample>& samples = recording.data->samples;
  const auto n = static_cast<py::ssize_t>(samples.size());
  const char* const names[] = {"time_s", "torque_nm", "misalignment_rad", "direction_rad",
                               "msy_measured_nm", "msz_measured_nm", "msy_predicted_nm",
                               "msz_predicted_nm", "msy_residual_nm", "msz_residual_nm"};
  constexpr std::size_t kColumns = sizeof(names) / sizeof(names[0]);
  std::vector<py::array_t<double>> arrays;
  std::vector<double*> data;
  for (std::size_t k = 0; k < kColumns; ++k) {
    arrays.emplace_back(n);
    data.push_back(arrays.back().mutable_data());
  }
  py::array_t<bool> ok(n);
  bool* ok_data = ok.mutable_data();
  std::vector<std::string> errors(samples.size());
  const CouplingModel& coupling_model = model.file->model;
  {
    py::gil_scoped_release release;
    thread_parallel_for(threads)(samples.size(), [&](std::size_t begin, std::size_t end) {
      constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
      // The slice at once, as validate predicts it (CouplingModel::moments_at).
      std::vector<std::size_t> rows(end - begin);
      std::iota(rows.begin(), rows.end(), begin);
      const CouplingModel::MomentsAtRows m = coupling_model.moments_at(samples, rows);
      for (std::size_t i = begin; i < end; ++i) {
        const RecordedSample& s = samples[i];
        const bool predicted_ok = m.errors[i - begin].empty();
        ok_data[i] = predicted_ok;
        if (!predicted_ok) errors[i] = m.errors[i - begin];
        const double predicted[2] = {predicted_ok ? m.moments[i - begin].y_nm : kNaN,
                                     predicted_ok ? m.moments[i - begin].z_nm : kNaN};
        const double row[kColumns] = {s.input.time_s, s.input.torque_nm, s.input.misalignment_rad,
                                      s.input.direction_rad, s.measured.y_nm, s.measured.z_nm,
                                      predicted[0], predicted[1], predicted[0] - s.measured.y_nm,
                                      predicted[1] - s.measured.z_nm};
        for (std::size_t k = 0; k < kColumns; ++k) data[k][i] = row[k];
      }
    });
  }
  py::dict columns;
  for (std::size_t k = 0; k < kColumns; ++k) columns[names[k]] = arrays[k];
  columns["ok"] = ok;
  py::list messages;
  for (const std::string& message : errors) messages.append(message);
  columns["error"] = n > 0 ? py::array(messages) : py::array(py::dtype("<U1"), std::vector<py::ssize_t>{0});
  return py::module_::import("gearcoupling._results").attr("CaseTable")(columns, py::dict());
}

}  // namespace gc::python
