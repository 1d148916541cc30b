#include "live/proposal.h"

#include <cmath>

#include "analysis/model_diagnosis.h"
#include "analysis/recording_csv.h"
#include "analysis/validation_result.h"
#include "codec/model_file.h"
#include "core/model_error.h"

namespace gc::live {
namespace {

namespace v1 = ::gearcoupling::v1;

/// The held-out RMSE of the candidate a round claimed, and of the model it started from on the
/// same (search) rows.
struct RoundFigures {
  double before_nm = 0.0, after_nm = 0.0;
  std::string kind;
};

RoundFigures figures_of(const v1::RoundRecord& round) {
  const v1::CandidateRecord& chosen =
      round.formula_chosen() || round.ranking().empty() ? round.formula() : round.ranking(0);
  const double after = chosen.held_out_rmse_nm();
  const double before = chosen.reduction() < 1.0 ? after / (1.0 - chosen.reduction()) : round.rmse_nm();
  return {before, after, chosen.kind()};
}

void add_parameters(const v1::ParameterSetRecord& claimed, std::vector<ProposalParameter>& out) {
  for (const v1::ParameterEstimateRecord& p : claimed.parameters()) {
    out.push_back({claimed.effect(), p.name(), p.unit(), p.value(), p.standard_error(), p.held(),
                   p.plausible(), p.note()});
  }
}

/// The effects `round` found alike to the one it claimed, with their held-out error from its
/// ranking (the same rows as the claim's).
std::vector<ProposalAlternative> alternatives_of(const v1::RoundRecord& round) {
  std::vector<ProposalAlternative> out;
  for (const v1::AlikeRecord& alike : round.alike()) {
    ProposalAlternative a{alike.effect(), 0.0, alike.correlation(), alike.experiment()};
    for (const v1::CandidateRecord& c : round.ranking()) {
      if (c.effect() == alike.effect()) a.held_out_rmse_nm = c.held_out_rmse_nm();
    }
    out.push_back(std::move(a));
  }
  return out;
}

}  // namespace

double Proposal::reduction() const {
  return before_rmse_nm > 0.0 ? 1.0 - after_rmse_nm / before_rmse_nm : 0.0;
}

std::optional<Proposal> proposal_from(const Diagnosis& diagnosis, const CellModel& base,
                                      const std::string& test_cell,
                                      std::span<const RecordedSample> window) {
  if (diagnosis.added.empty() || window.empty()) return std::nullopt;
  // The library's own account of the diagnosis and model, as `diagnose --json --write-model`.
  const v1::DiagnosisResult result = analysis::diagnosis_result(
      diagnosis, "test cell " + test_cell, base.name, analysis::RecordingCheck{}, analysis::Recording{});
  const codec::ModelFile diagnosed = analysis::diagnosed_model(
      codec::ModelFile{base.name, base.description, base.coupling, *base.model}, diagnosis);
  Proposal p;
  p.test_cell = test_cell;
  p.base_model = base.name;
  p.model_name = diagnosed.name;
  p.model_text = codec::write_model_text(diagnosed.name, diagnosed.description, diagnosed.coupling,
                                         diagnosed.model);
  p.model = std::make_shared<const CouplingModel>(diagnosed.model);
  p.window_begin_s = window.front().input.time_s;
  p.window_end_s = window.back().input.time_s;
  p.window_samples = window.size();
  bool first = true;
  for (const v1::RoundRecord& round : result.rounds()) {
    if (!round.has_claimed()) continue;
    const RoundFigures figures = figures_of(round);
    if (first) {
      p.kind = figures.kind;
      p.before_rmse_nm = figures.before_nm;
      p.noise_nm = round.noise_rmse_nm();
      p.alternatives = alternatives_of(round);
      first = false;
    }
    p.after_rmse_nm = figures.after_nm;
    p.outcome = round.outcome();
    p.effects += (p.effects.empty() ? "" : ", ") + round.claimed().effect();
    add_parameters(round.claimed(), p.parameters);
    p.verdict += (p.verdict.empty() ? "" : "\n") + round.verdict();
  }
  if (first) return std::nullopt;   // effects added, yet no round claims one: nothing to show
  return p;
}

bool replaces(const Proposal& candidate, const Proposal& standing) {
  if (standing.state != ProposalState::standing) return true;
  return candidate.reduction() > standing.reduction();
}

std::optional<double> pooled_rmse(const CouplingModel& model, std::span<const RecordedSample> samples) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const RecordedSample& s : samples) {
    try {
      const SensorMoments predicted = model.predict(s.input).moments;
      const double ey = predicted.y_nm - s.measured.y_nm, ez = predicted.z_nm - s.measured.z_nm;
      sum += ey * ey + ez * ez;
      n += 2;
    } catch (const ModelError&) {
      // Refused (beyond the jam angle, ...): as the monitor, not counted.
    }
  }
  if (n == 0) return std::nullopt;
  return std::sqrt(sum / static_cast<double>(n));
}

const char* to_string(ProposalState state) {
  switch (state) {
    case ProposalState::standing: return "standing";
    case ProposalState::applied: return "applied";
    case ProposalState::withdrawn: return "withdrawn";
  }
  return "standing";
}

}  // namespace gc::live
