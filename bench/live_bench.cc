// The live test cell under load (docs/benchmarks.md, "Live test cell"): N test cells publishing
// at R Hz each into a running gearcoupling-monitor (its pid given, for its CPU time), residuals
// read back. Reports, per run: samples published, residuals received, the monitor's counts
// (taken, evaluated, lost) from its health, publication-to-residual latency (p50, p99, max:
// from the dds_write of the batch carrying a sample to the monitor's write of its residual,
// CLOCK_REALTIME on one host) and the monitor's CPU share (utime + stime over wall time, of one
// core). bench/live_bench.sh starts the monitor and runs this for each batching.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>
#include <unistd.h>
#include <vector>

#include "analysis/recording_csv.h"
#include "gearcoupling.h"
#include "clients/status/cell_board.h"
#include "live/live_qos.h"
#include "live/live_topics.h"
#include "live/measurement_publisher.h"
#include "live/model_swap_publisher.h"
#include "protocol/samples.h"

namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t realtime_ns() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::system_clock::now().time_since_epoch()).count());
}

// utime + stime of `pid` [s].
double cpu_seconds(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  std::istringstream fields(text.substr(text.rfind(')') + 2));
  std::string field;
  double ticks = 0.0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14 || i == 15) ticks += std::stod(field);
  }
  return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

struct Cell {
  std::string name;
  std::vector<std::uint64_t> written_ns;   // by sequence number - 1
};

// One test cell at `rate_hz` for `count` samples: batches of what is due every `batch_us`
// (0: one sample per DDS sample).
void publish_cell(dds_entity_t participant, Cell& cell, const std::vector<gc::RecordedSample>& samples,
                  std::uint64_t count, double rate_hz, int batch_us, Clock::time_point start) {
  gc::live::MeasurementPublisher publisher(participant, cell.name);
  publisher.wait_for_readers(1, std::chrono::seconds(10));
  std::this_thread::sleep_until(start);
  std::uint64_t first_unwritten = 0;
  const auto flush = [&](std::uint64_t upto) {
    const std::uint64_t now = realtime_ns();   // before the write: a preempted write counts
    publisher.flush();
    for (; first_unwritten < upto; ++first_unwritten) cell.written_ns[first_unwritten] = now;
  };
  Clock::time_point next_flush = start;
  for (std::uint64_t i = 0; i < count; ++i) {
    // The recording's values, stamped at this stream's own rate: the derived inputs (rates over
    // the last 0.5 s) see the 5000 samples a 10 kHz stream has in their window.
    gc::RecordedSample sample = samples[i % samples.size()];
    sample.input.time_s = static_cast<double>(i) / rate_hz;
    const auto due = start + std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double>(static_cast<double>(i) / rate_hz));
    if (batch_us == 0 || due >= next_flush) {
      if (i > first_unwritten) flush(i);
      std::this_thread::sleep_until(due);
      next_flush = due + std::chrono::microseconds(batch_us);
    }
    publisher.add(sample);
  }
  flush(count);
}

double percentile(std::vector<double>& values, double p) {
  if (values.empty()) return 0.0;
  const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(p * static_cast<double>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
  return values[k];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("live test-cell benchmark (docs/benchmarks.md)");
  int domain = 0, cells = 4, monitor_pid = 0, batch_us = 1000;
  double rate_hz = 10000.0, seconds = 10.0;
  app.add_option("--domain", domain);
  app.add_option("--cells", cells)->check(CLI::Range(1, 64));
  app.add_option("--rate", rate_hz, "samples per second per cell");
  app.add_option("--seconds", seconds);
  app.add_option("--batch-us", batch_us, "publish what is due every this many us; 0: one sample a message");
  app.add_option("--monitor-pid", monitor_pid)->required();
  int swap_ms = 0;
  app.add_option("--swap-ms", swap_ms, "swap every cell's model every this many ms (0: never)");
  CLI11_PARSE(app, argc, argv);

  const auto samples = gc::analysis::read_recording(GC_SOURCE_DIR "/data/recordings/paper_torque_ramp.csv").samples;
  gc::protocol::Entity participant = gc::live::make_participant(domain);
  gc::protocol::Entity subscriber = gc::live::make_live_subscriber(participant.get());
  gc::protocol::Entity topic = gc::live::make_residual_topic(participant.get());
  gc::protocol::Qos qos;
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_ALL, 0);
  gc::protocol::Entity reader(dds_create_reader(subscriber.get(), topic.get(), qos.get(), nullptr));
  gc::status::CellBoardOptions health_options;
  health_options.read_residuals = false;  // read below, sample by sample
  health_options.max_cells = 4096;
  gc::status::CellBoard health(participant.get(), health_options);

  const auto count = static_cast<std::uint64_t>(rate_hz * seconds);
  std::vector<Cell> cell_list(static_cast<std::size_t>(cells));
  std::map<std::string, Cell*> by_name;
  for (int c = 0; c < cells; ++c) {
    cell_list[static_cast<std::size_t>(c)] = {fmt::format("bench-{}-{}", getpid(), c), std::vector<std::uint64_t>(count, 0)};
    by_name[cell_list[static_cast<std::size_t>(c)].name] = &cell_list[static_cast<std::size_t>(c)];
  }
  std::vector<std::pair<Cell*, std::pair<std::uint64_t, std::uint64_t>>> received;  // (cell, (seq, published_ns))
  received.reserve(count * static_cast<std::size_t>(cells));
  std::atomic<bool> reading{true};
  std::thread residual_reader([&] {
    while (reading) {
      gc::protocol::LoanedSamples<gearcoupling_ResidualBatch, 64> batches(reader.get());
      if (batches.size() == 0) {
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        continue;
      }
      for (std::size_t i = 0; i < batches.size(); ++i) {
        if (!batches.info(i).valid_data) continue;
        Cell* cell = by_name.at(batches[i].test_cell);
        for (std::uint32_t k = 0; k < batches[i].residuals._length; ++k) {
          received.push_back({cell, {batches[i].residuals._buffer[k].sequence_number, batches[i].published_ns}});
        }
      }
    }
  });
  std::this_thread::sleep_for(std::chrono::seconds(2));  // discovery
  const Clock::time_point start = Clock::now() + std::chrono::milliseconds(500);
  std::vector<std::thread> publishers;
  for (Cell& cell : cell_list) {
    publishers.emplace_back(publish_cell, participant.get(), std::ref(cell), std::cref(samples), count, rate_hz, batch_us, start);
  }
  // Model swaps during the run: the paper's model and one with mu 0.12, in turn, to every cell.
  std::atomic<bool> swapping{swap_ms > 0};
  std::uint64_t swaps_published = 0;
  std::thread swapper([&] {
    if (!swapping) return;
    std::vector<std::string> cell_names;
    for (const Cell& cell : cell_list) cell_names.push_back(cell.name);
    gc::live::ModelSwapPublisher swaps(participant.get(), cell_names);
    swaps.wait_for_readers(1, std::chrono::seconds(10));
    std::ifstream paper_file(GC_SOURCE_DIR "/data/models/paper.textproto");
    const std::string paper((std::istreambuf_iterator<char>(paper_file)), std::istreambuf_iterator<char>());
    std::string other = paper;
    other.replace(other.find("name: \"paper\""), 14, "name: \"mu012\"");
    other.replace(other.find("value: 0.1 "), 11, "value: 0.12 ");
    std::this_thread::sleep_until(start);
    while (swapping) {
      for (const Cell& cell : cell_list) swaps.publish(cell.name, swaps_published % 2 == 0 ? other : paper);
      ++swaps_published;
      std::this_thread::sleep_for(std::chrono::milliseconds(swap_ms));
    }
  });
  std::this_thread::sleep_until(start);
  const double cpu_before = cpu_seconds(monitor_pid);
  const Clock::time_point wall_before = Clock::now();
  for (std::thread& t : publishers) t.join();
  swapping = false;
  swapper.join();
  const double cpu_after = cpu_seconds(monitor_pid);
  const double wall_s = std::chrono::duration<double>(Clock::now() - wall_before).count();
  std::this_thread::sleep_for(std::chrono::seconds(2));
  reading = false;
  residual_reader.join();

  std::vector<double> latency_us;
  std::map<std::uint64_t, std::vector<double>> by_second;   // latency by second of the run
  latency_us.reserve(received.size());
  const std::uint64_t first_ns = cell_list.front().written_ns.front();
  for (const auto& [cell, entry] : received) {
    const std::uint64_t written = cell->written_ns[entry.first - 1];
    latency_us.push_back((static_cast<double>(entry.second) - static_cast<double>(written)) / 1e3);
    by_second[(written - std::min(written, first_ns)) / 1000000000ull].push_back(latency_us.back());
  }
  for (auto& [second, values] : by_second) {
    fmt::print("  second {}: p50 {:.0f} us, p99 {:.0f} us\n", second, percentile(values, 0.5),
               percentile(values, 0.99));
  }
  std::uint64_t taken = 0, evaluated = 0, lost = 0;
  for (const Cell& cell : cell_list) {
    const auto h = health.wait_for(cell.name, [&](const gc::status::HealthView& v) { return v.taken >= count; },
                                   std::chrono::seconds(5));
    if (h) {
      taken += h->taken;
      evaluated += h->evaluated;
      lost += h->lost;
    }
  }
  const std::uint64_t published = count * static_cast<std::uint64_t>(cells);
  fmt::print("cells {} x {} Hz for {:.1f} s, batch every {} us, {} model swaps per cell: "
             "published {}, monitor took {}, evaluated {}, lost {}, residuals received {}\n",
             cells, rate_hz, wall_s, batch_us, swaps_published, published, taken, evaluated, lost,
             received.size());
  const double p50 = percentile(latency_us, 0.50), p99 = percentile(latency_us, 0.99),
               max = latency_us.empty() ? 0.0 : *std::max_element(latency_us.begin(), latency_us.end());
  fmt::print("publication to residual: p50 {:.0f} us, p99 {:.0f} us, max {:.0f} us; monitor CPU "
             "{:.2f} s in {:.2f} s = {:.0f} % of one core\n",
             p50, p99, max, cpu_after - cpu_before, wall_s, 100.0 * (cpu_after - cpu_before) / wall_s);
  return taken == published && evaluated == published && lost == 0 && received.size() == published ? 0 : 1;
}
