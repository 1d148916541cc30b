// gearcoupling-dashboard: flags, logging, signals; DashboardServer does the rest.
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "calculators/client_id_prefix.h"
#include "clients/dashboard/dashboard_server.h"
#include "core/model_error.h"
#include "live/live_names.h"
#include "live/swap_operator.h"
#include "parallel/shutdown_signals.h"
#include "protocol/dds_config.h"
#include "protocol/domain_id.h"

namespace {

constexpr int kBadInput = 2;
/// An event stream holds a thread (~8 MB of address space, little resident) and a queue.
constexpr std::size_t kMostStreams = 1024;
/// A cell takes 1 to 1.8 kB of /metrics (a 64-character name the most): 256 keep it far under
/// 1 MB (docs/dashboard.md, "Bounds").
constexpr std::size_t kMostCells = 256;

/// "ADDR:PORT" (the port after the last colon, so "[::1]:8080" works too) into the options.
void parse_listen(const std::string& listen, gc::dashboard::DashboardOptions& options) {
  const std::size_t colon = listen.rfind(':');
  if (colon == std::string::npos || colon == 0) {
    throw CLI::ValidationError("--listen", "\"" + listen + "\" is not ADDR:PORT, e.g. 127.0.0.1:8080");
  }
  std::string host = listen.substr(0, colon);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  int port = -1;
  try {
    std::size_t used = 0;
    port = std::stoi(listen.substr(colon + 1), &used);
    if (used != listen.size() - colon - 1) port = -1;
  } catch (const std::exception&) {
  }
  if (port < 0 || port > 65535) {
    throw CLI::ValidationError("--listen", "port \"" + listen.substr(colon + 1) +
                                               "\" is out of range: allowed 0 to 65535 (0: any free port)");
  }
  options.listen_host = host;
  options.listen_port = port;
}

}  // namespace

int main(int argc, char** argv) {
  gc::dashboard::DashboardOptions options;
  std::string listen = "127.0.0.1:8080";
  int update_hz = 10;
  double query_timeout_s = 5.0;
  std::string client_id_prefix = gc::calculators::client_id_prefix_from_environment();
  CLI::App app{
      "gearcoupling-dashboard: the service instances, the live test cells and a query panel in "
      "the browser, and /metrics for Prometheus (docs/dashboard.md). Reads DDS; writes only the "
      "query panel's requests."};
  app.set_version_flag("--version", "gearcoupling-dashboard " GC_VERSION);
  app.set_config("--config", "",
                 "read flags from FILE (TOML: `name = value` a line, the long flag without --, "
                 "e.g. `listen = \"127.0.0.1:8080\"`); flags on the command line win. Its unit "
                 "reads /etc/gearcoupling/dashboard.conf");
  app.allow_config_extras(false);  // a misspelt name in the file is an error, not ignored
  app.add_option("--domain", options.domain, "DDS domain id; the network comes from CYCLONEDDS_URI, else the installed cyclonedds.xml")
      ->check(CLI::Range(0, gc::protocol::kMaxDomainId));
  app.add_option("--listen", listen,
                 "ADDR:PORT to serve on; localhost only by default, port 0 picks a free one "
                 "(printed)")
      ->capture_default_str();
  app.add_option("--update-hz", update_hz, "live updates to each browser per second, at most")
      ->check(CLI::Range(1, 10))
      ->capture_default_str();
  app.add_option("--query-timeout", query_timeout_s, "the query panel's wait for the service [s]")
      ->check(CLI::Range(0.1, 60.0))
      ->capture_default_str();
  app.add_option("--max-streams", options.max_streams,
                 "browsers on the live event stream at once; beyond it 503 with Retry-After "
                 "(the page, /metrics and queries keep 32 threads of their own)")
      ->check(CLI::Range(std::size_t{1}, kMostStreams))
      ->capture_default_str();
  app.add_option("--max-cells", options.max_cells,
                 "test cells shown at most; a new one beyond it replaces a gone or stale one, "
                 "else it is ignored and counted")
      ->check(CLI::Range(std::size_t{1}, kMostCells))
      ->capture_default_str();
  app.add_option("--operator-cells", options.operator_cells,
                 "test cells whose monitor proposals this dashboard may apply (the cell card's "
                 "apply button); under DDS Security its identity must be an operator granted them. "
                 "Default: none, read-only")
      ->delimiter(',');
  app.add_option("--operator", options.operator_name,
                 "with --operator-cells: the person applying proposals, as the monitor's audit "
                 "trail names them; required unless the DDS Security identity is an operator's "
                 "(GC_IDENTITY=operator-NAME), which names them");
  app.add_option("--allow-host", options.allow_hosts,
                 "host names the dashboard answers to in Host and Origin, besides localhost, the "
                 "--listen address and IP addresses (the names users type, e.g. "
                 "dyno-hall.example); any other is refused 403, which stops DNS rebinding")
      ->delimiter(',');
  app.add_option("--max-pending-per-peer", options.connections.max_reading_per_peer,
                 "connections one peer (IP address) may have sending their request at once; "
                 "beyond it 429 (each has 5 s for its whole request)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{64}))
      ->capture_default_str();
  app.add_option("--client-id-prefix", client_id_prefix,
                 std::string("for the query panel, ") + gc::calculators::kClientIdPrefixHelp);
  try {
    app.parse(argc, argv);
    parse_listen(listen, options);
    options.client_id_prefix = gc::calculators::parse_client_id_prefix(client_id_prefix);
    if (!options.operator_cells.empty()) {
      options.operator_name = gc::live::swap_operator(options.operator_name,
                                                      gc::live::operator_of_identity());
    }
  } catch (const CLI::ParseError& error) {
    // --help exits 0; bad flags exit 2, as the other programs' bad input does.
    return app.exit(error) == 0 ? 0 : kBadInput;
  } catch (const std::invalid_argument& error) {
    std::fprintf(stderr, "gearcoupling-dashboard: %s\n", error.what());
    return kBadInput;
  } catch (const gc::InvalidInput& error) {
    std::fprintf(stderr, "gearcoupling-dashboard: %s\n", error.what());
    return kBadInput;
  }
  options.update_interval = std::chrono::milliseconds(1000 / update_hz);
  options.query_timeout = std::chrono::milliseconds(static_cast<long>(query_timeout_s * 1000));

  const sigset_t signals = gc::parallel::block_shutdown_signals();
  try {
    gc::dashboard::DashboardServer server(options);
    // The port on stdout, alone on its line, for scripts that asked for port 0.
    std::printf("listening on http://%s:%d/\n", options.listen_host.c_str(), server.port());
    std::fflush(stdout);
    spdlog::info("dashboard on domain {} at http://{}:{}/, DDS configuration: {}", options.domain,
                 options.listen_host, server.port(),
                 gc::protocol::describe(gc::protocol::dds_config()));
    std::thread signal_waiter([&server, signals] {
      int signal = 0;
      sigwait(&signals, &signal);
      server.stop();
    });
    server.run();
    pthread_kill(signal_waiter.native_handle(), SIGTERM);
    signal_waiter.join();
  } catch (const std::exception& error) {
    spdlog::error("{}", error.what());
    return 1;
  }
  return 0;
}
