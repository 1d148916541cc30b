// Hidden physics written outside the effects library: the truths of the generalisation proof are
// the base model's prediction (core physics plus the effects the base model already has) with a
// change made here, in a different form from core/effects/, so that a diagnosis cannot pass by
// reproducing the library's own code.
#pragma once

#include <functional>

#include <Eigen/Dense>

#include "core/coupling_geometry.h"
#include "core/coupling_model.h"
#include "core/measurement_sample.h"
#include "core/operating_point.h"
#include "core/tooth_contact.h"

namespace gc::independent {

/// The tooth-contact moments alone (eqs 5-43) at `point`, turned into the coupling frame by
/// frame_shift + beta (eqs 44-47), without any output correction (no self-weight) [N·m].
Eigen::Vector2d contact_moments(const CouplingGeometry& geometry, const OperatingPoint& point,
                                const ContactOptions& options, double frame_shift_rad);

/// Changes the operating point or the frame shift the contact is solved at.
using ContactChange = std::function<void(OperatingPoint& point, double& frame_shift_rad)>;

/// The base model's prediction for `sample` plus what `change` does to the contact moments at the
/// state the base model reached: the base's output corrections (self-weight) are kept as they are.
SensorMoments with_contact_change(const CouplingModel& base, const MeasurementSample& sample,
                                  const ContactChange& change);

/// Unit vector of the base model's contact moment at `sample` (zero moment: (0, 0)).
Eigen::Vector2d contact_moment_direction(const CouplingModel& base, const MeasurementSample& sample);

/// `sample` with the misalignment vector (zeta0, beta0) [rad] added to its measured one, by
/// components in the plane of misalignment: (zeta cos beta, zeta sin beta).
MeasurementSample with_added_misalignment(MeasurementSample sample, double zeta0_rad, double beta0_rad);

/// Eq 48's weight moment by its own statics: the coupling's weight at the shaft length plus the
/// shaft's own weight at half of it, both scaled by the tilt's cosine, (W_c + w_sh L_s / 2) L_s cos(gamma) [N·m].
double weight_moment_nm(const CouplingDefinition& coupling);

}  // namespace gc::independent
