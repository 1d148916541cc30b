// httplib's server with ConnectionGuard's limits on every connection (connection_guard.h):
// httplib 0.11 reads a request with a timeout per read only, so a byte every few seconds keeps
// a thread for ever; this server reads each request through a stream of its own with a deadline
// for the whole request and a per-peer count. Includes httplib.h: not for files that include
// Eigen (its <resolv.h> defines `_res`).
#pragma once

#include <httplib.h>

#include "clients/dashboard/connection_guard.h"

namespace gc::dashboard {

class GuardedHttpServer : public httplib::Server {
 public:
  explicit GuardedHttpServer(ConnectionGuard& guard) : guard_(guard) {}

  /// From the pre-routing handler (on the connection's thread): the request's header is read,
  /// so the peer's place among those sending is free again; its body, if any, must still come
  /// before the deadline.
  static void header_read();

  /// After a bind: the kernel's queue of connections not yet accepted, `backlog` long. httplib
  /// listens with 5, so a host that reconnects as fast as it is refused fills it, and another
  /// host's connection waits for TCP's retransmission (1 s, then 3 s) instead of its turn.
  void widen_backlog(int backlog);

 private:
  bool process_and_close_socket(socket_t sock) override;

  ConnectionGuard& guard_;
};

}  // namespace gc::dashboard
