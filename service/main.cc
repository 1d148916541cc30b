// gearcoupling-service: configuration, logging, the catalogue, signals; Service does the rest.
#include <malloc.h>
#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "codec/coupling_catalog.h"
#include "core/model_error.h"
#include "parallel/shutdown_signals.h"
#include "protocol/dds_config.h"
#include "protocol/dds_entity.h"
#include "protocol/names.h"
#include "service/service.h"
#include "service/service_config.h"

int main(int argc, char** argv) {
  // Allocations of 128 kB and more are mmapped and go back to the system when freed, always.
  // glibc otherwise raises that threshold to the size of the first such block freed, and the
  // service frees some with every reply domain it replaces (Cyclone's receive buffers, 1 MiB
  // each; service/reply_domain.h): later ones then come from the heap and fragment it. With
  // clients coming and going ten a second, resident memory rose 4.8 MiB in 200 s without this
  // and stayed within 1.2 MiB with it (docs/benchmarks.md, "Soak").
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  // Fixing that threshold also fixes the trim threshold at glibc's 128 kB: a worker's arena gave
  // its free top back to the kernel after nearly every batch (issue 40) and took it again, page
  // by page, while computing the next: half a worker's CPU in page faults (0.9 s of system time
  // per 200,000 load cases, 0.1 s with this). At most 8 MB stay free at an arena's top; the
  // peak resident memory of that run was the same (33 MB).
  mallopt(M_TRIM_THRESHOLD, 8 * 1024 * 1024);
  sigset_t signals = gc::parallel::block_shutdown_signals();
  // SIGHUP re-creates the participant (a new CRL); blocked like the shutdown signals.
  sigaddset(&signals, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  auto logger = spdlog::stderr_color_mt("gearcoupling-service");
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("%Y-%m-%dT%H:%M:%S.%e %^%l%$ %v");

  gc::service::ServiceCommand command;
  try {
    command = gc::service::parse_service_command(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const gc::ModelError& e) {
    std::fprintf(stderr, "gearcoupling-service: %s\n\n%s", e.what(),
                 gc::service::service_usage().c_str());
    return 2;
  }
  if (command.bash_completion) {
    std::fputs(gc::service::service_bash_completion().c_str(), stdout);
    return 0;
  }
  if (command.help || command.version) {
    std::fputs(command.help ? gc::service::service_usage().c_str()
                            : gc::service::service_version().c_str(),
               stdout);
    return 0;
  }
  const gc::service::ServiceConfig& config = command.config;
  spdlog::set_level(spdlog::level::from_str(config.log_level));
  spdlog::flush_on(spdlog::level::info);

  try {
    // CYCLONEDDS_URI, else the installed configuration (docs/deploy.md, "Which Cyclone
    // configuration"); chosen once, so that a reload keeps it.
    const gc::protocol::DdsConfig dds = gc::protocol::dds_config();
    const std::filesystem::path catalogue_dir = config.catalogue_dir.empty()
                                                    ? gc::codec::default_catalog_dir()
                                                    : std::filesystem::path(config.catalogue_dir);
    spdlog::info("config: domain={} threads={} catalogue_dir={} log_level={} status_interval={}s "
                 "stats_interval={}s lease={}s reply_match_timeout={}s reply_block={}s departed_hold={}s "
                 "shutdown_grace={}s deadline={}s "
                 "DDS configuration: {}",
                 config.domain, config.threads, catalogue_dir.string(), config.log_level,
                 config.status_interval_s, config.stats_log_interval_s, config.liveliness_lease_s,
                 config.reply_match_timeout_s, config.reply_block_s, config.departed_hold_s,
                 config.shutdown_grace_s, config.calculation_deadline_s,
                 gc::protocol::describe(dds));
    if (dds.source == gc::protocol::DdsConfigSource::kCycloneDefault) {
      spdlog::warn("no CYCLONEDDS_URI and no installed etc/gearcoupling/cyclonedds.xml: Cyclone's "
                   "defaults apply (every interface, multicast); deploy/cyclonedds-loopback.xml "
                   "keeps DDS on loopback");
    }
    const gc::service::Catalogue catalogue(gc::codec::load_coupling_catalog(catalogue_dir));
    // SIGHUP: a new Service, so a new participant (docs/security.md, "Revoking an identity").
    for (int generation = 0;; ++generation) {
      const auto made = std::chrono::steady_clock::now();
      gc::service::Service service(config, catalogue, dds);
      if (generation > 0) {
        spdlog::info("reloaded: new participant, instance {} ({:.0f} ms to make it)",
                     gc::protocol::hex_id(service.instance_id()),
                     std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - made)
                         .count());
      }
      std::atomic<bool> reload{false};
      std::thread signal_waiter([&service, &reload, signals] {
        int signal = 0;
        sigwait(&signals, &signal);
        if (signal == SIGHUP) {
          spdlog::info("received SIGHUP: making a new participant (the identity, the CRL and the "
                       "permissions are read again)");
          reload = true;
          service.request_reload();
          return;
        }
        if (signal != SIGUSR1) spdlog::info("received signal {}", signal);
        service.request_stop();
      });
      service.run();
      // run() returned without a signal only if it failed; wake the waiter either way.
      if (!reload) pthread_kill(signal_waiter.native_handle(), SIGTERM);
      signal_waiter.join();
      if (!reload) break;
    }
  } catch (const gc::ModelError& e) {
    spdlog::error("cannot start: {}", e.what());
    return 1;
  } catch (const std::exception& e) {
    spdlog::error("cannot start: {}", e.what());
    return 1;
  }
  return 0;
}
