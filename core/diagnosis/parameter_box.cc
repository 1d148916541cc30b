#include "core/diagnosis/parameter_box.h"

#include <algorithm>

namespace gc {

ParameterBox::ParameterBox(const EffectInfo& info) : info_(info) {}

double ParameterBox::range(int parameter) const {
  const ParameterSpec& spec = info_.parameters[static_cast<std::size_t>(parameter)];
  return spec.upper - spec.lower;
}

double ParameterBox::to_unit(int parameter, double value) const {
  const ParameterSpec& spec = info_.parameters[static_cast<std::size_t>(parameter)];
  return range(parameter) > 0.0 ? std::clamp((value - spec.lower) / range(parameter), 0.0, 1.0) : 0.0;
}

Eigen::VectorXd ParameterBox::to_unit(const std::vector<double>& values) const {
  Eigen::VectorXd x(size());
  for (int i = 0; i < size(); ++i) x(i) = to_unit(i, values[static_cast<std::size_t>(i)]);
  return x;
}

ParameterValues ParameterBox::to_values(const Eigen::VectorXd& unit) const {
  ParameterValues values;
  for (int i = 0; i < size(); ++i) {
    const ParameterSpec& spec = info_.parameters[static_cast<std::size_t>(i)];
    values[spec.name] = std::clamp(spec.lower + std::clamp(unit(i), 0.0, 1.0) * range(i), spec.lower, spec.upper);
  }
  return values;
}

Eigen::VectorXd ParameterBox::defaults() const {
  Eigen::VectorXd x(size());
  for (int i = 0; i < size(); ++i) x(i) = to_unit(i, info_.parameters[static_cast<std::size_t>(i)].default_value);
  return x;
}

}  // namespace gc
