#include "live/proposal_wire.h"

#include <algorithm>
#include <vector>

#include "live/health_wire.h"
#include "live/wire_text.h"
#include "protocol/dds_entity.h"

namespace gc::live {
namespace {

gearcoupling_ProposalState state_wire(ProposalState state) {
  switch (state) {
    case ProposalState::standing: return gearcoupling_PROPOSAL_STANDING;
    case ProposalState::applied: return gearcoupling_PROPOSAL_APPLIED;
    case ProposalState::withdrawn: return gearcoupling_PROPOSAL_WITHDRAWN;
  }
  return gearcoupling_PROPOSAL_STANDING;
}

}  // namespace

void write_proposal(dds_entity_t writer, std::uint64_t monitor_id, const Proposal& p) {
  std::vector<gearcoupling_ProposedParameter> parameters;
  for (const ProposalParameter& q : p.parameters) {
    parameters.push_back({lend(q.effect), lend(q.name), lend(q.unit), q.value, q.standard_error,
                          q.held, q.plausible, lend(q.note)});
  }
  std::vector<gearcoupling_ProposalAlternative> alternatives;
  for (const ProposalAlternative& a : p.alternatives) {
    if (alternatives.size() == 8) break;   // the IDL's bound
    alternatives.push_back({lend(a.effect), a.held_out_rmse_nm, a.correlation, lend(a.experiment)});
  }
  gearcoupling_ModelProposal out{};
  set_test_cell(out.test_cell, p.test_cell);
  out.proposal_id = p.id;
  out.monitor_id = monitor_id;
  out.state = state_wire(p.state);
  out.state_reason = lend(p.state_reason);
  out.kind = lend(p.kind);
  out.effects = lend(p.effects);
  out.outcome = lend(p.outcome);
  out.parameters._buffer = parameters.data();
  out.parameters._length = out.parameters._maximum = static_cast<std::uint32_t>(parameters.size());
  out.parameters._release = false;
  out.base_model = lend(p.base_model);
  out.model_name = lend(p.model_name);
  out.model_text = lend(p.model_text);
  out.window_begin_s = p.window_begin_s;
  out.window_end_s = p.window_end_s;
  out.window_samples = p.window_samples;
  out.before_rmse_nm = p.before_rmse_nm;
  out.after_rmse_nm = p.after_rmse_nm;
  out.noise_nm = p.noise_nm;
  out.verdict = lend(p.verdict);
  out.proposed_unix_s = unix_seconds(p.proposed_at);
  out.onset_to_proposal_s = p.onset_to_proposal_s;
  out.diagnosis_cpu_s = p.diagnosis_cpu_s;
  out.alternatives._buffer = alternatives.data();
  out.alternatives._length = out.alternatives._maximum = static_cast<std::uint32_t>(alternatives.size());
  out.alternatives._release = false;
  protocol::check_dds(dds_write(writer, &out), "dds_write(proposal)");
}

void dispose_proposal(dds_entity_t writer, const std::string& test_cell) {
  gearcoupling_ModelProposal key{};
  set_test_cell(key.test_cell, test_cell);
  dds_dispose(writer, &key);
  dds_unregister_instance(writer, &key);
}

}  // namespace gc::live
