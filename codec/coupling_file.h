// Coupling files: gearcoupling.v1.CouplingDefinition (idl/coupling.proto) in protobuf text
// format, as bundled in data/couplings/. Translates to gc::CouplingDefinition: SI, radians.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/coupling_definition.h"

namespace gc::codec {

/// Parses one coupling in text format. Throws gc::InvalidInput naming the field and
/// `source_name` (with line and column for syntax errors and unknown fields) when the text does
/// not parse, names a field the schema lacks, or omits a required field: every field except
/// those the schema marks "optional use" (description, crown_radius_m, sleeve_root_diameter_m).
/// Angles in the file are degrees (_deg) and come out in radians. Checked here, in the file's
/// terms: the angles against the core's ranges in degrees, and the pitch diameter against N *
/// module and the base diameter against D cos(phi), naming every field of the check. The other
/// ranges are gc::CouplingGeometry's (load_coupling_geometry adds the file to its message).
CouplingDefinition parse_coupling_text(std::string_view text, std::string_view source_name);

/// Parses one coupling given as JSON with the file's fields (protobuf's JSON mapping of
/// gearcoupling.v1.CouplingDefinition, e.g. a Python dict): the same checks and errors as the text.
CouplingDefinition parse_coupling_json(std::string_view json, std::string_view source_name);

/// Reads and parses `path`; errors name the file by its file name.
CouplingDefinition load_coupling_file(const std::filesystem::path& path);

}  // namespace gc::codec
