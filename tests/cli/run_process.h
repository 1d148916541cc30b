// Runs the built gearcoupling executable as a child process, as a user would, and collects
// what it printed, its exit code and its peak memory.
#pragma once

#include <string>
#include <vector>

namespace gc::cli::testing {

struct ProcessResult {
  int exit_code = -1;      ///< -1 when the child did not exit normally (a crash)
  std::string out;         ///< standard output
  std::string err;         ///< standard error
  long max_rss_kb = 0;     ///< peak resident set size of this child [KiB] (wait4)
};

/// Runs GC_GEARCOUPLING_PATH with `args`, standard input from `stdin_path`.
ProcessResult run_gearcoupling(const std::vector<std::string>& args,
                               const std::string& stdin_path = "/dev/null");

/// A fresh path whose name starts with `stem`, in this process's scratch directory in the
/// temporary directory, which is removed when the process exits normally (GC_KEEP_TEST_FILES=1
/// keeps it).
std::string temp_path(const std::string& stem);

std::string read_file(const std::string& path);
void write_file(const std::string& path, const std::string& text);

}  // namespace gc::cli::testing
