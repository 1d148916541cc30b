// Bit-for-bit comparison of core results: every double compared by its bits (so -0.0 differs
// from 0.0 and NaN would equal only the same NaN), every count and flag by value.
#pragma once

#include <bit>
#include <cstdint>

#include <gtest/gtest.h>

#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/jam_angle.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"

namespace gc::test {

inline std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

#define GC_EXPECT_SAME_BITS(a, b, member) \
  EXPECT_EQ(::gc::test::bits((a).member), ::gc::test::bits((b).member)) << #member

inline void expect_identical(const ToothContact& a, const ToothContact& b) {
  GC_EXPECT_SAME_BITS(a, b, load_sharing.q);
  GC_EXPECT_SAME_BITS(a, b, load_sharing.ze_over_zo);
  EXPECT_EQ(a.load_sharing.iterations, b.load_sharing.iterations);
  GC_EXPECT_SAME_BITS(a, b, total_normal_load_n);
  GC_EXPECT_SAME_BITS(a, b, mean_tooth_load_n);
  GC_EXPECT_SAME_BITS(a, b, peak_tooth_load_n);
  GC_EXPECT_SAME_BITS(a, b, elastic_deformation_m);
  GC_EXPECT_SAME_BITS(a, b, max_separation_m);
  GC_EXPECT_SAME_BITS(a, b, offset_alpha_rad);
  GC_EXPECT_SAME_BITS(a, b, max_contact_offset_m);
  GC_EXPECT_SAME_BITS(a, b, z_axis_angle_rad);
  ASSERT_EQ(a.teeth.size(), b.teeth.size());
  for (std::size_t j = 0; j < a.teeth.size(); ++j) {
    GC_EXPECT_SAME_BITS(a.teeth[j], b.teeth[j], angle_rad);
    GC_EXPECT_SAME_BITS(a.teeth[j], b.teeth[j], load_n);
    GC_EXPECT_SAME_BITS(a.teeth[j], b.teeth[j], contact_offset_m);
    GC_EXPECT_SAME_BITS(a.teeth[j], b.teeth[j], deformation_m);
    GC_EXPECT_SAME_BITS(a.teeth[j], b.teeth[j], contact_length_m);
    GC_EXPECT_SAME_BITS(a.teeth[j], b.teeth[j], zone_begin_m);
    GC_EXPECT_SAME_BITS(a.teeth[j], b.teeth[j], zone_end_m);
  }
  EXPECT_EQ(a.teeth_in_contact, b.teeth_in_contact);
  EXPECT_EQ(a.max_load_tooth, b.max_load_tooth);
  GC_EXPECT_SAME_BITS(a, b, max_tooth_load_n);
  GC_EXPECT_SAME_BITS(a, b, sum_tooth_loads_n);
  EXPECT_EQ(a.edge_loaded, b.edge_loaded);
  EXPECT_EQ(a.slices, b.slices);
  GC_EXPECT_SAME_BITS(a, b, max_stress.contact_stress_pa);
  GC_EXPECT_SAME_BITS(a, b, max_stress.contact_half_width_m);
  GC_EXPECT_SAME_BITS(a, b, max_stress.bending_stress_pa);
  GC_EXPECT_SAME_BITS(a, b, max_stress.contact_safety_factor);
  GC_EXPECT_SAME_BITS(a, b, max_stress.bending_safety_factor);
}

inline void expect_identical(const JamAngle& a, const JamAngle& b) {
  GC_EXPECT_SAME_BITS(a, b, angle_rad);
  EXPECT_EQ(a.governing, b.governing);
  ASSERT_EQ(a.both_flanks_rad.has_value(), b.both_flanks_rad.has_value());
  if (a.both_flanks_rad) {
    EXPECT_EQ(bits(*a.both_flanks_rad), bits(*b.both_flanks_rad));
  }
  GC_EXPECT_SAME_BITS(a, b, facewidth_rad);
  GC_EXPECT_SAME_BITS(a, b, radial_rad);
}

inline void expect_identical(const InducedMoments& a, const InducedMoments& b) {
  GC_EXPECT_SAME_BITS(a, b, moment_y_dd_nm);
  GC_EXPECT_SAME_BITS(a, b, moment_z_dd_nm);
  GC_EXPECT_SAME_BITS(a, b, moment_y_nm);
  GC_EXPECT_SAME_BITS(a, b, moment_z_nm);
  GC_EXPECT_SAME_BITS(a, b, sensor_moment_y_nm);
  GC_EXPECT_SAME_BITS(a, b, sensor_moment_z_nm);
  GC_EXPECT_SAME_BITS(a, b, self_weight_moment_nm);
  GC_EXPECT_SAME_BITS(a, b, magnitude_nm);
  GC_EXPECT_SAME_BITS(a, b, direction_rad);
  EXPECT_EQ(a.teeth_summed, b.teeth_summed);
}

inline void expect_identical(const RestoringTorque& a, const RestoringTorque& b) {
  GC_EXPECT_SAME_BITS(a, b, torque_nm);
  EXPECT_EQ(a.contact, b.contact);
  EXPECT_EQ(a.teeth_in_contact, b.teeth_in_contact);
  GC_EXPECT_SAME_BITS(a, b, accessible_clearance_m);
  GC_EXPECT_SAME_BITS(a, b, design_clearance_m);
  GC_EXPECT_SAME_BITS(a, b, supported_weight_n);
  GC_EXPECT_SAME_BITS(a, b, sag_m);
}

inline void expect_identical(const FrictionEstimate& a, const FrictionEstimate& b) {
  GC_EXPECT_SAME_BITS(a, b, friction_coefficient);
  GC_EXPECT_SAME_BITS(a, b, moment_z_dd_nm);
}

}  // namespace gc::test
