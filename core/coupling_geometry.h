// A validated coupling with the quantities every equation shares derived once: pitch radius
// (eq 8), single-pair stiffness (eqs 5-6), crown radii (eq 12), sleeve tooth and space widths
// (eq 27) and the jam angle (eqs 23-35). Immutable after construction, so one instance can be
// shared by any number of threads.
#pragma once

#include <Eigen/Core>

#include "core/coupling_definition.h"
#include "core/jam_angle.h"

namespace gc {

class CouplingGeometry {
 public:
  /// Validates `definition` and derives the shared quantities. Throws InvalidInput naming the
  /// field ("coupling.backlash_m", ...) when the definition is not a physical coupling.
  explicit CouplingGeometry(CouplingDefinition definition);

  const CouplingDefinition& definition() const { return definition_; }
  const std::string& name() const { return definition_.name; }

  int teeth() const { return definition_.teeth; }                     ///< N [-]
  double pressure_angle_rad() const { return definition_.pressure_angle_rad; }  ///< phi
  double cos_pressure_angle() const { return cos_pressure_angle_; }  ///< cos phi (eq 7)
  double tan_pressure_angle() const { return tan_pressure_angle_; }  ///< tan phi (eq 11)
  double facewidth_m() const { return definition_.facewidth_m; }      ///< F [m]
  double backlash_m() const { return definition_.backlash_m; }        ///< b [m]
  double hub_tooth_thickness_m() const { return definition_.tooth_thickness_m; }  ///< t_c1 [m]

  double pitch_radius_m() const { return pitch_radius_m_; }           ///< R = N / (2P), eq 8
  double diametral_pitch_per_m() const { return diametral_pitch_; }   ///< P = N / D [1/m]
  double circular_pitch_m() const { return circular_pitch_m_; }       ///< pi / P [m]
  double sleeve_space_width_m() const { return sleeve_space_width_m_; }  ///< S_c2 = t_c1 + b
  double sleeve_tooth_thickness_m() const { return sleeve_tooth_m_; }    ///< t_c2, eq 27
  double crown_radius_m() const { return crown_radius_m_; }           ///< R_F [m]
  bool crown_radius_derived() const { return !definition_.crown_radius_m.has_value(); }
  double root_crown_radius_m() const { return root_crown_radius_m_; } ///< R_c, eq 12 [m]
  double mesh_stiffness_n_per_m() const { return stiffness_; }        ///< C, eqs 5-6 [N/m]
  double working_depth_m() const { return working_depth_m_; }         ///< h_w [m], stress.h
  double sleeve_root_diameter_m() const { return sleeve_root_diameter_m_; }
  const JamAngle& jam_angle() const { return jam_angle_; }           ///< eqs 23-35

  /// 2*pi*j/N for j = 0..N-1 and its sin and cos: tooth positions before the offset alpha
  /// (eqs 9 and 13). Tables once per coupling, so an evaluation runs over all teeth as arrays.
  const Eigen::ArrayXd& tooth_angle_rad() const { return tooth_angle_rad_; }
  const Eigen::ArrayXd& tooth_sin() const { return tooth_sin_; }
  const Eigen::ArrayXd& tooth_cos() const { return tooth_cos_; }

 private:
  CouplingDefinition definition_;
  double cos_pressure_angle_ = 1.0;
  double tan_pressure_angle_ = 0.0;
  double pitch_radius_m_ = 0.0;
  double diametral_pitch_ = 0.0;
  double circular_pitch_m_ = 0.0;
  double sleeve_space_width_m_ = 0.0;
  double sleeve_tooth_m_ = 0.0;
  double crown_radius_m_ = 0.0;
  double root_crown_radius_m_ = 0.0;
  double stiffness_ = 0.0;
  double working_depth_m_ = 0.0;
  double sleeve_root_diameter_m_ = 0.0;
  JamAngle jam_angle_;
  Eigen::ArrayXd tooth_angle_rad_;
  Eigen::ArrayXd tooth_sin_;
  Eigen::ArrayXd tooth_cos_;
};

}  // namespace gc
