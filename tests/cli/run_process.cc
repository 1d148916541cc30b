#include "run_process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace gc::cli::testing {

namespace {

/// This process's scratch directory in the temporary directory, removed with everything in it
/// when the process ends normally, so that a test run leaves nothing behind (a crashed test keeps
/// its files). GC_KEEP_TEST_FILES=1 (or the campaign's GC_CAMPAIGN_KEEP=1) keeps it.
class ScratchDirectory {
 public:
  ScratchDirectory()
      : owner_(::getpid()), path_(std::filesystem::temp_directory_path() / ("gc_test_" + std::to_string(owner_))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    const char* keep = std::getenv("GC_KEEP_TEST_FILES");
    const char* keep_campaign = std::getenv("GC_CAMPAIGN_KEEP");
    // A forked child that exits normally must not remove its parent's files.
    if (::getpid() != owner_ || (keep && *keep) || (keep_campaign && *keep_campaign)) return;
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  pid_t owner_;
  std::filesystem::path path_;
};

}  // namespace

std::string temp_path(const std::string& stem) {
  static const ScratchDirectory scratch;
  static std::atomic<int> counter{0};
  return (scratch.path() / (stem + "_" + std::to_string(counter++))).string();
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

ProcessResult run_gearcoupling(const std::vector<std::string>& args,
                               const std::string& stdin_path) {
  const std::string out_path = temp_path("gc_out");
  const std::string err_path = temp_path("gc_err");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, stdin_path.c_str(), O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0600);
  posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0600);
  std::vector<std::string> argv_text = {GC_GEARCOUPLING_PATH};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : argv_text) argv.push_back(arg.data());
  argv.push_back(nullptr);

  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, GC_GEARCOUPLING_PATH, &actions, nullptr, argv.data(),
                                  environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot start " GC_GEARCOUPLING_PATH);
  int status = 0;
  rusage usage{};
  ::wait4(pid, &status, 0, &usage);

  ProcessResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_file(out_path);
  result.err = read_file(err_path);
  result.max_rss_kb = usage.ru_maxrss;
  std::filesystem::remove(out_path);
  std::filesystem::remove(err_path);
  return result;
}

}  // namespace gc::cli::testing
