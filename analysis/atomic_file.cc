#include "analysis/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace gc::analysis {

void write_file_atomically(const std::filesystem::path& path, std::string_view text,
                           std::string_view what) {
  // Beside the target, so that the rename stays within one file system.
  std::string temporary = path.string() + ".XXXXXX";
  const int descriptor = mkstemp(temporary.data());
  if (descriptor < 0) {
    throw std::runtime_error(fmt::format("cannot write {} {}: {}", what, path.string(), std::strerror(errno)));
  }
  std::FILE* file = fdopen(descriptor, "wb");
  const bool written = file != nullptr && std::fwrite(text.data(), 1, text.size(), file) == text.size() &&
                       std::fflush(file) == 0;
  const int write_errno = errno;
  const bool closed = file != nullptr ? std::fclose(file) == 0 : close(descriptor) == 0;
  // mkstemp makes the file 0600; a report is as readable as any file the user writes.
  const mode_t mask = umask(0);
  umask(mask);
  if (written && closed && chmod(temporary.c_str(), 0666 & ~mask) == 0 &&
      std::rename(temporary.c_str(), path.c_str()) == 0) {
    return;
  }
  const int error = written ? errno : write_errno;
  std::remove(temporary.c_str());
  throw std::runtime_error(fmt::format("cannot write {} {}: {}", what, path.string(), std::strerror(error)));
}

}  // namespace gc::analysis
