#include "codec/bundled_data.h"

#include <array>
#include <system_error>

#include "platform/loaded_from_dir.h"

namespace gc::codec {
namespace {

// The folder this library (or the program it is linked into) was loaded from.
std::filesystem::path loaded_from_dir() { return platform::loaded_from_dir(reinterpret_cast<const void*>(&loaded_from_dir)); }

}  // namespace

std::filesystem::path bundled_data_dir(std::string_view kind) {
  const std::filesystem::path library_dir = loaded_from_dir();
  const std::array<std::filesystem::path, 3> candidates = {
      library_dir.empty() ? std::filesystem::path()
                          : library_dir / GC_DATA_DIR_FROM_LIBDIR / kind,
      std::filesystem::path(GC_SOURCE_DATA_DIR) / kind,
      std::filesystem::path(GC_INSTALLED_DATA_DIR) / kind,
  };
  for (const auto& candidate : candidates) {
    std::error_code error;
    if (!candidate.empty() && std::filesystem::is_directory(candidate, error)) {
      return candidate.lexically_normal();
    }
  }
  return candidates.back();
}

}  // namespace gc::codec
