// An effect's parameters scaled to a unit box, so that the fit treats a friction coefficient and
// an angle alike. The box is the range the fit searches: the plausible range for the coupling at
// first (ParameterSpec::plausible), widened toward the physical bounds when a fit sits on its edge.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "core/effects/effect.h"

namespace gc {

class ParameterBox {
 public:
  /// The box of the physical bounds.
  explicit ParameterBox(const EffectInfo& info);
  /// The box [lower, upper] per parameter (within the bounds).
  ParameterBox(const EffectInfo& info, std::vector<double> lower, std::vector<double> upper);
  /// The plausible ranges for a coupling of jam angle `jam_angle_rad`, widened to hold `include`
  /// (values in the order of the parameters; empty for none).
  static ParameterBox plausible(const EffectInfo& info, double jam_angle_rad,
                                const std::vector<double>& include = {});

  const EffectInfo& info() const { return *info_; }
  int size() const { return static_cast<int>(info_->parameters.size()); }
  double lower(int parameter) const { return lower_[static_cast<std::size_t>(parameter)]; }
  double upper(int parameter) const { return upper_[static_cast<std::size_t>(parameter)]; }
  /// True when the box edge at unit value `unit` (0 or 1) is a physical bound.
  bool at_physical_bound(int parameter, double unit) const;
  /// This box with the edge the parameter's unit value sits on moved to the physical bound.
  ParameterBox widened(int parameter, double unit) const;

  /// x in [0, 1] for each parameter: (value - lower) / (upper - lower); 0 for a fixed-point range.
  Eigen::VectorXd to_unit(const std::vector<double>& values) const;
  double to_unit(int parameter, double value) const;
  /// Physical values, clamped to the box.
  ParameterValues to_values(const Eigen::VectorXd& unit) const;
  double range(int parameter) const;

  /// Every parameter at its default, in the unit box.
  Eigen::VectorXd defaults() const;

 private:
  const EffectInfo* info_;  ///< never null
  std::vector<double> lower_, upper_;
};

}  // namespace gc
