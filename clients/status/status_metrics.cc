#include "clients/status/status_metrics.h"

#include <cmath>

#include "clients/status/model_health.h"
#include "clients/status/prometheus_text.h"
#include "protocol/names.h"

namespace gc::status {
namespace {

/// "service_instance", not "instance": Prometheus sets "instance" to the scrape target (this
/// dashboard) and would rename ours "exported_instance".
Labels instance_labels(const InstanceView& instance) {
  return {{"service_instance", protocol::hex_id(instance.info.id)}, {"host", instance.info.host}};
}

Labels calculation_labels(const InstanceView& instance, const client::CalculationStatus& c) {
  Labels labels = instance_labels(instance);
  labels.emplace_back("calculation", c.calculation);
  return labels;
}

void instance_gauges(const std::vector<InstanceView>& instances, PrometheusText& out) {
  out.family("gearcoupling_instance_up", "gauge",
             "1 while the service instance's status is fresh, 0 once stale or stopped.");
  for (const InstanceView& i : instances) {
    out.sample("gearcoupling_instance_up", instance_labels(i), i.liveness == Liveness::kAlive);
  }
  out.family("gearcoupling_instance_accepting", "gauge",
             "1 while the instance accepts new requests (0 while it shuts down).");
  for (const InstanceView& i : instances) {
    out.sample("gearcoupling_instance_accepting", instance_labels(i), i.info.accepting);
  }
  out.family("gearcoupling_instance_uptime_seconds", "gauge",
             "Seconds since the instance started, as of its latest status.");
  for (const InstanceView& i : instances) {
    out.sample("gearcoupling_instance_uptime_seconds", instance_labels(i), i.info.uptime_s);
  }
  out.family("gearcoupling_instance_status_age_seconds", "gauge",
             "Seconds since the instance's latest status sample arrived.");
  for (const InstanceView& i : instances) {
    out.sample("gearcoupling_instance_status_age_seconds", instance_labels(i), i.status_age_s);
  }
}

/// One counter family over every instance's calculations: `count` of each.
void calculation_counter(const std::vector<InstanceView>& instances, std::string_view name,
                         std::string_view help, std::uint64_t client::CalculationStatus::*count,
                         PrometheusText& out) {
  out.family(name, "counter", help);
  for (const InstanceView& i : instances) {
    for (const auto& c : i.info.calculations) {
      out.sample(name, calculation_labels(i, c), static_cast<double>(c.*count));
    }
  }
}

void request_counters(const std::vector<InstanceView>& instances, PrometheusText& out) {
  calculation_counter(instances, "gearcoupling_requests_served_total",
                      "Requests answered with STATUS_OK, per instance and calculation.",
                      &client::CalculationStatus::served, out);
  calculation_counter(instances, "gearcoupling_requests_refused_total",
                      "Requests whose input the service refused (invalid input, unknown "
                      "coupling): the client's, not failures of the service.",
                      &client::CalculationStatus::refused, out);
  calculation_counter(instances, "gearcoupling_requests_failed_total",
                      "Requests the service failed (not converged, model or internal error, "
                      "deadline exceeded), per instance and calculation.",
                      &client::CalculationStatus::failed, out);
}

/// Quantiles over the instance's last 4096 requests (NaN while none came, as the format says
/// of an empty summary), _sum and _count over every request since it started.
void service_time_summary(const std::vector<InstanceView>& instances, PrometheusText& out) {
  constexpr std::string_view kName = "gearcoupling_service_time_seconds";
  out.family(kName, "summary",
             "Service time per request: quantiles over the instance's last (up to) 4096 "
             "requests, sum and count since it started.");
  for (const InstanceView& i : instances) {
    for (const auto& c : i.info.calculations) {
      for (const auto& [quantile, seconds] :
           {std::pair{"0.5", c.p50_service_time_s}, std::pair{"0.99", c.p99_service_time_s}}) {
        Labels labels = calculation_labels(i, c);
        labels.emplace_back("quantile", quantile);
        out.sample(kName, labels, c.called() ? seconds : std::nan(""));
      }
      out.sample("gearcoupling_service_time_seconds_sum", calculation_labels(i, c),
                 c.service_time_sum_s);
      out.sample("gearcoupling_service_time_seconds_count", calculation_labels(i, c),
                 static_cast<double>(c.served + c.failed + c.refused));
    }
  }
}

Labels cell_labels(const v1::TestCellRecord& cell) { return {{"test_cell", cell.test_cell()}}; }

void cell_gauges(const std::vector<v1::TestCellRecord>& cells, PrometheusText& out) {
  out.family("gearcoupling_cell_up", "gauge",
             "1 while the monitor reports the test cell alive, 0 once stale or gone.");
  for (const auto& cell : cells) out.sample("gearcoupling_cell_up", cell_labels(cell), cell.state() == "alive");
  out.family("gearcoupling_cell_model_info", "gauge",
             "1, labelled by the model in force for the test cell (none before its health).");
  for (const auto& cell : cells) {
    if (!cell.has_model() || cell.model().model_name().empty()) continue;
    Labels labels = cell_labels(cell);
    labels.emplace_back("model", cell.model().model_name());
    out.sample("gearcoupling_cell_model_info", labels, 1.0);
  }
  out.family("gearcoupling_cell_model_health", "gauge",
             "1 for the test cell's model health (the dashboard's badge: at_noise_level, "
             "systematic, far_off, unit_error, unknown; stale once the cell is stale or gone: its last "
             "health is no news), 0 for the others.");
  for (const auto& cell : cells) {
    const bool alive = cell.state() == "alive";
    for (const ModelHealth health : {ModelHealth::unknown, ModelHealth::at_noise_level, ModelHealth::systematic,
                                     ModelHealth::far_off, ModelHealth::unit_error}) {
      Labels labels = cell_labels(cell);
      labels.emplace_back("health", std::string(to_string(health)));
      out.sample("gearcoupling_cell_model_health", labels, alive && cell.model_health() == to_string(health));
    }
    Labels labels = cell_labels(cell);
    labels.emplace_back("health", "stale");
    out.sample("gearcoupling_cell_model_health", labels, !alive);
  }
}

/// The learning loop per cell (live/learning_status.h): 1 for its state, and what it lacks.
void cell_learning(const std::vector<v1::TestCellRecord>& cells, PrometheusText& out) {
  out.family("gearcoupling_cell_learning_state", "gauge",
             "1, labelled by what the monitor's learning loop does for the test cell (waiting_for_"
             "samples, too_few_samples_in_window, beyond_noise, diagnosis_running, proposed, "
             "found_nothing, unit_error, ...; docs/dashboard.md).");
  for (const auto& cell : cells) {
    if (cell.learning_state().empty()) continue;
    Labels labels = cell_labels(cell);
    labels.emplace_back("state", cell.learning_state());
    out.sample("gearcoupling_cell_learning_state", labels, 1.0);
  }
  out.family("gearcoupling_cell_learning_samples_missing", "gauge",
             "Samples the test cell's rolling window still lacks before a diagnosis can run.");
  for (const auto& cell : cells) {
    out.sample("gearcoupling_cell_learning_samples_missing", cell_labels(cell),
               static_cast<double>(cell.learning_samples_missing()));
  }
  out.family("gearcoupling_cell_sample_rate_hertz", "gauge",
             "Evaluated samples per second of measurement time over the monitor's window [Hz].");
  for (const auto& cell : cells) {
    out.sample("gearcoupling_cell_sample_rate_hertz", cell_labels(cell), cell.sample_rate_hz());
  }
  out.family("gearcoupling_cell_unit_slip_batches_total", "counter",
             "Measurement batches evaluated while the window's moments were 1000 times the "
             "model's: a unit error (kN·m sent as N·m), not a model error.");
  for (const auto& cell : cells) {
    out.sample("gearcoupling_cell_unit_slip_batches_total", cell_labels(cell),
               static_cast<double>(cell.counts().unit_slip_batches()));
  }
}

void cell_counters(const std::vector<v1::TestCellRecord>& cells, PrometheusText& out) {
  out.family("gearcoupling_cell_samples_taken_total", "counter",
             "Measurement samples the monitor received for the test cell.");
  for (const auto& cell : cells) {
    out.sample("gearcoupling_cell_samples_taken_total", cell_labels(cell),
               static_cast<double>(cell.counts().taken()));
  }
  out.family("gearcoupling_cell_samples_evaluated_total", "counter",
             "Samples compared with the test cell's model.");
  for (const auto& cell : cells) {
    out.sample("gearcoupling_cell_samples_evaluated_total", cell_labels(cell),
               static_cast<double>(cell.counts().evaluated()));
  }
  out.family("gearcoupling_cell_samples_refused_total", "counter",
             "Samples refused, by reason (not_finite, by_model, out_of_order).");
  for (const auto& cell : cells) {
    const v1::SampleCountsRecord& c = cell.counts();
    for (const auto& [reason, count] :
         {std::pair{"not_finite", c.refused_not_finite()}, std::pair{"by_model", c.refused_by_model()},
          std::pair{"out_of_order", c.refused_out_of_order()}}) {
      Labels labels = cell_labels(cell);
      labels.emplace_back("reason", reason);
      out.sample("gearcoupling_cell_samples_refused_total", labels, static_cast<double>(count));
    }
  }
  out.family("gearcoupling_cell_samples_lost_total", "counter",
             "Sequence numbers the monitor never received (gaps).");
  for (const auto& cell : cells) {
    out.sample("gearcoupling_cell_samples_lost_total", cell_labels(cell),
               static_cast<double>(cell.counts().lost()));
  }
}

/// `value` of each channel's health, labelled channel="msy" / "msz".
template <typename Value>
void channel_gauge(const std::vector<v1::TestCellRecord>& cells, std::string_view name,
                   std::string_view help, Value value, PrometheusText& out) {
  out.family(name, "gauge", help);
  for (const auto& cell : cells) {
    for (const auto& [channel, health] :
         {std::pair{"msy", &cell.model().msy()}, std::pair{"msz", &cell.model().msz()}}) {
      Labels labels = cell_labels(cell);
      labels.emplace_back("channel", channel);
      out.sample(name, labels, value(*health));
    }
  }
}

void cell_errors(const std::vector<v1::TestCellRecord>& cells, PrometheusText& out) {
  channel_gauge(cells, "gearcoupling_cell_rmse_newton_metres",
                "Rolling RMSE of the model's moment over the monitor's window [N m].",
                [](const v1::ChannelHealthRecord& h) { return h.rmse_nm(); }, out);
  channel_gauge(cells, "gearcoupling_cell_bias_newton_metres",
                "Mean error of the model's moment (model - measured) over the window [N m].",
                [](const v1::ChannelHealthRecord& h) { return h.bias_nm(); }, out);
  channel_gauge(cells, "gearcoupling_cell_noise_newton_metres",
                "Noise level of the measured moment over the window [N m].",
                [](const v1::ChannelHealthRecord& h) { return h.noise_nm(); }, out);
  channel_gauge(cells, "gearcoupling_cell_systematic_error_newton_metres",
                "Part of the RMSE above the noise, sqrt(rmse^2 - noise^2) [N m].",
                [](const v1::ChannelHealthRecord& h) { return h.systematic_nm(); }, out);
}

}  // namespace

std::string metrics_text(const std::vector<InstanceView>& instances,
                         const std::vector<v1::TestCellRecord>& cells) {
  PrometheusText out;
  instance_gauges(instances, out);
  request_counters(instances, out);
  service_time_summary(instances, out);
  cell_gauges(cells, out);
  cell_counters(cells, out);
  cell_learning(cells, out);
  cell_errors(cells, out);
  return out.text();
}

}  // namespace gc::status
