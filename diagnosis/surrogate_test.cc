#include "diagnosis/surrogate_test.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <random>
#include <array>
#include <utility>

#include <unsupported/Eigen/FFT>

#include "diagnosis/beta_tail.h"
#include "diagnosis/median.h"
#include "diagnosis/prewhitening.h"
#include "diagnosis/stacked_channels.h"

namespace gc {
namespace {

/// The variance of a rise from the first row to the last: the square of the rise from the first
/// fifth's mean to the last's, scaled to the whole length (a fifth's mean sits a tenth of the length
/// from its end). A random walk rises by as much again in another draw; a stationary noise's fifths
/// hardly differ. Means, not the end rows: a spike on the first or last row would set it.
double rise_variance(const Eigen::VectorXd& x) {
  const Eigen::Index n = x.size();
  if (n < 10) return 0.0;
  const double rise = 1.25 * (x.tail(n / 5).mean() - x.head(n / 5).mean());
  return rise * rise;
}

/// The unit vector (2n rows, stacked) whose product with a series is its rise on `channel`, up to
/// rise_variance's scale: the last fifth's mean less the first's.
Eigen::VectorXd rise_direction(Eigen::Index n, int channel) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(2 * n);
  const Eigen::Index fifth = n / 5;
  if (fifth < 1) return out;
  out.segment(channel * n, fifth).setConstant(-1.0);
  out.segment(channel * n + n - fifth, fifth).setConstant(1.0);
  return out / std::sqrt(2.0 * static_cast<double>(fifth));
}

/// What a contrast of one channel's rows shows of a white noise of unit variance and of a walk of
/// unit variance a row, once least squares on a design (its orthonormal `span`, 2n rows stacked)
/// took what the design spans: |u|^2 and |R u|^2, with u = (I - P) c and R u the sums of u from each
/// row to its channel's last (a walk's covariance is min(i, j)). Without a span, the contrast's own.
struct ContrastVariances {
  Eigen::MatrixXd span;      ///< 2n x m, orthonormal
  Eigen::MatrixXd tails;     ///< the span's sums from each row to its channel's last (R span)
  Eigen::MatrixXd tails_gram;  ///< tails' tails
  Eigen::Index n = 0;

  ContrastVariances(const Eigen::MatrixXd& s, Eigen::Index rows) : span(s), tails(s.rows(), s.cols()), n(rows) {
    for (int c = 0; c < 2; ++c) {
      Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(s.cols());
      for (Eigen::Index i = n - 1; i >= 0; --i) tails.row(c * n + i) = sum += s.row(c * n + i);
    }
    tails_gram = tails.transpose() * tails;
  }

  /// The contrast of the mean of `length` rows from `to` less the mean of `length` rows from `from`,
  /// on `channel` (from + length <= to).
  Eigen::Vector2d operator()(int channel, Eigen::Index from, Eigen::Index to, Eigen::Index length) const {
    const double l = static_cast<double>(length);
    const Eigen::Index o = channel * n;  // the channel's first row in the stacked span
    // The contrast's own tail sums: 0 before `from`, climbing to 1 across the first block, 1 between,
    // falling to 0 across the second.
    const auto tail = [&](Eigen::Index i) {
      if (i < from || i >= to + length) return 0.0;
      if (i < from + length) return static_cast<double>(i - from) / l;
      if (i < to) return 1.0;
      return static_cast<double>(to + length - i) / l;
    };
    double white = 2.0 / l, walk = 0.0;
    for (Eigen::Index i = from; i < to + length; ++i) walk += tail(i) * tail(i);
    if (span.cols() == 0) return {white, walk};
    const Eigen::VectorXd v =
        (span.middleRows(o + to, length).colwise().sum() - span.middleRows(o + from, length).colwise().sum()).transpose() / l;
    Eigen::VectorXd cross = Eigen::VectorXd::Zero(span.cols());
    for (Eigen::Index i = from; i < to + length; ++i) {
      if (const double t = tail(i); t != 0.0) cross += t * tails.row(o + i).transpose();
    }
    return {white - v.squaredNorm(), walk - 2.0 * v.dot(cross) + v.dot(tails_gram * v)};
  }
};

/// The rise variance of the noise in `x` (one channel of what a design with `span` leaves) over
/// the recording's fifths, were no design taken from it: fitted as white noise and a walk, a |u|^2 +
/// b |R u|^2 (ContrastVariances), to how the means of adjacent blocks of a tenth, a twentieth and a
/// fortieth of the rows differ (at least 4 rows a block), each scale weighted by its count of
/// contrasts, the walk kept only where it is significant (one-sided 1 %); then the fifths' contrast
/// without the design, scaled as rise_variance. The design's share of each contrast is taken out of
/// what the fit expects, not out of the noise: a slow effect (a thermal growth as the oil warms)
/// takes the slow part of the leftover's contrasts and the fit expects it taken, so neither its own
/// rise nor a walk's is lost. Measured on 400 draws of 1,500 rows without a design: the rise's
/// spread within 0.7-1.2 of the truth's at the 10th-90th percentiles for white noise, a walk and
/// both; 0.6-0.8 for AR(1) noise of phi 0.95.
double extrapolated_rise_variance(const Eigen::VectorXd& x, int channel, const ContrastVariances& projected,
                                  const ContrastVariances& own) {
  const Eigen::Index n = x.size();
  std::vector<Eigen::Vector3d> rows;  // weighted: white, walk; the weight itself (the scaled observation)
  for (const Eigen::Index parts : {10, 20, 40}) {
    const Eigen::Index length = n / parts;
    if (length < 4) break;
    double sum = 0.0, previous = x.segment(0, length).mean();
    Eigen::Vector2d expected = Eigen::Vector2d::Zero();
    for (Eigen::Index k = 1; k < parts; ++k) {
      const double mean = x.segment(k * length, length).mean();
      sum += (mean - previous) * (mean - previous);
      previous = mean;
      expected += projected(channel, (k - 1) * length, k * length, length);
    }
    const double contrasts = static_cast<double>(parts - 1), d = sum / contrasts;
    if (!(d > 0.0) || !(expected(0) > 0.0)) continue;
    // A mean of m squared contrasts has a relative spread of about sqrt(2 / m).
    const double w = std::sqrt(contrasts / 2.0) / d;
    rows.push_back({w * expected(0) / contrasts, w * std::max(expected(1), 0.0) / contrasts, w * d});
  }
  if (rows.empty()) return 0.0;
  Eigen::MatrixX2d a(static_cast<Eigen::Index>(rows.size()), 2);
  Eigen::VectorXd b(a.rows());
  for (Eigen::Index j = 0; j < a.rows(); ++j) a.row(j) = rows[static_cast<std::size_t>(j)].head<2>().transpose(), b(j) = rows[static_cast<std::size_t>(j)](2);
  double white = (a.col(0).dot(b)) / a.col(0).squaredNorm(), walk = 0.0;
  if (a.rows() >= 3) {
    const Eigen::Matrix2d normal = a.transpose() * a;
    const Eigen::Vector2d both = normal.ldlt().solve(a.transpose() * b);
    const double se = std::sqrt(normal.inverse()(1, 1));
    if (both(1) > 2.33 * se) {
      white = std::max(both(0), 0.0);
      // A standard error up: a walk's rise is taken at the upper end of what its blocks say (the
      // fit alone left 6 of 300 walks under a staircase claimed, for a level of 1 %).
      walk = (both(0) >= 0.0 ? both(1) : a.col(1).dot(b) / a.col(1).squaredNorm()) + se;
    }
  }
  const Eigen::Index fifth = n / 5;
  const Eigen::Vector2d rise = own(channel, 0, n - fifth, fifth);
  return 1.25 * 1.25 * (std::max(white, 0.0) * rise(0) + walk * rise(1));
}

/// The rise variance of the noise a candidate leaves, per channel: the larger of the leftover's
/// own rise, given back the share the design's `span` (orthonormal) took of the rise's direction
/// (as the spectrum is, SurrogateSpectrum::removed), and the rise its blocks extrapolate to
/// (extrapolated_rise_variance); the blocks alone where the span takes more than half the rise.
/// Not the residual's own: it gives every surrogate the rise of a real effect whose programme ends
/// elsewhere than it began (a compliance of 8 kN·m in 5 kN·m of brown and resonant noise was judged
/// against surrogates with rises of 25 kN·m and lost its claim; a thermal misalignment as the oil
/// warmed, 1.8 kN·m in 1.1 kN·m of white noise, the same).
///
/// A design `chosen` for this residual among many columns (a formula's terms) is chosen again on
/// every surrogate. Terms that follow one time profile (a speed term, or one on each channel, as a
/// drag in a direction between them is) take one direction of each channel's block contrasts and
/// leave the wander in the rest, so the leftover's rise serves as for a fixed design; with the
/// residual's own rise, which is the terms' too, a term following a speed ramp in white noise was
/// found less often the stronger it was (6 and 3 of 100 at 0.5 and 0.8 noise sigma; 100 and 100 with
/// the leftover's; a drag between the channels, two terms, 15 and 12: 100 and 100), and a zoo speed
/// drag of 45 % of the held-out error was no claim (power seed 20261299, draw 7). Terms of several
/// profiles (time_profiles) take the slow subspace together, the wander from the blocks with it,
/// and keep the residual's own rise (five slow terms took a brown noise's rise of 17 kN·m, its
/// leftover's blocks said 0.9). On wandering zeros one slow term chosen was claimed in 2 of 300
/// draws (5 with the residual's rise); two and three in 10 and 17 with the residual's rise, about 19
/// and 30 with the leftover's, and 3 and 5 with the larger of the two, which lost 3 of 30 zoo
/// twice-per-revolution draws under brown and hidden AR(1) noise, a forward order's cosine and sine
/// (power seeds 20261299 draws 0 and 4, 20261303 draw 0), so it is not used.
/// `profiles`: those of the chosen terms. Where the candidate claims terms other than the greedy
/// choice on the residual takes (SurrogateDesign::own_profiles), its own count: a speed drag's
/// speed on M_sy' and M_sz', claimed, where the greedy choice took speed on M_sy' and t^3 on M_sz'
/// (two profiles), had the residual's rise, the drag's own, and surrogate p = 0.38 with a held-out
/// cut of 44 % (zoo power seed 20261329, draw 4).
Eigen::Array2d rise_of_the_noise(const Eigen::MatrixX2d& residual, const Eigen::MatrixX2d& left,
                                 const Eigen::MatrixXd& span, bool chosen, int profiles) {
  const Eigen::Index n = left.rows();
  if (chosen && profiles > 1) return {rise_variance(residual.col(0)), rise_variance(residual.col(1))};
  const ContrastVariances projected(span, n), own(Eigen::MatrixXd(2 * n, 0), n);
  Eigen::Array2d out;
  for (int c = 0; c < 2; ++c) {
    const double taken = (span.transpose() * rise_direction(n, c)).squaredNorm();
    const double blocks = extrapolated_rise_variance(left.col(c), c, projected, own);
    out(c) = taken > 0.5 ? blocks : std::max(rise_variance(left.col(c)) / (1.0 - taken), blocks);
  }
  return out;
}

/// A bin this many times the median power about it is a line (a cycle, or a test programme that
/// repeats), not the noise's continuum.
constexpr double kLineRatio = 10.0;

/// A line is narrow: it stands kLineRatio above the bins kNearFrom to kNearTo away on either side
/// too, where a sinusoid's leakage between bins has fallen to under 2 % of its power. A resonance
/// of the noise is broad, its neighbours as strong: an AR(2) peak 2.3 Hz wide on 8.6 s (20 bins),
/// brought down as a line, left surrogates without it, and a cycle at its top took 3 % of a
/// noise-only recording's held-out error at surrogate p = 0 (zoo seed 20261284, draw 495).
constexpr std::size_t kNearFrom = 3, kNearTo = 10;

/// The power of the bins kNearFrom..kNearTo away from k on either side (within 1..half).
std::vector<double> near_bins(const std::vector<double>& power, std::size_t k, std::size_t half) {
  std::vector<double> near;
  for (std::size_t d = kNearFrom; d <= kNearTo; ++d) {
    if (k > d) near.push_back(power[k - d]);
    if (k + d <= half) near.push_back(power[k + d]);
  }
  return near;
}

/// `spectrum`'s amplitudes for k = 0..n/2, each line brought down to the median about it (bins
/// k/2..2k): a surrogate keeps the noise's continuum but not a line, which a design in phase with
/// it would otherwise explain in many surrogates as well as in the residual (a hysteresis on
/// repeated misalignment sweeps lost its claim that way).
std::vector<double> without_lines(const std::vector<std::complex<double>>& spectrum) {
  const std::size_t half = spectrum.size() / 2;
  std::vector<double> power(half + 1), amplitude(half + 1);
  for (std::size_t k = 0; k <= half; ++k) power[k] = std::norm(spectrum[k]);
  for (std::size_t k = 0; k <= half; ++k) {
    amplitude[k] = std::sqrt(power[k]);
    if (k == 0) continue;
    std::vector<double> about(power.begin() + static_cast<std::ptrdiff_t>(std::max<std::size_t>(1, k / 2)),
                              power.begin() + static_cast<std::ptrdiff_t>(std::min(half, 2 * k) + 1));
    if (about.size() < 5) continue;
    const double continuum = median(std::move(about));
    if (!(power[k] > kLineRatio * continuum)) continue;
    const std::vector<double> near = near_bins(power, k, half);
    if (near.size() >= 4 && !(power[k] > kLineRatio * median(near))) continue;  // broad: a resonance
    amplitude[k] = std::sqrt(continuum);
  }
  return amplitude;
}

/// The largest length up to `n` whose only prime factors are 2, 3 and 5.
Eigen::Index smooth_length(Eigen::Index n) {
  for (Eigen::Index m = n; m > 1; --m) {
    Eigen::Index r = m;
    for (const Eigen::Index f : {2, 3, 5}) {
      while (r % f == 0) r /= f;
    }
    if (r == 1) return m;
  }
  return 1;
}

/// One design made ready to project many right-hand sides.
class Projector {
 public:
  /// `rows`: the rows of each channel (the design has 2 * rows).
  Projector(const SurrogateDesign& design, Eigen::Index rows) : Projector(design, levels(rows)) {}

  /// With the channels' levels given (orthonormal, or zero where a filter left no level).
  Projector(const SurrogateDesign& design, Eigen::MatrixXd channel_levels)
      : choose_(design.choose), levels_(std::move(channel_levels)) {
    if (choose_ <= 0) {
      basis_ = orthonormal(concatenated(levels_, design.columns));
      return;
    }
    normalised_ = design.columns;
    normalised_ -= levels_ * (levels_.transpose() * normalised_);
    for (Eigen::Index j = 0; j < normalised_.cols(); ++j) {
      const double norm = normalised_.col(j).norm();
      const double before = design.columns.col(j).norm();
      // A term some row cannot evaluate, or a level, is never chosen.
      if (std::isfinite(norm) && norm > 1e-9 * before) {
        normalised_.col(j) /= norm;
      } else {
        normalised_.col(j).setZero();
      }
    }
    gram_ = normalised_.transpose() * normalised_;
  }

  /// The share of what varies about each channel's level that the design explains beyond it.
  double share(const Eigen::VectorXd& y) const { return shares(y)(0); }

  /// share() of each column of `ys`, their products with the design's columns found together: one
  /// pass over the design's rows for all of them, where each alone streamed it from memory (a
  /// formula's 148 terms on 19,098 dense rows are 45 MB, read for each of 6,400 surrogates).
  Eigen::VectorXd shares(const Eigen::MatrixXd& ys) const {
    const Eigen::MatrixXd level = levels_.transpose() * ys;
    const Eigen::MatrixXd products = choose_ <= 0 ? basis_.transpose() * ys : normalised_.transpose() * ys;
    Eigen::VectorXd out(ys.cols());
    for (Eigen::Index b = 0; b < ys.cols(); ++b) {
      const double of_level = level.col(b).squaredNorm();
      const double total = ys.col(b).squaredNorm() - of_level;
      const double beyond = choose_ <= 0 ? products.col(b).squaredNorm() - of_level : greedy_share_of(products.col(b));
      out(b) = total > 0.0 ? std::clamp(beyond / total, 0.0, 1.0) : 0.0;
    }
    return out;
  }

  /// Orthonormal columns spanning the levels and the design (the columns chosen for `y`).
  Eigen::MatrixXd span(const Eigen::VectorXd& y) const { return choose_ <= 0 ? basis_ : greedy_basis(y); }

 private:
  /// What greedy_basis's chosen columns explain of y beyond the levels, |P_S y|^2, found from
  /// c = N'y and the Gram matrix G = N'N of the unit columns N (which are clear of the levels): a
  /// step's correlations with what the chosen S leave are c - G_{.S} G_SS^-1 c_S, and the fit is
  /// c_S' G_SS^-1 c_S. One pass over the rows, where greedy_basis takes one a step: a formula's
  /// catalogue of 112 fast terms on 20,000 dense rows, tested on 6,400 surrogates, took a minute.
  double greedy_share_of(const Eigen::VectorXd& c) const {
    const Eigen::Index steps = std::min<Eigen::Index>(choose_, normalised_.cols());
    std::vector<Eigen::Index> chosen;
    std::vector<bool> taken(static_cast<std::size_t>(c.size()), false);
    Eigen::LLT<Eigen::MatrixXd> chosen_gram;
    Eigen::VectorXd coefficients;
    for (Eigen::Index step = 0; step < steps; ++step) {
      Eigen::VectorXd scores = c;
      if (!chosen.empty()) scores -= gram_(Eigen::all, chosen) * coefficients;
      Eigen::Index best = -1;
      for (Eigen::Index j = 0; j < scores.size(); ++j) {
        if (!taken[static_cast<std::size_t>(j)] && (best < 0 || std::abs(scores(j)) > std::abs(scores(best)))) best = j;
      }
      if (best < 0) break;
      taken[static_cast<std::size_t>(best)] = true;
      // The column's part clear of the chosen ones, squared (greedy_basis's q).
      double clear = gram_(best, best);
      if (!chosen.empty()) {
        const Eigen::VectorXd g = gram_(chosen, best);
        clear -= g.dot(chosen_gram.solve(g));
      }
      if (!(clear > 1e-18)) continue;
      chosen.push_back(best);
      chosen_gram.compute(gram_(chosen, chosen));
      coefficients = chosen_gram.solve(c(chosen));
    }
    return chosen.empty() ? 0.0 : c(chosen).dot(coefficients);
  }

  /// Orthogonal matching pursuit: `choose_` steps, each taking the column most correlated with
  /// what the chosen ones leave; returns the orthonormal basis of the levels and the chosen.
  Eigen::MatrixXd greedy_basis(const Eigen::VectorXd& y) const {
    const Eigen::Index steps = std::min<Eigen::Index>(choose_, normalised_.cols());
    Eigen::MatrixXd basis(y.size(), levels_.cols() + steps);
    basis.leftCols(levels_.cols()) = levels_;
    Eigen::Index kept = levels_.cols();
    Eigen::VectorXd left = y - basis.leftCols(kept) * (basis.leftCols(kept).transpose() * y);
    std::vector<bool> taken(static_cast<std::size_t>(normalised_.cols()), false);
    for (Eigen::Index step = 0; step < steps; ++step) {
      const Eigen::VectorXd scores = (normalised_.transpose() * left).cwiseAbs();
      Eigen::Index best = -1;
      for (Eigen::Index j = 0; j < scores.size(); ++j) {
        if (!taken[static_cast<std::size_t>(j)] && (best < 0 || scores(j) > scores(best))) best = j;
      }
      if (best < 0) break;
      taken[static_cast<std::size_t>(best)] = true;
      Eigen::VectorXd q = normalised_.col(best);
      for (int pass = 0; pass < 2; ++pass) q -= basis.leftCols(kept) * (basis.leftCols(kept).transpose() * q);
      const double norm = q.norm();
      if (!(norm > 1e-9)) continue;
      basis.col(kept++) = q / norm;
      left = y - basis.leftCols(kept) * (basis.leftCols(kept).transpose() * y);
    }
    return basis.leftCols(kept);
  }

 public:
  /// Each channel's level, as orthonormal columns.
  static Eigen::MatrixXd levels(Eigen::Index rows) {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(2 * rows, 2);
    const double unit = 1.0 / std::sqrt(static_cast<double>(std::max<Eigen::Index>(rows, 1)));
    out.col(0).head(rows).setConstant(unit);
    out.col(1).tail(rows).setConstant(unit);
    return out;
  }

 private:
  static Eigen::MatrixXd concatenated(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    Eigen::MatrixXd out(a.rows(), a.cols() + b.cols());
    out << a, b;
    return out;
  }

  /// Orthonormal columns spanning `m`'s finite columns.
  static Eigen::MatrixXd orthonormal(Eigen::MatrixXd m) {
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if (!m.col(j).allFinite()) m.col(j).setZero();
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
    return qr.householderQ() * Eigen::MatrixXd::Identity(m.rows(), qr.rank());
  }

  int choose_;
  Eigen::MatrixXd levels_;      ///< each channel's level, orthonormal
  Eigen::MatrixXd basis_;       ///< orthonormal columns spanning the levels and the design (choose_ 0)
  Eigen::MatrixXd normalised_;  ///< unit columns, less the levels (choose_ > 0)
  Eigen::MatrixXd gram_;        ///< normalised_' normalised_ (choose_ > 0)
};

/// A design judged on the residual prewhitened: one filter applied alike to the residual, to every
/// surrogate, to the design's columns (its others in the box too) and to the channels' levels. The
/// same surrogates judge it, so the filter is a choice of statistic.
class WhitenedDesign {
 public:
  WhitenedDesign(const SurrogateDesign& design, const Prewhitening& filter, Eigen::Index rows)
      : filter_(filter),
        levels_(whitened_levels(filter_, rows)),
        projector_(SurrogateDesign{filter_.applied(design.columns), design.choose, false, {}}, levels_) {
    for (const Eigen::MatrixXd& columns : design.elsewhere) {
      scan_.emplace_back(SurrogateDesign{filter_.applied(columns), 0, false, {}}, levels_);
    }
  }

  /// The largest share the design, or any of its others, explains of each column of `xs` (stacked,
  /// not yet filtered).
  Eigen::VectorXd largest_shares(const Eigen::MatrixXd& xs) const {
    const Eigen::MatrixXd filtered = filter_.applied(xs);
    Eigen::VectorXd best = projector_.shares(filtered);
    for (const Projector& other : scan_) best = best.cwiseMax(other.shares(filtered));
    return best;
  }

 private:
  /// Each channel's level filtered, as unit columns; none where the filter takes it (a difference).
  static Eigen::MatrixXd whitened_levels(const Prewhitening& filter, Eigen::Index rows) {
    Eigen::MatrixXd out = filter.applied(Projector::levels(rows));
    for (Eigen::Index j = 0; j < out.cols(); ++j) {
      const double norm = out.col(j).norm();
      if (norm > 1e-6) {
        out.col(j) /= norm;
      } else {
        out.col(j).setZero();
      }
    }
    return out;
  }

  Prewhitening filter_;
  Eigen::MatrixXd levels_;
  Projector projector_;
  std::vector<Projector> scan_;
};

}  // namespace

std::vector<double> SurrogateSpectrum::leverage(const Eigen::MatrixXd& basis, Eigen::Index n, int channel) {
  const Eigen::Index m = smooth_length(n);
  std::vector<double> out(static_cast<std::size_t>(m / 2 + 1), 0.0);
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  for (Eigen::Index j = 0; j < basis.cols(); ++j) {
    const Eigen::VectorXd q = basis.col(j).segment(channel * n + (n - m), m);
    fft.fwd(spectrum, std::vector<double>(q.data(), q.data() + m));
    for (std::size_t k = 0; k < out.size(); ++k) out[k] += std::norm(spectrum[k]) / static_cast<double>(m);
  }
  return out;
}

struct SurrogateSource::Workspace::Transform {
  Eigen::FFT<double> fft;
};
SurrogateSource::Workspace::Workspace() : fft_(std::make_unique<Transform>()) {}
SurrogateSource::Workspace::~Workspace() = default;
SurrogateSource::Workspace::Workspace(Workspace&&) noexcept = default;

SurrogateSource::~SurrogateSource() = default;

SurrogateSource::SurrogateSource(const Eigen::MatrixX2d& residual, std::uint64_t seed, const SurrogateSpectrum& shape)
    : n_(residual.rows()), m_(smooth_length(residual.rows())), random_(seed) {
  if (n_ < 8) return;
  // The FFT's length has only the factors 2, 3 and 5 (a prime length costs n^2): the last m rows;
  // a surrogate is circular, so it wraps to the n rows.
  for (int c = 0; c < 2; ++c) {
    // End-matched: less the line from its level at the start to its level at the end, which a
    // circular surrogate cannot hold; a rise of its own is drawn for each surrogate instead
    // (rise_sigma_). Each level is the mean of a twentieth of the rows: the first and last rows
    // alone would put a line through two samples of the noise, a slope as large as the noise (a
    // sixth of white noise's power) that no recording has, and that slow terms then explain in
    // every surrogate.
    Eigen::VectorXd tail = residual.col(c).tail(m_);
    const Eigen::Index ends = std::max<Eigen::Index>(1, m_ / 20);
    const double first = tail.head(ends).mean(), last = tail.tail(ends).mean();
    for (Eigen::Index i = 0; i < m_; ++i) tail(i) -= first + (last - first) * static_cast<double>(i) / static_cast<double>(m_ - 1);
    std::vector<std::complex<double>> spectrum;
    workspace_.fft_->fft.fwd(spectrum, std::vector<double>(tail.data(), tail.data() + m_));
    const std::vector<double>& removed = shape.removed[static_cast<std::size_t>(c)];
    if (removed.size() == static_cast<std::size_t>(m_ / 2 + 1)) {
      for (Eigen::Index k = 1; k <= m_ / 2; ++k) {
        const double kept = 1.0 - std::min(removed[static_cast<std::size_t>(k)], SurrogateSpectrum::kMostRestored);
        spectrum[static_cast<std::size_t>(k)] /= std::sqrt(kept);
        spectrum[static_cast<std::size_t>(m_ - k)] = std::conj(spectrum[static_cast<std::size_t>(k)]);
      }
    }
    amplitudes_[static_cast<std::size_t>(c)] = without_lines(spectrum);
    rise_sigma_[static_cast<std::size_t>(c)] =
        std::sqrt(shape.rise_variance ? (*shape.rise_variance)(c) : rise_variance(residual.col(c)));
  }
}

SurrogateSource::Draw SurrogateSource::draw() {
  Draw out;
  if (n_ < 8) return out;
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  std::normal_distribution<double> normal;
  out.phases.resize(static_cast<std::size_t>(m_ / 2 + 1));
  for (Eigen::Index k = 1; k <= m_ / 2; ++k) out.phases[static_cast<std::size_t>(k)] = phase(random_);
  for (double& rise : out.rises) rise = normal(random_);
  return out;
}

Eigen::MatrixX2d SurrogateSource::next() {
  const Draw numbers = draw();
  return made(numbers, workspace_);
}

Eigen::MatrixX2d SurrogateSource::made(const Draw& draw, Workspace& workspace) const {
  if (n_ < 8) return Eigen::MatrixX2d::Zero(n_, 2);
  std::vector<std::complex<double>> rotation(static_cast<std::size_t>(m_ / 2 + 1));
  for (Eigen::Index k = 1; k <= m_ / 2; ++k) {
    rotation[static_cast<std::size_t>(k)] = std::polar(1.0, draw.phases[static_cast<std::size_t>(k)]);
  }
  std::vector<std::complex<double>> turned(static_cast<std::size_t>(m_));
  std::vector<double> back;
  Eigen::MatrixX2d surrogate(n_, 2);
  for (int c = 0; c < 2; ++c) {
    const std::vector<double>& x = amplitudes_[static_cast<std::size_t>(c)];
    turned[0] = 0.0;  // the level is not judged (Projector::share)
    for (Eigen::Index k = 1; k <= (m_ - 1) / 2; ++k) {
      const std::complex<double> v = x[static_cast<std::size_t>(k)] * rotation[static_cast<std::size_t>(k)];
      turned[static_cast<std::size_t>(k)] = v;
      turned[static_cast<std::size_t>(m_ - k)] = std::conj(v);
    }
    if (m_ % 2 == 0) {
      turned[static_cast<std::size_t>(m_ / 2)] =
          x[static_cast<std::size_t>(m_ / 2)] * (rotation[static_cast<std::size_t>(m_ / 2)].real() < 0.0 ? -1.0 : 1.0);
    }
    workspace.fft_->fft.inv(back, turned);
    const double rise = draw.rises[static_cast<std::size_t>(c)] * rise_sigma_[static_cast<std::size_t>(c)];
    for (Eigen::Index i = 0; i < n_; ++i) {
      surrogate(i, c) = back[static_cast<std::size_t>(i % m_)] + rise * (static_cast<double>(i) / static_cast<double>(n_ - 1) - 0.5);
    }
  }
  return surrogate;
}

std::vector<Eigen::MatrixX2d> phase_randomised_surrogates(const Eigen::MatrixX2d& residual, int count,
                                                          std::uint64_t seed, const SurrogateSpectrum& shape) {
  std::vector<Eigen::MatrixX2d> out;
  if (residual.rows() < 8 || count <= 0) return out;
  SurrogateSource source(residual, seed, shape);
  for (int s = 0; s < count; ++s) out.push_back(source.next());
  return out;
}

/// Two-sided p-value of Student's t with an even number of degrees of freedom `nu`:
/// 1 - sin(theta) (1 + cos^2/2 + 1*3/(2*4) cos^4 + ... ), theta = atan(t / sqrt(nu))
/// (Abramowitz and Stegun 26.7.3).
double student_two_sided_p(double t, int nu) {
  const double theta = std::atan(std::abs(t) / std::sqrt(static_cast<double>(nu)));
  const double c2 = std::cos(theta) * std::cos(theta);
  double term = 1.0, sum = 1.0;
  for (int k = 2; k <= nu - 2; k += 2) {
    term *= c2 * (k - 1.0) / k;
    sum += term;
  }
  return std::clamp(1.0 - std::sin(theta) * sum, 0.0, 1.0);
}

/// After this many surrogates, none explained as well, a residual far out of their spread is judged
/// by the tail of their distribution instead of thousands more (a strong effect needs no 6,000
/// surrogates).
constexpr int kBeforeTail = 199;
/// Surrogates whose shares are found side by side at first: at most this less one are drawn past a
/// stop among the first. Each batch without a stop doubles the next, up to kMostSurrogatesAtOnce.
constexpr int kSurrogatesAtOnce = 8;
constexpr int kMostSurrogatesAtOnce = 64;

/// Standard deviations out of the surrogates' shares beyond which their Beta's tail is trusted.
constexpr double kFarOut = 8.0;

/// The chance that a surrogate of shares with `mean` and `variance` explains `observed`: Cantelli's
/// one-sided Chebyshev bound 1 / (1 + k^2), k standard deviations above the mean, which holds for
/// any distribution, or, where smaller, ten times the tail of the Beta with those moments (a share
/// explained of Gaussian noise is Beta-distributed; the factor of ten is room for the surrogates'
/// own shape), kFarOut standard deviations out or more: nearer, the surrogates are all drawn (a
/// bump searched over 24 places in AR(1) noise, its share the largest of 24, was claimed in 10 of
/// 300 draws with the Beta's tail at any distance, for a level of 1 %). Cantelli alone needed all
/// 6,000 surrogates for an effect 20 sigma out (1/401).
double tail_bound(double observed, double mean, double variance) {
  if (!(observed > mean)) return 1.0;
  if (!(variance > 0.0)) return 0.0;
  const double k2 = (observed - mean) * (observed - mean) / variance;
  const double cantelli = 1.0 / (1.0 + k2);
  return k2 >= kFarOut * kFarOut ? std::min(cantelli, 10.0 * beta_upper_tail(observed, mean, variance)) : cantelli;
}

/// The level test's blocks: 21 contiguous ones, 20 degrees of freedom.
constexpr Eigen::Index kLevelBlocks = 21;

namespace {

/// The spectrum a null drawn from what `design` leaves is given: the rise it leaves given back, and
/// the share of each frequency its columns (`span`, orthonormal) took.
SurrogateSpectrum left_shape(const Eigen::MatrixX2d& residual, const Eigen::MatrixX2d& left, const Eigen::MatrixXd& span,
                             const SurrogateDesign& design) {
  // Counted only for a design chosen again, and from the greedy choice only where the claimed
  // terms are not given (an effect's fixed design has no choice to count).
  const bool chosen = design.choose > 0;
  const int profiles = !chosen                 ? 0
                       : design.own_profiles   ? *design.own_profiles
                                               : time_profiles(span.rightCols(std::max<Eigen::Index>(span.cols() - 2, 0)),
                                                               residual.rows());
  SurrogateSpectrum shape{rise_of_the_noise(residual, left, span, chosen, profiles), {}};
  for (int c = 0; c < 2; ++c) shape.removed[static_cast<std::size_t>(c)] = SurrogateSpectrum::leverage(span, residual.rows(), c);
  return shape;
}

}  // namespace

namespace {

/// The statistics that judge a design, and how their p-values combine.
struct Statistics {
  bool as_it_is = true;        ///< the share of the residual as it is
  bool filtered = false;       ///< the share of everything prewhitened
  bool all_must_pass = false;  ///< the larger p-value counts (each must pass); else the smaller, Bonferroni'd
  double bonferroni() const { return all_must_pass ? 1.0 : (as_it_is && filtered ? 2.0 : 1.0); }
};

/// The largest sum of a filter's coefficients, a_1 + ... + a_p, at which a channel is not a walk.
constexpr double kWalkSum = 0.95;

/// How a design is judged, from `filter` (the residual's, marked where the inputs' noise would show
/// in it) and `noise`, what the null is drawn from (`of_the_residual`: the residual itself, whose
/// filter is `filter`).
/// Where the null is a walk on both channels (its own autoregression's coefficients sum to
/// kWalkSum or more: 5-95 % of 200 simulated draws of 600 rows, up to 12 lags, gave 0.96-1.00 for
/// a walk less a staircase and 0.48-0.87 for an AR(1) of 0.98 beside as much white noise, less a
/// slow term at 1.5 times it), the share as it is has no calibrated
/// null: a phase-randomised surrogate is stationary, a walk is not, and a gain and offset took
/// 62 % of a brown noise's variation where none of 12,000 surrogates reached 62 % (zoo size seed
/// 20261317, draw 22). The filtered share then judges alone; and where the inputs' noise would
/// show in it, both must pass, each at the level (an intersection-union test: valid when either
/// statistic is). Elsewhere, the share as it is, and the filtered one beside it (the smaller
/// p-value, doubled) where the inputs are clean.
Statistics statistics_for(const Prewhitening& filter, const Eigen::MatrixX2d& noise, bool of_the_residual) {
  if (filter.identity()) return {};
  const Prewhitening own = of_the_residual ? filter : Prewhitening::fitted(noise);
  bool walk = true;
  for (const Eigen::VectorXd& a : own.coefficients) walk = walk && a.size() > 0 && a.sum() >= kWalkSum;
  if (walk) return {filter.exposes_input_noise, true, filter.exposes_input_noise};
  return {true, !filter.exposes_input_noise, false};
}

}  // namespace

double level_standard_error(const Eigen::VectorXd& means) {
  const double m = static_cast<double>(means.size());
  const Eigen::ArrayXd about = means.array() - means.mean();
  const double sum_squares = about.square().sum();
  const double spread = std::sqrt(sum_squares / (m - 1.0));
  if (!(sum_squares > 0.0)) return spread;
  // Adjacent means' correlation, its bias on m means added back (Marriott and Pope 1954:
  // -(1 + 3 rho) / m), and 2.33 of its standard errors above that: a one-sided 1 % bound.
  const double r1 = (about.head(means.size() - 1) * about.tail(means.size() - 1)).sum() / sum_squares;
  const double bias = (1.0 + 3.0 * std::max(r1, 0.0)) / m;
  const double rho = std::min(0.999, r1 + bias + 2.326 * std::sqrt(std::max(1.0 - r1 * r1, 0.05) / m));
  // The mean's standard error with means correlated as an AR(1) of rho: (1 + rho) / (1 - rho)
  // times the independent one; never beyond the spread itself.
  const double inflation = std::sqrt(std::max(1.0 + rho, 0.0) / (1.0 - rho));
  return spread * std::min(1.0, inflation / std::sqrt(m));
}

double level_p_value(const Eigen::MatrixX2d& residual, const Eigen::MatrixX2d& wander) {
  double p = 1.0;
  for (int c = 0; c < 2; ++c) {
    const Eigen::VectorXd x = wander.col(c);
    const double level = residual.col(c).mean();
    const Eigen::Index n = x.size(), parts = kLevelBlocks;
    if (n < 2 * parts) continue;
    Eigen::VectorXd means(parts);
    for (Eigen::Index k = 0; k < parts; ++k) means(k) = x.segment(k * n / parts, (k + 1) * n / parts - k * n / parts).mean();
    const double error = level_standard_error(means);
    const double t = error > 0.0 ? std::abs(level) / error : (level != 0.0 ? 1e300 : 0.0);
    p = std::min(p, student_two_sided_p(t, static_cast<int>(parts - 1)));
  }
  return std::min(1.0, 2.0 * p);  // either channel
}

double explained_share(const Eigen::MatrixX2d& residual, const SurrogateDesign& design) {
  const Eigen::VectorXd y = stacked(residual);
  double best = Projector(design, residual.rows()).share(y);
  for (const Eigen::MatrixXd& columns : design.elsewhere) {
    best = std::max(best, Projector(SurrogateDesign{columns, 0, false, {}}, residual.rows()).share(y));
  }
  return best;
}

int time_profiles(const Eigen::MatrixXd& columns, Eigen::Index n) {
  Eigen::MatrixXd parts(n, 2 * columns.cols());
  Eigen::Index m = 0;
  for (Eigen::Index j = 0; j < columns.cols(); ++j) {
    for (int c = 0; c < 2; ++c) {
      Eigen::VectorXd part = columns.col(j).segment(c * n, n);
      part.array() -= part.mean();
      // A part under a millionth of its column's squares is the other channel's rounding.
      if (part.squaredNorm() > 1e-6 * columns.col(j).squaredNorm()) parts.col(m++) = part.normalized();
    }
  }
  if (m == 0) return 0;
  const Eigen::MatrixXd gram = parts.leftCols(m).transpose() * parts.leftCols(m);
  const Eigen::VectorXd eigen = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(gram).eigenvalues();
  return static_cast<int>((eigen.array() > 0.01 * eigen.maxCoeff()).count());
}

std::vector<double> surrogate_p_values(const Eigen::MatrixX2d& residual, const std::vector<SurrogateDesign>& designs,
                                       double level, std::uint64_t seed, std::size_t family_size,
                                       const ParallelFor& parallel) {
  return surrogate_p_values(residual, designs, level, seed, family_size, parallel, Prewhitening{});
}

std::vector<double> surrogate_p_values(const Eigen::MatrixX2d& residual, const std::vector<SurrogateDesign>& designs,
                                       double level, std::uint64_t seed, std::size_t family_size,
                                       const ParallelFor& parallel, const Prewhitening& filter) {
  std::vector<double> adjusted(designs.size(), 1.0);
  if (designs.empty() || !(level > 0.0)) return adjusted;
  const double family = static_cast<double>(std::max(family_size, designs.size()));
  const Eigen::VectorXd y = stacked(residual);
  // With a filter, each design can be judged on everything prewhitened for the noise too
  // (generalised least squares, prewhitening.h; statistics_for says when): slow noise fits a slow
  // design about as well as an effect does, but not the effect's steps. The filter is the
  // residual's own, not each leftover's: a staircase's leftover is a walk pulled
  // back to zero at every stair, whose filter (a_1 near 0.98, not 1) leaves a fiftieth of the walk
  // in the filtered residual, a slow part its surrogates lack; a level and a staircase were claimed
  // on 9 of 300 random walks, 3 with it (with the share as it is beside it, before statistics_for).
  for (std::size_t d = 0; d < designs.size(); ++d) {
    const Projector projector(designs[d], residual.rows());
    std::vector<Projector> scan;
    for (const Eigen::MatrixXd& columns : designs[d].elsewhere) scan.emplace_back(SurrogateDesign{columns, 0, false, {}}, residual.rows());
    // The largest share the design, or any of its others in the box, explains (Davies' statistic).
    const auto largest_shares = [&](const Eigen::MatrixXd& xs) {
      Eigen::VectorXd best = projector.shares(xs);
      for (const Projector& other : scan) best = best.cwiseMax(other.shares(xs));
      return best;
    };
    // The levels and the design's columns (those chosen for the residual), once: the leftover
    // and the leverage the surrogates give back both come from them.
    const Eigen::MatrixXd span = projector.span(y);
    const Eigen::MatrixX2d left = unstacked(y - span * (span.transpose() * y));
    double p = 1.0;
    if (designs[d].columns.cols() > 0) {
      // The null is noise like what the candidate leaves, with the rise it leaves given back
      // (rise_of_the_noise): a real effect's own spectrum (a drag that follows a speed programme, a
      // cross-talk of the model's moments) is not noise against it. Least squares took from the leftover the share of each frequency
      // that the design spans (its leverage there): the surrogates give it back, or a slow design
      // fitted to a slow noise would leave a null with less of the slow power than it took (ter
      // Braak's scheme is liberal by that much where a design has few degrees of freedom to spare).
      const bool of_the_residual = designs[d].null_of_the_residual;
      const SurrogateSpectrum shape = of_the_residual ? SurrogateSpectrum{} : left_shape(residual, left, span, designs[d]);
      SurrogateSource surrogates(of_the_residual ? residual : left, seed + d, shape);
      // Which statistics judge the design, and how (Statistics, below).
      const Statistics statistics = statistics_for(filter, of_the_residual ? residual : left, of_the_residual);
      std::optional<WhitenedDesign> whitened;
      if (statistics.filtered) whitened.emplace(designs[d], filter, residual.rows());
      const std::size_t first = statistics.as_it_is ? 0 : 1, last = statistics.filtered ? 2 : 1;
      // Each statistic's p-value must reach `per` for a claim at the level.
      const double per = level / (2.0 * family * statistics.bonferroni());
      // Enough surrogates that the smallest p-value reaches half of it.
      const int count = std::max(199, static_cast<int>(std::ceil(2.0 / per)) - 1);
      // Besag and Clifford's sequential stop: once this many surrogates are explained as well, the
      // p-value is above `per` whatever the rest say.
      const int enough = static_cast<int>(std::ceil(per * (count + 1.0)));
      struct Tally {
        double observed = 0.0;
        int as_well = 0;
        double sum = 0.0, sum_of_squares = 0.0;
        double beyond_doubt = -1.0;  // the tail's bound once it settles the test; negative before
      };
      std::array<Tally, 2> tallies;
      if (statistics.as_it_is) tallies[0].observed = largest_shares(y)(0);
      if (whitened) tallies[1].observed = whitened->largest_shares(y)(0);
      int drawn = 0;
      // A few surrogates drawn in order, their shares found side by side, then taken in order as
      // one at a time would take them: a stop leaves the rest of the batch unused. Their random
      // numbers are drawn in order; each half of a batch is made and judged on a thread of its own
      // (making them was a quarter of the time), its shares found together (Projector::shares).
      // The batches grow while no stop comes: most stop within the first few, where noise is
      // explained as well.
      std::vector<SurrogateSource::Draw> numbers;
      std::array<SurrogateSource::Workspace, 2> workspaces;
      Eigen::MatrixXd batch;
      Eigen::MatrixX2d shares;
      bool stopped = false;
      int at_once = kSurrogatesAtOnce;
      while (drawn < count && !stopped) {
        const int ahead = std::min(at_once, count - drawn);
        at_once = std::min(2 * at_once, kMostSurrogatesAtOnce);
        numbers.clear();
        for (int i = 0; i < ahead; ++i) numbers.push_back(surrogates.draw());
        batch.resize(y.size(), ahead);
        shares.setZero(ahead, 2);
        const std::size_t halves = ahead >= 2 ? 2 : 1;
        parallel(halves, [&](std::size_t begin, std::size_t end) {
          for (std::size_t h = begin; h < end; ++h) {
            const Eigen::Index from = static_cast<Eigen::Index>(h) * ahead / static_cast<Eigen::Index>(halves);
            const Eigen::Index to = static_cast<Eigen::Index>(h + 1) * ahead / static_cast<Eigen::Index>(halves);
            for (Eigen::Index i = from; i < to; ++i) {
              batch.col(i) = stacked(surrogates.made(numbers[static_cast<std::size_t>(i)], workspaces[h]));
            }
            const auto part = batch.middleCols(from, to - from);
            if (statistics.as_it_is) shares.col(0).segment(from, to - from) = largest_shares(part);
            if (whitened) shares.col(1).segment(from, to - from) = whitened->largest_shares(part);
          }
        });
        for (Eigen::Index i = 0; i < shares.rows() && !stopped; ++i) {
          ++drawn;
          // Settled once every statistic (the smaller p-value counts) or any (the larger) is
          // explained as well often enough.
          bool all_as_well = true, any_as_well = false;
          for (std::size_t s = first; s < last; ++s) {
            Tally& tally = tallies[s];
            const double share = shares(i, static_cast<Eigen::Index>(s));
            tally.sum += share;
            tally.sum_of_squares += share * share;
            if (share >= tally.observed) ++tally.as_well;
            all_as_well = all_as_well && tally.as_well >= enough;
            any_as_well = any_as_well || tally.as_well >= enough;
          }
          stopped = statistics.all_must_pass ? any_as_well : all_as_well;
          if (!stopped && drawn == kBeforeTail) {
            bool all_beyond = true, any_beyond = false;
            for (std::size_t s = first; s < last; ++s) {
              Tally& tally = tallies[s];
              const double mean = tally.sum / drawn;
              const double bound =
                  tally.as_well > 0 ? 1.0 : tail_bound(tally.observed, mean, tally.sum_of_squares / drawn - mean * mean);
              if (bound <= per / 2.0) tally.beyond_doubt = bound;
              all_beyond = all_beyond && bound <= per / 2.0;
              any_beyond = any_beyond || bound <= per / 2.0;
            }
            stopped = statistics.all_must_pass ? all_beyond : any_beyond;
            if (!stopped) {
              for (std::size_t s = first; s < last; ++s) tallies[s].beyond_doubt = -1.0;
            }
          }
        }
      }
      std::array<double, 2> ps{1.0, 1.0};
      for (std::size_t s = first; s < last; ++s) {
        const Tally& tally = tallies[s];
        ps[s] = tally.as_well >= enough       ? 1.0
                : tally.beyond_doubt >= 0.0   ? tally.beyond_doubt
                                              : (1.0 + tally.as_well) / (1.0 + static_cast<double>(drawn));
      }
      const double largest = *std::max_element(ps.begin() + first, ps.begin() + last);
      const double least = *std::min_element(ps.begin() + first, ps.begin() + last);
      p = statistics.all_must_pass ? largest : std::min(1.0, statistics.bonferroni() * least);
    }
    // A level the design moves, against the wander of what it leaves (its levels taken out with it).
    if (designs[d].level) p = std::min(p, level_p_value(residual, designs[d].level_against_the_residual ? residual : left));
    adjusted[d] = std::min(1.0, 2.0 * family * p);
  }
  return adjusted;
}

}  // namespace gc
