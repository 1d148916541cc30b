// Which Cyclone DDS configuration a program of gearcoupling joins its domain with, and the words
// that name it in messages (docs/deploy.md, "Which Cyclone configuration"). No Cyclone type here:
// the client library's users may include it.
#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gc::protocol {

/// Where a DDS configuration came from.
enum class DdsConfigSource {
  kEnvironment,     ///< CYCLONEDDS_URI, set by the user: always wins
  kInstalled,       ///< <sysconfdir>/gearcoupling/cyclonedds.xml of an install
  kCycloneDefault,  ///< neither: Cyclone's built-in defaults (every interface, multicast)
};

struct DdsConfig {
  DdsConfigSource source = DdsConfigSource::kCycloneDefault;
  /// The configuration as dds_create_domain() takes it (a CYCLONEDDS_URI value); empty for
  /// Cyclone's default.
  std::string uri;
};

/// The choice, pure: `environment_uri` (the value of CYCLONEDDS_URI, nullptr or empty when unset)
/// when set; else the first of `installed_paths` that is a regular file, as a file:// URI; else
/// Cyclone's default.
DdsConfig choose_dds_config(const char* environment_uri,
                            const std::vector<std::filesystem::path>& installed_paths);

/// The installed configuration's possible paths, most specific first:
///   1. etc/gearcoupling/cyclonedds.xml of the install tree this code was loaded from (the
///      program in <prefix>/bin or libgearcoupling-client in <prefix>/<libdir>; prefix /usr
///      means /etc/gearcoupling): the .deb, any `cmake --install --prefix`;
///   2. the one under the install prefix this was configured with (CMake's
///      GC_INSTALLED_DDS_CONFIG, as cmake/install_system_files.cmake installs it).
/// A program run from its build tree finds only 2., and only once installed there.
std::vector<std::filesystem::path> installed_dds_config_paths();

/// The installed configuration of the install tree whose <libdir> or <bindir> is `loaded_from`
/// (a prefix of /usr: /etc/gearcoupling/cyclonedds.xml, else <prefix>/etc/gearcoupling/...);
/// nullopt when `loaded_from` is neither (a build tree).
std::optional<std::filesystem::path> install_tree_dds_config(
    const std::filesystem::path& loaded_from);

/// choose_dds_config(getenv("CYCLONEDDS_URI"), installed_dds_config_paths()).
DdsConfig dds_config();

/// The configuration in words, for logs and messages: "CYCLONEDDS_URI=<uri>",
/// "<uri> (installed; CYCLONEDDS_URI unset)" or "Cyclone's default (CYCLONEDDS_URI unset)".
std::string describe(const DdsConfig& config);

/// "no gearcoupling-service instance ready on domain N within T ms ([K instance(s) discovered; ]
/// DDS configuration: <configuration>); start one with `systemctl start gearcoupling-service` or
/// `gearcoupling-service --domain N`, on the same configuration and domain".
std::string no_instance_message(int domain, std::chrono::milliseconds timeout,
                                const std::string& configuration,
                                std::optional<std::size_t> discovered = std::nullopt);

}  // namespace gc::protocol
