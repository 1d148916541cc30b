// gearcoupling proposals: what the monitors propose for the live test cells
// (gearcoupling/live/proposal, clients/status/monitor_board.h), once or on every change.
#include <csignal>
#include <thread>

#include <fmt/format.h>

#include "clients/cli/subcommand.h"
#include "clients/status/learning_table.h"
#include "clients/status/monitor_board.h"
#include "codec/result_json.h"
#include "live/live_names.h"
#include "live/live_topics.h"

namespace gc::cli {
namespace {

volatile std::sig_atomic_t interrupted = 0;

std::vector<FlagSpec> proposals_flags() {
  FlagSpec catalogue = catalogue_flag();
  catalogue.refused = "not taken by proposals: a proposal's model names its coupling itself";
  return {
      {"test-cell", "ID", "only this test cell's proposal (\"\": every test cell's)", ""},
      {"watch", "", "print again whenever a proposal changes, until Ctrl-C (or --count prints)",
       std::nullopt, true},
      {"count", "N", "with --watch: stop after N prints (0: until Ctrl-C)", "0"},
      {"discovery-s", "s", "seconds to discover the monitors before the first print, [0, 60]",
       "1.5", false, '\0', {"discovery"}},
      json_flag(),
      live_domain_flag(),
      catalogue,
  };
}

std::vector<status::v1::ProposalRecord> selected(status::MonitorBoard& board, const std::string& cell) {
  std::vector<status::v1::ProposalRecord> out;
  for (auto& p : board.proposals()) {
    if (cell.empty() || p.test_cell() == cell) out.push_back(std::move(p));
  }
  return out;
}

void print(const std::vector<status::v1::ProposalRecord>& proposals, bool json, std::FILE* out) {
  if (json) {
    status::v1::ProposalList list;
    list.set_time_unix_s(std::chrono::duration<double>(
                             std::chrono::system_clock::now().time_since_epoch()).count());
    for (const auto& p : proposals) *list.add_proposals() = p;
    fmt::print(out, "{}\n", codec::to_compact_json(list));
  } else {
    status::print_proposals(proposals, out);
  }
  std::fflush(out);
}

/// A proposal's identity and state: a change of either is printed again with --watch.
std::string signature(const std::vector<status::v1::ProposalRecord>& proposals) {
  std::string s;
  for (const auto& p : proposals) s += p.test_cell() + p.proposal_id() + p.state() + ";";
  return s;
}

int run_proposals(const Flags& flags, const Calculator&, std::FILE* out) {
  const std::string& cell = flags.text("test-cell");
  if (!cell.empty()) live::require_test_cell_name(cell);
  const double discovery_s = flags.number("discovery-s");
  if (!(discovery_s >= 0.0 && discovery_s <= 60.0)) {
    throw UsageError(fmt::format("--discovery-s {} is out of range: allowed 0 to 60 s",
                                 flags.text("discovery-s")));
  }
  const unsigned count = static_cast<unsigned>(flags.integer("count", 0, 1000000));
  const protocol::Entity participant = live::make_participant(domain_from(flags));
  status::MonitorBoard board(participant.get());
  interrupted = 0;
  std::signal(SIGINT, [](int) { interrupted = 1; });
  std::this_thread::sleep_for(std::chrono::milliseconds(static_cast<long>(discovery_s * 1e3)));
  std::vector<status::v1::ProposalRecord> shown = selected(board, cell);
  print(shown, flags.enabled("json"), out);
  for (unsigned printed = 1; flags.enabled("watch") && (count == 0 || printed < count);) {
    if (interrupted != 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::vector<status::v1::ProposalRecord> now = selected(board, cell);
    if (signature(now) == signature(shown)) continue;
    shown = std::move(now);
    if (!flags.enabled("json")) fmt::print(out, "\n");
    print(shown, flags.enabled("json"), out);
    ++printed;
  }
  return 0;
}

}  // namespace

const Subcommand& proposals_subcommand() {
  static const Subcommand subcommand{
      "proposals",
      "What gearcoupling-monitor proposes for the live test cells.\n"
      "When a test cell's error stays beyond the noise, the monitor runs diagnose's search on its "
      "latest samples in the background; each proposal says what it adds (an effect, a "
      "refinement or a formula) with the fitted values, the held-out error now and with it, and "
      "an ID to give swap-model --proposal. --json prints one JSON object a print "
      "(idl/live_status.proto ProposalList).",
      proposals_flags, run_proposals};
  return subcommand;
}

}  // namespace gc::cli
