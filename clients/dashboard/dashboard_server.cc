#include "clients/dashboard/dashboard_server.h"

#include <stdexcept>

#include <fmt/format.h>

#include "analysis/validation_report_html.h"
#include "clients/status/prometheus_text.h"
#include "clients/status/status_messages.h"
#include "clients/status/status_metrics.h"
#include "codec/result_json.h"
#include "dashboard_page_html.h"  // kDashboardPageHtml, generated from dashboard_page.html

#include <httplib.h>  // last: its <resolv.h> defines `_res`, which Eigen's headers use

namespace gc::dashboard {
namespace {

/// How long an event stream waits for an update before it sends a comment line: a browser (or
/// proxy) that sees nothing for a long time may think the connection dead.
constexpr std::chrono::milliseconds kKeepAlive{2000};
/// httplib serves each connection on a pool thread, and an event stream holds its thread: room
/// for a few dozen browsers at once plus page, metrics and query requests.
constexpr std::size_t kHttpThreads = 64;

client::ClientOptions query_client_options(const DashboardOptions& options) {
  client::ClientOptions client;
  client.domain = options.domain;
  client.timeout = options.query_timeout;
  client.client_id_prefix = options.client_id_prefix;
  return client;
}

std::map<std::string, std::string> parameters_of(const httplib::Request& request) {
  std::map<std::string, std::string> parameters;
  for (const auto& [name, value] : request.params) parameters[name] = value;
  return parameters;
}

}  // namespace

DashboardServer::DashboardServer(DashboardOptions options)
    : options_(std::move(options)),
      chart_js_(analysis::chart_js()),
      participant_(protocol::check_dds(
          dds_create_participant(static_cast<dds_domainid_t>(options_.domain), nullptr, nullptr),
          "dds_create_participant")),
      instances_(participant_.get()),
      cells_(participant_.get()),
      query_(query_client_options(options_)),
      hub_(options_.queue_capacity),
      http_(std::make_unique<httplib::Server>()) {
  http_->new_task_queue = [] { return new httplib::ThreadPool(kHttpThreads); };
  add_routes();
  port_ = options_.listen_port == 0 ? http_->bind_to_any_port(options_.listen_host)
                                    : (http_->bind_to_port(options_.listen_host,
                                                          options_.listen_port)
                                           ? options_.listen_port
                                           : -1);
  if (port_ < 0) {
    throw std::runtime_error(fmt::format("--listen {}:{}: cannot listen there (in use, or not an "
                                         "address of this host)",
                                         options_.listen_host, options_.listen_port));
  }
  publisher_ = std::thread([this] { publish_loop(); });
}

DashboardServer::~DashboardServer() {
  stop();
  if (publisher_.joinable()) publisher_.join();
}

void DashboardServer::run() { http_->listen_after_bind(); }

void DashboardServer::stop() {
  stopping_ = true;
  hub_.close();
  http_->stop();
}

void DashboardServer::add_routes() {
  http_->Get("/", [](const httplib::Request&, httplib::Response& response) {
    response.set_content(std::string(kDashboardPageHtml), "text/html; charset=utf-8");
  });
  http_->Get("/chart.js", [this](const httplib::Request&, httplib::Response& response) {
    response.set_header("Cache-Control", "max-age=3600");
    response.set_content(chart_js_, "text/javascript; charset=utf-8");
  });
  http_->Get("/api/state", [this](const httplib::Request&, httplib::Response& response) {
    response.set_content(state_json(false), "application/json");
  });
  http_->Get("/metrics", [this](const httplib::Request&, httplib::Response& response) {
    response.set_content(metrics(), "text/plain; version=0.0.4; charset=utf-8");
  });
  http_->Get("/api/query", [this](const httplib::Request& request, httplib::Response& response) {
    const JsonAnswer answer = query_.answer(parameters_of(request));
    response.status = answer.status;
    response.set_content(answer.body, "application/json");
  });
  http_->Get("/events", [this](const httplib::Request&, httplib::Response& response) {
    std::shared_ptr<EventQueue> queue = hub_.subscribe();
    response.set_header("Cache-Control", "no-cache");
    response.set_chunked_content_provider(
        "text/event-stream",
        [queue](std::size_t, httplib::DataSink& sink) {
          const std::shared_ptr<const std::string> event = queue->pop(kKeepAlive);
          const std::string text = event ? "data: " + *event + "\n\n" : std::string(": alive\n\n");
          // A closed hub (shutdown) ends the stream; a failed write means the browser went.
          return !(event == nullptr && queue->closed()) && sink.write(text.data(), text.size());
        },
        [this, queue](bool) { hub_.unsubscribe(queue); });
  });
}

void DashboardServer::publish_loop() {
  auto next = std::chrono::steady_clock::now();
  while (!stopping_) {
    next += options_.update_interval;
    std::string state = state_json(true);
    if (hub_.subscribers() > 0) {
      hub_.publish(std::move(state));
      updates_published_ += 1;
    }
    std::this_thread::sleep_until(next);
  }
}

std::string DashboardServer::state_json(bool drain) {
  return codec::to_compact_json(status::to_message(
      instances_.snapshot(), drain ? cells_.drain() : cells_.snapshot()));
}

std::string DashboardServer::metrics() {
  std::string text = status::metrics_text(instances_.snapshot(), cells_.snapshot());
  status::PrometheusText own;
  own.family("gearcoupling_dashboard_connections", "gauge",
             "Browsers connected to the dashboard's event stream.");
  own.sample("gearcoupling_dashboard_connections", {}, static_cast<double>(hub_.subscribers()));
  own.family("gearcoupling_dashboard_updates_total", "counter",
             "Live updates published to the connected browsers.");
  own.sample("gearcoupling_dashboard_updates_total", {}, static_cast<double>(updates_published_));
  own.family("gearcoupling_dashboard_updates_dropped_total", "counter",
             "Updates dropped for browsers that read too slowly (their oldest first).");
  own.sample("gearcoupling_dashboard_updates_dropped_total", {}, static_cast<double>(hub_.dropped()));
  return text + own.text();
}

}  // namespace gc::dashboard
