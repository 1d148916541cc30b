// A DDS Security test cell made at test time: deploy/security/make-security.sh writes a CA,
// identities (service-main, client-a, client-b, dashboard-main, and any the test adds) and
// signed documents into a
// fresh temporary directory, and these helpers give processes and in-process domains those
// identities on the test's own domain, over loopback.
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <map>
#include <string>

#include "protocol/dds_entity.h"

namespace gc::test {

/// True when Cyclone's three DDS Security plugins are installed where the script looks.
bool security_plugins_installed();

class SecureCell {
 public:
  /// Runs the script into a fresh temporary directory with "--client a --client b" and
  /// `more_args` (e.g. "--monitor m"); throws std::runtime_error with its output when it fails.
  explicit SecureCell(const std::string& more_args = {});
  /// Removes the directory.
  ~SecureCell();
  SecureCell(const SecureCell&) = delete;
  SecureCell& operator=(const SecureCell&) = delete;

  const std::string& dir() const { return dir_; }
  /// Runs the script again on this directory with the constructor's arguments and `more_args`
  /// (e.g. "--revoke client-b"); throws std::runtime_error with its output when it fails.
  void rerun(const std::string& more_args) const;
  /// CYCLONEDDS_URI for a process of `identity`: the network configuration `network` (a
  /// file:// URI; the loopback one unless given) plus its security.xml.
  std::string uri(const std::string& identity, const std::string& network = {}) const;
  /// Every file under dir() (path: content), to compare a rerun's output byte for byte.
  std::map<std::string, std::string> files() const;
  /// The client_id_prefix of client `name` ("a" or "b"), as the script wrote it.
  std::uint32_t client_prefix(const std::string& name) const { return prefix_of("client-" + name); }
  /// The client_id_prefix of any identity that asks the service (client-*, console-*).
  std::uint32_t prefix_of(const std::string& identity) const;

 private:
  std::string dir_;
  std::string args_;
};

/// Runs `command` with /bin/sh; its exit status and what it printed (standard output and error).
struct ShellResult {
  int exit_code = -1;
  std::string output;
};
ShellResult run_shell(const std::string& command);

/// A DDS domain of this process under `local_id` (not test_domain(): 210-230) configured by
/// `config` (a CYCLONEDDS_URI value) that appears on the wire as test_domain()
/// (Discovery/ExternalDomainId). So one test process holds several identities and a plain
/// participant (on test_domain() itself), each talking to the others like separate hosts.
class LocalDomain {
 public:
  LocalDomain(int local_id, const std::string& config);
  ~LocalDomain();
  LocalDomain(const LocalDomain&) = delete;
  LocalDomain& operator=(const LocalDomain&) = delete;

  int id() const { return local_id_; }
  /// A new participant in this domain (owned by the caller); throws protocol::DdsError when
  /// security refuses it.
  protocol::Entity participant() const;

 private:
  int local_id_;
  dds_entity_t domain_;
};

}  // namespace gc::test
