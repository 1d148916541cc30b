#include "core/operating_point.h"

#include <cmath>
#include <sstream>

#include "core/coupling_geometry.h"
#include "core/model_error.h"

namespace gc {

namespace {
constexpr double kMaxTorqueNm = 1e12;
}  // namespace

void validate_operating_point(const CouplingGeometry& coupling, const OperatingPoint& point) {
  // The upper bound keeps every product of eqs 7-47 finite; no coupling transmits 1e12 N·m.
  if (!(point.torque_nm > 0.0 && point.torque_nm <= kMaxTorqueNm)) {
    throw InvalidInput("operating_point.torque_nm", point.torque_nm, "(0, 1e12] N·m");
  }
  require_finite("operating_point.direction_rad", point.direction_rad);
  require_in_range("operating_point.friction_coefficient", point.friction_coefficient, 0.0, 1.0);
  require_below_jam_angle(coupling, "operating_point.misalignment_rad", point.misalignment_rad);
  // tan(zeta) < 1.56 zeta up to 1 rad, so below that and with mu zeta < 1/4 the bound holds
  // without a tangent (every coupling's jam angle is a few degrees).
  const bool near_the_bound =
      point.misalignment_rad > 1.0 || point.friction_coefficient * point.misalignment_rad >= 0.25;
  if (near_the_bound && point.friction_coefficient * std::tan(point.misalignment_rad) >= 1.0) {
    throw InvalidInput("operating_point.friction_coefficient", point.friction_coefficient,
                       "mu tan(zeta) < 1 (eq 37)");
  }
}

void require_below_jam_angle(const CouplingGeometry& coupling, std::string_view field,
                             double misalignment_rad) {
  const JamAngle& jam = coupling.jam_angle();
  if (std::isfinite(misalignment_rad) && misalignment_rad >= 0.0 &&
      misalignment_rad < jam.angle_rad) {
    return;
  }
  std::ostringstream allowed;
  allowed.precision(6);
  allowed << "[0, " << jam.angle_rad << ") rad: below the jam angle of " << coupling.name()
          << ", " << jam.angle_rad * 180.0 / M_PI << " deg (" << to_string(jam.governing)
          << ", eqs 23-35)";
  throw InvalidInput(std::string(field), misalignment_rad, allowed.str());
}

}  // namespace gc
