#include "clients/status/status_report.h"

#include <thread>

#include <fmt/format.h>

#include "clients/status/cell_board.h"
#include "clients/status/instance_board.h"
#include "clients/status/learning_table.h"
#include "clients/status/monitor_board.h"
#include "clients/status/status_messages.h"
#include "clients/status/status_table.h"
#include "codec/result_json.h"
#include "protocol/dds_entity.h"

namespace gc::status {
namespace {

/// Sleeps `duration` in short steps, returning early (true) when `stop` says so.
bool sleep_unless_stopped(std::chrono::milliseconds duration, const std::function<bool()>& stop) {
  const auto until = std::chrono::steady_clock::now() + duration;
  while (std::chrono::steady_clock::now() < until) {
    if (stop()) return true;
    std::this_thread::sleep_for(std::min<std::chrono::milliseconds>(
        std::chrono::milliseconds(50),
        std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now())));
  }
  return stop();
}

void print_once(InstanceBoard& instances, CellBoard& cells, MonitorBoard& monitors, bool json,
                std::FILE* out) {
  if (json) {
    v1::LiveStatus status = to_message(instances.snapshot(), cells.drain());
    add_learning(monitors.monitors(), monitors.proposals(), status);
    fmt::print(out, "{}\n", codec::to_compact_json(status));
  } else {
    print_instances(instances.snapshot(), out);
    print_cells(cells.snapshot(), out);
    print_learning(monitors.monitors(), monitors.proposals(), out);
  }
  std::fflush(out);
}

}  // namespace

int print_status(const StatusReportOptions& options, std::FILE* out,
                 const std::function<bool()>& stop) {
  const protocol::Entity participant(
      protocol::create_participant(options.domain, protocol::dds_config()));
  InstanceBoard instances(participant.get());
  CellBoard cells(participant.get());
  MonitorBoard monitors(participant.get());
  if (sleep_unless_stopped(options.discovery, stop)) return 0;
  for (unsigned report = 1;; ++report) {
    if (options.watch && !options.json && report > 1) fmt::print(out, "\n");
    print_once(instances, cells, monitors, options.json, out);
    if (!options.watch || (options.count > 0 && report >= options.count)) return 0;
    if (sleep_unless_stopped(options.interval, stop)) return 0;
  }
}

}  // namespace gc::status
