// The catalogue of couplings: every *.textproto in one directory, keyed by the coupling's name.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "core/coupling_geometry.h"

namespace gc::codec {

/// Loads and validates every *.textproto in `dir`. Throws gc::InvalidInput naming the field and
/// file when one does not parse or is not a physical coupling, and "coupling.name" when two
/// files define the same name or the directory cannot be read.
std::map<std::string, CouplingGeometry> load_coupling_catalog(const std::filesystem::path& dir);

/// Loads one coupling file and validates it; errors name the field and the file.
CouplingGeometry load_coupling_geometry(const std::filesystem::path& file);

/// $GEARCOUPLING_CATALOG when set and not empty, else the bundled couplings:
/// bundled_data_dir("couplings") (installed share/gearcoupling/couplings, or the source tree's
/// data/couplings for a program run from its build tree).
std::filesystem::path default_catalog_dir();

}  // namespace gc::codec
