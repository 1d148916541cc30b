#include "diagnosis/formula_search.h"

#include <algorithm>
#include <cmath>

#include "diagnosis/change_point.h"
#include "diagnosis/cycle_period.h"
#include "diagnosis/noise_estimate.h"
#include "diagnosis/ringing_estimate.h"
#include "diagnosis/stacked_channels.h"
#include "diagnosis/time_step.h"
#include "core/effects/expression.h"
#include "core/effects/expression_terms.h"
#include "core/model_error.h"

namespace gc {
namespace {

/// Ridge on the normalised columns (each of mean square 1): 1e-4 shrinks a coefficient by 0.01 %,
/// yet keeps near-collinear columns from cancelling each other with large opposite coefficients.
constexpr double kRidge = 1e-4;
/// The share of a column's squares that the columns already chosen must leave for it to be chosen.
constexpr double kLeastNewShare = 1e-2;
/// The forward test a step must pass (block-paired t over the last fifth), the claim's own bar.
constexpr double kStepForwardT = 3.5;
/// A cycle this long or longer drifts like a slow term (FormulaSettings::fast_terms_only) [s].
constexpr double kSlowestFastCycleS = 10.0;

/// Rows of the stacked design for the positions `at` (y rows, then z rows).
Eigen::MatrixXd stacked_rows(const Eigen::MatrixXd& m, const std::vector<std::size_t>& at, Eigen::Index n) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(2 * at.size()), m.cols());
  for (std::size_t k = 0; k < at.size(); ++k) {
    out.row(static_cast<Eigen::Index>(k)) = m.row(static_cast<Eigen::Index>(at[k]));
    out.row(static_cast<Eigen::Index>(at.size() + k)) = m.row(n + static_cast<Eigen::Index>(at[k]));
  }
  return out;
}

/// Least squares on the columns in `keep` (others zero), lightly damped so that columns that
/// coincide on this recording (four directions make constants along beta and on y/z alike) share
/// rather than cancel.
Eigen::VectorXd solve_on(const Eigen::MatrixXd& x, const Eigen::VectorXd& y, const std::vector<bool>& keep) {
  std::vector<Eigen::Index> columns;
  for (std::size_t j = 0; j < keep.size(); ++j) if (keep[j]) columns.push_back(static_cast<Eigen::Index>(j));
  Eigen::VectorXd c = Eigen::VectorXd::Zero(x.cols());
  if (columns.empty()) return c;
  Eigen::MatrixXd a(x.rows(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t k = 0; k < columns.size(); ++k) a.col(static_cast<Eigen::Index>(k)) = x.col(columns[k]);
  Eigen::MatrixXd normal = a.transpose() * a;
  normal.diagonal().array() += kRidge * static_cast<double>(x.rows());
  const Eigen::VectorXd s = normal.ldlt().solve(a.transpose() * y);
  for (std::size_t k = 0; k < columns.size(); ++k) c(columns[k]) = s(static_cast<Eigen::Index>(k));
  return c;
}

/// How much of what a term explains counts when forward selection compares it with the others: a
/// shaft-order term whose amplitude follows torque or speed is one more assumption than the plain
/// order, and on a recording where that input barely moves the two columns nearly coincide, the
/// scaled one winning on noise (and extrapolating with the input). It must explain a quarter more.
constexpr double kModulatedTermWeight = 0.8;

std::vector<double> term_weights(const std::vector<std::string>& names) {
  std::vector<double> weights;
  for (const std::string& name : names) {
    const ExpressionTerm* term = find_expression_term(name);
    const bool modulated = term && term->modulation != ExpressionTerm::Modulation::none;
    weights.push_back(modulated ? kModulatedTermWeight : 1.0);
  }
  return weights;
}

/// `v` (a stacked column: y rows, then z rows) less each channel's mean.
template <typename V>
void remove_levels(V&& v) {
  const Eigen::Index n = v.size() / 2;
  v.head(n).array() -= v.head(n).mean();
  v.tail(n).array() -= v.tail(n).mean();
}

/// Forward selection (orthogonal matching pursuit): at each step the column whose part orthogonal
/// to the columns chosen so far explains most of what is left, weighted by `weights`. Columns that
/// the chosen ones already span are never taken. `within_channels`: the order is found on what
/// varies within each channel, each channel's level over the rows taken out of the residual and of
/// every column first; a constant on a channel has no part left and is never chosen.
std::vector<Eigen::Index> forward_order(const Eigen::MatrixXd& x, const Eigen::VectorXd& y, int steps,
                                        const std::vector<double>& weights, bool within_channels) {
  std::vector<Eigen::Index> order;
  Eigen::MatrixXd q = x;
  Eigen::VectorXd r = y;
  if (within_channels) {
    remove_levels(r);
    for (Eigen::Index j = 0; j < q.cols(); ++j) remove_levels(q.col(j));
  }
  std::vector<bool> used(static_cast<std::size_t>(x.cols()), false);
  for (int step = 0; step < steps; ++step) {
    Eigen::Index best = -1;
    double best_gain = 0.0;
    for (Eigen::Index j = 0; j < x.cols(); ++j) {
      const double n2 = q.col(j).squaredNorm();
      // A column the chosen ones already explain to 99 % (variance inflation over 100) is a near
      // duplicate: its small remainder fits noise, and the pair cancels with large coefficients
      // that do not predict (T sign(dzeta/dt) M beside sign(dzeta/dt) M on sweeps at one torque).
      if (used[static_cast<std::size_t>(j)] || n2 <= kLeastNewShare * x.col(j).squaredNorm()) continue;
      const double gain = weights[static_cast<std::size_t>(j)] * std::pow(q.col(j).dot(r), 2) / n2;
      if (gain > best_gain) { best_gain = gain; best = j; }
    }
    if (best < 0) break;
    order.push_back(best);
    used[static_cast<std::size_t>(best)] = true;
    const Eigen::VectorXd u = q.col(best).normalized();
    r -= u * u.dot(r);
    for (Eigen::Index j = 0; j < x.cols(); ++j) {
      if (!used[static_cast<std::size_t>(j)]) q.col(j) -= u * u.dot(q.col(j));
    }
  }
  return order;
}

/// The first `m` columns of `order` as a mask.
std::vector<bool> first_terms(const std::vector<Eigen::Index>& order, std::size_t m, Eigen::Index columns) {
  std::vector<bool> keep(static_cast<std::size_t>(columns), false);
  for (std::size_t k = 0; k < std::min(m, order.size()); ++k) keep[static_cast<std::size_t>(order[k])] = true;
  return keep;
}

int count(const std::vector<bool>& keep) { return static_cast<int>(std::count(keep.begin(), keep.end(), true)); }

/// Each fold's training and held-out rows of a stacked design and its response, cut once for a
/// search that scores many formulas on the same folds.
struct FoldRows {
  Eigen::MatrixXd training_x, held_out_x;
  Eigen::VectorXd training_y;
};

std::vector<FoldRows> fold_rows(const Eigen::MatrixXd& x, const Eigen::VectorXd& y, const Folds& folds, Eigen::Index n) {
  std::vector<FoldRows> out(folds.training.size());
  for (std::size_t f = 0; f < folds.training.size(); ++f) {
    out[f].training_x = stacked_rows(x, folds.training[f], n);
    out[f].training_y = stacked_rows(y, folds.training[f], n).col(0);
    out[f].held_out_x = stacked_rows(x, folds.held_out[f], n);
  }
  return out;
}

/// Per search row, the held-out residual of the formula `choose(f, x, y)` picks for fold f from its
/// training rows (`rows`: fold_rows of the design and the stacked residual).
template <typename Choose>
Eigen::MatrixX2d held_out(const std::vector<FoldRows>& rows, const Eigen::MatrixX2d& residual, const Folds& folds,
                          Choose choose) {
  Eigen::MatrixX2d out = residual;
  for (std::size_t f = 0; f < folds.training.size(); ++f) {
    const FoldRows& fold = rows[f];
    const Eigen::VectorXd c = solve_on(fold.training_x, fold.training_y, choose(f, fold.training_x, fold.training_y));
    const Eigen::VectorXd prediction = fold.held_out_x * c;
    const std::size_t m = folds.held_out[f].size();
    for (std::size_t k = 0; k < m; ++k) {
      const Eigen::Index row = static_cast<Eigen::Index>(folds.held_out[f][k]);
      out(row, 0) -= prediction(static_cast<Eigen::Index>(k));
      out(row, 1) -= prediction(static_cast<Eigen::Index>(m + k));
    }
  }
  return out;
}

template <typename Choose>
Eigen::MatrixX2d held_out(const Eigen::MatrixXd& x, const Eigen::MatrixX2d& residual, const Folds& folds, Choose choose) {
  return held_out(fold_rows(x, stacked(residual), folds, residual.rows()), residual, folds, choose);
}

/// Mean and standard error of the held-out mean square over the blocks.
std::pair<double, double> block_mean_square(const Eigen::MatrixX2d& r, const Folds& folds) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(folds.blocks), n = Eigen::VectorXd::Zero(folds.blocks);
  for (Eigen::Index i = 0; i < r.rows(); ++i) {
    sum(folds.block_of[static_cast<std::size_t>(i)]) += 0.5 * r.row(i).squaredNorm();
    n(folds.block_of[static_cast<std::size_t>(i)]) += 1.0;
  }
  std::vector<double> means;
  for (int b = 0; b < folds.blocks; ++b) if (n(b) > 0) means.push_back(sum(b) / n(b));
  const Eigen::Map<const Eigen::VectorXd> m(means.data(), static_cast<Eigen::Index>(means.size()));
  const double mean = m.mean();
  const double sd = m.size() > 1 ? std::sqrt((m.array() - mean).square().sum() / (m.size() - 1.0)) : 0.0;
  return {mean, sd / std::sqrt(std::max<double>(1.0, static_cast<double>(m.size())))};
}

/// Terms that may follow a slow wander of the noise: in time alone (t, t^2, t^3, a cycle, a step)
/// or in the oil temperature, which rises through a test as slowly as a bridge's zero drifts (a
/// 15 N·m/deg C term took a drift's share on recordings with no temperature effect). A real
/// temperature effect predicts forward as well as a real step does.
bool drifts_slowly(const std::string& name) {
  return name.rfind("time", 0) == 0 || name.rfind("step_at_", 0) == 0 || name.rfind("temperature", 0) == 0;
}

/// The partner of a periodic term in `terms` (its cosine for a sine, and back), if offered: its sine
/// and cosine on a channel are one component of unknown phase.
std::optional<std::size_t> phase_partner(const std::vector<std::string>& terms, std::size_t j) {
  static const std::pair<const char*, const char*> kPairs[] = {
      {"_sin_on_", "_cos_on_"}, {"_forward_sin", "_forward_cos"}, {"_backward_sin", "_backward_cos"}};
  for (const auto& [sine, cosine] : kPairs) {
    for (const auto& [from, to] : {std::pair{sine, cosine}, std::pair{cosine, sine}}) {
      const std::size_t at = terms[j].find(from);
      if (at == std::string::npos) continue;
      const std::string partner = terms[j].substr(0, at) + to + terms[j].substr(at + std::string(from).size());
      const auto k = std::find(terms.begin(), terms.end(), partner);
      if (k != terms.end()) return static_cast<std::size_t>(k - terms.begin());
    }
  }
  return std::nullopt;
}

/// A formula that keeps one of a phase pair keeps the other. Forward selection takes them one at a
/// time and can stop between them: a 2 kN·m tone at phase 2.0 on M_sz' put 0.8 kN·m in its sine,
/// which was left out.
void complete_phase_pairs(const std::vector<std::string>& terms, std::vector<bool>& support) {
  const std::vector<bool> chosen = support;
  for (std::size_t j = 0; j < terms.size(); ++j) {
    if (!chosen[j]) continue;
    if (const std::optional<std::size_t> k = phase_partner(terms, j)) support[*k] = true;
  }
}

/// A term in time alone (t, t^2, t^3, a cycle, a step) may be a drift of the noise, which the
/// interleaved folds let it interpolate. It must also predict **forward**: fitted on the rows
/// before a stretch, it must lower the error on the last fifth of the rows (block-paired t of 2
/// over 10 blocks of it), as the next test would need it to. A polynomial in t is fitted on the
/// first three fifths only, so that it must carry across a gap of a fifth, as into a test after a
/// pause: a linear drift that balanced a step within one test took the next run 6 kN·m off, and a
/// cubic took one from 6.8 to 93 kN·m. A step or a cycle that is real carries on, and is fitted on
/// the first four fifths (a step in the gap could not be seen).
void drop_drift_that_does_not_extrapolate(const Eigen::MatrixXd& z, const Eigen::MatrixX2d& residual,
                                          const std::vector<std::string>& names, std::vector<bool>& support) {
  const std::size_t n = static_cast<std::size_t>(residual.rows()), last = 4 * n / 5;
  constexpr int kBlocks = 10;
  if (n - last < 2 * static_cast<std::size_t>(kBlocks)) return;
  const auto forward = [&](std::size_t fitted) {
    Folds f;
    f.training.resize(1);
    f.held_out.resize(1);
    for (std::size_t i = 0; i < fitted; ++i) f.training[0].push_back(i);
    for (std::size_t i = fitted; i < n; ++i) f.held_out[0].push_back(i);
    return f;
  };
  const Folds after_four_fifths = forward(last), after_a_gap = forward(3 * n / 5);
  std::vector<int> block_of;
  for (std::size_t i = last; i < n; ++i) block_of.push_back(static_cast<int>((i - last) * kBlocks / (n - last)));
  const auto last_fifth = [&](const Eigen::MatrixX2d& r) { return Eigen::MatrixX2d(r.bottomRows(static_cast<Eigen::Index>(n - last))); };
  for (std::size_t j = 0; j < support.size(); ++j) {
    if (!support[j] || !drifts_slowly(names[j])) continue;
    const bool polynomial = names[j].rfind("time", 0) == 0 && names[j].rfind("time_cycle", 0) != 0;
    const Folds& folds = polynomial ? after_a_gap : after_four_fifths;
    std::vector<bool> without = support;
    without[j] = false;
    const auto fixed = [](const std::vector<bool>& keep) {
      return [keep](std::size_t, const Eigen::MatrixXd&, const Eigen::VectorXd&) { return keep; };
    };
    const Eigen::MatrixX2d with_it = held_out(z, residual, folds, fixed(support));
    const Eigen::MatrixX2d without_it = held_out(z, residual, folds, fixed(without));
    // A step is chosen from every row by its time, so its forward test is held to the claim's bar.
    const double least_t = names[j].rfind("step_at_", 0) == 0 ? kStepForwardT : 2.0;
    if (paired_block_test(last_fifth(without_it), last_fifth(with_it), block_of, kBlocks).t < least_t) support[j] = false;
  }
}

/// Block means in time of a stacked (y rows, then z rows) column: `blocks` equal runs of rows, each
/// channel's mean [N·m], both channels in one vector.
Eigen::VectorXd block_means(const Eigen::VectorXd& stacked_column, int blocks) {
  const Eigen::Index n = stacked_column.size() / 2;
  Eigen::VectorXd out(2 * blocks);
  for (int b = 0; b < blocks; ++b) {
    const Eigen::Index from = n * b / blocks, to = n * (b + 1) / blocks;
    out(b) = stacked_column.segment(from, to - from).mean();
    out(blocks + b) = stacked_column.segment(n + from, to - from).mean();
  }
  return out;
}

/// A term on one channel that varies as slowly as a drift (t, a step, the oil temperature; not a
/// cycle) must stand out of the slow wander the formula leaves beside it: the spread of its
/// contribution's means over twenty blocks in time at least twice that of the residual's. Within
/// one recording a slow term and a bridge's zero drift that happens to follow it are the same
/// thing; only its size against the wander tells a temperature effect from a share of the drift (a
/// 14 N·m/deg C term took 0.3 kN·m of a 0.6 kN·m drift, and cost the next run 2 points). A real
/// step or temperature effect of a size that matters stands well out of it.
void drop_slow_terms_within_the_wander(const Eigen::MatrixXd& z, const Eigen::MatrixX2d& residual,
                                       const std::vector<std::string>& names, std::vector<bool>& support) {
  constexpr int kBlocks = 20;
  constexpr double kLeastRatio = 2.0;
  if (residual.rows() < 4 * kBlocks) return;
  const Eigen::VectorXd y = stacked(residual);
  const Eigen::VectorXd c = solve_on(z, y, support);
  const auto spread = [](const Eigen::VectorXd& v) { return std::sqrt((v.array() - v.mean()).square().mean()); };
  const double wander = spread(block_means(y - z * c, kBlocks));
  for (std::size_t j = 0; j < support.size(); ++j) {
    const ExpressionTerm* term = find_expression_term(names[j]);
    // A zero drift is a moment on one channel: terms in a direction that turns with the
    // misalignment or the model's moment cannot follow it.
    const bool on_one_channel = names[j].ends_with("_on_y") || names[j].ends_with("_on_z");
    if (!support[j] || !drifts_slowly(names[j]) || !on_one_channel || (term && term->period_s > 0.0)) continue;
    const Eigen::VectorXd contribution = z.col(static_cast<Eigen::Index>(j)) * c(static_cast<Eigen::Index>(j));
    if (spread(block_means(contribution, kBlocks)) < kLeastRatio * wander) support[j] = false;
  }
}

/// A channel's intercept (constant_on_y, constant_on_z) stays in the formula only when its level
/// stands out of the slow wander the formula leaves: at least three times the spread of the
/// residual's means over twenty blocks in time. A zero drift slower than the run (a correlation
/// time tau up to about three runs of length T) has a level over the run sqrt(3 tau / T) times its
/// wander within it, and the next run has its own: on rig hysteresis the training run's 0.77 and
/// 1.06 kN·m (1.9 and 2.6 times the wander), kept, cost the next run 6 points of its cut. A bridge
/// offset or a weight that matters stands well out of it, as does the level that a term carrying
/// one needs beside it (a speed drag about 12 rpm: 30 kN·m).
void drop_levels_within_the_wander(const Eigen::MatrixXd& z, const Eigen::MatrixX2d& residual,
                                   const std::vector<bool>& levels, std::vector<bool>& support) {
  constexpr int kBlocks = 20;
  constexpr double kLeastRatio = 3.0;
  if (residual.rows() < 4 * kBlocks) return;
  const Eigen::VectorXd y = stacked(residual);
  const Eigen::VectorXd c = solve_on(z, y, support);
  const Eigen::VectorXd means = block_means(y - z * c, kBlocks);
  const double wander = std::sqrt((means.array() - means.mean()).square().mean());
  for (std::size_t j = 0; j < support.size(); ++j) {
    if (!support[j] || !levels[j]) continue;
    const double level = std::abs(c(static_cast<Eigen::Index>(j))) * z.col(static_cast<Eigen::Index>(j)).cwiseAbs().maxCoeff();
    if (level < kLeastRatio * wander) support[j] = false;
  }
}

/// A term the fit on every row cannot tell from zero is dropped, the weakest first, and the rest
/// refitted: its coefficient within two standard errors (t^2 < 4, those errors with the noise's
/// correlation), a phase pair judged together (t_sin^2 + t_cos^2 < 6, a chi-square of two degrees
/// at 95 %). Forward selection on interleaved folds takes a term that lowers the held-out error by
/// a hair, and a formula that carries such terms counts more parameters than it uses: two speed
/// terms (t = 22 and 5) came with a misalignment rate (t = 1.2) and twice per revolution (t = 0.9
/// and 0.4), and as five terms lost to a channel gain and offset of four, which the next round left
/// with a speed drag unclaimed (noise zoo power seed 20261310, draw 3). The channels' levels, where
/// they are the intercepts (`levels`: the search within the channels), keep their own rule
/// (drop_levels_within_the_wander).
///
/// A term that others stand in for is not judged alone: where its variance inflation factor among
/// the kept columns of `z` exceeds 10, its error is the collinearity's, not the data's silence, and
/// which of the alike terms to keep is not the t's to say. T zeta along the moment, on a sweep at
/// one torque, shared its error with zeta on M_sy' and zeta times the moment; dropped as the
/// weakest, it left them to be claimed in its place (`outside_torque_times_misalignment`).
void drop_terms_within_their_errors(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                    const Eigen::MatrixX2d& residual, const Eigen::MatrixXd& z,
                                    const std::vector<std::string>& terms, const std::vector<bool>& levels,
                                    double variance_inflation, std::vector<bool>& support) {
  constexpr double kLeastSquaredT[] = {0.0, 4.0, 6.0};  // by the number of terms judged together
  constexpr double kMostInflation = 10.0;
  while (true) {
    std::vector<std::string> kept;
    std::vector<Eigen::Index> at;
    for (std::size_t j = 0; j < support.size(); ++j) {
      if (support[j]) kept.push_back(terms[j]), at.push_back(static_cast<Eigen::Index>(j));
    }
    if (kept.empty()) return;
    // Each kept column's variance inflation factor: the diagonal of the inverse Gram matrix of the
    // columns at unit norm (a column that others span exactly has an enormous one).
    Eigen::MatrixXd unit(z.rows(), static_cast<Eigen::Index>(at.size()));
    for (std::size_t k = 0; k < at.size(); ++k) {
      unit.col(static_cast<Eigen::Index>(k)) = z.col(at[k]) / std::max(z.col(at[k]).norm(), 1e-300);
    }
    Eigen::MatrixXd gram = unit.transpose() * unit;
    gram.diagonal().array() += 1e-12;
    const Eigen::VectorXd inflation =
        gram.ldlt().solve(Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).diagonal();
    const auto collinear = [&](std::size_t j) {
      const auto k = std::find(at.begin(), at.end(), static_cast<Eigen::Index>(j)) - at.begin();
      return !(inflation(k) <= kMostInflation);
    };
    const std::optional<EffectFit> fit = fit_formula(observations, rows, residual, kept, variance_inflation);
    if (!fit) return;
    const auto squared_t = [&](std::size_t j) {
      for (const ParameterEstimate& p : fit->parameters) {
        if (p.name != terms[j]) continue;
        const double error = p.standard_error.value_or(0.0);
        return error > 0.0 ? std::pow(p.value / error, 2) : INFINITY;
      }
      return 0.0;  // the fit dropped it (a sum of others, or out of its bounds)
    };
    std::optional<std::size_t> weakest;
    double weakest_share = 1.0;  // of its least squared t
    for (std::size_t j = 0; j < support.size(); ++j) {
      if (!support[j] || levels[j]) continue;
      const std::optional<std::size_t> partner = phase_partner(terms, j);
      const bool pair = partner && support[*partner];
      if (collinear(j) || (pair && collinear(*partner))) continue;
      const double share = (squared_t(j) + (pair ? squared_t(*partner) : 0.0)) / kLeastSquaredT[pair ? 2 : 1];
      if (share < weakest_share) { weakest_share = share; weakest = j; }
    }
    if (!weakest) return;
    support[*weakest] = false;
    if (const std::optional<std::size_t> partner = phase_partner(terms, *weakest)) support[*partner] = false;
  }
}

/// The design without the terms that vary as slowly as a drift (FormulaSettings::fast_terms_only).
/// The share of a stacked column's squares that is each channel's mean over the rows.
double level_share(const Eigen::VectorXd& column) {
  const Eigen::Index n = column.size() / 2;
  const double squares = column.squaredNorm();
  if (squares <= 0.0) return 0.0;
  const double y = column.head(n).mean(), z = column.tail(n).mean();
  return static_cast<double>(n) * (y * y + z * z) / squares;
}

/// A column with more than this share of its squares in its level over the rows carries a level
/// (a constant, T on one channel, T along a direction that holds), which the fast-terms search
/// leaves to the drift; a ripple, a cycle or a rate has next to none.
constexpr double kMostLevelShare = 0.05;

TermDesign fast_terms(TermDesign design) {
  TermDesign out;
  std::vector<Eigen::Index> keep;
  for (std::size_t j = 0; j < design.terms.size(); ++j) {
    const std::string& name = design.terms[j];
    const ExpressionTerm* term = find_expression_term(name);
    const bool slow_cycle = term && term->period_s >= kSlowestFastCycleS;
    // A term that carries a level takes the zero drift's level over the run: the claim keeps its
    // level, which the next run does not share (and the search, on the levels taken out, would
    // claim it again round after round).
    const bool carries_level = level_share(design.columns.col(static_cast<Eigen::Index>(j))) > kMostLevelShare;
    if (slow_cycle || carries_level || (drifts_slowly(name) && !(term && term->period_s > 0.0))) continue;
    out.terms.push_back(name);
    keep.push_back(static_cast<Eigen::Index>(j));
  }
  out.columns.resize(design.columns.rows(), static_cast<Eigen::Index>(keep.size()));
  for (std::size_t k = 0; k < keep.size(); ++k) out.columns.col(static_cast<Eigen::Index>(k)) = design.columns.col(keep[k]);
  return out;
}

/// The Nyquist frequency of `rows` [Hz]: half their typical sampling rate (infinite for one row).
double nyquist_hz(std::span<const RecordedSample> observations, std::span<const std::size_t> rows) {
  Eigen::VectorXd t(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t k = 0; k < rows.size(); ++k) t(static_cast<Eigen::Index>(k)) = observations[rows[k]].input.time_s;
  const double dt = typical_time_step(t);
  return dt > 0.0 ? 0.5 / dt : INFINITY;
}

/// Whether `term` oscillates below the Nyquist frequency on every row: an order, a cycle or a mode
/// above it aliases onto a slower wave, which would be claimed under the wrong name (a tooth-mesh
/// ripple at 20 Hz sampled at 25 Hz looks like a 5 Hz cycle).
/// Also whether a periodic term (an order, a cycle) turns at least kLeastCycles times over the rows:
/// fewer, and it is a slow curve that a drift or a wandering noise fits as well (twice per
/// revolution over 2.6 s at 10 rpm is less than one cycle, and took a random walk's wander for
/// "an oval sleeve"). A ringing mode decays after each step and is judged by its own test.
constexpr double kLeastCycles = 4.0;

bool resolved(const ExpressionTerm& term, std::span<const RecordedSample> observations,
              std::span<const std::size_t> rows, double nyquist) {
  double cycles = 0.0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double f = term.frequency_hz(observations[rows[k]].input);
    if (f >= nyquist) return false;
    if (k > 0) cycles += f * (observations[rows[k]].input.time_s - observations[rows[k - 1]].input.time_s);
  }
  const bool periodic = term.period_s > 0.0 || term.order > 0;
  return !periodic || cycles >= kLeastCycles;
}

/// The column of a term of the history (ExpressionTerm::reads_history) on `rows`: its transient over
/// the whole recording in its own order (as CouplingModel::predict_at sees it), at those rows.
Eigen::VectorXd history_column(const ExpressionTerm& term, std::span<const RecordedSample> observations,
                               std::span<const std::size_t> rows) {
  std::vector<double> times, torques;
  for (const RecordedSample& o : observations) {
    times.push_back(o.input.time_s);
    torques.push_back(o.input.torque_nm);
  }
  const std::vector<double> r = ringing_sequence(times, torques, term.ringing);
  const auto n = static_cast<Eigen::Index>(rows.size());
  const Eigen::Vector2d channel = term.history_channel();
  Eigen::VectorXd column(2 * n);
  for (Eigen::Index k = 0; k < n; ++k) {
    column(k) = channel.x() * r[rows[static_cast<std::size_t>(k)]];
    column(n + k) = channel.y() * r[rows[static_cast<std::size_t>(k)]];
  }
  return column;
}

/// The columns of `offered` on `rows` (as term_design), without those the rows cannot evaluate,
/// those above the rows' Nyquist frequency, and those zero throughout.
TermDesign design_of(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                     const Eigen::MatrixX2d& residual, const std::vector<const ExpressionTerm*>& offered) {
  TermDesign design;
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  const double nyquist = nyquist_hz(observations, rows);
  std::vector<Eigen::VectorXd> columns;
  for (const ExpressionTerm* t : offered) {
    const ExpressionTerm& term = *t;
    if (!resolved(term, observations, rows, nyquist)) continue;
    Eigen::VectorXd column(2 * n);
    bool complete = true;
    if (term.reads_history()) {
      column = history_column(term, observations, rows);
    } else {
      for (Eigen::Index k = 0; k < n && complete; ++k) {
        const RecordedSample& o = observations[rows[static_cast<std::size_t>(k)]];
        const SensorMoments model{o.measured.y_nm - residual(k, 0), o.measured.z_nm - residual(k, 1)};
        const std::optional<Eigen::Vector2d> v = term.value(o.input, model);
        complete = v.has_value();
        if (complete) { column(k) = v->x(); column(n + k) = v->y(); }
      }
    }
    if (!complete || column.norm() == 0.0) continue;
    design.terms.push_back(term.name);
    columns.push_back(std::move(column));
  }
  design.columns.resize(2 * n, static_cast<Eigen::Index>(columns.size()));
  for (std::size_t j = 0; j < columns.size(); ++j) design.columns.col(static_cast<Eigen::Index>(j)) = columns[j];
  return design;
}

/// The columns of the named terms only (a formula already chosen), in that order; nullopt when one
/// is unknown or cannot be evaluated on these rows.
std::optional<Eigen::MatrixXd> columns_of(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                          const Eigen::MatrixX2d& residual, const std::vector<std::string>& names) {
  std::vector<const ExpressionTerm*> offered;
  for (const std::string& name : names) {
    const ExpressionTerm* term = find_expression_term(name);
    if (!term) return std::nullopt;
    offered.push_back(term);
  }
  TermDesign design = design_of(observations, rows, residual, offered);
  if (design.terms != names) return std::nullopt;
  return std::move(design.columns);
}

/// Each column less its mean on each channel (rows 0..n-1 are M_sy', n..2n-1 M_sz').
void remove_channel_levels(Eigen::MatrixXd& columns) {
  for (Eigen::Index j = 0; j < columns.cols(); ++j) remove_levels(columns.col(j));
}

}  // namespace

TermDesign term_design(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                       const Eigen::MatrixX2d& residual, const std::vector<std::string>& extra) {
  std::vector<const ExpressionTerm*> offered;
  for (const ExpressionTerm& term : expression_terms()) offered.push_back(&term);
  for (const std::string& name : extra) {
    const ExpressionTerm* term = find_expression_term(name);
    if (term && std::find(offered.begin(), offered.end(), term) == offered.end()) offered.push_back(term);
  }
  return design_of(observations, rows, residual, offered);
}

std::vector<std::string> time_terms_for(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                        const Eigen::MatrixX2d& residual, const ParallelFor& parallel) {
  // The three searches side by side (each has stretches on one thread), named in this order.
  std::optional<double> period, step;
  std::optional<RingingMode> mode;
  parallel(2, [&](std::size_t begin, std::size_t end) {
    for (std::size_t part = begin; part < end; ++part) {
      if (part == 0) {
        period = dominant_cycle_period(observations, rows, residual, parallel);
        step = dominant_step_time(observations, rows, residual);
      } else {
        mode = dominant_ringing(observations, rows, residual, parallel);
      }
    }
  });
  std::vector<std::string> terms;
  if (period) terms = cycle_term_names(*period);
  if (step) {
    for (std::string& name : step_term_names(*step)) terms.push_back(std::move(name));
  }
  if (mode) {
    for (std::string& name : ringing_term_names(*mode)) terms.push_back(std::move(name));
  }
  return terms;
}

std::optional<EffectFit> fit_formula(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                     const Eigen::MatrixX2d& residual, const std::vector<std::string>& terms,
                                     double variance_inflation) {
  if (terms.empty()) return std::nullopt;  // no formula
  const auto design_for = [&](const EffectInfo& info) {
    std::vector<std::string> names;
    for (const ParameterSpec& p : info.parameters) names.push_back(p.name);
    return columns_of(observations, rows, residual, names);  // nullopt: not available on these rows
  };
  const EffectInfo* info_of = &expression_info(terms);
  std::optional<Eigen::MatrixXd> design = design_for(*info_of);
  if (!design) return std::nullopt;
  // A term that is a sum of others on this recording (M itself is the two channel gains together)
  // says nothing they do not: keep the independent ones, in the pivoting order of the QR.
  const auto pivoted = design->colPivHouseholderQr();
  if (pivoted.rank() < design->cols()) {
    std::vector<std::string> independent;
    for (Eigen::Index k = 0; k < pivoted.rank(); ++k) {
      independent.push_back(info_of->parameters[static_cast<std::size_t>(pivoted.colsPermutation().indices()(k))].name);
    }
    info_of = &expression_info(independent);
    design = design_for(*info_of);
  }
  const EffectInfo& info = *info_of;
  const Eigen::MatrixXd& x = *design;
  const Eigen::VectorXd y = stacked(residual);
  const auto qr = x.colPivHouseholderQr();
  const Eigen::VectorXd c = qr.solve(y);
  const Eigen::VectorXd r = y - x * c;
  const double dof = std::max(1.0, static_cast<double>(x.rows() - x.cols()));
  // In normalised columns: the terms' scales span 1e-7 (1/T) to 1e7 (t^3), and X'X in physical
  // units loses the small variances to rounding.
  const Eigen::VectorXd scale = x.colwise().norm().transpose().cwiseMax(1e-300);
  const Eigen::MatrixXd xn = x * scale.cwiseInverse().asDiagonal();
  const Eigen::MatrixXd covariance = (r.squaredNorm() / dof) * variance_inflation * scale.cwiseInverse().asDiagonal() *
                                     (xn.transpose() * xn).completeOrthogonalDecomposition().pseudoInverse() *
                                     scale.cwiseInverse().asDiagonal();
  EffectFit fit;
  fit.info = &info;
  ParameterValues values;
  fit.unit_values.resize(x.cols());
  for (std::size_t j = 0; j < info.parameters.size(); ++j) {
    const ParameterSpec& spec = info.parameters[j];
    const double v = c(static_cast<Eigen::Index>(j));
    if (!std::isfinite(v) || std::abs(v) > spec.upper) {
      // Two terms that nearly cancel on this recording (a sign of travel held for long stretches
      // times the moment, and the same times torque) can leave their bounds together: drop the
      // offending term and fit the rest, rather than lose the formula (a speed drag went unclaimed).
      if (terms.size() <= 1) return std::nullopt;
      std::vector<std::string> rest;
      for (const std::string& t : terms) if (t != spec.name) rest.push_back(t);
      return fit_formula(observations, rows, residual, rest, variance_inflation);
    }
    values[spec.name] = v;
    fit.parameters.push_back({spec.name, spec.unit, v, std::sqrt(std::max(0.0, covariance(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j)))),
                              false, "", true});
    fit.unit_values(static_cast<Eigen::Index>(j)) = (v - spec.lower) / (spec.upper - spec.lower);
    fit.box_lower.push_back(spec.lower);
    fit.box_upper.push_back(spec.upper);
  }
  fit.effect = make_expression(values);
  fit.free.assign(info.parameters.size(), true);
  fit.sum_of_squares = r.squaredNorm();
  fit.rows = rows.size();
  return fit;
}

Eigen::MatrixX2d without_levels(const Eigen::MatrixX2d& residual) {
  return residual.rowwise() - residual.colwise().mean();
}

std::optional<Eigen::MatrixX2d> formula_held_out(std::span<const RecordedSample> observations,
                                                 std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                                 const std::vector<std::string>& terms, const Folds& folds) {
  std::optional<Eigen::MatrixXd> x = columns_of(observations, rows, residual, terms);
  if (!x) return std::nullopt;  // not available on these rows
  // Normalised as formula_candidate's columns, for the same ridge.
  for (Eigen::Index j = 0; j < x->cols(); ++j) x->col(j) /= x->col(j).norm() / std::sqrt(static_cast<double>(x->rows()));
  const std::vector<bool> every(terms.size(), true);
  return held_out(*x, residual, folds, [&every](std::size_t, const Eigen::MatrixXd&, const Eigen::VectorXd&) { return every; });
}

namespace {

/// The search's columns on the search rows: normalised (a coefficient is then the term's RMS
/// contribution [N·m], one threshold for all), and which are the channels' levels.
struct SearchDesign {
  std::vector<std::string> terms;
  Eigen::MatrixXd z;
  std::vector<double> weights;
  std::vector<bool> levels;  ///< constant_on_y, constant_on_z
};

/// The formula the blocked cross-validation chooses on `design` (formula_search.h), its terms
/// ordered on the whole residual or, `within_channels`, on what varies within each channel with the
/// channels' levels as intercepts of every fit (forward_order). nullopt when none beats no formula.
std::optional<CandidateScore> search(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                     const Eigen::MatrixX2d& residual, const SearchDesign& design, const Folds& folds,
                                     const FormulaSettings& settings, bool within_channels) {
  const Eigen::MatrixXd& z = design.z;
  const Eigen::VectorXd y = stacked(residual);
  const std::vector<bool> none(design.levels.size(), false);
  const std::vector<bool>& levels = within_channels ? design.levels : none;
  const std::size_t first = count(levels) > 0 ? 1 : 0;  // the path's step that adds the intercepts
  const auto terms_at = [&](const std::vector<Eigen::Index>& order, std::size_t m) {
    if (m < first) return none;
    std::vector<bool> keep = first_terms(order, m - first, z.cols());
    for (std::size_t j = 0; j < keep.size(); ++j) keep[j] = keep[j] || levels[j];
    return keep;
  };
  // The path: no formula, (the intercepts,) then formulas of 1, ... max_terms terms, each fold
  // choosing its own terms on its training rows, scored on its held-out rows.
  // Forward selection is greedy, so the formula of m terms is the first m of the longest: each
  // fold's order is found once, on the first pass, and cut for every m.
  std::vector<std::vector<Eigen::Index>> order(folds.training.size());
  std::vector<std::pair<double, double>> scores;
  const std::vector<FoldRows> cut = fold_rows(z, y, folds, residual.rows());
  for (std::size_t m = 0; m <= static_cast<std::size_t>(settings.max_terms) + first; ++m) {
    const Eigen::MatrixX2d r = held_out(cut, residual, folds, [&](std::size_t f, const Eigen::MatrixXd& xt, const Eigen::VectorXd& yt) {
      if (m == 0) order[f] = forward_order(xt, yt, settings.max_terms, design.weights, within_channels);
      return terms_at(order[f], m);
    });
    scores.push_back(block_mean_square(r, folds));
  }
  std::size_t best = 0;
  for (std::size_t m = 1; m < scores.size(); ++m) if (scores[m].first < scores[best].first) best = m;
  if (best == 0) return std::nullopt;  // no formula beats none on held-out rows
  // One-standard-error rule: the fewest terms within one standard error of the best.
  std::size_t chosen = best;
  for (std::size_t m = 1; m < best; ++m) {
    if (scores[m].first <= scores[best].first + scores[best].second) { chosen = m; break; }
  }
  // The terms most folds chose among their first `chosen` (stability selection, as in bagged
  // SINDy): a term that only the fit on every row picks first has fitted what the held-out blocks
  // do not repeat (a pair of travel-sign terms did, beside a speed drag, which every fold chose).
  // The fit on every row orders the rest when no term has a majority.
  const std::size_t chosen_terms = chosen - first;
  std::vector<bool> support =
      terms_at(forward_order(z, y, static_cast<int>(chosen_terms), design.weights, within_channels), chosen);
  std::vector<int> votes(static_cast<std::size_t>(z.cols()), 0);
  for (const auto& fold_order : order) {
    for (std::size_t k = 0; k < std::min(chosen_terms, fold_order.size()); ++k) ++votes[static_cast<std::size_t>(fold_order[k])];
  }
  std::vector<bool> stable(support.size(), false);
  for (std::size_t j = 0; j < votes.size(); ++j) stable[j] = levels[j] || 2 * votes[j] > static_cast<int>(order.size());
  if (count(stable) > count(levels)) support = stable;
  complete_phase_pairs(design.terms, support);
  drop_drift_that_does_not_extrapolate(z, residual, design.terms, support);
  drop_slow_terms_within_the_wander(z, residual, design.terms, support);
  drop_levels_within_the_wander(z, residual, levels, support);
  drop_terms_within_their_errors(observations, rows, residual, z, design.terms, levels, settings.variance_inflation,
                                 support);
  if (count(support) == 0) return std::nullopt;

  std::vector<std::string> terms;
  for (std::size_t j = 0; j < support.size(); ++j) if (support[j]) terms.push_back(design.terms[j]);
  CandidateScore score;
  score.kind = CandidateKind::formula;
  score.fit = fit_formula(observations, rows, residual, terms, settings.variance_inflation);
  if (!score.fit) return std::nullopt;
  score.info = score.fit->info;
  score.held_out_residual =
      held_out(z, residual, folds, [&](std::size_t, const Eigen::MatrixXd&, const Eigen::VectorXd&) { return support; });
  score_held_out(score, residual, folds);
  return score;
}

/// A candidate's held-out mean square without each channel's level over the rows.
double within_channel_mean_square(const CandidateScore& c, const Folds& folds) {
  return block_mean_square(without_levels(c.held_out_residual), folds).first;
}

}  // namespace

std::optional<CandidateScore> formula_candidate(std::span<const RecordedSample> observations,
                                                std::span<const std::size_t> rows, const Eigen::MatrixX2d& given,
                                                const Folds& folds, const FormulaSettings& settings) {
  // Fast terms only: each channel's level over the rows is its zero drift's, for no term to take
  // (FormulaSettings::fast_terms_only).
  const Eigen::MatrixX2d residual = settings.fast_terms_only ? without_levels(given) : given;
  std::vector<std::string> extra = settings.time_terms ? *settings.time_terms : time_terms_for(observations, rows, residual);
  for (std::string& name : mesh_term_names(settings.teeth)) extra.push_back(std::move(name));
  TermDesign design = term_design(observations, rows, given, extra);
  if (settings.fast_terms_only) design = fast_terms(std::move(design));
  if (design.terms.empty()) return std::nullopt;
  if (settings.fast_terms_only) remove_channel_levels(design.columns);
  SearchDesign search_design;
  const Eigen::VectorXd scale =
      (design.columns.colwise().norm() / std::sqrt(static_cast<double>(design.columns.rows()))).transpose();
  search_design.z = design.columns * scale.cwiseInverse().asDiagonal();
  search_design.weights = term_weights(design.terms);
  for (const std::string& name : design.terms) search_design.levels.push_back(name == "constant_on_y" || name == "constant_on_z");
  search_design.terms = std::move(design.terms);
  std::optional<CandidateScore> whole = search(observations, rows, residual, search_design, folds, settings, false);
  if (count(search_design.levels) == 0) return whole;
  // A run's level is the bridge's zero drift at that time as much as anything physical, and a
  // term that carries a level (T along the misalignment, always positive) can win the ordering on
  // it: on rig hysteresis it took the training run's 0.8 and 1.1 kN·m with the part of
  // T sign(dzeta/dt) that it shares, and the next run, with its own level, lost 6 points of its
  // cut that the right term keeps. So the terms are also ordered on what varies within each
  // channel, with the levels as intercepts, and that formula is taken when it explains more of
  // what varies within the channels on held-out rows; the interleaved folds share the run's level
  // and cannot tell the two apart on it. Where the level is the physics' (a speed drag, T zeta
  // along the moment), the formula ordered on the whole residual explains the variation as well.
  std::optional<CandidateScore> within = search(observations, rows, residual, search_design, folds, settings, true);
  if (!whole || (within && within_channel_mean_square(*within, folds) < within_channel_mean_square(*whole, folds))) return within;
  return whole;
}

}  // namespace gc
