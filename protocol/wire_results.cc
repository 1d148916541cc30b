#include "protocol/wire_results.h"

#include "protocol/field_copy.h"

#include <optional>

namespace gc::protocol {
namespace {

template <typename Element>
Element* wire_buffer(std::size_t count) {
  return count == 0 ? nullptr : static_cast<Element*>(dds_alloc(count * sizeof(Element)));
}

// The scalar fields of a tooth-contact result, one list for both directions (see
// coupling_numeric_fields in wire_inputs.cc): `copy(core_field, wire_field)` for each.
template <typename Core, typename Wire, typename Copy>
void tooth_contact_scalars(Core& core, Wire& wire, Copy copy) {
  copy(core.load_sharing.q, wire.load_sharing.q);
  copy(core.load_sharing.ze_over_zo, wire.load_sharing.ze_over_zo);
  copy(core.load_sharing.iterations, wire.load_sharing.iterations);
  copy(core.total_normal_load_n, wire.total_normal_load_n);
  copy(core.mean_tooth_load_n, wire.mean_tooth_load_n);
  copy(core.peak_tooth_load_n, wire.peak_tooth_load_n);
  copy(core.elastic_deformation_m, wire.elastic_deformation_m);
  copy(core.max_separation_m, wire.max_separation_m);
  copy(core.offset_alpha_rad, wire.offset_alpha_rad);
  copy(core.max_contact_offset_m, wire.max_contact_offset_m);
  copy(core.z_axis_angle_rad, wire.z_axis_angle_rad);
  copy(core.teeth_in_contact, wire.teeth_in_contact);
  copy(core.max_load_tooth, wire.max_load_tooth);
  copy(core.max_tooth_load_n, wire.max_tooth_load_n);
  copy(core.sum_tooth_loads_n, wire.sum_tooth_loads_n);
  copy(core.edge_loaded, wire.edge_loaded);
  copy(core.slices, wire.slices);
  copy(core.max_stress.contact_stress_pa, wire.max_stress.contact_stress_pa);
  copy(core.max_stress.contact_half_width_m, wire.max_stress.contact_half_width_m);
  copy(core.max_stress.bending_stress_pa, wire.max_stress.bending_stress_pa);
  copy(core.max_stress.contact_safety_factor, wire.max_stress.contact_safety_factor);
  copy(core.max_stress.bending_safety_factor, wire.max_stress.bending_safety_factor);
}

template <typename Core, typename Wire, typename Copy>
void tooth_fields(Core& core, Wire& wire, Copy copy) {
  copy(core.angle_rad, wire.angle_rad);
  copy(core.load_n, wire.load_n);
  copy(core.contact_offset_m, wire.contact_offset_m);
  copy(core.deformation_m, wire.deformation_m);
  copy(core.contact_length_m, wire.contact_length_m);
  copy(core.zone_begin_m, wire.zone_begin_m);
  copy(core.zone_end_m, wire.zone_end_m);
}

template <typename Core, typename Wire, typename Copy>
void restoring_torque_scalars(Core& core, Wire& wire, Copy copy) {
  copy(core.torque_nm, wire.torque_nm);
  copy(core.teeth_in_contact, wire.teeth_in_contact);
  copy(core.accessible_clearance_m, wire.accessible_clearance_m);
  copy(core.design_clearance_m, wire.design_clearance_m);
  copy(core.supported_weight_n, wire.supported_weight_n);
  copy(core.sag_m, wire.sag_m);
}

}  // namespace

void to_wire(const ToothContact& in, gearcoupling_ToothContactResult& out) {
  tooth_contact_scalars(in, out, kToWire);
  const auto teeth = static_cast<std::uint32_t>(in.teeth.size());
  out.teeth._buffer = wire_buffer<gearcoupling_ToothLoad>(teeth);
  out.teeth._length = out.teeth._maximum = teeth;
  out.teeth._release = true;
  for (std::uint32_t j = 0; j < teeth; ++j) tooth_fields(in.teeth[j], out.teeth._buffer[j], kToWire);
}

ToothContact from_wire(const gearcoupling_ToothContactResult& in) {
  ToothContact out;
  tooth_contact_scalars(out, in, kFromWire);
  out.teeth.resize(in.teeth._length);
  for (std::uint32_t j = 0; j < in.teeth._length; ++j) tooth_fields(out.teeth[j], in.teeth._buffer[j], kFromWire);
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
  restoring_torque_scalars(in, out, kToWire);
  out.contact = in.contact == RootContact::kSleeveSides ? gearcoupling_ROOT_SLEEVE_SIDES
                                                        : gearcoupling_ROOT_SLEEVE_BOTTOM;
}

RestoringTorque from_wire(const gearcoupling_RestoringTorqueResult& in) {
  RestoringTorque out;
  restoring_torque_scalars(out, in, kFromWire);
  out.contact = in.contact == gearcoupling_ROOT_SLEEVE_SIDES ? RootContact::kSleeveSides
                                                             : RootContact::kSleeveBottom;
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
