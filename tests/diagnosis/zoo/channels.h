// One recording as columns, SI: the true run of the rig and, after the noise, what the DAQ logged.
#pragma once

#include <cstddef>
#include <vector>

#include "core/measurement_sample.h"

namespace gc::zoo {

struct Channels {
  std::vector<double> time_s;         ///< [s] (logged: the time stamps as written)
  std::vector<double> torque_nm;      ///< T [N·m]
  std::vector<double> zeta_rad;       ///< misalignment amplitude [rad]
  std::vector<double> beta_rad;       ///< misalignment direction [rad]
  std::vector<double> speed_rpm;      ///< shaft speed [rpm]
  std::vector<double> temperature_c;  ///< oil temperature [deg C]
  std::vector<double> msy_nm;         ///< M_sy' [N·m]
  std::vector<double> msz_nm;         ///< M_sz' [N·m]
  std::size_t rows() const { return time_s.size(); }
  void resize(std::size_t n);
  /// Row i's inputs as the model takes them.
  MeasurementSample sample(std::size_t i) const;
};

}  // namespace gc::zoo
