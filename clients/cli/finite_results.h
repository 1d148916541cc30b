// The last guard before results reach the user: the core promises finite numbers, but its
// input ranges do not cover every overflow (eq 4 divides measured moments by the torque:
// 1e308 N·m / 1e-300 N·m; before the core bounded the torque, 1e308 N·m gave NaN moments).
// Rather than print a NaN or an infinity, the calculator refuses the load case by name.
#pragma once

#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/operating_point.h"
#include "core/tooth_contact.h"

namespace gc::cli {

/// Throws gc::InvalidInput naming operating_point.torque_nm when a quantity of `contact` is
/// not finite (the only input that can overflow the model is the torque's magnitude).
void require_finite_result(const OperatingPoint& point, const ToothContact& contact);
void require_finite_result(const OperatingPoint& point, const InducedMoments& moments);
/// Same for eq 4, naming measurement.torque_nm.
void require_finite_result(const FrictionMeasurement& measurement,
                           const FrictionEstimate& estimate);

}  // namespace gc::cli
