// Coupling-induced bending moments (Section 4.3, eqs 36-48): offsets of the tooth contact and
// axial sliding friction, in the double-prime frame, the coupling frame and at the sensors.
#pragma once

#include "core/operating_point.h"
#include "core/tooth_contact.h"
#include "core/tooth_load_pattern.h"

namespace gc {

class CouplingGeometry;

struct InducedMoments {
  double moment_y_dd_nm = 0.0;    ///< M_ty'', eq 43 [N·m]
  double moment_z_dd_nm = 0.0;    ///< M_tz'', eq 42 [N·m]
  double moment_y_nm = 0.0;       ///< M_y', eq 46 [N·m]
  double moment_z_nm = 0.0;       ///< M_z', eq 47 [N·m]
  double sensor_moment_y_nm = 0.0;  ///< M_sy', eq 48 [N·m]
  double sensor_moment_z_nm = 0.0;  ///< M_sz', eq 48 [N·m]
  double self_weight_moment_nm = 0.0;  ///< W_c cos(gamma) L_s + w_sh cos(gamma) L_s^2 / 2 [N·m]
  double magnitude_nm = 0.0;      ///< |(M_y', M_z')| [N·m]
  double direction_rad = 0.0;     ///< atan2(M_z', M_y') [rad]
  int teeth_summed = 0;           ///< 4 (int(qN/4) + 1): the symmetric sums of eqs 42-43;
                                  ///< + 4 for the continuous variant's fractional tooth
};

/// Eq 37's ratio W_d / P_d = (mu cos zeta + sin zeta) / (cos zeta - mu sin zeta) [-].
double axial_load_factor(double misalignment_rad, double friction);

/// Axial tooth load W_d = P_d (mu cos zeta + sin zeta) / (cos zeta - mu sin zeta) [N], eq 37.
double axial_tooth_load_n(double tooth_load_n, double misalignment_rad, double friction);

/// Eq 48's self-weight moment at the sensors [N·m] for coupling weight W_c [N], shaft weight
/// per length w_sh [N/m], shaft length L_s [m] and tilt gamma [rad].
double self_weight_moment_nm(const CouplingGeometry& coupling);

/// Eqs 42-43: the moments M_ty'', M_tz'' in the double-prime frame, summed over the symmetric quarter.
struct QuarterSums {
  double moment_y_dd_nm = 0.0;  ///< eq 43 [N·m]
  double moment_z_dd_nm = 0.0;  ///< eq 42 [N·m]
  int teeth_summed = 0;         ///< as InducedMoments::teeth_summed
};

/// Eqs 5-43 for the double-prime moments alone, what a model prediction turns into the coupling
/// frame: tooth_contact() then the quarter sums, without listing the teeth, their zones and the
/// stress (bit for bit the same moments, and the same errors). Throws as tooth_contact().
QuarterSums double_prime_moments(const CouplingGeometry& coupling, const OperatingPoint& point,
                                 const ContactOptions& options);

/// Eqs 36-48 from a solved tooth contact at `point` (point.friction_coefficient is mu). Reads
/// the contact's members, not its table of teeth: a contact from tooth_contact_without_teeth()
/// gives the same moments, bit for bit.
InducedMoments induced_moments(const CouplingGeometry& coupling, const OperatingPoint& point,
                               const ToothContact& contact);

/// A load case: tooth_contact_without_teeth() into `contact`, then eqs 36-48 from it, bit for
/// bit the two calls, sharing what both read (eq 13's alpha, zeta's sine and cosine). What a
/// batch, the service's load cases and Python's induced_moments_many need; with a reused
/// `contact` it allocates nothing. Throws as tooth_contact().
InducedMoments induced_moments(const CouplingGeometry& coupling, const OperatingPoint& point,
                               const ContactOptions& options, ToothContact& contact);

/// Tooth contact (eqs 5-22, without listing the teeth) then eqs 36-48.
InducedMoments induced_moments(const CouplingGeometry& coupling, const OperatingPoint& point,
                               const ContactOptions& options = {});

}  // namespace gc
