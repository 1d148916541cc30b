#include "diagnosis/surrogate_claims.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <iomanip>
#include <sstream>

#include "diagnosis/formula_search.h"
#include "diagnosis/input_noise_in_prediction.h"
#include "diagnosis/model_residuals.h"
#include "diagnosis/prewhitening.h"
#include "diagnosis/stacked_channels.h"

namespace gc {
namespace {

/// Whether the span of `columns` (2n stacked) holds a channel's level: an offset among its
/// parameters.
bool moves_a_level(const Eigen::MatrixXd& columns, Eigen::Index n) {
  if (columns.cols() == 0) return false;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(columns);
  const Eigen::MatrixXd basis = qr.householderQ() * Eigen::MatrixXd::Identity(columns.rows(), qr.rank());
  for (int c = 0; c < 2; ++c) {
    Eigen::VectorXd level = Eigen::VectorXd::Zero(2 * n);
    level.segment(c * n, n).setConstant(1.0 / std::sqrt(static_cast<double>(n)));
    if ((basis.transpose() * level).squaredNorm() > 0.5) return true;
  }
  return false;
}

/// The formula's design: the catalogue and the round's time terms, with its own terms beside
/// (the mesh orders are offered by the coupling, not the catalogue); as many chosen as it has.
std::optional<SurrogateDesign> formula_design(const CandidateScore& formula, const std::vector<std::string>& time_terms,
                                              std::span<const RecordedSample> observations,
                                              std::span<const std::size_t> rows, const Eigen::MatrixX2d& base) {
  if (!formula.fit || formula.fit->parameters.empty()) return std::nullopt;
  // A step has its own test (change_point.h) and is not judged here: a re-zeroed bridge is one
  // sharp rise, which no phase-randomised noise makes, but which sets the surrogates' own rise.
  const auto is_step = [](const std::string& name) { return name.rfind("step_at_", 0) == 0; };
  std::vector<std::string> extra;
  for (const std::string& name : time_terms) {
    if (!is_step(name)) extra.push_back(name);
  }
  for (const ParameterEstimate& p : formula.fit->parameters) {
    if (!is_step(p.name)) extra.push_back(p.name);
  }
  std::sort(extra.begin(), extra.end());
  extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
  TermDesign design = term_design(observations, rows, base, extra);
  if (design.columns.cols() == 0) return std::nullopt;
  // The formula's terms that are more than a level (the test judges what varies about the levels).
  const Eigen::Index n = base.rows();
  int beyond_levels = 0;
  int steps = 0;
  std::vector<Eigen::VectorXd> own;  // the formula's own columns, steps aside
  for (const ParameterEstimate& p : formula.fit->parameters) {
    if (is_step(p.name)) {
      ++steps;
      continue;
    }
    const auto it = std::find(design.terms.begin(), design.terms.end(), p.name);
    if (it == design.terms.end()) continue;
    const Eigen::VectorXd column = design.columns.col(it - design.terms.begin());
    own.push_back(column);
    Eigen::VectorXd within = column;
    within.head(n).array() -= column.head(n).mean();
    within.tail(n).array() -= column.tail(n).mean();
    if (within.norm() > 1e-9 * column.norm()) ++beyond_levels;
  }
  const bool level = beyond_levels + steps < static_cast<int>(formula.fit->parameters.size());
  if (beyond_levels == 0 && steps > 0) return std::nullopt;
  if (beyond_levels == 0) return SurrogateDesign{Eigen::MatrixXd(2 * n, 0), 0, true, {}};
  SurrogateDesign out{std::move(design.columns), beyond_levels, level, {}};
  // Terms that vary but stand mostly on a level (a speed of 5-14 rpm, a torque that never turns)
  // move the level as an offset does, and are judged on it as an effect's design is (a speed drag
  // of 454 N·m/rpm is an offset of 4.5 kN·m and a ripple of a fifth of the noise, which the
  // surrogates' own rise matched, p = 1: noise zoo power seed 20261253, draw 9). Against the
  // residual's own wander: the formula's slow terms, chosen for this residual, took some of what
  // the leftover would show (a random walk's level is no offset).
  Eigen::MatrixXd columns(2 * n, static_cast<Eigen::Index>(own.size()));
  for (std::size_t j = 0; j < own.size(); ++j) columns.col(static_cast<Eigen::Index>(j)) = own[j];
  if (!level && moves_a_level(columns, n)) {
    out.level = true;
    out.level_against_the_residual = true;
  }
  out.own_profiles = time_profiles(columns, n);
  return out;
}

/// Where the scan of an effect's box looks beside its fit (SurrogateDesign::elsewhere): this many
/// points drawn uniformly in the box of its free parameters, the same for every recording.
constexpr int kPointsElsewhere = 12;

/// The design at `values`: the correction there and the forward-difference Jacobian of the free
/// parameters (a thousandth of the box, stepped inward at its upper bound). Empty when a row cannot
/// be predicted.
std::optional<Eigen::MatrixXd> design_at(const ParameterValues& values, const EffectFit& fit,
                                         const EffectRegistration& registration, const CouplingModel& model,
                                         std::span<const RecordedSample> observations,
                                         std::span<const std::size_t> rows, const Eigen::MatrixX2d& base,
                                         const ParallelFor& parallel) {
  const ModelResiduals at = model_residuals(model_with(model, registration, values), observations, rows, parallel);
  if (!at.failed_rows.empty()) return std::nullopt;
  std::vector<Eigen::VectorXd> columns{stacked(base - at.residual)};
  for (std::size_t j = 0; j < fit.parameters.size(); ++j) {
    if (j < fit.free.size() && !fit.free[j]) continue;
    const std::string& name = fit.parameters[j].name;
    const double value = values.at(name);
    const double width = j < fit.box_upper.size() ? fit.box_upper[j] - fit.box_lower[j] : 0.0;
    double step = 1e-3 * (width > 0.0 ? width : std::max(std::abs(value), 1.0));
    if (j < fit.box_upper.size() && value + step > fit.box_upper[j]) step = -step;
    ParameterValues moved = values;
    moved[name] = value + step;
    const ModelResiduals there = model_residuals(model_with(model, registration, moved), observations, rows, parallel);
    if (!there.failed_rows.empty()) return std::nullopt;
    columns.push_back(stacked(at.residual - there.residual) / step);
  }
  Eigen::MatrixXd out(2 * base.rows(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t j = 0; j < columns.size(); ++j) out.col(static_cast<Eigen::Index>(j)) = columns[j];
  return out;
}

}  // namespace

std::optional<SurrogateDesign> effect_design(const CandidateScore& candidate, const EffectRegistration& registration,
                                             const CouplingModel& model, std::span<const RecordedSample> observations,
                                             std::span<const std::size_t> rows, const Eigen::MatrixX2d& base,
                                             const ParallelFor& parallel) {
  if (!candidate.fit || !candidate.fit->effect) return std::nullopt;
  const EffectFit& fit = *candidate.fit;
  ParameterValues values;
  for (const ParameterEstimate& p : fit.parameters) values[p.name] = p.value;
  std::optional<Eigen::MatrixXd> at_fit = design_at(values, fit, registration, model, observations, rows, base, parallel);
  if (!at_fit) return std::nullopt;
  SurrogateDesign design{std::move(*at_fit), 0, false, {}};
  design.level = moves_a_level(design.columns, base.rows());
  // The box the fit searched, scanned as the null must be (SurrogateDesign::elsewhere).
  std::mt19937_64 random(0x5ca7'7e2d);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<ParameterValues> points;
  for (int k = 0; k < kPointsElsewhere; ++k) {
    ParameterValues there = values;
    bool moved = false;
    for (std::size_t j = 0; j < fit.parameters.size() && j < fit.box_upper.size(); ++j) {
      if (j < fit.free.size() && !fit.free[j]) continue;
      there[fit.parameters[j].name] = fit.box_lower[j] + unit(random) * (fit.box_upper[j] - fit.box_lower[j]);
      moved = true;
    }
    if (!moved) break;
    points.push_back(std::move(there));
  }
  // A point to a thread: each is a few evaluations of a few thousand rows, too short to share
  // their rows over threads started for each (they ran on one thread).
  std::vector<std::optional<Eigen::MatrixXd>> at_points(points.size());
  parallel(points.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      at_points[k] = design_at(points[k], fit, registration, model, observations, rows, base, serial_for());
    }
  });
  for (std::optional<Eigen::MatrixXd>& columns : at_points) {
    if (columns && columns->allFinite()) design.elsewhere.push_back(std::move(*columns));
  }
  return design;
}

Prewhitening surrogate_filter(const CouplingModel& model, std::span<const RecordedSample> observations,
                              std::span<const std::size_t> rows, const Eigen::MatrixX2d& base) {
  Prewhitening filter = Prewhitening::fitted(base);
  if (!filter.identity()) {
    filter.exposes_input_noise = exposes_input_noise(base, input_noise_in_prediction(model, observations, rows));
  }
  return filter;
}

void demote_what_noise_explains(
    std::vector<CandidateScore>& ranking, std::optional<CandidateScore>& formula,
    const std::vector<std::string>& time_terms, const CouplingModel& model,
    std::span<const RecordedSample> observations, std::span<const std::size_t> rows, const Eigen::MatrixX2d& base,
    const ParallelFor& parallel, const std::function<bool(const CandidateScore&)>& claimable,
    const std::function<std::optional<EffectRegistration>(const Effect&)>& registration_for,
    const SurrogateClaimSettings& settings, std::size_t also_tried) {
  if (!(settings.level > 0.0)) return;
  std::vector<SurrogateDesign> designs;
  std::vector<CandidateScore*> tested;
  for (CandidateScore& c : ranking) {
    if (!claimable(c) || !c.fit || !c.fit->effect || !c.replaces.empty() || !c.fit->effect->members().empty()) continue;
    const std::optional<EffectRegistration> registration = registration_for(*c.fit->effect);
    if (!registration) continue;
    std::optional<SurrogateDesign> design = effect_design(c, *registration, model, observations, rows, base, parallel);
    if (!design) continue;
    designs.push_back(std::move(*design));
    tested.push_back(&c);
  }
  if (formula && claimable(*formula)) {
    if (std::optional<SurrogateDesign> design = formula_design(*formula, time_terms, observations, rows, base)) {
      designs.push_back(std::move(*design));
      tested.push_back(&*formula);
    }
  }
  if (designs.empty()) return;
  // The family is every candidate the round tried, not only those that came this far: the
  // claimable ones were picked from them on this same residual.
  const std::size_t family = ranking.size() + (formula ? 1 : 0) + also_tried;
  const Prewhitening filter = surrogate_filter(model, observations, rows, base);
  const std::vector<double> p = surrogate_p_values(base, designs, settings.level, settings.seed, family, parallel, filter);
  for (std::size_t k = 0; k < tested.size(); ++k) {
    tested[k]->surrogate_p = p[k];
    if (p[k] <= settings.level) continue;
    std::ostringstream why;
    why << "noise with the residual's own spectrum and no relation to the inputs is explained as well (surrogate p = "
        << std::fixed << std::setprecision(3) << p[k] << " in a family of " << family << " candidates tried)";
    tested[k]->failure = why.str();
  }
  std::stable_partition(ranking.begin(), ranking.end(), [](const CandidateScore& c) { return c.failure.empty(); });
}

}  // namespace gc
