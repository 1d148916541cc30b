#include "clients/status/learning_metrics.h"

#include "clients/status/prometheus_text.h"

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
  return text.text();
}

}  // namespace gc::status
