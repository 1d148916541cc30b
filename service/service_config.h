// How one gearcoupling-service instance runs: defaults, then a config file
// (service_config.proto in text format), then command-line flags, each overriding the last.
#pragma once

#include <string>
#include <vector>

namespace gc::service {

struct ServiceConfig {
  int domain = 0;                     ///< DDS domain id, [0, protocol::kMaxDomainId]
  unsigned threads = 0;               ///< workers; 0 = one per core
  std::string catalogue_dir;          ///< "" = codec::default_catalog_dir()
  std::string log_level = "info";     ///< spdlog level: trace, debug, info, warn, error, off
  double status_interval_s = 1.0;     ///< status topic period [s]
  double stats_log_interval_s = 10.0; ///< periodic stats log line [s]
  double liveliness_lease_s = 2.0;    ///< status writer lease: a killed instance is noticed
                                      ///< within this time [s]
  double reply_match_timeout_s = 1.0; ///< longest a request waits, parked outside the
                                      ///< workers, for its client's reply reader [s]
  double reply_block_s = 0.5;         ///< longest a reply waits (retried, never blocking a
                                      ///< worker) for an unacknowledging client [s]
  double departed_hold_s = 5.0;       ///< how long such a client's requests are then dropped;
                                      ///< longer than any participant lease in use [s]
  double shutdown_grace_s = 0.2;      ///< after SIGINT/SIGTERM: keep answering requests already
                                      ///< on their way this long, then drain and exit [s]
  /// Longest time from a request's arrival to its answer [s], in [1e-6, 60]: later, queued or
  /// mid-iteration, it is answered STATUS_DEADLINE_EXCEEDED, so no request holds a worker (or
  /// the drain at shutdown) longer. The largest allowed request computes in tens of ms at most
  /// (docs/protocol.md), so the default only ever fires on an overloaded instance.
  double calculation_deadline_s = 1.0;
};

/// What the command line asked for.
struct ServiceCommand {
  ServiceConfig config;
  bool help = false;     ///< --help: print service_usage()
  bool version = false;  ///< --version: print service_version()
  bool bash_completion = false;  ///< --bash-completion: print service_bash_completion()
};

/// Parses `args` (without the program name) with CLI11, "--flag value" or "--flag=value":
/// --config FILE is applied first wherever it appears, then --domain N, -j/--jobs N,
/// --catalogue DIR, --log-level L and the durations in seconds (--status-interval-s,
/// --stats-interval-s, --lease-s, --reply-match-timeout-s, --reply-block-s, --departed-hold-s,
/// --shutdown-grace-s, --deadline-s; each also without "-s"), --help, --version. Throws
/// InvalidInput naming the flag, or the setting out of range, or the file's field.
ServiceCommand parse_service_command(const std::vector<std::string>& args);

/// Reads a config file into `config` (fields it sets override). Errors name the file, line and
/// field.
void apply_config_file(const std::string& path, ServiceConfig& config);

/// Throws InvalidInput naming the first setting out of range.
void validate(const ServiceConfig& config);

/// The usage text of gearcoupling-service: every flag with its unit and default.
std::string service_usage();

/// "gearcoupling-service <version>\n", the CMake project version.
std::string service_version();

/// The bash completion of gearcoupling-service, from the same flag declarations as the parser
/// (each flag under its canonical name; paths after --config and --catalogue, the levels after
/// --log-level). Installed to share/bash-completion/completions/gearcoupling-service.
std::string service_bash_completion();

}  // namespace gc::service
