// gearcoupling replay: a recording published as a live test cell (live/replay.h).
#include <fmt/format.h>

#include "analysis/scale_check.h"
#include "analysis/validation_result.h"
#include "clients/cli/model_flags.h"
#include "clients/cli/recording_flags.h"
#include "clients/cli/subcommand.h"
#include "live/live_topics.h"
#include "live/replay.h"

namespace gc::cli {
namespace {

std::vector<FlagSpec> replay_flags() {
  return {
      {"in", "FILE", "the recording to publish (CSV, docs/recordings.md)", std::nullopt},
      {"test-cell", "ID", "the test cell to publish as (1-64 of A-Z a-z 0-9 . _ -)", std::nullopt},
      {"rate-hz", "Hz", "samples per second (or --speed)", "", false, '\0', {"rate"}},
      {"speed", "X", "times the recording's own pace (or --rate)", ""},
      {"batch", "N", "most samples per DDS sample (those already due)", "64"},
      {"readers", "N", "matched readers (monitor, record, ...) to wait for before the first sample", "1"},
      {"wait-s", "s", "seconds to wait for them at most", "10", false, '\0', {"wait"}},
      columns_flag(),
      negate_flag(),
      {"model", "FILE|NAME",
       "the model the unit check compares the moments with (validate's: moments 1000 times the "
       "model's are refused; a .textproto file or a name in data/models)",
       "paper"},
      force_scale_flag(),
      live_domain_flag(),
      catalogue_flag(),   // where --model's coupling is looked up
  };
}

std::optional<double> optional_number(const Flags& flags, std::string_view name) {
  if (flags.text(name).empty()) return std::nullopt;
  return flags.number(name);
}

/// Rows the unit check reads from the recording's start: enough for the RMS of each channel,
/// and a replay of a long recording need not read it twice.
constexpr std::size_t kUnitCheckRows = 4096;

/// validate's unit check (analysis/scale_check.h) on the recording's first rows against
/// --model: replay refuses what validate refuses, before anything is published.
void check_units(const Flags& flags, const analysis::RecordingOptions& options) {
  if (flags.enabled("force-scale")) return;
  analysis::RecordingReader reader(flags.text("in"), options);
  std::vector<RecordedSample> rows;
  reader.next_chunk(rows, kUnitCheckRows);
  const codec::ModelFile model = load_model_flag(flags);
  const analysis::RecordingCheck check = analysis::check_recording(model.model, model.name, rows);
  print_recording_notes("replay", {}, check.warnings);
  analysis::refuse_unit_slip(flags.text("in"), check.refusal);
}

int run_replay(const Flags& flags, const Calculator&, std::FILE* out) {
  live::ReplayOptions options;
  options.test_cell = flags.text("test-cell");
  options.rate_hz = optional_number(flags, "rate-hz");
  options.speed = optional_number(flags, "speed");
  options.max_batch = static_cast<std::size_t>(flags.integer("batch", 1, 4096));
  options.wait_s = flags.number("wait-s");
  options.wait_for_readers = static_cast<std::uint32_t>(flags.integer("readers", 0, 1000));
  options.recording.renames = column_renames(flags);
  options.recording.negated = negated_quantities(flags);
  check_units(flags, options.recording);
  const protocol::Entity participant = live::make_participant(domain_from(flags));
  const live::ReplayResult result = live::replay_recording(participant.get(), flags.text("in"), options);
  fmt::print(out, "replayed {} samples of {} as test cell {} in {:.3f} s (run {:016x})\n",
             result.published, flags.text("in"), options.test_cell, result.seconds, result.run_id);
  if (result.excluded_rows > 0) {
    fmt::print(stderr, "gearcoupling replay: {} malformed rows not published (validate lists them)\n",
               result.excluded_rows);
  }
  return 0;
}

}  // namespace

const Subcommand& replay_subcommand() {
  static const Subcommand subcommand{
      "replay",
      "Publishes a recording as a live test cell over DDS (docs/protocol.md).\n"
      "At --rate samples per second or --speed times its own pace; gearcoupling-monitor reads it.",
      replay_flags, run_replay};
  return subcommand;
}

}  // namespace gc::cli
