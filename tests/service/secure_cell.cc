#include "tests/service/secure_cell.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "tests/service/service_process.h"

namespace gc::test {
namespace {

constexpr const char* kPluginDir = "/usr/lib/x86_64-linux-gnu/libddsc0debian";
constexpr const char* kLoopback = "file://" GC_SOURCE_DIR "/deploy/cyclonedds-loopback.xml";

}  // namespace

bool security_plugins_installed() {
  for (const char* plugin : {"auth", "ac", "crypto"}) {
    const std::string path = std::string(kPluginDir) + "/libdds_security_" + plugin + ".so";
    if (!std::filesystem::exists(path)) return false;
  }
  return true;
}

ShellResult run_shell(const std::string& command) {
  ShellResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("popen failed: " + command);
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

SecureCell::SecureCell(const std::string& more_args) : args_("--client a --client b " + more_args) {
  char pattern[] = "/tmp/gc-security-XXXXXX";
  if (mkdtemp(pattern) == nullptr) throw std::runtime_error("mkdtemp failed");
  dir_ = pattern;
  rerun({});
}

void SecureCell::rerun(const std::string& more_args) const {
  const ShellResult made = run_shell(GC_SOURCE_DIR "/deploy/security/make-security.sh " + dir_ +
                                     " " + args_ + " " + more_args);
  if (made.exit_code != 0) {
    throw std::runtime_error("make-security.sh failed (" + std::to_string(made.exit_code) +
                             "): " + made.output);
  }
}

SecureCell::~SecureCell() {
  std::error_code ignored;
  std::filesystem::remove_all(dir_, ignored);
}

std::string SecureCell::uri(const std::string& identity, const std::string& network) const {
  return (network.empty() ? std::string(kLoopback) : network) + ",file://" + dir_ + "/" + identity + "/security.xml";
}

std::map<std::string, std::string> SecureCell::files() const {
  std::map<std::string, std::string> out;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir_)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    out[entry.path()] = std::string(std::istreambuf_iterator<char>(in), {});
  }
  return out;
}

std::uint32_t SecureCell::prefix_of(const std::string& identity) const {
  std::ifstream in(dir_ + "/" + identity + "/client_id_prefix");
  std::string hex;
  in >> hex;
  return static_cast<std::uint32_t>(std::stoul(hex, nullptr, 16));
}

LocalDomain::LocalDomain(int local_id, const std::string& config) : local_id_(local_id) {
  const std::string on_the_wire =
      "<Discovery><ExternalDomainId>" + std::to_string(test_domain()) +
      "</ExternalDomainId></Discovery>";
  domain_ = protocol::check_dds(
      dds_create_domain(static_cast<dds_domainid_t>(local_id), (config + "," + on_the_wire).c_str()),
      "dds_create_domain");
}

LocalDomain::~LocalDomain() { dds_delete(domain_); }

protocol::Entity LocalDomain::participant() const {
  return protocol::Entity(protocol::check_dds(
      dds_create_participant(static_cast<dds_domainid_t>(local_id_), nullptr, nullptr),
      "dds_create_participant"));
}

}  // namespace gc::test
