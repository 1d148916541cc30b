#include "protocol/wire_results.h"

#include <optional>

namespace gc::protocol {
namespace {

template <typename Element>
Element* wire_buffer(std::size_t count) {
  return count == 0 ? nullptr : static_cast<Element*>(dds_alloc(count * sizeof(Element)));
}

}  // namespace

void to_wire(const ToothContact& in, gearcoupling_ToothContactResult& out) {
  out.load_sharing.q = in.load_sharing.q;
  out.load_sharing.ze_over_zo = in.load_sharing.ze_over_zo;
  out.load_sharing.iterations = in.load_sharing.iterations;
  out.total_normal_load_n = in.total_normal_load_n;
  out.mean_tooth_load_n = in.mean_tooth_load_n;
  out.peak_tooth_load_n = in.peak_tooth_load_n;
  out.elastic_deformation_m = in.elastic_deformation_m;
  out.max_separation_m = in.max_separation_m;
  out.offset_alpha_rad = in.offset_alpha_rad;
  out.max_contact_offset_m = in.max_contact_offset_m;
  out.z_axis_angle_rad = in.z_axis_angle_rad;
  const auto teeth = static_cast<std::uint32_t>(in.teeth.size());
  out.teeth._buffer = wire_buffer<gearcoupling_ToothLoad>(teeth);
  out.teeth._length = out.teeth._maximum = teeth;
  out.teeth._release = true;
  for (std::uint32_t j = 0; j < teeth; ++j) {
    const ToothLoad& t = in.teeth[j];
    out.teeth._buffer[j] = gearcoupling_ToothLoad{t.angle_rad,        t.load_n,
                                                  t.contact_offset_m, t.deformation_m,
                                                  t.contact_length_m, t.zone_begin_m,
                                                  t.zone_end_m};
  }
  out.teeth_in_contact = in.teeth_in_contact;
  out.max_load_tooth = in.max_load_tooth;
  out.max_tooth_load_n = in.max_tooth_load_n;
  out.sum_tooth_loads_n = in.sum_tooth_loads_n;
  out.edge_loaded = in.edge_loaded;
  out.slices = in.slices;
  out.max_stress = gearcoupling_ToothStress{
      in.max_stress.contact_stress_pa, in.max_stress.contact_half_width_m,
      in.max_stress.bending_stress_pa, in.max_stress.contact_safety_factor,
      in.max_stress.bending_safety_factor};
}

ToothContact from_wire(const gearcoupling_ToothContactResult& in) {
  ToothContact out;
  out.load_sharing.q = in.load_sharing.q;
  out.load_sharing.ze_over_zo = in.load_sharing.ze_over_zo;
  out.load_sharing.iterations = in.load_sharing.iterations;
  out.total_normal_load_n = in.total_normal_load_n;
  out.mean_tooth_load_n = in.mean_tooth_load_n;
  out.peak_tooth_load_n = in.peak_tooth_load_n;
  out.elastic_deformation_m = in.elastic_deformation_m;
  out.max_separation_m = in.max_separation_m;
  out.offset_alpha_rad = in.offset_alpha_rad;
  out.max_contact_offset_m = in.max_contact_offset_m;
  out.z_axis_angle_rad = in.z_axis_angle_rad;
  out.teeth.resize(in.teeth._length);
  for (std::uint32_t j = 0; j < in.teeth._length; ++j) {
    const gearcoupling_ToothLoad& t = in.teeth._buffer[j];
    out.teeth[j] = ToothLoad{t.angle_rad,        t.load_n,       t.contact_offset_m,
                             t.deformation_m,    t.contact_length_m, t.zone_begin_m,
                             t.zone_end_m};
  }
  out.teeth_in_contact = in.teeth_in_contact;
  out.max_load_tooth = in.max_load_tooth;
  out.max_tooth_load_n = in.max_tooth_load_n;
  out.sum_tooth_loads_n = in.sum_tooth_loads_n;
  out.edge_loaded = in.edge_loaded;
  out.slices = in.slices;
  out.max_stress = ToothStress{in.max_stress.contact_stress_pa, in.max_stress.contact_half_width_m,
                               in.max_stress.bending_stress_pa,
                               in.max_stress.contact_safety_factor,
                               in.max_stress.bending_safety_factor};
  return out;
}

void to_wire(const JamAngleResult& result, gearcoupling_JamAngleResult& out) {
  const JamAngle& in = result.jam;
  out.crown_radius_m = result.crown_radius_m;
  out.crown_radius_derived = result.crown_radius_derived;
  out.angle_rad = in.angle_rad;
  switch (in.governing) {
    case JamCriterion::kBothFlanks: out.governing = gearcoupling_JAM_BOTH_FLANKS; break;
    case JamCriterion::kFacewidth: out.governing = gearcoupling_JAM_FACEWIDTH; break;
    case JamCriterion::kRadial: out.governing = gearcoupling_JAM_RADIAL; break;
  }
  out.both_flanks_rad = nullptr;
  if (in.both_flanks_rad) {
    out.both_flanks_rad = static_cast<double*>(dds_alloc(sizeof(double)));
    *out.both_flanks_rad = *in.both_flanks_rad;
  }
  out.facewidth_rad = in.facewidth_rad;
  out.radial_rad = in.radial_rad;
}

JamAngleResult from_wire(const gearcoupling_JamAngleResult& in) {
  JamAngleResult result{{}, in.crown_radius_m, in.crown_radius_derived};
  JamAngle& out = result.jam;
  out.angle_rad = in.angle_rad;
  switch (in.governing) {
    case gearcoupling_JAM_BOTH_FLANKS: out.governing = JamCriterion::kBothFlanks; break;
    case gearcoupling_JAM_FACEWIDTH: out.governing = JamCriterion::kFacewidth; break;
    case gearcoupling_JAM_RADIAL: out.governing = JamCriterion::kRadial; break;
  }
  if (in.both_flanks_rad != nullptr) out.both_flanks_rad = *in.both_flanks_rad;
  out.facewidth_rad = in.facewidth_rad;
  out.radial_rad = in.radial_rad;
  return result;
}

void to_wire(const InducedMoments& in, gearcoupling_InducedMomentsResult& out) {
  out = gearcoupling_InducedMomentsResult{
      in.moment_y_dd_nm,     in.moment_z_dd_nm,        in.moment_y_nm,  in.moment_z_nm,
      in.sensor_moment_y_nm, in.sensor_moment_z_nm,    in.self_weight_moment_nm,
      in.magnitude_nm,       in.direction_rad,         in.teeth_summed};
}

InducedMoments from_wire(const gearcoupling_InducedMomentsResult& in) {
  return InducedMoments{in.moment_y_dd_nm,     in.moment_z_dd_nm,     in.moment_y_nm,
                        in.moment_z_nm,        in.sensor_moment_y_nm, in.sensor_moment_z_nm,
                        in.self_weight_moment_nm, in.magnitude_nm,    in.direction_rad,
                        in.teeth_summed};
}

void to_wire(const RestoringTorque& in, gearcoupling_RestoringTorqueResult& out) {
  out.torque_nm = in.torque_nm;
  out.contact = in.contact == RootContact::kSleeveSides ? gearcoupling_ROOT_SLEEVE_SIDES
                                                        : gearcoupling_ROOT_SLEEVE_BOTTOM;
  out.teeth_in_contact = in.teeth_in_contact;
  out.accessible_clearance_m = in.accessible_clearance_m;
  out.design_clearance_m = in.design_clearance_m;
  out.supported_weight_n = in.supported_weight_n;
  out.sag_m = in.sag_m;
}

RestoringTorque from_wire(const gearcoupling_RestoringTorqueResult& in) {
  RestoringTorque out;
  out.torque_nm = in.torque_nm;
  out.contact = in.contact == gearcoupling_ROOT_SLEEVE_SIDES ? RootContact::kSleeveSides
                                                             : RootContact::kSleeveBottom;
  out.teeth_in_contact = in.teeth_in_contact;
  out.accessible_clearance_m = in.accessible_clearance_m;
  out.design_clearance_m = in.design_clearance_m;
  out.supported_weight_n = in.supported_weight_n;
  out.sag_m = in.sag_m;
  return out;
}

void to_wire(const FrictionEstimate& in, gearcoupling_FrictionEstimateResult& out) {
  out.friction_coefficient = in.friction_coefficient;
  out.moment_z_dd_nm = in.moment_z_dd_nm;
}

FrictionEstimate from_wire(const gearcoupling_FrictionEstimateResult& in) {
  return FrictionEstimate{in.friction_coefficient, in.moment_z_dd_nm};
}

}  // namespace gc::protocol
