// gearcoupling synth: a synthetic recording from a model configuration along one of the
// paper's load sequences (diagnosis/synthesis/), with reproducible noise.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <fmt/format.h>

#include "clients/cli/model_flags.h"
#include "analysis/recording_csv.h"
#include "clients/cli/subcommand.h"
#include "diagnosis/synthesis/load_sequence.h"
#include "diagnosis/synthesis/synthesize.h"

namespace gc::cli {

using analysis::append_recording_row;
using analysis::recording_header;
namespace {

std::vector<FlagSpec> synth_flags() {
  std::vector<FlagSpec> flags = {
      model_flag(),
      {"sequence", "KIND",
       "load sequence: moment-sweep (Figures 10-11), torque-sweep (Figures 12-13) or "
       "torque-ramp (Figure 14)",
       "moment-sweep"},
      {"samples", "N", "samples in the sequence", "2000"},
      {"noise-nm", "N·m", "standard deviation of the noise on M_sy' and M_sz'", "0"},
      {"seed", "N", "noise seed: the same seed gives the same file", "1"},
      {"reference-torque-nm", "N·m", "T_ref the sequence's torque fractions refer to", "1.5e6",
       false, '\0', {"reference-torque"}},
      {"sample-period-s", "s", "time between samples", "0.01", false, '\0', {"sample-period"}},
      {"out", "FILE", "the recording (CSV, docs/recordings.md); '-' for standard output", "-"},
      catalogue_flag(),
      {"json", "", "", std::nullopt, true, '\0', {},
       "synth writes the recording as CSV (docs/recordings.md; see --out)"},
  };
  append(flags, refused_calculator_flags("synth"));
  return flags;
}

LoadSequenceOptions sequence_options(const Flags& flags, const CouplingModel& model) {
  LoadSequenceOptions options;
  const std::string& kind = flags.text("sequence");
  const auto parsed = load_sequence_kind(kind);
  if (!parsed) {
    throw UsageError("--sequence '" + kind + "': one of moment-sweep, torque-sweep, torque-ramp");
  }
  options.kind = *parsed;
  options.samples = flags.integer("samples", 2, 100'000'000);
  options.jam_angle_rad = model.geometry().jam_angle().angle_rad;
  options.reference_torque_nm = flags.number("reference-torque-nm");
  options.sample_period_s = flags.number("sample-period-s");
  return options;
}

SynthesisOptions synthesis_options(const Flags& flags) {
  const double seed = flags.number("seed");
  if (seed < 0 || seed != static_cast<double>(static_cast<std::uint64_t>(seed))) {
    throw UsageError(fmt::format("--seed '{}': a whole number >= 0", flags.text("seed")));
  }
  return {flags.number("noise-nm"), static_cast<std::uint64_t>(seed)};
}

void write_recording(const SynthesizedRecording& recording, std::FILE* out) {
  if (recording.samples.empty()) return;
  std::string text = recording_header(recording.samples.front());
  for (const RecordedSample& sample : recording.samples) {
    append_recording_row(text, sample);
    if (text.size() > (1u << 20)) {
      std::fwrite(text.data(), 1, text.size(), out);
      text.clear();
    }
  }
  std::fwrite(text.data(), 1, text.size(), out);
}

int run_synth(const Flags& flags, const Calculator&, std::FILE* out) {
  const codec::ModelFile model = load_model_flag(flags);
  const std::vector<MeasurementSample> inputs =
      load_sequence(sequence_options(flags, model.model));
  const SynthesizedRecording recording =
      synthesize(model.model, inputs, synthesis_options(flags));
  if (!recording.rejected.empty()) {
    fmt::print(stderr, "gearcoupling synth: {} of {} samples refused by model {} (left out; "
               "first, sample {}: {})\n", recording.rejected.size(), inputs.size(), model.name,
               recording.rejected.front().index, recording.rejected.front().reason);
  }
  const std::string& path = flags.text("out");
  if (path == "-") {
    write_recording(recording, out);
    return 0;
  }
  std::FILE* file = std::fopen(path.c_str(), "wb");
  // The OS's reason: no such directory, permission denied, disk full (issue 39).
  if (file == nullptr) throw std::runtime_error("cannot write --out " + path + ": " + std::strerror(errno));
  write_recording(recording, file);
  if (std::fclose(file) != 0) throw std::runtime_error("cannot write --out " + path + ": " + std::strerror(errno));
  return 0;
}

}  // namespace

const Subcommand& synth_subcommand() {
  static const Subcommand subcommand{
      "synth",
      "Synthetic recording from a model along a load sequence of the paper.\n"
      "Moment sweeps, torque sweeps or the torque ramp, with reproducible Gaussian noise.",
      synth_flags, run_synth};
  return subcommand;
}

}  // namespace gc::cli
