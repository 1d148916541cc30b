// gearcoupling-dashboard's HTTP side: one page (dashboard_page.html) with Chart.js served from
// this process (Debian's libjs-chart.js: test-cell networks are offline), the live state as
// Server-Sent Events at most every `update_interval` (aggregated, never one event per sample),
// the same state once as JSON, /metrics in Prometheus text, and the query panel. DDS is read
// only, through the boards of gc_status, except for the query panel's requests.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "clients/dashboard/connection_guard.h"
#include "clients/dashboard/event_hub.h"
#include "clients/dashboard/host_allow_list.h"
#include "clients/dashboard/proposal_apply.h"
#include "clients/dashboard/query_panel.h"
#include "clients/status/cell_board.h"
#include "clients/status/instance_board.h"
#include "clients/status/monitor_board.h"
#include "protocol/dds_entity.h"

namespace httplib {
class Server;
struct Request;
struct Response;
}

namespace gc::dashboard {

struct DashboardOptions {
  int domain = 0;                      ///< DDS domain id [0, protocol::kMaxDomainId]
  std::string listen_host = "127.0.0.1";  ///< localhost only unless asked otherwise
  int listen_port = 8080;              ///< 0: any free port (port() says which)
  /// Live updates to the browser at most this often: 100 ms is 10 updates a second.
  std::chrono::milliseconds update_interval{100};
  /// Updates a slow browser may fall behind before its oldest is dropped.
  std::size_t queue_capacity = 16;
  /// The same in bytes: a queued update is the whole state (~650 B a test cell, 42 kB for 64,
  /// more with long refusal texts), and this keeps a browser that stopped reading from holding
  /// 16 of the largest. The newest update is always kept.
  std::size_t queue_bytes = 1 << 20;
  /// Event streams at once. Each holds one HTTP thread for as long as the browser stays, so
  /// the server runs max_streams + kThreadsBesideStreams threads: the page, /metrics and the
  /// query panel keep theirs whatever the browsers do. Beyond it: 503 with Retry-After.
  std::size_t max_streams = 32;
  /// Test cells on the board (status::CellBoardOptions::max_cells).
  std::size_t max_cells = 64;
  /// The query panel's wait for the service, discovery included.
  std::chrono::milliseconds query_timeout{5000};
  /// The query panel's client_id_prefix under DDS Security (client::ClientOptions); 0: none.
  std::uint32_t client_id_prefix = 0;
  /// Test cells whose proposals this dashboard may apply (POST /api/apply, the cell card's
  /// "apply"); empty: read-only. Under DDS Security its identity must be an operator granted
  /// them (clients/dashboard/proposal_apply.h).
  std::vector<std::string> operator_cells;
  /// The person applying proposals, as the monitor's audit trail names them (`--operator`;
  /// live::swap_operator): required with operator_cells unless the DDS Security identity is an
  /// operator's, whose name then stands instead.
  std::string operator_name;
  /// Host names (besides localhost, the listen address and IP addresses) that requests may
  /// name in Host and Origin; any other is refused 403 (DNS rebinding: host_allow_list.h).
  std::vector<std::string> allow_hosts;
  /// Deadlines and the per-peer count of connections still sending their request
  /// (connection_guard.h).
  ConnectionLimits connections;
};

class DashboardServer {
 public:
  /// Joins the domain and binds the address. Throws protocol::DdsError, or std::runtime_error
  /// naming the address when it cannot be bound or Chart.js cannot be read.
  explicit DashboardServer(DashboardOptions options);
  ~DashboardServer();
  DashboardServer(const DashboardServer&) = delete;
  DashboardServer& operator=(const DashboardServer&) = delete;

  /// HTTP threads beside the event streams' (for the page, /metrics, /api/*): a query waits up
  /// to query_timeout for the service, so a few dozen users may ask at once.
  static constexpr std::size_t kThreadsBesideStreams = 32;

  int port() const { return port_; }
  /// Serves until stop(). Call once.
  void run();
  /// From any thread: ends run(), closes the browsers' event streams.
  void stop();

 private:
  void add_routes();
  /// 403 for a Host or Origin not of this dashboard (allow_hosts): before any route runs.
  bool refuse_foreign_host(const httplib::Request& request, httplib::Response& response);
  /// Answers an event stream beyond max_streams: 503, Retry-After, the connection closed.
  void refuse_stream(httplib::Response& response);
  void publish_loop();
  /// The whole live state as compact JSON; `drain` takes the residual aggregates since the last
  /// drain (only the publisher does, so every interval's aggregate goes out once).
  std::string state_json(bool drain);
  std::string metrics();

  DashboardOptions options_;
  std::string chart_js_;
  protocol::Entity participant_;
  status::InstanceBoard instances_;
  status::CellBoard cells_;
  status::MonitorBoard learning_;   // proposals, the monitors' refusals and audit trail
  ProposalApplier applier_;
  QueryPanel query_;
  EventHub hub_;
  HostAllowList hosts_;
  ConnectionGuard guard_;
  // Behind a pointer: httplib.h includes <resolv.h>, whose `_res` macro breaks Eigen's headers
  // in any file that includes both.
  std::unique_ptr<httplib::Server> http_;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::atomic<std::uint64_t> updates_published_{0};
  std::atomic<bool> stream_refusal_logged_{false};
  std::thread publisher_;
};

}  // namespace gc::dashboard
