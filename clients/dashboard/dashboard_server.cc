#include "clients/dashboard/dashboard_server.h"

#include <stdexcept>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "analysis/validation_report_html.h"
#include "clients/status/learning_metrics.h"
#include "clients/status/prometheus_text.h"
#include "clients/status/status_messages.h"
#include "clients/status/status_metrics.h"
#include "codec/result_json.h"
#include "dashboard_page_html.h"  // kDashboardPageHtml, generated from dashboard_page.html

// last: httplib's <resolv.h> defines `_res`, which Eigen's headers use
#include "clients/dashboard/guarded_http_server.h"

namespace gc::dashboard {
namespace {

/// How long an event stream waits for an update before it sends a comment line: a browser (or
/// proxy) that sees nothing for a long time may think the connection dead.
constexpr std::chrono::milliseconds kKeepAlive{2000};
/// What a browser beyond max_streams is told to wait before it tries again [s]; EventSource
/// reconnects by itself, after its own delay (about 3 s) when it ignores the header.
constexpr const char* kRetryAfterSeconds = "10";
/// Connections the kernel queues before they are accepted (SOMAXCONN's default, 4096, caps it).
constexpr int kListenBacklog = 1024;

client::ClientOptions query_client_options(const DashboardOptions& options) {
  client::ClientOptions client;
  client.domain = options.domain;
  client.timeout = options.query_timeout;
  client.client_id_prefix = options.client_id_prefix;
  return client;
}

status::CellBoardOptions cell_board_options(const DashboardOptions& options) {
  status::CellBoardOptions cells;
  cells.max_cells = options.max_cells;
  return cells;
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
      participant_(protocol::create_participant(options_.domain, protocol::dds_config())),
      instances_(participant_.get()),
      cells_(participant_.get(), cell_board_options(options_)),
      learning_(participant_.get(), options_.max_cells),
      applier_(participant_.get(), learning_, options_.operator_cells, options_.operator_name),
      query_(query_client_options(options_)),
      hub_(options_.queue_capacity, options_.max_streams, options_.queue_bytes),
      hosts_(options_.listen_host, options_.allow_hosts),
      guard_(options_.connections),
      http_(std::make_unique<GuardedHttpServer>(guard_)) {
  const std::size_t threads = options_.max_streams + kThreadsBesideStreams;
  http_->new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
  // One request per connection. httplib serves a connection on one thread until it closes, so a
  // kept-alive connection holds a thread for up to 5 s after each answer: a browser refused a
  // stream (or anyone) could pin the threads meant for the page and /metrics that way. A new
  // connection per request costs a dashboard (a page of three requests, a scrape every few
  // seconds) nothing measurable.
  http_->set_keep_alive_max_count(1);
  // The only body is /api/apply's few parameters: a larger one is refused (413), not read.
  http_->set_payload_max_length(64 * 1024);
  add_routes();
  port_ = options_.listen_port == 0 ? http_->bind_to_any_port(options_.listen_host)
                                    : (http_->bind_to_port(options_.listen_host,
                                                          options_.listen_port)
                                           ? options_.listen_port
                                           : -1);
  if (port_ >= 0) static_cast<GuardedHttpServer&>(*http_).widen_backlog(kListenBacklog);
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

bool DashboardServer::refuse_foreign_host(const httplib::Request& request, httplib::Response& response) {
  const std::string host = request.get_header_value("Host");
  const bool has_origin = request.has_header("Origin");
  const std::string origin = request.get_header_value("Origin");
  if (hosts_.host_allowed(host) && (!has_origin || hosts_.origin_allowed(origin))) return false;
  guard_.count_foreign_host();
  response.status = 403;
  response.set_content(
      fmt::format("{{\"error\": \"{} is not a name of this dashboard: it answers to {} "
                  "(--allow-host adds names)\"}}",
                  hosts_.host_allowed(host) ? "Origin" : "Host", hosts_.describe()),
      "application/json");
  return true;
}

void DashboardServer::add_routes() {
  // Every route: a page of another site re-pointed at this address (DNS rebinding) names its own
  // host; it gets nothing, neither the state nor an apply.
  http_->set_pre_routing_handler([this](const httplib::Request& request, httplib::Response& response) {
    GuardedHttpServer::header_read();
    return refuse_foreign_host(request, response) ? httplib::Server::HandlerResponse::Handled
                                                  : httplib::Server::HandlerResponse::Unhandled;
  });
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
  // The cell card's "apply": a POST with a header of our own, which a page of another origin
  // cannot send without a CORS preflight that this server never grants (no cross-site apply).
  http_->Post("/api/apply", [this](const httplib::Request& request, httplib::Response& response) {
    const JsonAnswer answer = request.get_header_value("X-Gearcoupling-Apply") != "1"
        ? JsonAnswer{403, "{\"error\": \"X-Gearcoupling-Apply: 1 header missing (the page sends it)\"}"}
        : applier_.apply(parameters_of(request));
    response.status = answer.status;
    response.set_content(answer.body, "application/json");
  });
  http_->Get("/events", [this](const httplib::Request&, httplib::Response& response) {
    std::shared_ptr<EventQueue> queue = hub_.subscribe();
    if (queue == nullptr) {
      refuse_stream(response);
      return;
    }
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

void DashboardServer::refuse_stream(httplib::Response& response) {
  response.status = 503;
  response.set_header("Retry-After", kRetryAfterSeconds);
  response.set_content(fmt::format("{{\"error\": \"{} event streams are open, the most this dashboard "
                                   "serves (--max-streams): try again in {} s\"}}",
                                   options_.max_streams, kRetryAfterSeconds),
                       "application/json");
  if (!stream_refusal_logged_.exchange(true)) {
    spdlog::warn("an event stream refused: {} are open, the most --max-streams allows; counted "
                 "in gearcoupling_dashboard_connections_refused_total, not logged again",
                 options_.max_streams);
  }
}

void DashboardServer::publish_loop() {
  auto next = std::chrono::steady_clock::now();
  while (!stopping_) {
    next += options_.update_interval;
    // Nobody listens: build nothing. The residual aggregates keep running on the board (bounded:
    // one per cell), and the first browser gets them in its first update.
    if (hub_.subscribers() > 0) {
      hub_.publish(state_json(true));
      updates_published_ += 1;
    }
    std::this_thread::sleep_until(next);
  }
}

std::string DashboardServer::state_json(bool drain) {
  status::v1::LiveStatus state =
      status::to_message(instances_.snapshot(), drain ? cells_.drain() : cells_.snapshot());
  status::add_learning(learning_.monitors(), learning_.proposals(), state);
  for (const std::string& cell : applier_.operator_cells()) state.add_operator_cells(cell);
  return codec::to_compact_json(state);
}

std::string DashboardServer::metrics() {
  std::string text = status::metrics_text(instances_.snapshot(), cells_.snapshot()) +
                     status::learning_metrics_text(learning_.monitors());
  status::PrometheusText own;
  own.family("gearcoupling_dashboard_connections", "gauge",
             "Browsers connected to the dashboard's event stream.");
  own.sample("gearcoupling_dashboard_connections", {}, static_cast<double>(hub_.subscribers()));
  own.family("gearcoupling_dashboard_max_connections", "gauge",
             "Browsers the event stream serves at once (--max-streams).");
  own.sample("gearcoupling_dashboard_max_connections", {}, static_cast<double>(options_.max_streams));
  own.family("gearcoupling_dashboard_connections_refused_total", "counter",
             "Event streams refused with 503 because --max-streams were open.");
  own.sample("gearcoupling_dashboard_connections_refused_total", {}, static_cast<double>(hub_.refused()));
  own.family("gearcoupling_dashboard_cells_refused_total", "counter",
             "Test-cell samples (health or residuals) ignored because --max-cells cells were on the board.");
  own.sample("gearcoupling_dashboard_cells_refused_total", {}, static_cast<double>(cells_.refused()));
  own.family("gearcoupling_dashboard_instances_refused_total", "counter",
             "Service status samples ignored because 64 live instances were on the board.");
  own.sample("gearcoupling_dashboard_instances_refused_total", {}, static_cast<double>(instances_.refused()));
  own.family("gearcoupling_dashboard_max_cells", "gauge",
             "Test cells the board holds at most (--max-cells).");
  own.sample("gearcoupling_dashboard_max_cells", {}, static_cast<double>(options_.max_cells));
  own.family("gearcoupling_dashboard_queries_total", "counter",
             "Query-panel queries by outcome: answered; refused (the user's input: a bad "
             "parameter or one the model refuses); failed (no instance answered, or DDS "
             "Security refused the panel).");
  const QueryCounts queries = query_.counts();
  for (const auto& [outcome, count] : {std::pair{"answered", queries.answered},
                                       std::pair{"refused", queries.refused},
                                       std::pair{"failed", queries.failed}}) {
    own.sample("gearcoupling_dashboard_queries_total", {{"outcome", outcome}},
               static_cast<double>(count));
  }
  own.family("gearcoupling_dashboard_http_refused_total", "counter",
             "HTTP connections and requests refused: foreign_host (a Host or Origin not of this "
             "dashboard, --allow-host), peer_limit (a peer already sending the most requests at "
             "once), timeout (a request not sent within its deadline).");
  for (const auto& [reason, count] : {std::pair{"foreign_host", guard_.refused_foreign_host()},
                                      std::pair{"peer_limit", guard_.refused_peer_limit()},
                                      std::pair{"timeout", guard_.timeouts()}}) {
    own.sample("gearcoupling_dashboard_http_refused_total", {{"reason", reason}},
               static_cast<double>(count));
  }
  own.family("gearcoupling_dashboard_updates_total", "counter",
             "Live updates published to the connected browsers.");
  own.sample("gearcoupling_dashboard_updates_total", {}, static_cast<double>(updates_published_));
  own.family("gearcoupling_dashboard_updates_dropped_total", "counter",
             "Updates dropped for browsers that read too slowly (their oldest first).");
  own.sample("gearcoupling_dashboard_updates_dropped_total", {}, static_cast<double>(hub_.dropped()));
  return text + own.text();
}

}  // namespace gc::dashboard
