#include "clients/status/learning_table.h"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <cmath>
#include <ctime>

#include "analysis/table.h"
#include "clients/status/parameter_display.h"

namespace gc::status {
namespace {

namespace v1 = ::gearcoupling::v1;

std::string knm(double nm) { return fmt::format("{:.2f}", nm / 1e3); }

/// ISO 8601 UTC to the second, as the page shows times ("2026-11-28T19:07:59Z").
std::string utc_text(double unix_s) {
  const auto seconds = static_cast<std::time_t>(std::floor(unix_s));
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(seconds));
}

/// The effects the data cannot tell from the proposed one, side by side with it, each with the
/// run that would separate them (issue 39: they were only in the verdict's prose).
void print_alternatives(const v1::ProposalRecord& p, std::FILE* out) {
  if (p.alternatives().empty()) return;
  fmt::print(out, "  the data cannot tell it from:\n");
  analysis::Table table({"effect", "held-out RMSE [kN·m]", "correlation", "to tell them apart"});
  table.add_row({p.effects() + " (proposed)", knm(p.after_rmse_nm()), "1", ""});
  for (const v1::ProposalAlternativeRecord& a : p.alternatives()) {
    table.add_row({a.effect(), knm(a.held_out_rmse_nm()), fmt::format("{:.2f}", a.correlation()),
                   a.experiment().empty() ? "no recorded input separates them" : a.experiment()});
  }
  table.print(out);
}

void print_swaps(const std::vector<v1::MonitorRecord>& monitors, std::FILE* out) {
  analysis::Table table({"test cell", "when [UTC]", "by", "operator identity", "source", "model before", "model after",
                         "RMSE before M_sy'/M_sz' [kN·m]", "RMSE after M_sy'/M_sz' [kN·m]"});
  // "interrupted": the monitor that followed the swap was killed, the after-figures are the last
  // it wrote to its state directory (live/swap_audit_file.h).
  bool any = false;
  for (const v1::MonitorRecord& m : monitors) {
    for (const v1::SwapAuditRecord& s : m.recent_swaps()) {
      any = true;
      table.add_row({s.test_cell(), utc_text(s.at_unix_s()), s.by(),
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
    for (const v1::ProposedParameterRecord& q : p.parameters()) fmt::print(out, "  {}\n", parameter_display(q));
    print_alternatives(p, out);
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
