// gearcoupling-monitor: flags, logging and signals; live::Monitor does the rest
// (docs/architecture.md, "The live test cell").
#include <pthread.h>
#include <signal.h>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <thread>

#include "codec/bundled_data.h"
#include "codec/coupling_catalog.h"
#include "core/model_error.h"
#include "live/monitor.h"
#include "parallel/shutdown_signals.h"
#include "protocol/dds_config.h"

namespace {

constexpr const char* kConfigHelp =
    "read flags from FILE (TOML: `name = value` a line, the long flag without --, e.g. `domain = "
    "0`, `cell = [\"dyno1=paper\"]`); flags on the command line win. Its unit reads "
    "/etc/gearcoupling/monitor.conf";

gc::live::MonitorOptions parse_flags(CLI::App& app, int argc, char** argv, std::string& log_level) {
  gc::live::MonitorOptions o;
  o.models_dir = gc::codec::bundled_data_dir("models");
  o.catalog_dir = gc::codec::default_catalog_dir();
  std::vector<std::string> cell_models;
  app.set_version_flag("--version", "gearcoupling-monitor " GC_VERSION);
  app.set_config("--config", "", kConfigHelp);
  app.allow_config_extras(false);  // a misspelt name in the file is an error, not ignored
  app.add_option("--domain", o.domain, "DDS domain id")->capture_default_str();
  app.add_option("--model", o.default_model,
                 "model of every test cell not named by --cell: a .textproto file, or a name in "
                 "data/models")->capture_default_str();
  app.add_option("--cell", cell_models, "CELL=MODEL: test cell CELL's model (repeatable)");
  app.add_option("--catalogue", o.catalog_dir, "coupling catalogue directory")->capture_default_str();
  app.add_option("--window-s,--window", o.cell.window_s, "health window in measurement time [s]")
      ->check(CLI::Range(1e-3, 1e6))->capture_default_str();
  app.add_option("--reference-torque-nm,--reference-torque", o.cell.reference_torque_nm,
                 "T_ref of the worst-region wording [N·m]")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--loading-dead-band-rad,--loading-dead-band", o.cell.loading_dead_band_rad,
                 "dead band of the loading direction [rad]")->check(CLI::NonNegativeNumber)->capture_default_str();
  app.add_option("--health-period-s,--health-period", o.health_period_s, "health publication period [s]")
      ->check(CLI::Range(0.01, 3600.0))->capture_default_str();
  app.add_option("--stale-s,--stale", o.stale_s, "health stale after this long without samples [s]")
      ->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--dispose-s,--dispose", o.dispose_s, "health disposed after this long without samples [s]")
      ->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--decimate", o.decimation, "publish one residual per N evaluated samples")
      ->check(CLI::Range(1u, 1000000u))->capture_default_str();
  app.add_option("--max-cells", o.max_cells,
                 "test cells followed at once besides those of --cell; a new one beyond it is "
                 "refused and counted until a followed one is disposed")
      ->check(CLI::Range(std::size_t{1}, std::size_t{4096}))->capture_default_str();
  bool no_diagnosis = false;
  app.add_flag("--no-diagnosis", no_diagnosis,
               "never diagnose nor propose models (the learning loop off)");
  app.add_option("--diagnose-after-s", o.learning.diagnose_after_s,
                 "diagnose a test cell whose error stays beyond the noise this long (wall clock) [s]")
      ->check(CLI::Range(0.0, 86400.0))->capture_default_str();
  app.add_option("--rediagnose-s", o.learning.rediagnose_s,
                 "a test cell's next diagnosis no sooner than this after the last [s]")
      ->check(CLI::Range(0.0, 86400.0))->capture_default_str();
  app.add_option("--recheck-s", o.learning.recheck_s,
                 "recheck a standing proposal on newer samples this often; withdrawn when they "
                 "contradict it [s]")->check(CLI::Range(0.1, 86400.0))->capture_default_str();
  app.add_option("--diagnosis-samples", o.cell.diagnosis_samples,
                 "a test cell's rolling window for the diagnosis: at most this many samples")
      ->check(CLI::Range(std::size_t{400}, std::size_t{100000}))->capture_default_str();
  app.add_option("--diagnosis-window-s", o.cell.diagnosis_window_s,
                 "the rolling window spans at least this much measurement time (thinned to "
                 "--diagnosis-samples) [s]")->check(CLI::Range(1e-3, 1e6))->capture_default_str();
  app.add_option("--diagnosis-queue", o.learning.queue,
                 "diagnoses waiting at most (one runs at a time, at --diagnosis-nice)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{4096}))->capture_default_str();
  app.add_option("--diagnosis-cpu-share", o.learning.cpu_share,
                 "the diagnosis thread's CPU at most, as a share of one core (it sleeps between "
                 "its loops in proportion)")->check(CLI::Range(0.01, 1.0))->capture_default_str();
  app.add_option("--diagnosis-nice", o.learning.nice,
                 "nice value of the diagnosis thread; 19 runs it under SCHED_IDLE (the monitor's own "
                 "thread keeps its priority)")
      ->check(CLI::Range(0, 19))->capture_default_str();
  // systemd's StateDirectory=gearcoupling sets STATE_DIRECTORY=/var/lib/gearcoupling: the unit
  // needs no flag (deploy/gearcoupling-monitor.service).
  if (const char* state_directory = std::getenv("STATE_DIRECTORY")) o.state_dir = state_directory;
  app.add_option("--state-dir", o.state_dir,
                 "directory of the audit trail of model swaps (swap_audit.log, kept across "
                 "restarts; \"\" keeps it in memory only); default $STATE_DIRECTORY, which "
                 "systemd's StateDirectory= sets, else \"\"")->capture_default_str();
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}))->capture_default_str();
  app.parse(argc, argv);
  o.learning.enabled = !no_diagnosis;
  for (const std::string& item : cell_models) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size()) {
      throw CLI::ValidationError("--cell", "'" + item + "' is not CELL=MODEL");
    }
    o.cell_models[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  sigset_t signals = gc::parallel::block_shutdown_signals();
  // SIGHUP makes a new participant (a new CRL, docs/security.md); blocked like the others.
  sigaddset(&signals, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  spdlog::set_default_logger(spdlog::stderr_color_mt("gearcoupling-monitor"));
  spdlog::set_pattern("%Y-%m-%dT%H:%M:%S.%e %^%l%$ %v");
  spdlog::flush_on(spdlog::level::info);
  CLI::App app("gearcoupling-monitor: the model against live test-cell measurements over DDS "
               "(docs/protocol.md, \"The live test cell\")");
  gc::live::MonitorOptions options;
  std::string log_level = "info";
  try {
    options = parse_flags(app, argc, argv, log_level);
  } catch (const CLI::ParseError& e) {
    // --help is exit 0; a bad flag is bad input, exit 2 as everywhere in gearcoupling.
    return app.exit(e) == 0 ? 0 : 2;
  }
  spdlog::set_level(spdlog::level::from_str(log_level));
  try {
    // SIGHUP: a new Monitor, so a new participant. Its followed cells start afresh (health
    // windows restart, as after a restart); model swaps come back from their publishers
    // (TRANSIENT_LOCAL), models given by --cell and --model stay.
    for (bool reload = true; reload;) {
      reload = false;
      gc::live::Monitor monitor(options);
      spdlog::info("monitor {:016x} on domain {}, model {} by default, window {} s, DDS "
                   "configuration: {}",
                   monitor.monitor_id(), options.domain, options.default_model,
                   options.cell.window_s, gc::protocol::describe(gc::protocol::dds_config()));
      if (options.state_dir.empty()) {
        spdlog::warn("no --state-dir: the audit trail of model swaps is kept in memory only, "
                     "a restart forgets it");
      }
      std::thread waiter([&] {
        int signal = 0;
        sigwait(&signals, &signal);
        if (signal == SIGHUP) {
          spdlog::info("SIGHUP: making a new participant (the identity, the CRL and the "
                       "permissions are read again)");
          reload = true;
        } else {
          spdlog::info("signal {}: stopping", signal);
        }
        monitor.stop();
      });
      // If run() throws, the process ends at once: the waiter must not make that a terminate().
      struct DetachIfThrown {
        std::thread& thread;
        ~DetachIfThrown() { if (thread.joinable()) thread.detach(); }
      } guard{waiter};
      monitor.run();
      waiter.join();
    }
    return 0;
  } catch (const gc::ModelError& e) {
    spdlog::error("{}", e.what());
    return 2;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}
