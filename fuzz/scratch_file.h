// The readers under test take a path, not bytes: each fuzz input is written to a file of this
// process in the temporary directory for the time of one run, and removed after it. (Removal at
// exit would not happen: libFuzzer ends a timed run with _Exit, which skips atexit handlers.)
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace gc::fuzz {

class ScratchFile {
 public:
  /// Writes `data` to "<temp>/<stem>_<pid><extension>".
  ScratchFile(const std::string& stem, const std::string& extension, const std::uint8_t* data, std::size_t size)
      : path_(std::filesystem::temp_directory_path() / (stem + "_" + std::to_string(::getpid()) + extension)) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~ScratchFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace gc::fuzz
