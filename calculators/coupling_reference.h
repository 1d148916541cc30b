// How the CLI reads a coupling reference: a path (containing '/' or ending in ".textproto") is
// a coupling file; anything else is a name in the catalogue.
#pragma once

#include <string_view>

namespace gc::calculators {

inline bool is_file_reference(std::string_view coupling) {
  return coupling.find('/') != std::string_view::npos || coupling.ends_with(".textproto");
}

}  // namespace gc::calculators
