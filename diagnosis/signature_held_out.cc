#include "diagnosis/signature_held_out.h"

#include <algorithm>
#include <string>
#include <vector>

namespace gc {
namespace {

/// One column per bin beyond each input's first, and a constant: the additive model as a design.
Eigen::MatrixXd bin_design(const std::vector<std::vector<int>>& bins, std::size_t rows) {
  std::vector<int> offset{1};
  for (const std::vector<int>& b : bins) offset.push_back(offset.back() + *std::max_element(b.begin(), b.end()));
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows), offset.back());
  x.col(0).setOnes();
  for (std::size_t j = 0; j < bins.size(); ++j) {
    for (std::size_t i = 0; i < rows; ++i) {
      if (bins[j][i] > 0) x(static_cast<Eigen::Index>(i), offset[j] + bins[j][i] - 1) = 1.0;
    }
  }
  return x;
}

/// The bins of the signature's systematic inputs but time, on `rows`; empty when there are none.
std::vector<std::vector<int>> systematic_bins(std::span<const RecordedSample> observations,
                                              std::span<const std::size_t> rows, const ResidualSignature& signature) {
  std::vector<std::vector<int>> bins;
  for (const InputSignature& s : signature.inputs) {
    if (!s.systematic || s.input == "time") continue;
    std::vector<int> b = signature_bins(observations, rows, s.input);
    if (!b.empty() && *std::max_element(b.begin(), b.end()) > 0) bins.push_back(std::move(b));
  }
  return bins;
}

Eigen::MatrixXd take_rows(const Eigen::MatrixXd& m, const std::vector<std::size_t>& rows) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(rows.size()), m.cols());
  for (std::size_t k = 0; k < rows.size(); ++k) out.row(static_cast<Eigen::Index>(k)) = m.row(static_cast<Eigen::Index>(rows[k]));
  return out;
}

}  // namespace

std::optional<CandidateScore> signature_held_out(std::span<const RecordedSample> observations,
                                                 std::span<const std::size_t> rows, const Eigen::MatrixX2d& base,
                                                 const Folds& folds, const ResidualSignature& signature) {
  const std::vector<std::vector<int>> bins = systematic_bins(observations, rows, signature);
  if (bins.empty()) return std::nullopt;
  const Eigen::MatrixXd x = bin_design(bins, rows.size());
  const Eigen::MatrixXd y = base;
  CandidateScore score;
  score.kind = CandidateKind::formula;
  score.held_out_residual = base;
  // A small ridge keeps a bin that a fold's training rows leave empty at zero, not undefined.
  const double ridge = 1e-9 * static_cast<double>(rows.size());
  for (std::size_t f = 0; f < folds.training.size(); ++f) {
    const Eigen::MatrixXd xt = take_rows(x, folds.training[f]);
    const Eigen::MatrixXd normal = xt.transpose() * xt + ridge * Eigen::MatrixXd::Identity(x.cols(), x.cols());
    const Eigen::MatrixXd coefficients = normal.ldlt().solve(xt.transpose() * take_rows(y, folds.training[f]));
    for (std::size_t i : folds.held_out[f]) {
      const auto r = static_cast<Eigen::Index>(i);
      score.held_out_residual.row(r) = base.row(r) - x.row(r) * coefficients;
    }
  }
  score_held_out(score, base, folds);
  return score;
}

std::optional<SurrogateDesign> signature_design(std::span<const RecordedSample> observations,
                                               std::span<const std::size_t> rows, const ResidualSignature& signature) {
  const std::vector<std::vector<int>> bins = systematic_bins(observations, rows, signature);
  if (bins.empty()) return std::nullopt;
  const Eigen::MatrixXd x = bin_design(bins, rows.size());
  const Eigen::Index n = x.rows(), p = x.cols();
  // Each channel its own levels: the stacked rows (M_sy' then M_sz') against a block diagonal.
  Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(2 * n, 2 * p);
  columns.topLeftCorner(n, p) = x;
  columns.bottomRightCorner(n, p) = x;
  // Judged on what it explains about the levels only, against noise with the residual's own
  // spectrum: its bins follow the programme, so a level test against what they leave, or a null
  // drawn from it, would take a walk they follow for structure.
  return SurrogateDesign{std::move(columns), 0, false, {}, true};
}

}  // namespace gc
