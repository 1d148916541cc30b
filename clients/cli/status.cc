// gearcoupling status: the service instances and live test cells of a DDS domain, like
// `ros2 topic echo` for the status topic (clients/status/status_report.h does the work).
#include <csignal>

#include <fmt/format.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "clients/cli/subcommand.h"
#include "clients/status/status_report.h"

namespace gc::cli {
namespace {

volatile std::sig_atomic_t interrupted = 0;

std::vector<FlagSpec> status_flags() {
  FlagSpec catalogue = catalogue_flag();
  catalogue.refused = "not taken by status: it shows the instances' own catalogues";
  return {
      domain_flag("DDS domain to report on (the network: CYCLONEDDS_URI)"),
      {"watch", "", "report again every --interval-s until Ctrl-C (or --count reports)",
       std::nullopt, true},
      {"interval-s", "s", "seconds between reports, with --watch, [0.1, 3600]", "1", false, '\0',
       {"interval"}},
      {"count", "N", "with --watch: stop after N reports (0: until Ctrl-C)", "0"},
      {"discovery-s", "s", "seconds to discover the domain before the first report, [0, 60]",
       "1.5", false, '\0', {"discovery"}},
      json_flag(),
      catalogue,
  };
}

/// Flag `name` in seconds, within [lo, hi], as milliseconds; UsageError naming it otherwise.
std::chrono::milliseconds seconds_flag(const Flags& flags, std::string_view name, double lo,
                                       double hi) {
  const double seconds = flags.number(name);
  if (!(seconds >= lo && seconds <= hi)) {
    throw UsageError(fmt::format("--{} {} is out of range: allowed {} to {} s", name,
                                 flags.text(name), lo, hi));
  }
  return std::chrono::milliseconds(static_cast<long>(seconds * 1000.0));
}

int run_status(const Flags& flags, const Calculator&, std::FILE* out) {
  status::StatusReportOptions options;
  options.domain = domain_from(flags);
  options.json = flags.enabled("json");
  options.watch = flags.enabled("watch");
  options.interval = seconds_flag(flags, "interval-s", 0.1, 3600.0);
  options.discovery = seconds_flag(flags, "discovery-s", 0.0, 60.0);
  options.count = static_cast<unsigned>(flags.integer("count", 0, 1000000));
  // The boards warn (once) when they refuse instances or cells beyond their caps: on stderr,
  // so that --json keeps one JSON object a line on stdout.
  if (spdlog::get("gearcoupling-status") == nullptr) {
    spdlog::set_default_logger(spdlog::stderr_color_mt("gearcoupling-status"));
  }
  interrupted = 0;
  std::signal(SIGINT, [](int) { interrupted = 1; });
  return status::print_status(options, out, [] { return interrupted != 0; });
}

}  // namespace

const Subcommand& status_subcommand() {
  static const Subcommand subcommand{
      "status",
      "The service instances and live test cells of a DDS domain (--domain).\n"
      "Each instance's catalogue, whether it accepts requests, requests served and failed and\n"
      "p50/p99 per calculation, alive/stale/stopped; each test cell's health. --json prints one\n"
      "JSON object a report (idl/live_status.proto), the dashboard's data.",
      status_flags, run_status};
  return subcommand;
}

}  // namespace gc::cli
