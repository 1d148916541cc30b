// Writes Channels as a recording CSV (docs/recordings.md): SI columns, or the units a DAQ export
// uses (time in ms, torque in kN·m or MN·m, angles in deg or mrad, moments in kN·m). Numbers with
// 12 significant digits, so the rounding of the export moves nothing a model could see.
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <utility>

#include "tests/diagnosis/zoo/channels.h"
#include "tests/diagnosis/zoo/rng.h"

namespace gc::zoo {

/// Column indices, in the order written.
enum Column : int { kTime = 0, kTorque, kZeta, kBeta, kSpeed, kTemperature, kMsy, kMsz, kColumns };
/// The quantity names of docs/recordings.md ("time", "torque", "misalignment", ...).
const char* column_name(int column);

struct CsvStyle {
  std::string time = "s";         ///< s | ms
  std::string torque = "nm";      ///< nm | knm | mnm
  std::string angle = "rad";      ///< rad | deg | mrad (misalignment and direction)
  std::string moment = "nm";      ///< nm | knm | mnm
  bool extra_column = false;      ///< a channel of no known quantity (Ch9_V, noise), as an export has
  std::string describe() const;   ///< "SI" or e.g. "ms, kNm, deg, kNm, +Ch9"
};

/// SI most of the time; a DAQ export's units in about a quarter of the draws.
CsvStyle draw_style(Rng& rng);

/// The CSV text. A NaN value is written "nan"; the cells in `empty` ((row, column)) are left empty.
std::string write_csv(const Channels& c, const CsvStyle& style,
                      const std::set<std::pair<std::size_t, int>>& empty = {}, std::uint64_t extra_seed = 0);

}  // namespace gc::zoo
