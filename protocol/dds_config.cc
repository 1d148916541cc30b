#include "protocol/dds_config.h"

#include <cstdlib>
#include <system_error>

#include <fmt/format.h>

#include "platform/loaded_from_dir.h"

namespace gc::protocol {
namespace {

// The folder this library (or the program it is linked into) was loaded from.
std::filesystem::path loaded_from_dir() { return platform::loaded_from_dir(reinterpret_cast<const void*>(&loaded_from_dir)); }

// The prefix `dir` is `<prefix>/<relative>` of; nullopt when it is not.
std::optional<std::filesystem::path> prefix_of(const std::filesystem::path& dir,
                                               const std::filesystem::path& relative) {
  std::filesystem::path prefix = dir;
  std::filesystem::path rest = relative.lexically_normal();
  std::vector<std::filesystem::path> parts(rest.begin(), rest.end());
  for (auto part = parts.rbegin(); part != parts.rend(); ++part) {
    if (part->empty()) continue;
    if (prefix.filename() != *part) return std::nullopt;
    prefix = prefix.parent_path();
  }
  return prefix;
}

// cmake/install_system_files.cmake's rule: /usr's configuration is in /etc.
std::filesystem::path config_under(const std::filesystem::path& prefix) {
  const std::filesystem::path etc =
      prefix == "/usr" || prefix == "/" ? std::filesystem::path("/etc") : prefix / "etc";
  return etc / "gearcoupling" / "cyclonedds.xml";
}

}  // namespace

DdsConfig choose_dds_config(const char* environment_uri,
                            const std::vector<std::filesystem::path>& installed_paths) {
  if (environment_uri != nullptr && *environment_uri != '\0') {
    return {DdsConfigSource::kEnvironment, environment_uri};
  }
  for (const auto& path : installed_paths) {
    std::error_code error;
    if (!path.empty() && std::filesystem::is_regular_file(path, error)) {
      return {DdsConfigSource::kInstalled, "file://" + path.lexically_normal().string()};
    }
  }
  return {DdsConfigSource::kCycloneDefault, ""};
}

std::optional<std::filesystem::path> install_tree_dds_config(
    const std::filesystem::path& loaded_from) {
  if (loaded_from.empty()) return std::nullopt;
  const std::filesystem::path dir = loaded_from.lexically_normal();
  for (const char* relative : {GC_INSTALL_LIBDIR, GC_INSTALL_BINDIR}) {
    if (const auto prefix = prefix_of(dir, relative)) return config_under(*prefix);
  }
  return std::nullopt;
}

std::vector<std::filesystem::path> installed_dds_config_paths() {
  std::vector<std::filesystem::path> paths;
  if (auto path = install_tree_dds_config(loaded_from_dir())) paths.push_back(std::move(*path));
  paths.emplace_back(GC_INSTALLED_DDS_CONFIG);
  return paths;
}

DdsConfig dds_config() {
  return choose_dds_config(std::getenv("CYCLONEDDS_URI"), installed_dds_config_paths());
}

std::string describe(const DdsConfig& config) {
  switch (config.source) {
    case DdsConfigSource::kEnvironment:
      return "CYCLONEDDS_URI=" + config.uri;
    case DdsConfigSource::kInstalled:
      return config.uri + " (installed; CYCLONEDDS_URI unset)";
    case DdsConfigSource::kCycloneDefault:
      break;
  }
  return "Cyclone's default (CYCLONEDDS_URI unset)";
}

std::string no_instance_message(int domain, std::chrono::milliseconds timeout,
                                const std::string& configuration,
                                std::optional<std::size_t> discovered) {
  return fmt::format(
      "no gearcoupling-service instance ready on domain {} within {} ms ({}DDS configuration: "
      "{}); start one with `systemctl start gearcoupling-service` or `gearcoupling-service "
      "--domain {}`, on the same configuration and domain",
      domain, timeout.count(),
      discovered ? fmt::format("{} instance(s) discovered; ", *discovered) : std::string(),
      configuration, domain);
}

}  // namespace gc::protocol
