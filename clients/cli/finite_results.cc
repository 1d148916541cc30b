#include "clients/cli/finite_results.h"

#include <cmath>
#include <initializer_list>

#include "core/model_error.h"

namespace gc::cli {
namespace {

bool all_finite(std::initializer_list<double> values) {
  for (double value : values) {
    if (!std::isfinite(value)) return false;
  }
  return true;
}

[[noreturn]] void overflow(const char* field, double torque_nm) {
  throw InvalidInput(field, torque_nm,
                     "a torque for which the model's loads and moments stay finite");
}

}  // namespace

void require_finite_result(const OperatingPoint& point, const ToothContact& contact) {
  bool finite = all_finite({contact.total_normal_load_n, contact.peak_tooth_load_n,
                            contact.elastic_deformation_m, contact.sum_tooth_loads_n,
                            contact.max_stress.contact_stress_pa,
                            contact.max_stress.bending_stress_pa});
  for (const ToothLoad& tooth : contact.teeth) {
    finite = finite && all_finite({tooth.load_n, tooth.contact_length_m, tooth.deformation_m});
  }
  if (!finite) overflow("operating_point.torque_nm", point.torque_nm);
}

void require_finite_result(const OperatingPoint& point, const InducedMoments& moments) {
  if (!all_finite({moments.moment_y_dd_nm, moments.moment_z_dd_nm, moments.moment_y_nm,
                   moments.moment_z_nm, moments.magnitude_nm, moments.direction_rad})) {
    overflow("operating_point.torque_nm", point.torque_nm);
  }
}

void require_finite_result(const FrictionMeasurement& measurement,
                           const FrictionEstimate& estimate) {
  if (!all_finite({estimate.friction_coefficient, estimate.moment_z_dd_nm})) {
    overflow("measurement.torque_nm", measurement.torque_nm);
  }
}

}  // namespace gc::cli
