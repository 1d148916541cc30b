#include "analysis/diagnosis_messages.h"

#include "codec/count_field.h"

namespace gc::codec {
namespace {

namespace v1 = gearcoupling::v1;

void fill(const EffectFit& fit, google::protobuf::RepeatedPtrField<v1::ParameterEstimateRecord>& out) {
  for (const ParameterEstimate& p : fit.parameters) {
    v1::ParameterEstimateRecord& r = *out.Add();
    r.set_name(p.name);
    r.set_unit(p.unit);
    r.set_value(p.value);
    if (p.standard_error) r.set_standard_error(*p.standard_error);
    r.set_held(p.held);
    r.set_note(p.note);
    r.set_plausible(p.plausible);
  }
}

v1::CandidateRecord to_message(const CandidateScore& c) {
  v1::CandidateRecord r;
  r.set_effect(c.info->name);
  r.set_held_out_rmse_nm(c.held_out_rmse_nm);
  r.set_reduction(c.reduction);
  r.set_t(c.against_base.t);
  if (c.fit) fill(*c.fit, *r.mutable_parameters());
  r.set_failure(c.failure);
  if (c.surrogate_p) r.set_surrogate_p(*c.surrogate_p);
  r.set_kind(c.kind == CandidateKind::addition ? "addition" : c.kind == CandidateKind::refinement ? "refinement" : "formula");
  return r;
}

v1::InputSignatureRecord to_message(const InputSignature& s) {
  v1::InputSignatureRecord r;
  r.set_input(s.input);
  r.set_unit(s.unit);
  r.set_explained_share(s.explained_share);
  r.set_f(s.dispersion);
  r.set_systematic(s.systematic);
  r.set_slope_y(s.slope_y);
  r.set_slope_z(s.slope_z);
  r.set_marginal_share(s.marginal_share);
  for (const std::string& c : s.confounded_with) r.add_confounded_with(c);
  for (const SignatureBin& b : s.bins) {
    v1::SignatureBinRecord& bin = *r.add_bins();
    bin.set_lower(b.lower);
    bin.set_upper(b.upper);
    bin.set_count(count_field(b.count, "bins.count"));
    bin.set_mean_y_nm(b.mean_y_nm);
    bin.set_mean_z_nm(b.mean_z_nm);
  }
  return r;
}

void fill(const RowSpan& span, v1::RowSpanRecord& out) {
  out.set_first_row(count_field(span.first_row, "first_row"));
  out.set_last_row(count_field(span.last_row, "last_row"));
  out.set_t_start_s(span.t_start_s);
  out.set_t_end_s(span.t_end_s);
}

v1::DataQualityFinding to_message(const DataQualityFinding& f) {
  v1::DataQualityFinding r;
  r.set_kind(gc::to_string(f.kind));
  r.set_channel(f.channel);
  if (!f.spans.empty()) {
    r.set_first_row(count_field(f.spans.front().first_row, "first_row"));
    r.set_last_row(count_field(f.spans.back().last_row, "last_row"));
    r.set_t_start_s(f.spans.front().t_start_s);
    r.set_t_end_s(f.spans.back().t_end_s);
  }
  r.set_rows(count_field(f.rows.size(), "rows"));
  r.set_excluded(f.excluded);
  r.set_detail(f.detail);
  for (const RowSpan& span : f.spans) fill(span, *r.add_spans());
  return r;
}

v1::RoundRecord to_message(const DiagnosisRound& round) {
  v1::RoundRecord r;
  for (const std::string& e : round.model_effects) r.add_model_effects(e);
  r.set_rmse_nm(round.rmse_nm);
  r.set_noise_y_nm(round.noise.sigma_nm(0));
  r.set_noise_z_nm(round.noise.sigma_nm(1));
  r.set_noise_rmse_nm(round.noise.pooled_sigma_nm());
  r.set_systematic(round.systematic);
  r.set_outcome(gc::to_string(round.outcome));
  for (const CandidateScore& c : round.ranking) *r.add_ranking() = to_message(c);
  if (round.claimed) {
    r.mutable_claimed()->set_effect(round.claimed->info->name);
    fill(*round.claimed, *r.mutable_claimed()->mutable_parameters());
  }
  for (const AlikeEffect& a : round.alike) {
    v1::AlikeRecord& alike = *r.add_alike();
    alike.set_effect(a.name);
    alike.set_correlation(a.correlation);
    alike.set_t_against_best(a.against_best.t);
    alike.set_separating_input(a.experiment.input);
    alike.set_separating_value(a.experiment.value);
    alike.set_experiment(a.experiment.advice);
  }
  for (const InputSignature& s : round.signature.inputs) *r.add_signature() = to_message(s);
  r.set_verdict(round.verdict);
  r.set_noise_phi_y(round.noise.phi(0));
  r.set_noise_phi_z(round.noise.phi(1));
  if (round.formula) *r.mutable_formula() = to_message(*round.formula);
  r.set_formula_chosen(round.formula_chosen);
  for (const std::string& d : round.dropped) r.add_dropped(d);
  for (const std::string& t : round.time_terms) r.add_time_terms(t);
  r.set_formula_on_dense_rows(round.formula_on_dense_rows);
  return r;
}

}  // namespace

v1::DiagnosisResult to_message(const Diagnosis& diagnosis) {
  v1::DiagnosisResult r;
  r.set_recording_rows(count_field(diagnosis.rows, "recording_rows"));
  r.set_refused_rows(count_field(diagnosis.excluded_rows.size(), "refused_rows"));
  r.set_excluded_rows(r.refused_rows());
  r.set_exclusion_reason(diagnosis.exclusion_reason);
  r.set_search_rows(count_field(diagnosis.search_rows, "search_rows"));
  r.set_refit_rows(count_field(diagnosis.refit_rows, "refit_rows"));
  for (const DiagnosisRound& round : diagnosis.rounds) *r.add_rounds() = to_message(round);
  r.set_summary(diagnosis.summary);
  r.set_outlier_rows(count_field(diagnosis.outlier_rows.size(), "outlier_rows"));
  for (const DataQualityFinding& f : diagnosis.data_quality) *r.add_data_quality() = to_message(f);
  for (const ExcludedRange& range : diagnosis.excluded_ranges) {
    v1::ExcludedRangeRecord& record = *r.add_excluded_ranges();
    fill(range.span, *record.mutable_span());
    record.set_reason(range.reason);
  }
  return r;
}

}  // namespace gc::codec
