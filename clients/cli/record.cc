// gearcoupling record: a live test cell's measurements captured as a recording (live/recorder.h).
#include <fmt/format.h>

#include "analysis/atomic_file.h"
#include "clients/cli/subcommand.h"
#include "live/live_topics.h"
#include "live/recorder.h"

namespace gc::cli {
namespace {

std::vector<FlagSpec> record_flags() {
  return {
      {"test-cell", "ID", "the test cell to record", std::nullopt},
      {"seconds", "s", "how long to record", std::nullopt},
      {"out", "FILE", "the recording to write (CSV, docs/recordings.md); - for standard output",
       std::nullopt},
      live_domain_flag(),
      catalogue_flag(),   // every subcommand has one (make_calculator); not read here
  };
}

int run_record(const Flags& flags, const Calculator&, std::FILE* out) {
  const protocol::Entity participant = live::make_participant(domain_from(flags));
  const live::Capture capture = live::capture_measurements(
      participant.get(), {flags.text("test-cell"), flags.number("seconds")});
  if (capture.refused > 0) {
    fmt::print(stderr, "gearcoupling record: {} samples with a non-finite member not written "
               "(first: {})\n", capture.refused, capture.first_refusal);
  }
  if (capture.runs > 1) {
    fmt::print(stderr, "gearcoupling record: note: {} runs captured; time restarts with each, "
               "validate excludes the rows that go back in time\n", capture.runs);
  }
  const std::string csv = live::capture_csv(capture);
  if (flags.text("out") == "-") {
    fmt::print(out, "{}", csv);
  } else {
    analysis::write_file_atomically(flags.text("out"), csv, "--out");
    fmt::print(stderr, "gearcoupling record: {} samples of test cell {} written to {}\n",
               capture.samples.size(), flags.text("test-cell"), flags.text("out"));
  }
  return 0;
}

}  // namespace

const Subcommand& record_subcommand() {
  static const Subcommand subcommand{
      "record",
      "Captures a live test cell's measurements as a recording (docs/recordings.md).\n"
      "validate and diagnose read the capture unchanged.",
      record_flags, run_record};
  return subcommand;
}

}  // namespace gc::cli
