// The HTML report's data as JSON, the same text as codec::to_json(report) but written faster:
// protobuf's printer took 0.1 s of validate's 1e6 samples on one thread after the run, nearly
// all of it on the ~8,000 plotted points (9 numbers each, through its default-value writer). The
// result and every other field still go through protobuf; each model's points are written here,
// as protobuf writes them (indented by one space a level, doubles as "%.15g", or "%.17g" when
// that does not read back), and put where protobuf put an empty list.
#pragma once

#include <string>

#include "idl/validation.pb.h"

namespace gc::analysis {

/// codec::to_json(report), to the byte. Falls back to protobuf whole for what this does not
/// write (a non-finite number, a PlotPoint with fields it does not know).
std::string report_json(const gearcoupling::v1::ValidationReport& report);

}  // namespace gc::analysis
