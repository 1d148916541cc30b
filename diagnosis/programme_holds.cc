#include "diagnosis/programme_holds.h"

#include <algorithm>
#include <string>
#include <unordered_map>

namespace gc {
namespace {

bool is_input(const std::string& channel) {
  return channel == "torque" || channel == "misalignment" || channel == "direction" || channel == "speed" ||
         channel == "temperature";
}

/// Mean square of the residual over `data_rows` that the model predicted (-1 when none).
double mean_square(const std::vector<std::size_t>& data_rows, const std::unordered_map<std::size_t, Eigen::Index>& at,
                   const ModelResiduals& residuals) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const std::size_t r : data_rows) {
    const auto found = at.find(r);
    if (found == at.end()) continue;
    sum += residuals.residual.row(found->second).squaredNorm() / 2.0;
    ++count;
  }
  return count == 0 ? -1.0 : sum / static_cast<double>(count);
}

}  // namespace

bool has_held_inputs(const DataQuality& quality) {
  return std::any_of(quality.findings.begin(), quality.findings.end(), [](const DataQualityFinding& f) {
    return f.kind == DataQualityKind::stuck && f.excluded && is_input(f.channel);
  });
}

void release_programme_holds(DataQuality& quality, std::span<const RecordedSample> observations,
                             std::span<const std::size_t> rows, const ModelResiduals& residuals, double most_ratio) {
  if (!has_held_inputs(quality) || residuals.residual.rows() != static_cast<Eigen::Index>(rows.size())) return;
  std::unordered_map<std::size_t, Eigen::Index> at;  // data row -> residual row, predicted rows only
  for (std::size_t k = 0; k < rows.size(); ++k) at.emplace(rows[k], static_cast<Eigen::Index>(k));
  for (const std::size_t r : residuals.failed_rows) at.erase(r);
  std::vector<std::size_t> elsewhere;
  for (const std::size_t r : rows) {
    if (!std::binary_search(quality.excluded_rows.begin(), quality.excluded_rows.end(), r)) elsewhere.push_back(r);
  }
  const double reference = mean_square(elsewhere, at, residuals);
  if (!(reference > 0.0)) return;
  for (DataQualityFinding& f : quality.findings) {
    if (f.kind != DataQualityKind::stuck || !f.excluded || !is_input(f.channel)) continue;
    std::vector<std::size_t> kept;
    std::size_t released = 0, released_rows = 0;
    for (const RowSpan& span : f.spans) {
      std::vector<std::size_t> run;
      for (std::size_t r = span.first_row; r <= span.last_row; ++r) {
        if (std::binary_search(f.rows.begin(), f.rows.end(), r)) run.push_back(r);
      }
      const double inside = mean_square(run, at, residuals);
      if (inside >= 0.0 && inside <= most_ratio * reference) {
        ++released;
        released_rows += run.size();
      } else {
        kept.insert(kept.end(), run.begin(), run.end());
      }
    }
    if (released == 0) continue;
    const std::string old_spans = spans_text(f.spans);
    f.rows = kept;
    f.spans = row_spans(f.rows, observations);
    if (const std::size_t place = f.detail.rfind(old_spans); place != std::string::npos) {
      f.detail.replace(place, old_spans.size(), spans_text(f.spans));
    }
    f.detail += "; " + std::to_string(released) + (released == 1 ? " run" : " runs") + " (" + std::to_string(released_rows) +
                " rows) kept: the model, fed the held value, predicts the moments there as well as elsewhere, as a "
                "programme's hold";
  }
  std::erase_if(quality.findings, [](const DataQualityFinding& f) {
    return f.kind == DataQualityKind::stuck && f.excluded && f.rows.empty();
  });
  quality.excluded_rows = excluded_rows_of(quality.findings);
}

}  // namespace gc
