#include "clients/status/learning_table.h"

#include <fmt/format.h>

#include "analysis/table.h"

namespace gc::status {
namespace {

namespace v1 = ::gearcoupling::v1;

std::string knm(double nm) { return fmt::format("{:.2f}", nm / 1e3); }

std::string parameter_text(const v1::ProposedParameterRecord& p) {
  const std::string unit = p.unit() == "-" ? "" : " " + p.unit();
  if (p.held()) return fmt::format("{}.{} = {:.6g}{} (held)", p.effect(), p.name(), p.value(), unit);
  return fmt::format("{}.{} = {:.6g} +/- {:.2g}{}{}", p.effect(), p.name(), p.value(),
                     p.standard_error(), unit, p.plausible() ? "" : " (implausible)");
}

void print_swaps(const std::vector<v1::MonitorRecord>& monitors, std::FILE* out) {
  analysis::Table table({"test cell", "when [unix s]", "by", "operator identity", "source", "model before", "model after",
                         "RMSE before M_sy'/M_sz' [kN·m]", "RMSE after M_sy'/M_sz' [kN·m]"});
  // "interrupted": the monitor that followed the swap was killed, the after-figures are the last
  // it wrote to its state directory (live/swap_audit_file.h).
  bool any = false;
  for (const v1::MonitorRecord& m : monitors) {
    for (const v1::SwapAuditRecord& s : m.recent_swaps()) {
      any = true;
      table.add_row({s.test_cell(), fmt::format("{:.1f}", s.at_unix_s()), s.by(),
                     s.operator_identity().empty() ? "none" : s.operator_identity(), s.source(),
                     s.model_before(), s.model_after(),
                     knm(s.before_msy_rmse_nm()) + " / " + knm(s.before_msz_rmse_nm()),
                     knm(s.after_msy_rmse_nm()) + " / " + knm(s.after_msz_rmse_nm()) +
                         (s.after_state() == "interrupted" ? " (interrupted)" : "")});
    }
  }
  if (!any) return;
  fmt::print(out, "\nmodel swaps (audit trail):\n");
  table.print(out);
}

void print_refusals(const std::vector<v1::MonitorRecord>& monitors, std::FILE* out) {
  for (const v1::MonitorRecord& m : monitors) {
    if (m.refused_cell_batches() + m.refused_foreign() == 0) continue;
    fmt::print(out, "monitor {}: {} batches ({} samples) of test cells beyond --max-cells {} "
               "refused, {} batches or swaps from another cell's partition refused\n",
               m.monitor_id(), m.refused_cell_batches(), m.refused_cell_samples(), m.max_cells(),
               m.refused_foreign());
  }
}

}  // namespace

void print_proposals(const std::vector<v1::ProposalRecord>& proposals, std::FILE* out) {
  if (proposals.empty()) {
    fmt::print(out, "no proposal\n");
    return;
  }
  analysis::Table table({"test cell", "proposal", "state", "adds", "kind", "RMSE now [kN·m]",
                         "RMSE with it [kN·m]", "noise [kN·m]", "model"});
  for (const v1::ProposalRecord& p : proposals) {
    table.add_row({p.test_cell(), p.proposal_id(), p.state(), p.effects(), p.kind(),
                   knm(p.before_rmse_nm()), knm(p.after_rmse_nm()), knm(p.noise_nm()), p.model_name()});
  }
  table.print(out);
  for (const v1::ProposalRecord& p : proposals) {
    fmt::print(out, "\n{} proposal {} ({}{}{}), on {} samples ({:.1f} to {:.1f} s):\n", p.test_cell(),
               p.proposal_id(), p.state(), p.state_reason().empty() ? "" : ": ", p.state_reason(),
               p.window_samples(), p.window_begin_s(), p.window_end_s());
    for (const v1::ProposedParameterRecord& q : p.parameters()) fmt::print(out, "  {}\n", parameter_text(q));
    fmt::print(out, "  {}\n", p.verdict());
  }
}

void print_learning(const std::vector<v1::MonitorRecord>& monitors,
                    const std::vector<v1::ProposalRecord>& proposals, std::FILE* out) {
  if (!proposals.empty()) {
    fmt::print(out, "\n");
    print_proposals(proposals, out);
  }
  print_swaps(monitors, out);
  print_refusals(monitors, out);
}

}  // namespace gc::status
