// The HTML report's data as JSON, the same text as codec::to_json(report) but written directly
// from the message: protobuf's printer (through its default-value writer) took 0.1 s of
// validate's 1e6 samples on one thread after the run, most of it on the ~8,000 plotted points.
// Written as protobuf writes it: indented by one space a level, every field but an unset one
// with presence, doubles as "%.15g" or "%.17g" when that does not read back, strings escaped.
#pragma once

#include <string>

#include "idl/validation.pb.h"

namespace gc::analysis {

/// codec::to_json(report), to the byte. Falls back to protobuf for what this does not write
/// (a non-finite number; a field type the report does not use: an enum, int64, float, map).
std::string report_json(const gearcoupling::v1::ValidationReport& report);

}  // namespace gc::analysis
