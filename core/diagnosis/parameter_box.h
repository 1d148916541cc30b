// An effect's parameters scaled to the unit box by their physical bounds, so that the fit
// treats a friction coefficient and an angle alike; some parameters may be held fixed.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "core/effects/effect.h"

namespace gc {

class ParameterBox {
 public:
  explicit ParameterBox(const EffectInfo& info);

  const EffectInfo& info() const { return info_; }
  int size() const { return static_cast<int>(info_.parameters.size()); }

  /// x in [0, 1] for each parameter: (value - lower) / (upper - lower); 0 for a fixed-point range.
  Eigen::VectorXd to_unit(const std::vector<double>& values) const;
  double to_unit(int parameter, double value) const;
  /// Physical values, clamped to the bounds.
  ParameterValues to_values(const Eigen::VectorXd& unit) const;
  double range(int parameter) const;

  /// Every parameter at its default, in the unit box.
  Eigen::VectorXd defaults() const;

 private:
  const EffectInfo& info_;
};

}  // namespace gc
