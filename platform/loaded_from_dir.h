// The folder of the file (a shared library or a program) that holds a given function: where an
// installed library finds what was installed beside it (bundled data, the DDS configuration),
// whatever prefix it was installed under. Header-only: each library passes a function of its own,
// so the answer is that library's folder.
#pragma once

#include <dlfcn.h>

#include <filesystem>
#include <system_error>

namespace gc::platform {

/// The folder of the loaded file that holds `function`; empty when the loader cannot say.
/// Canonical: a library the loader found through a symlinked folder (/lib on a merged /usr, where
/// ld.so.cache points) is under its real prefix (/usr).
inline std::filesystem::path loaded_from_dir(const void* function) {
  Dl_info info{};
  if (dladdr(function, &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code error;
  const std::filesystem::path dir =
      std::filesystem::weakly_canonical(std::filesystem::absolute(info.dli_fname, error).parent_path(), error);
  return error ? std::filesystem::path() : dir;
}

}  // namespace gc::platform
