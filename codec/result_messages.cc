#include "codec/result_messages.h"

#include <cmath>
#include <string>

#include "codec/angle_units.h"

namespace gc::codec {
namespace {

v1::ToothStressRecord to_message(const ToothStress& stress) {
  v1::ToothStressRecord m;
  m.set_contact_stress_pa(stress.contact_stress_pa);
  m.set_contact_half_width_m(stress.contact_half_width_m);
  m.set_bending_stress_pa(stress.bending_stress_pa);
  m.set_contact_safety_factor(stress.contact_safety_factor);
  m.set_bending_safety_factor(stress.bending_safety_factor);
  return m;
}

v1::LoadSharingRecord to_message(const LoadSharing& sharing) {
  v1::LoadSharingRecord m;
  m.set_q(sharing.q);
  // Aligned couplings have z_o = 0: the ratio is infinite, which JSON cannot carry as a number.
  if (std::isfinite(sharing.ze_over_zo)) m.set_ze_over_zo(sharing.ze_over_zo);
  m.set_iterations(sharing.iterations);
  return m;
}

void add_tooth(const ToothContact& contact, const Eigen::MatrixXd& slice_loads, int j,
               v1::ToothContactResult& result) {
  const ToothLoad& tooth = contact.teeth[static_cast<std::size_t>(j)];
  v1::ToothLoadRecord* m = result.add_teeth();
  m->set_index(j);
  m->set_angle_deg(degrees_from_radians(tooth.angle_rad));
  m->set_load_n(tooth.load_n);
  m->set_contact_offset_m(tooth.contact_offset_m);
  m->set_deformation_m(tooth.deformation_m);
  m->set_contact_length_m(tooth.contact_length_m);
  m->set_zone_begin_m(tooth.zone_begin_m);
  m->set_zone_end_m(tooth.zone_end_m);
  const int slices = contact.slices;
  for (int column = 0; column <= slices; ++column) {
    m->add_slice_loads_n(slice_loads(j, column));
    m->add_slice_positions_m(contact.slice_position_m(j, column - slices / 2));
  }
}

}  // namespace

v1::OperatingPointRecord to_message(const OperatingPoint& point) {
  v1::OperatingPointRecord m;
  m.set_torque_nm(point.torque_nm);
  m.set_misalignment_deg(degrees_from_radians(point.misalignment_rad));
  m.set_direction_deg(degrees_from_radians(point.direction_rad));
  m.set_friction_coefficient(point.friction_coefficient);
  return m;
}

v1::ToothContactResult to_message(std::string_view coupling, const OperatingPoint& point,
                                  const ToothContact& contact) {
  v1::ToothContactResult m;
  m.set_coupling(std::string(coupling));
  *m.mutable_operating_point() = to_message(point);
  *m.mutable_load_sharing() = to_message(contact.load_sharing);
  m.set_total_normal_load_n(contact.total_normal_load_n);
  m.set_mean_tooth_load_n(contact.mean_tooth_load_n);
  m.set_peak_tooth_load_n(contact.peak_tooth_load_n);
  m.set_elastic_deformation_m(contact.elastic_deformation_m);
  m.set_max_separation_m(contact.max_separation_m);
  m.set_offset_alpha_deg(degrees_from_radians(contact.offset_alpha_rad));
  m.set_max_contact_offset_m(contact.max_contact_offset_m);
  m.set_z_axis_angle_deg(degrees_from_radians(contact.z_axis_angle_rad));
  m.set_teeth_in_contact(contact.teeth_in_contact);
  m.set_max_load_tooth(contact.max_load_tooth);
  m.set_max_tooth_load_n(contact.max_tooth_load_n);
  m.set_sum_tooth_loads_n(contact.sum_tooth_loads_n);
  m.set_edge_loaded(contact.edge_loaded);
  for (double weight : contact.slice_weights()) m.add_slice_weights(weight);
  *m.mutable_max_stress() = to_message(contact.max_stress);
  const Eigen::MatrixXd slice_loads = contact.slice_loads();
  for (int j = 0; j < static_cast<int>(contact.teeth.size()); ++j) {
    add_tooth(contact, slice_loads, j, m);
  }
  return m;
}

v1::JamAngleResult to_message(std::string_view coupling, const JamAngle& jam,
                              double crown_radius_m, bool crown_radius_derived) {
  v1::JamAngleResult m;
  m.set_coupling(std::string(coupling));
  m.set_angle_deg(degrees_from_radians(jam.angle_rad));
  m.set_angle_rad(jam.angle_rad);
  m.set_governing(std::string(to_string(jam.governing)));
  if (jam.both_flanks_rad) m.set_both_flanks_deg(degrees_from_radians(*jam.both_flanks_rad));
  m.set_facewidth_deg(degrees_from_radians(jam.facewidth_rad));
  m.set_radial_deg(degrees_from_radians(jam.radial_rad));
  m.set_crown_radius_m(crown_radius_m);
  m.set_crown_radius_derived(crown_radius_derived);
  return m;
}

v1::InducedMomentsResult to_message(std::string_view coupling, const OperatingPoint& point,
                                    const ToothContact& contact, const InducedMoments& moments) {
  v1::InducedMomentsResult m;
  m.set_coupling(std::string(coupling));
  *m.mutable_operating_point() = to_message(point);
  m.set_q(contact.load_sharing.q);
  m.set_teeth_in_contact(contact.teeth_in_contact);
  m.set_max_tooth_load_n(contact.max_tooth_load_n);
  m.set_moment_y_dd_nm(moments.moment_y_dd_nm);
  m.set_moment_z_dd_nm(moments.moment_z_dd_nm);
  m.set_moment_y_nm(moments.moment_y_nm);
  m.set_moment_z_nm(moments.moment_z_nm);
  m.set_sensor_moment_y_nm(moments.sensor_moment_y_nm);
  m.set_sensor_moment_z_nm(moments.sensor_moment_z_nm);
  m.set_self_weight_moment_nm(moments.self_weight_moment_nm);
  m.set_magnitude_nm(moments.magnitude_nm);
  m.set_direction_deg(degrees_from_radians(moments.direction_rad));
  m.set_teeth_summed(moments.teeth_summed);
  return m;
}

v1::RestoringTorqueResult to_message(std::string_view coupling, const RestoringTorque& torque) {
  v1::RestoringTorqueResult m;
  m.set_coupling(std::string(coupling));
  m.set_torque_nm(torque.torque_nm);
  m.set_root_contact(std::string(to_string(torque.contact)));
  m.set_teeth_in_contact(torque.teeth_in_contact);
  m.set_accessible_clearance_m(torque.accessible_clearance_m);
  m.set_design_clearance_m(torque.design_clearance_m);
  m.set_supported_weight_n(torque.supported_weight_n);
  m.set_sag_m(torque.sag_m);
  return m;
}

v1::FrictionEstimateResult to_message(std::string_view coupling,
                                      const FrictionMeasurement& measurement,
                                      const FrictionEstimate& estimate) {
  v1::FrictionEstimateResult m;
  m.set_coupling(std::string(coupling));
  auto* recorded = m.mutable_measurement();
  recorded->set_torque_nm(measurement.torque_nm);
  recorded->set_misalignment_deg(degrees_from_radians(measurement.misalignment_rad));
  recorded->set_direction_deg(degrees_from_radians(measurement.direction_rad));
  recorded->set_sensor_moment_y_nm(measurement.sensor_moment_y_nm);
  recorded->set_sensor_moment_z_nm(measurement.sensor_moment_z_nm);
  m.set_friction_coefficient(estimate.friction_coefficient);
  m.set_moment_z_dd_nm(estimate.moment_z_dd_nm);
  return m;
}

}  // namespace gc::codec
