#include "diagnosis/residual_signature.h"

#include "diagnosis/noise_estimate.h"

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

/// One input of the signature: its values, bins and the bin of every row.
struct BinnedInput {
  const InputAxis* axis;
  Eigen::VectorXd x;
  std::vector<int> bin;
  std::vector<std::pair<double, double>> edges;
  std::vector<std::size_t> count;
  Eigen::MatrixX2d term;  ///< f_j per bin [N·m]
};

BinnedInput bin_input(const InputAxis& axis, Eigen::VectorXd x) {
  BinnedInput b{&axis, std::move(x), {}, {}, {}, {}};
  b.bin = assign_bins(b.x, axis.binning, b.edges);
  b.count.assign(b.edges.size(), 0);
  for (int k : b.bin) ++b.count[static_cast<std::size_t>(k)];
  b.term = Eigen::MatrixX2d::Zero(static_cast<Eigen::Index>(b.edges.size()), 2);
  return b;
}

/// Bin means of `r` (count-weighted centred).
Eigen::MatrixX2d bin_means(const BinnedInput& b, const Eigen::MatrixX2d& r) {
  Eigen::MatrixX2d sum = Eigen::MatrixX2d::Zero(b.term.rows(), 2);
  for (Eigen::Index i = 0; i < r.rows(); ++i) sum.row(b.bin[static_cast<std::size_t>(i)]) += r.row(i);
  Eigen::Vector2d weighted = Eigen::Vector2d::Zero();
  for (Eigen::Index k = 0; k < sum.rows(); ++k) {
    if (b.count[static_cast<std::size_t>(k)] > 0) sum.row(k) /= static_cast<double>(b.count[static_cast<std::size_t>(k)]);
    weighted += static_cast<double>(b.count[static_cast<std::size_t>(k)]) * sum.row(k).transpose();
  }
  const Eigen::Vector2d mean = weighted / static_cast<double>(r.rows());
  for (Eigen::Index k = 0; k < sum.rows(); ++k) if (b.count[static_cast<std::size_t>(k)] > 0) sum.row(k) -= mean.transpose();
  return sum;
}

/// Backfitting of the additive model: each input's term from the residual less the others'. Row by
/// row, without whole-recording temporaries: a signature runs a backfit per input on up to 20,000
/// rows on the diagnosis's serial path.
Eigen::MatrixX2d backfit(std::vector<BinnedInput>& inputs, const Eigen::MatrixX2d& centred) {
  const Eigen::Index n = centred.rows();
  Eigen::MatrixX2d total = Eigen::MatrixX2d::Zero(n, 2);
  Eigen::MatrixX2d partial(n, 2);  // the residual less the other inputs' terms
  for (int sweep = 0; sweep < 30; ++sweep) {
    double change = 0.0;
    for (BinnedInput& b : inputs) {
      for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index k = b.bin[static_cast<std::size_t>(i)];
        for (int c = 0; c < 2; ++c) partial(i, c) = centred(i, c) - (total(i, c) - b.term(k, c));
      }
      const Eigen::MatrixX2d next = bin_means(b, partial);
      change = std::max(change, (next - b.term).cwiseAbs().maxCoeff());
      for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index k = b.bin[static_cast<std::size_t>(i)];
        for (int c = 0; c < 2; ++c) total(i, c) += next(k, c) - b.term(k, c);
      }
      b.term = next;
    }
    if (change <= 1e-9 * std::max(1.0, centred.cwiseAbs().maxCoeff())) break;
  }
  return total;
}

double correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::VectorXd ca = a.array() - a.mean(), cb = b.array() - b.mean();
  const double d = ca.norm() * cb.norm();
  return d > 0.0 ? ca.dot(cb) / d : 0.0;
}

/// `without`: the residual of the additive model fitted without this input; its extra sum of
/// squares over `leftover` is what this input adds given the others (an input that only moves with
/// another adds nothing, however its backfitted term splits with the other's).
InputSignature signature_for(const BinnedInput& b, const Eigen::MatrixX2d& centred, const Eigen::MatrixX2d& leftover,
                             const Eigen::MatrixX2d& without, int leftover_dof, double inflation) {
  InputSignature s{b.axis->name, b.axis->unit, {}, 0.0, 0.0, 0.0, false, 0.0, 0.0, {}};
  const Eigen::MatrixX2d marginal = bin_means(b, centred);
  Eigen::Vector2d between = Eigen::Vector2d::Zero();
  double marginal_between = 0.0;
  for (std::size_t k = 0; k < b.edges.size(); ++k) {
    if (b.count[k] == 0) continue;
    const Eigen::Index row = static_cast<Eigen::Index>(k);
    s.bins.push_back({b.edges[k].first, b.edges[k].second, b.count[k], b.term(row, 0), b.term(row, 1)});
    between += static_cast<double>(b.count[k]) * b.term.row(row).transpose().cwiseAbs2();
    marginal_between += static_cast<double>(b.count[k]) * marginal.row(row).squaredNorm();
  }
  const double total = centred.squaredNorm();
  s.explained_share = total > 0.0 ? std::min(1.0, between.sum() / total) : 0.0;
  s.marginal_share = total > 0.0 ? marginal_between / total : 0.0;
  const int dof = static_cast<int>(s.bins.size()) - 1;
  if (dof >= 1 && leftover_dof >= 1) {
    const Eigen::Array2d within = (leftover.colwise().squaredNorm().transpose().array() / leftover_dof).max(1e-300);
    const Eigen::Array2d extra = (without.colwise().squaredNorm() - leftover.colwise().squaredNorm()).transpose().array().max(0.0);
    s.dispersion = ((extra / dof) / within).maxCoeff() / std::max(1.0, inflation);
    // z = 3.7: a one-sided 1e-4 level, strict because many inputs and two channels are tested.
    s.systematic = s.dispersion > chi_square_per_dof(dof, 3.7);
  }
  const Eigen::VectorXd x = b.x.array() - b.x.mean();
  const double sxx = x.squaredNorm();
  if (sxx > 0.0) { s.slope_y = x.dot(centred.col(0)) / sxx; s.slope_z = x.dot(centred.col(1)) / sxx; }
  return s;
}

}  // namespace

std::vector<int> signature_bins(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                const std::string& input) {
  for (const InputAxis& axis : axes()) {
    if (axis.name != input) continue;
    Eigen::VectorXd x(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const std::optional<double> v = axis.read(observations[rows[k]].input);
      if (!v) return {};
      x(static_cast<Eigen::Index>(k)) = *v;
    }
    std::vector<std::pair<double, double>> edges;
    return assign_bins(x, axis.binning, edges);
  }
  return {};
}

const InputSignature* ResidualSignature::find(const std::string& input) const {
  for (const InputSignature& s : inputs) if (s.input == input) return &s;
  return nullptr;
}

bool ResidualSignature::systematic() const {
  return std::any_of(inputs.begin(), inputs.end(), [](const InputSignature& s) { return s.systematic; });
}

ResidualSignature residual_signature(std::span<const RecordedSample> observations,
                                     std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                     const ParallelFor& parallel, double variance_inflation) {
  ResidualSignature out;
  if (rows.size() < 2) return out;
  const std::vector<InputAxis> all = axes();
  std::vector<BinnedInput> inputs;
  for (const InputAxis& axis : all) {
    Eigen::VectorXd x(static_cast<Eigen::Index>(rows.size()));
    bool complete = true;
    for (std::size_t k = 0; k < rows.size() && complete; ++k) {
      const std::optional<double> v = axis.read(observations[rows[k]].input);
      complete = v.has_value();
      if (complete) x(static_cast<Eigen::Index>(k)) = *v;
    }
    if (complete) inputs.push_back(bin_input(axis, std::move(x)));
  }
  const Eigen::MatrixX2d centred = residual.rowwise() - residual.colwise().mean();
  const Eigen::MatrixX2d leftover = centred - backfit(inputs, centred);
  int used = 1;
  for (const BinnedInput& b : inputs) used += static_cast<int>(std::count_if(b.count.begin(), b.count.end(), [](auto c) { return c > 0; })) - 1;
  const int leftover_dof = static_cast<int>(rows.size()) - used;
  // The noise's correlation as the leftover shows it, when it is more than the caller's estimate
  // (a short variogram cannot tell a long correlation from slow structure; the leftover has no
  // structure of any input left to confuse it with).
  // (A block-means estimate, noise_estimate.h: about 1 for white noise; 30 for AR(1) noise with a
  // correlation time of 1.5 s at 10 Hz, where the lag-1 fit of a short variogram saw 4.)
  for (int c = 0; c < 2; ++c) variance_inflation = std::max(variance_inflation, long_run_inflation(leftover.col(c)));
  out.variance_inflation = variance_inflation;
  // The additive model without each input in turn: a backfit each, independent of one another.
  std::vector<Eigen::MatrixX2d> without(inputs.size());
  parallel(inputs.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j) {
      std::vector<BinnedInput> others;
      for (std::size_t k = 0; k < inputs.size(); ++k) if (k != j) others.push_back(inputs[k]);
      without[j] = centred - backfit(others, centred);
    }
  });
  for (std::size_t j = 0; j < inputs.size(); ++j) {
    const BinnedInput& b = inputs[j];
    InputSignature s = signature_for(b, centred, leftover, without[j], leftover_dof, variance_inflation);
    if (b.axis->binning == InputAxis::Binning::quantile) {
      for (const BinnedInput& other : inputs) {
        if (&other != &b && other.axis->binning == InputAxis::Binning::quantile && std::abs(correlation(b.x, other.x)) >= 0.9) {
          s.confounded_with.push_back(other.axis->name);
        }
      }
    }
    out.inputs.push_back(std::move(s));
  }
  std::stable_sort(out.inputs.begin(), out.inputs.end(),
                   [](const InputSignature& a, const InputSignature& b) { return a.explained_share > b.explained_share; });
  return out;
}

}  // namespace gc
