#include "clients/status/monitor_board.h"

#include "clients/status/cell_board.h"
#include "clients/status/listening_reader.h"
#include "clients/status/parameter_display.h"
#include "gearcoupling.h"
#include "live/live_qos.h"
#include "live/live_topics.h"
#include "protocol/names.h"

namespace gc::status {
namespace {

const char* state_text(gearcoupling_ProposalState state) {
  switch (state) {
    case gearcoupling_PROPOSAL_APPLIED: return "applied";
    case gearcoupling_PROPOSAL_WITHDRAWN: return "withdrawn";
    default: return "standing";
  }
}

v1::ProposalRecord record_of(const gearcoupling_ModelProposal& in) {
  v1::ProposalRecord out;
  out.set_test_cell(sample_text(in.test_cell));
  out.set_proposal_id(protocol::hex_id(in.proposal_id));
  out.set_monitor_id(protocol::hex_id(in.monitor_id));
  out.set_state(state_text(in.state));
  out.set_state_reason(sample_text(in.state_reason));
  out.set_kind(sample_text(in.kind));
  out.set_effects(sample_text(in.effects));
  out.set_outcome(sample_text(in.outcome));
  for (std::uint32_t i = 0; i < in.parameters._length && i < 256; ++i) {
    const gearcoupling_ProposedParameter& p = in.parameters._buffer[i];
    v1::ProposedParameterRecord& r = *out.add_parameters();
    r.set_effect(sample_text(p.effect));
    r.set_name(sample_text(p.name));
    r.set_unit(sample_text(p.unit));
    r.set_value(p.value);
    r.set_standard_error(p.standard_error);
    r.set_held(p.held);
    r.set_plausible(p.plausible);
    r.set_note(sample_text(p.note));
    out.add_parameters_display(parameter_display(r));
  }
  for (std::uint32_t i = 0; i < in.alternatives._length && i < 8; ++i) {
    const gearcoupling_ProposalAlternative& a = in.alternatives._buffer[i];
    v1::ProposalAlternativeRecord& r = *out.add_alternatives();
    r.set_effect(sample_text(a.effect));
    r.set_held_out_rmse_nm(a.held_out_rmse_nm);
    r.set_correlation(a.correlation);
    r.set_experiment(sample_text(a.experiment, 4 * kMaxTextBytes));
  }
  out.set_base_model(sample_text(in.base_model));
  out.set_model_name(sample_text(in.model_name));
  out.set_model_text(sample_text(in.model_text, kMaxModelTextBytes));
  out.set_window_begin_s(in.window_begin_s);
  out.set_window_end_s(in.window_end_s);
  out.set_window_samples(in.window_samples);
  out.set_before_rmse_nm(in.before_rmse_nm);
  out.set_after_rmse_nm(in.after_rmse_nm);
  out.set_noise_nm(in.noise_nm);
  out.set_verdict(sample_text(in.verdict, 8 * kMaxTextBytes));
  out.set_proposed_unix_s(in.proposed_unix_s);
  out.set_onset_to_proposal_s(in.onset_to_proposal_s);
  out.set_diagnosis_cpu_s(in.diagnosis_cpu_s);
  return out;
}

v1::MonitorRecord record_of(const gearcoupling_MonitorStatus& in) {
  v1::MonitorRecord out;
  out.set_monitor_id(protocol::hex_id(in.monitor_id));
  out.set_cells(in.cells);
  out.set_max_cells(in.max_cells);
  out.set_refused_cell_batches(in.refused_cell_batches);
  out.set_refused_cell_samples(in.refused_cell_samples);
  out.set_refused_foreign(in.refused_foreign);
  out.set_proposals_published(in.proposals_published);
  out.set_proposals_withdrawn(in.proposals_withdrawn);
  out.set_diagnoses_run(in.diagnoses_run);
  out.set_diagnoses_dropped(in.diagnoses_dropped);
  out.set_swaps(in.swaps);
  out.set_diagnosing(sample_text(in.diagnosing));
  for (std::uint32_t i = 0; i < in.refusals._length; ++i) {
    (*out.mutable_refusals())[sample_text(in.refusals._buffer[i].kind)] = in.refusals._buffer[i].count;
  }
  for (std::uint32_t i = 0; i < in.recent_swaps._length; ++i) {
    const gearcoupling_SwapRecord& s = in.recent_swaps._buffer[i];
    v1::SwapAuditRecord& r = *out.add_recent_swaps();
    r.set_test_cell(sample_text(s.test_cell));
    r.set_at_unix_s(s.at_unix_s);
    r.set_by(sample_text(s.by));
    r.set_source(sample_text(s.source));
    r.set_proposal_id(s.proposal_id != 0 ? protocol::hex_id(s.proposal_id) : "");
    r.set_model_before(sample_text(s.model_before));
    r.set_model_after(sample_text(s.model_after));
    r.set_before_msy_rmse_nm(s.before_msy_rmse_nm);
    r.set_before_msz_rmse_nm(s.before_msz_rmse_nm);
    r.set_after_msy_rmse_nm(s.after_msy_rmse_nm);
    r.set_after_msz_rmse_nm(s.after_msz_rmse_nm);
    r.set_after_samples(s.after_samples);
    r.set_operator_identity(sample_text(s.operator_identity));
    r.set_after_state(sample_text(s.after_state));
  }
  return out;
}

/// Keeps `sample`'s record under `key` in `kept` (at most `max`), or drops the key when the
/// instance is no longer alive (disposed, or its writer gone).
template <typename Record>
void keep(std::map<std::string, Record>& kept, const std::string& key, const dds_sample_info_t& info,
          const std::function<Record()>& record, std::size_t max) {
  if (info.instance_state != DDS_IST_ALIVE) {
    kept.erase(key);
  } else if (info.valid_data && (kept.count(key) != 0 || kept.size() < max)) {
    kept[key] = record();
  }
}

}  // namespace

MonitorBoard::MonitorBoard(dds_entity_t participant, std::size_t max_entries)
    : max_entries_(max_entries),
      proposal_topic_(live::make_proposal_topic(participant)),
      monitor_topic_(live::make_monitor_status_topic(participant)),
      subscriber_(live::make_live_subscriber(participant)) {
  proposal_reader_ = make_listening_reader<&MonitorBoard::take_proposals>(
      subscriber_.get(), proposal_topic_.get(), live::proposal_qos(), this,
      "dds_create_reader(proposal)");
  monitor_reader_ = make_listening_reader<&MonitorBoard::take_monitors>(
      subscriber_.get(), monitor_topic_.get(), live::monitor_status_qos(), this,
      "dds_create_reader(monitor status)");
  take_proposals();
  take_monitors();
}

void MonitorBoard::take_proposals() {
  take_each_batch<gearcoupling_ModelProposal>(proposal_reader_.get(), [&](const auto& samples) {
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const std::string cell = sample_text(samples[i].test_cell);
      keep<v1::ProposalRecord>(proposals_, cell, samples.info(i), [&] { return record_of(samples[i]); },
                               max_entries_);
    }
  });
  changed_.notify_all();
}

void MonitorBoard::take_monitors() {
  take_each_batch<gearcoupling_MonitorStatus>(monitor_reader_.get(), [&](const auto& samples) {
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      keep<v1::MonitorRecord>(monitors_, protocol::hex_id(samples[i].monitor_id), samples.info(i),
                              [&] { return record_of(samples[i]); }, max_entries_);
    }
  });
}

std::vector<v1::ProposalRecord> MonitorBoard::proposals() {
  std::lock_guard lock(mutex_);
  std::vector<v1::ProposalRecord> out;
  for (const auto& [cell, record] : proposals_) out.push_back(record);
  return out;
}

std::vector<v1::MonitorRecord> MonitorBoard::monitors() {
  std::lock_guard lock(mutex_);
  std::vector<v1::MonitorRecord> out;
  for (const auto& [id, record] : monitors_) out.push_back(record);
  return out;
}

std::optional<v1::ProposalRecord> MonitorBoard::wait_for(
    const std::string& test_cell, const std::function<bool(const v1::ProposalRecord&)>& ready,
    std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  auto latest = [&]() -> std::optional<v1::ProposalRecord> {
    const auto found = proposals_.find(test_cell);
    if (found == proposals_.end()) return std::nullopt;
    return found->second;
  };
  changed_.wait_for(lock, timeout, [&] {
    const auto p = latest();
    return p && ready(*p);
  });
  return latest();
}

}  // namespace gc::status
