// libFuzzer target: a test-cell recording (CSV) through RecordingReader, as `validate` and
// `diagnose` read it (clients/cli/recording_csv.h). The reader takes a path, so each input is
// written to one scratch file first.
//
// Checks: the only exception is InvalidInput naming a field (a bad header, an empty file); every
// sample it keeps is finite with time never going backwards; every row is counted as kept or
// excluded, so nothing is dropped in silence.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "analysis/recording_csv.h"
#include "fuzz/fuzz_checks.h"
#include "fuzz/scratch_file.h"

namespace {

void check_optional(const char* name, const std::optional<double>& value) {
  if (value) gc::fuzz::check_finite(name, *value);
}

void check_sample(const gc::RecordedSample& s) {
  using gc::fuzz::check_finite;
  check_finite("time_s", s.input.time_s);
  check_finite("torque_nm", s.input.torque_nm);
  check_finite("misalignment_rad", s.input.misalignment_rad);
  check_finite("direction_rad", s.input.direction_rad);
  check_finite("msy_nm", s.measured.y_nm);
  check_finite("msz_nm", s.measured.z_nm);
  check_optional("speed_rpm", s.input.speed_rpm);
  check_optional("temperature_c", s.input.temperature_c);
  check_optional("rotation_phase_rad", s.input.rotation_phase_rad);
  check_optional("applied_moment_y_nm", s.input.applied_moment_y_nm);
  check_optional("applied_moment_z_nm", s.input.applied_moment_z_nm);
  check_optional("hub_motion_m", s.hub_motion_m);
}

void read_all(const std::filesystem::path& path) {
  gc::analysis::RecordingReader reader(path);
  gc::fuzz::check_finite("loading_dead_band_rad", reader.loading_dead_band_rad());
  std::vector<gc::RecordedSample> chunk;
  std::size_t kept = 0;
  std::optional<double> last_time;
  // A small chunk, so inputs of a few rows still cross chunk boundaries.
  while (reader.next_chunk(chunk, 3)) {
    for (const gc::RecordedSample& sample : chunk) {
      check_sample(sample);
      if (last_time && sample.input.time_s < *last_time) gc::fuzz::fail("time went backwards");
      last_time = sample.input.time_s;
    }
    kept += chunk.size();
  }
  if (kept + reader.excluded_rows() != reader.rows_read()) {
    gc::fuzz::fail("rows neither kept nor excluded: " + std::to_string(reader.rows_read()) +
                   " read, " + std::to_string(kept) + " kept, " +
                   std::to_string(reader.excluded_rows()) + " excluded");
  }
  for (const gc::analysis::RowProblem& problem : reader.problems()) {
    if (problem.line < 2 || problem.message.empty()) gc::fuzz::fail("a problem without line or reason");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const gc::fuzz::ScratchFile scratch("gc_recording_fuzz", ".csv", data, size);
  const std::filesystem::path& input = scratch.path();
  gc::fuzz::expect_result_or<gc::InvalidInput>([&] { read_all(input); });
  return 0;
}
