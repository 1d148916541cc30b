// gearcoupling swap-model: a new model for a live test cell (live/model_swap_publisher.h),
// checked here as --model is, then by the monitor; waits for the monitor's health to show it.
#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "clients/cli/model_flags.h"
#include "clients/cli/subcommand.h"
#include "clients/status/cell_board.h"
#include "live/live_topics.h"
#include "live/model_swap_publisher.h"

namespace gc::cli {
namespace {

std::vector<FlagSpec> swap_model_flags() {
  return {
      {"test-cell", "ID", "the test cell whose model to change", std::nullopt},
      model_flag(),
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

int run_swap_model(const Flags& flags, const Calculator&, std::FILE* out) {
  // Checked here first, so a typo is an error at once rather than a refusal in the health.
  const codec::ModelFile model = load_model_flag(flags);
  const std::string& test_cell = flags.text("test-cell");
  const auto wait = std::chrono::milliseconds(static_cast<long>(flags.number("wait-s") * 1e3));
  const protocol::Entity participant = live::make_participant(domain_from(flags));
  live::ModelSwapPublisher swaps(participant.get(), {test_cell});
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
  swaps.publish(test_cell, read_text(model_flag_path(flags)),
                static_cast<std::uint32_t>(flags.integer("decimate", 0, 1000000)));
  const auto shown = health.wait_for(test_cell, [&](const status::HealthView& h) {
    return h.model_name == model.name || h.last_model_refusal != previous_refusal;
  }, wait);
  if (shown && shown->model_name == model.name) {
    fmt::print(out, "test cell {}: model {} in force\n", test_cell, model.name);
    return 0;
  }
  if (shown && shown->last_model_refusal != previous_refusal) {
    throw std::runtime_error("the monitor refused the model: " + shown->last_model_refusal);
  }
  fmt::print(out, "test cell {}: model {} published; no health of the test cell within --wait "
             "(it takes effect with the test cell's next sample)\n", test_cell, model.name);
  return 0;
}

}  // namespace

const Subcommand& swap_model_subcommand() {
  static const Subcommand subcommand{
      "swap-model",
      "Puts a model file in force for a live test cell (gearcoupling-monitor).\n"
      "Switches between two samples; the health shows before and after side by side.",
      swap_model_flags, run_swap_model};
  return subcommand;
}

}  // namespace gc::cli
