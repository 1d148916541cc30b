// gearcoupling swap-model: a new model for a live test cell (live/model_swap_publisher.h), a
// model file checked here as --model is, or a monitor's proposal (--proposal), then checked by the
// monitor; waits for the monitor's health to show it.
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "clients/cli/model_flags.h"
#include "codec/untrusted_model_text.h"
#include "clients/cli/subcommand.h"
#include "clients/status/cell_board.h"
#include "clients/status/monitor_board.h"
#include "live/live_topics.h"
#include "live/live_names.h"
#include "live/model_swap_publisher.h"
#include "live/swap_operator.h"

namespace gc::cli {
namespace {

std::vector<FlagSpec> swap_model_flags() {
  return {
      {"test-cell", "ID", "the test cell whose model to change", std::nullopt},
      {"model", "FILE|NAME",
       "model configuration: a .textproto file, or a name in data/models ($GEARCOUPLING_MODELS); "
       "or give --proposal", ""},
      {"proposal", "ID", "put the monitor's proposal ID in force (gearcoupling proposals lists them)",
       ""},
      {"operator", "NAME",
       "the person putting the model in force, for the monitor's audit trail; required unless "
       "the DDS Security identity is an operator's (GC_IDENTITY=operator-NAME), which names them",
       ""},
      {"decimate", "N", "also publish one residual per N evaluated samples (0: keep)", "0"},
      {"wait-s", "s", "seconds to wait for the monitor's health to show the model in force", "10",
       false, '\0', {"wait"}},
      catalogue_flag(),
      live_domain_flag(),
  };
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// What to put in force: the model's name and file text, and where it came from.
struct SwapText {
  std::string model_name, text, source;
};

/// The standing proposal `id` of `test_cell`, waiting up to `wait` for it to be seen. Throws
/// UsageError naming --proposal when there is none or it is not standing.
SwapText proposal_text(dds_entity_t participant, const std::string& test_cell, const std::string& id,
                       std::chrono::milliseconds wait) {
  status::MonitorBoard board(participant);
  const auto found = board.wait_for(
      test_cell, [&](const status::v1::ProposalRecord& p) { return p.proposal_id() == id; }, wait);
  if (!found) {
    throw UsageError(fmt::format("--proposal {}: test cell {} has no proposal (none seen within "
                                 "--wait-s {} s)", id, test_cell, wait.count() / 1e3));
  }
  if (found->proposal_id() != id) {
    throw UsageError(fmt::format("--proposal {}: not test cell {}'s proposal; its proposal is {} ({})",
                                 id, test_cell, found->proposal_id(), found->state()));
  }
  if (found->state() != "standing") {
    throw UsageError(fmt::format("--proposal {}: {}: {}", id, found->state(), found->state_reason()));
  }
  return {found->model_name(), found->model_text(), "proposal " + id};
}

SwapText file_text(const Flags& flags) {
  // Checked here first, so a typo is an error at once rather than a refusal in the health.
  const codec::ModelFile model = load_model_flag(flags);
  const std::filesystem::path path = model_flag_path(flags);
  std::string text = read_text(path);
  // And as the monitor will check it (no coupling_file, sizes bounded), naming the file.
  codec::parse_untrusted_model_text(text, path.filename().string(), flags.text("catalogue"));
  return {model.name, std::move(text), "file " + path.string()};
}

int run_swap_model(const Flags& flags, const Calculator&, std::FILE* out) {
  const bool by_proposal = !flags.text("proposal").empty();
  if (by_proposal == !flags.text("model").empty()) {
    throw UsageError("give --model FILE|NAME or --proposal ID (one of them)");
  }
  const std::string& test_cell = flags.text("test-cell");
  // Before any DDS work: who swaps is the first thing the audit trail needs.
  const std::string by = live::swap_operator(flags.text("operator"), live::operator_of_identity());
  const auto wait = std::chrono::milliseconds(static_cast<long>(flags.number("wait-s") * 1e3));
  const protocol::Entity participant = live::make_participant(domain_from(flags));
  const SwapText swap = by_proposal ? proposal_text(participant.get(), test_cell,
                                                    flags.text("proposal"), wait)
                                    : file_text(flags);
  live::ModelSwapPublisher swaps(participant.get(), {test_cell},
                                 live::swap_user_data(by, swap.source),
                                 live::operator_of_identity());
  status::CellBoardOptions board;
  board.read_residuals = false;  // an operator identity may read the health alone
  board.only_cell = test_cell;
  status::CellBoard health(participant.get(), board);
  if (!swaps.wait_for_readers(1, wait)) {
    throw std::runtime_error("no gearcoupling-monitor matched within --wait " + flags.text("wait-s") + " s");
  }
  const std::string previous_refusal = health.wait_for(test_cell, [](const auto&) { return true; },
                                                       std::chrono::milliseconds(500))
                                           .value_or(status::HealthView{}).last_model_refusal;
  swaps.publish(test_cell, swap.text,
                static_cast<std::uint32_t>(flags.integer("decimate", 0, 1000000)));
  const auto shown = health.wait_for(test_cell, [&](const status::HealthView& h) {
    return h.model_name == swap.model_name || h.last_model_refusal != previous_refusal;
  }, wait);
  if (shown && shown->model_name == swap.model_name) {
    fmt::print(out, "test cell {}: model {} in force\n", test_cell, swap.model_name);
    return 0;
  }
  if (shown && shown->last_model_refusal != previous_refusal) {
    throw std::runtime_error("the monitor refused the model: " + shown->last_model_refusal);
  }
  fmt::print(out, "test cell {}: model {} published; no health of the test cell within --wait "
             "(it takes effect with the test cell's next sample)\n", test_cell, swap.model_name);
  return 0;
}

}  // namespace

const Subcommand& swap_model_subcommand() {
  static const Subcommand subcommand{
      "swap-model",
      "Puts a model file, or a monitor's proposal, in force for a live test cell "
      "(gearcoupling-monitor).\n"
      "Switches between two samples; the health shows before and after side by side, and the "
      "monitor's audit trail (status --json) who swapped, when and from what.",
      swap_model_flags, run_swap_model};
  return subcommand;
}

}  // namespace gc::cli
