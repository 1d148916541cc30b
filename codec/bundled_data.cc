#include "codec/bundled_data.h"

#include <dlfcn.h>

#include <array>
#include <system_error>

namespace gc::codec {
namespace {

// The folder of the file (shared library or program) this function was loaded from; empty when
// the loader cannot say.
std::filesystem::path loaded_from_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&loaded_from_dir), &info) == 0 ||
      info.dli_fname == nullptr) {
    return {};
  }
  std::error_code error;
  // Canonical: a library the loader found through a symlinked folder (/lib on a merged /usr,
  // where ld.so.cache points) is under its real prefix (/usr).
  const std::filesystem::path dir =
      std::filesystem::weakly_canonical(std::filesystem::absolute(info.dli_fname, error).parent_path(), error);
  return error ? std::filesystem::path() : dir;
}

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
