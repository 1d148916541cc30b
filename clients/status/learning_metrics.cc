#include "clients/status/learning_metrics.h"

#include "clients/status/prometheus_text.h"

#include <map>
#include <string>

namespace gc::status {

namespace {

using Monitor = gearcoupling::v1::MonitorRecord;

struct Counter {
  const char* name;
  const char* help;
  std::uint64_t (Monitor::*value)() const;
};

constexpr Counter kCounters[] = {
    {"gearcoupling_monitor_proposals_total", "Model proposals a monitor published (new or better).",
     &Monitor::proposals_published},
    {"gearcoupling_monitor_proposals_withdrawn_total",
     "Proposals withdrawn: later data contradicted them, or their base model was replaced.",
     &Monitor::proposals_withdrawn},
    {"gearcoupling_monitor_diagnoses_total", "Diagnoses (and rechecks) a monitor finished.",
     &Monitor::diagnoses_run},
    {"gearcoupling_monitor_swaps_total", "Model swaps a monitor took (its audit trail).",
     &Monitor::swaps},
    {"gearcoupling_monitor_cell_batches_refused_total",
     "Measurement batches of test cells beyond the monitor's --max-cells, refused.",
     &Monitor::refused_cell_batches},
    {"gearcoupling_monitor_foreign_refused_total",
     "Measurement batches and swaps written from another test cell's partition, refused.",
     &Monitor::refused_foreign},
};

}  // namespace

std::string learning_metrics_text(const std::vector<Monitor>& monitors) {
  if (monitors.empty()) return "";
  PrometheusText text;
  for (const Counter& counter : kCounters) {
    text.family(counter.name, "counter", counter.help);
    for (const Monitor& m : monitors) {
      text.sample(counter.name, {{"monitor", m.monitor_id()}}, static_cast<double>((m.*counter.value)()));
    }
  }
  text.family("gearcoupling_monitor_refusals_total", "counter",
              "Everything a monitor refused, by kind: measurement batches (bad name, oversized, "
              "another cell's partition, beyond --max-cells) and model swaps (bad name, another "
              "cell's partition, no room, a model that does not load).");
  for (const Monitor& m : monitors) {
    // Sorted by kind (a protobuf map has no order): the same text for the same counts.
    const std::map<std::string, std::uint64_t> kinds(m.refusals().begin(), m.refusals().end());
    for (const auto& [kind, count] : kinds) {
      text.sample("gearcoupling_monitor_refusals_total", {{"monitor", m.monitor_id()}, {"kind", kind}},
                  static_cast<double>(count));
    }
  }
  return text.text();
}

}  // namespace gc::status
