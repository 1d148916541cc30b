#include "diagnosis/parameter_box.h"

#include <algorithm>

namespace gc {

ParameterBox::ParameterBox(const EffectInfo& info) : info_(&info) {
  for (const ParameterSpec& spec : info.parameters) {
    lower_.push_back(spec.lower);
    upper_.push_back(spec.upper);
  }
}

ParameterBox::ParameterBox(const EffectInfo& info, std::vector<double> lower, std::vector<double> upper)
    : info_(&info), lower_(std::move(lower)), upper_(std::move(upper)) {}

ParameterBox ParameterBox::plausible(const EffectInfo& info, double jam_angle_rad, const std::vector<double>& include) {
  std::vector<double> lower, upper;
  for (std::size_t i = 0; i < info.parameters.size(); ++i) {
    auto [low, high] = plausible_range(info.parameters[i], jam_angle_rad);
    if (i < include.size()) {
      low = std::min(low, include[i]);
      high = std::max(high, include[i]);
    }
    lower.push_back(low);
    upper.push_back(high);
  }
  return ParameterBox(info, std::move(lower), std::move(upper));
}

bool ParameterBox::at_physical_bound(int parameter, double unit) const {
  const ParameterSpec& spec = info_->parameters[static_cast<std::size_t>(parameter)];
  return unit <= 0.5 ? lower(parameter) <= spec.lower : upper(parameter) >= spec.upper;
}

ParameterBox ParameterBox::widened(int parameter, double unit) const {
  ParameterBox out = *this;
  const ParameterSpec& spec = info_->parameters[static_cast<std::size_t>(parameter)];
  if (unit <= 0.5) out.lower_[static_cast<std::size_t>(parameter)] = spec.lower;
  else out.upper_[static_cast<std::size_t>(parameter)] = spec.upper;
  return out;
}

double ParameterBox::range(int parameter) const { return upper(parameter) - lower(parameter); }

double ParameterBox::to_unit(int parameter, double value) const {
  return range(parameter) > 0.0 ? std::clamp((value - lower(parameter)) / range(parameter), 0.0, 1.0) : 0.0;
}

Eigen::VectorXd ParameterBox::to_unit(const std::vector<double>& values) const {
  Eigen::VectorXd x(size());
  for (int i = 0; i < size(); ++i) x(i) = to_unit(i, values[static_cast<std::size_t>(i)]);
  return x;
}

ParameterValues ParameterBox::to_values(const Eigen::VectorXd& unit) const {
  ParameterValues values;
  for (int i = 0; i < size(); ++i) {
    const ParameterSpec& spec = info_->parameters[static_cast<std::size_t>(i)];
    values[spec.name] = std::clamp(lower(i) + std::clamp(unit(i), 0.0, 1.0) * range(i), lower(i), upper(i));
  }
  return values;
}

Eigen::VectorXd ParameterBox::defaults() const {
  Eigen::VectorXd x(size());
  for (int i = 0; i < size(); ++i) x(i) = to_unit(i, info_->parameters[static_cast<std::size_t>(i)].default_value);
  return x;
}

}  // namespace gc
