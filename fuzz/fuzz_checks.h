// What every fuzz target asserts about the code it drives: a result has no NaN (and no infinity
// where the result's documentation allows none), and an error is one of the types the function
// documents. A broken promise aborts, so libFuzzer records the input as a crash.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/jam_angle.h"
#include "core/model_error.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"

namespace gc::fuzz {

[[noreturn]] inline void fail(std::string_view what) {
  std::fprintf(stderr, "fuzz check failed: %.*s\n", static_cast<int>(what.size()), what.data());
  std::abort();
}

inline void check_finite(std::string_view name, double value) {
  if (!std::isfinite(value)) fail(std::string(name) + " = " + std::to_string(value));
}

inline void check_not_nan(std::string_view name, double value) {
  if (std::isnan(value)) fail(std::string(name) + " is NaN");
}

/// An InvalidInput must name the field it blames and say something about it.
inline void check_invalid_input(const InvalidInput& error) {
  if (error.field().empty()) fail(std::string("InvalidInput without a field: ") + error.what());
  if (std::string_view(error.what()).empty()) fail("InvalidInput without a message");
}

/// Runs `call`; an exception that is not one of `Allowed...` (or derived from one) fails the run.
template <typename... Allowed, typename Call>
void expect_result_or(Call&& call) {
  try {
    call();
  } catch (const std::exception& error) {
    const bool allowed = (... || (dynamic_cast<const Allowed*>(&error) != nullptr));
    if (!allowed) fail(std::string("undocumented exception: ") + error.what());
    if (const auto* invalid = dynamic_cast<const InvalidInput*>(&error)) {
      check_invalid_input(*invalid);
    }
  } catch (...) {
    fail("an exception that is not a std::exception");
  }
}

inline void check(const ToothContact& c, int teeth) {
  check_finite("load_sharing.q", c.load_sharing.q);
  check_not_nan("load_sharing.ze_over_zo", c.load_sharing.ze_over_zo);  // infinite when aligned
  if (!(c.load_sharing.q > 0.0 && c.load_sharing.q <= 1.0)) fail("q outside (0, 1]");
  for (double v : {c.total_normal_load_n, c.mean_tooth_load_n, c.peak_tooth_load_n,
                   c.elastic_deformation_m, c.max_separation_m, c.offset_alpha_rad,
                   c.max_contact_offset_m, c.z_axis_angle_rad, c.max_tooth_load_n,
                   c.sum_tooth_loads_n}) {
    check_finite("tooth contact", v);
  }
  if (static_cast<int>(c.teeth.size()) != teeth) fail("tooth contact: not one load per tooth");
  if (c.teeth_in_contact < 0 || c.teeth_in_contact > teeth) fail("teeth_in_contact out of range");
  for (const ToothLoad& t : c.teeth) {
    for (double v : {t.angle_rad, t.load_n, t.contact_offset_m, t.deformation_m,
                     t.contact_length_m, t.zone_begin_m, t.zone_end_m}) {
      check_finite("tooth load", v);
    }
    if (t.load_n < 0.0) fail("negative tooth load");
  }
  for (double v : {c.max_stress.contact_stress_pa, c.max_stress.contact_half_width_m,
                   c.max_stress.bending_stress_pa}) {
    check_finite("stress", v);
  }
  // A tooth without load reports its infinite safety as the largest double (stress.h).
  check_finite("contact_safety_factor", c.max_stress.contact_safety_factor);
  check_finite("bending_safety_factor", c.max_stress.bending_safety_factor);
}

inline void check(const InducedMoments& m) {
  for (double v : {m.moment_y_dd_nm, m.moment_z_dd_nm, m.moment_y_nm, m.moment_z_nm,
                   m.sensor_moment_y_nm, m.sensor_moment_z_nm, m.self_weight_moment_nm,
                   m.magnitude_nm, m.direction_rad}) {
    check_finite("induced moments", v);
  }
}

inline void check(const JamAngle& jam) {
  check_finite("jam angle", jam.angle_rad);
  if (!(jam.angle_rad > 0.0)) fail("jam angle not positive");
  check_not_nan("jam facewidth_rad", jam.facewidth_rad);
  check_not_nan("jam radial_rad", jam.radial_rad);
  if (jam.both_flanks_rad) check_finite("jam both_flanks_rad", *jam.both_flanks_rad);
}

inline void check(const RestoringTorque& r) {
  for (double v : {r.torque_nm, r.accessible_clearance_m, r.design_clearance_m,
                   r.supported_weight_n, r.sag_m}) {
    check_finite("restoring torque", v);
  }
  if (r.teeth_in_contact < 0) fail("restoring torque: negative teeth in contact");
}

inline void check(const FrictionEstimate& f) {
  check_finite("friction_coefficient", f.friction_coefficient);
  check_finite("moment_z_dd_nm", f.moment_z_dd_nm);
  if (f.friction_coefficient < 0.0 || f.friction_coefficient > 1.0) fail("mu outside [0, 1]");
}

}  // namespace gc::fuzz
