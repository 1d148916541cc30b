#include "core/diagnosis/residual_signature.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

namespace gc {
namespace {

constexpr int kBins = 8;

struct InputAxis {
  std::string name, unit;
  std::function<std::optional<double>(const MeasurementSample&)> read;
  enum class Binning { quantile, angle, category } binning;
};

std::vector<InputAxis> axes() {
  using B = InputAxis::Binning;
  return {
      {"torque", "N·m", [](const MeasurementSample& s) { return std::optional(s.torque_nm); }, B::quantile},
      {"misalignment", "rad", [](const MeasurementSample& s) { return std::optional(s.misalignment_rad); }, B::quantile},
      {"direction", "rad",
       [](const MeasurementSample& s) {
         return std::optional(std::fmod(std::fmod(s.direction_rad, 2 * std::numbers::pi) + 2 * std::numbers::pi,
                                        2 * std::numbers::pi));
       },
       B::angle},
      {"loading_direction", "-", [](const MeasurementSample& s) { return std::optional<double>(s.loading_direction); }, B::category},
      {"time", "s", [](const MeasurementSample& s) { return std::optional(s.time_s); }, B::quantile},
      {"speed", "rpm", [](const MeasurementSample& s) { return s.speed_rpm; }, B::quantile},
      {"temperature", "deg C", [](const MeasurementSample& s) { return s.temperature_c; }, B::quantile},
      {"rotation_phase", "rad",
       [](const MeasurementSample& s) -> std::optional<double> {
         if (!s.rotation_phase_rad) return std::nullopt;
         const double p = std::fmod(*s.rotation_phase_rad, 2 * std::numbers::pi);
         return p < 0.0 ? p + 2 * std::numbers::pi : p;
       },
       B::angle},
  };
}

/// Bin index per row (-1 never happens: every row gets a bin).
std::vector<int> assign_bins(const Eigen::VectorXd& x, InputAxis::Binning binning, std::vector<std::pair<double, double>>& edges) {
  std::vector<int> bin(static_cast<std::size_t>(x.size()));
  if (binning == InputAxis::Binning::category) {
    for (Eigen::Index i = 0; i < x.size(); ++i) bin[static_cast<std::size_t>(i)] = static_cast<int>(x(i)) + 1;
    edges = {{-1, -1}, {0, 0}, {1, 1}};
    return bin;
  }
  if (binning == InputAxis::Binning::angle) {
    const double width = 2 * std::numbers::pi / kBins;
    for (int b = 0; b < kBins; ++b) edges.emplace_back(b * width, (b + 1) * width);
    for (Eigen::Index i = 0; i < x.size(); ++i) bin[static_cast<std::size_t>(i)] = std::min(kBins - 1, static_cast<int>(x(i) / width));
    return bin;
  }
  std::vector<Eigen::Index> order(static_cast<std::size_t>(x.size()));
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<Eigen::Index>(i);
  std::stable_sort(order.begin(), order.end(), [&x](auto a, auto b) { return x(a) < x(b); });
  // Equal-count bins; ties stay together so a bin never splits one input value.
  int b = 0;
  const std::size_t n = order.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0 && x(order[k]) != x(order[k - 1]) && k * kBins / n > static_cast<std::size_t>(b)) ++b;
    bin[static_cast<std::size_t>(order[k])] = b;
  }
  edges.assign(static_cast<std::size_t>(b + 1), {INFINITY, -INFINITY});
  for (std::size_t k = 0; k < n; ++k) {
    auto& e = edges[static_cast<std::size_t>(bin[static_cast<std::size_t>(order[k])])];
    e.first = std::min(e.first, x(order[k]));
    e.second = std::max(e.second, x(order[k]));
  }
  return bin;
}

/// The chi-square quantile per degree of freedom at z standard deviations (Wilson-Hilferty).
double chi_square_per_dof(int dof, double z) {
  const double a = 2.0 / (9.0 * dof);
  return std::pow(1.0 - a + z * std::sqrt(a), 3.0);
}

InputSignature signature_for(const InputAxis& axis, const Eigen::VectorXd& x, const Eigen::MatrixX2d& r,
                             double inflation) {
  InputSignature s{axis.name, axis.unit, {}, 0.0, 0.0, false, 0.0, 0.0};
  std::vector<std::pair<double, double>> edges;
  const std::vector<int> bin = assign_bins(x, axis.binning, edges);
  s.bins.resize(edges.size());
  for (std::size_t b = 0; b < edges.size(); ++b) { s.bins[b].lower = edges[b].first; s.bins[b].upper = edges[b].second; }
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    SignatureBin& b = s.bins[static_cast<std::size_t>(bin[static_cast<std::size_t>(i)])];
    ++b.count;
    b.mean_y_nm += r(i, 0);
    b.mean_z_nm += r(i, 1);
  }
  std::erase_if(s.bins, [](const SignatureBin& b) { return b.count == 0; });
  const Eigen::Vector2d mean = r.colwise().mean();
  Eigen::Vector2d between = Eigen::Vector2d::Zero();
  for (SignatureBin& b : s.bins) {
    b.mean_y_nm /= static_cast<double>(b.count);
    b.mean_z_nm /= static_cast<double>(b.count);
    between(0) += b.count * std::pow(b.mean_y_nm - mean(0), 2);
    between(1) += b.count * std::pow(b.mean_z_nm - mean(1), 2);
  }
  const double total = (r.rowwise() - mean.transpose()).squaredNorm();
  s.explained_share = total > 0.0 ? between.sum() / total : 0.0;
  // One-way analysis of variance per channel: the bin means' scatter against the scatter
  // within the bins, so that a residual driven by another input (spread evenly over these
  // bins) does not make this input look systematic.
  const int dof = static_cast<int>(s.bins.size()) - 1;
  const double within_dof = static_cast<double>(x.size()) - static_cast<double>(s.bins.size());
  if (dof >= 1 && within_dof >= 1.0) {
    const Eigen::Vector2d total_per_channel = (r.rowwise() - mean.transpose()).colwise().squaredNorm().transpose();
    const Eigen::Array2d within = (total_per_channel - between).array().max(1e-300);
    s.dispersion = ((between.array() / dof) / (within / within_dof)).maxCoeff() / std::max(1.0, inflation);
    // z = 3.7: a one-sided 1e-4 level, strict because many inputs and two channels are tested.
    s.systematic = s.dispersion > chi_square_per_dof(dof, 3.7);
  }
  const Eigen::VectorXd centred = x.array() - x.mean();
  const double sxx = centred.squaredNorm();
  if (sxx > 0.0) { s.slope_y = centred.dot(r.col(0)) / sxx; s.slope_z = centred.dot(r.col(1)) / sxx; }
  return s;
}

}  // namespace

bool ResidualSignature::systematic() const {
  return std::any_of(inputs.begin(), inputs.end(), [](const InputSignature& s) { return s.systematic; });
}

ResidualSignature residual_signature(std::span<const RecordedSample> observations,
                                     std::span<const std::size_t> rows,
                                     const Eigen::MatrixX2d& residual, double variance_inflation) {
  ResidualSignature out;
  if (rows.size() < 2) return out;
  for (const InputAxis& axis : axes()) {
    Eigen::VectorXd x(static_cast<Eigen::Index>(rows.size()));
    bool complete = true;
    for (std::size_t k = 0; k < rows.size() && complete; ++k) {
      const std::optional<double> v = axis.read(observations[rows[k]].input);
      complete = v.has_value();
      if (complete) x(static_cast<Eigen::Index>(k)) = *v;
    }
    if (complete) out.inputs.push_back(signature_for(axis, x, residual, variance_inflation));
  }
  std::stable_sort(out.inputs.begin(), out.inputs.end(),
                   [](const InputSignature& a, const InputSignature& b) { return a.explained_share > b.explained_share; });
  return out;
}

}  // namespace gc
