#include "tests/diagnosis/load_sequences.h"

#include <random>

namespace gc::testing {
namespace {

MeasurementSample at(double t, double torque, double zeta, double beta, int loading) {
  MeasurementSample s;
  s.time_s = t;
  s.torque_nm = torque;
  s.misalignment_rad = zeta;
  s.direction_rad = beta;
  s.loading_direction = loading;
  return s;
}

}  // namespace

std::vector<MeasurementSample> misalignment_sweeps(const std::vector<double>& torques_nm,
                                                   const std::vector<double>& directions_rad,
                                                   double max_misalignment_rad, int points) {
  std::vector<MeasurementSample> out;
  for (double torque : torques_nm) {
    for (double beta : directions_rad) {
      for (int k = 0; k < points; ++k) {
        out.push_back(at(out.size(), torque, max_misalignment_rad * k / (points - 1.0), beta, +1));
      }
      for (int k = points - 1; k >= 0; --k) {
        out.push_back(at(out.size(), torque, max_misalignment_rad * k / (points - 1.0), beta, -1));
      }
    }
  }
  return out;
}

std::vector<MeasurementSample> torque_sweeps(const std::vector<double>& misalignments_rad,
                                             const std::vector<double>& directions_rad, double low_nm,
                                             double high_nm, int points) {
  std::vector<MeasurementSample> out;
  for (double zeta : misalignments_rad) {
    for (double beta : directions_rad) {
      for (int k = 0; k < 2 * points; ++k) {
        const int step = k < points ? k : 2 * points - 1 - k;
        out.push_back(at(out.size(), low_nm + (high_nm - low_nm) * step / (points - 1.0), zeta, beta, 0));
      }
    }
  }
  return out;
}

std::vector<MeasurementSample> concatenated(std::vector<MeasurementSample> a, const std::vector<MeasurementSample>& b) {
  const double start = a.empty() ? 0.0 : a.back().time_s + 1.0;
  for (MeasurementSample s : b) {
    s.time_s += start;
    a.push_back(s);
  }
  return a;
}

std::vector<Observation> synthesize(const CouplingModel& truth, const std::vector<MeasurementSample>& samples,
                                    double noise_sigma_nm, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0.0, noise_sigma_nm);
  std::vector<Observation> out;
  for (const MeasurementSample& s : samples) {
    const SensorMoments m = truth.predict(s).moments;
    out.push_back({s, {m.y_nm + noise(random), m.z_nm + noise(random)}});
  }
  return out;
}

}  // namespace gc::testing
