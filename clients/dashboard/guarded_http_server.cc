#include "clients/dashboard/guarded_http_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <string>

namespace gc::dashboard {
namespace {

using Clock = std::chrono::steady_clock;

void address_of(const sockaddr_storage& address, std::string& ip, int& port) {
  char text[INET6_ADDRSTRLEN] = "";
  if (address.ss_family == AF_INET) {
    const auto& v4 = reinterpret_cast<const sockaddr_in&>(address);
    inet_ntop(AF_INET, &v4.sin_addr, text, sizeof text);
    port = ntohs(v4.sin_port);
  } else if (address.ss_family == AF_INET6) {
    const auto& v6 = reinterpret_cast<const sockaddr_in6&>(address);
    inet_ntop(AF_INET6, &v6.sin6_addr, text, sizeof text);
    port = ntohs(v6.sin6_port);
  }
  ip = text;
}

/// The stream httplib reads the request from and writes the answer to. Until the answer's first
/// write the request is being read: each read waits at most read_timeout, and not beyond the
/// deadline; then the peer's place in the guard is given back.
class DeadlineStream final : public httplib::Stream {
 public:
  /// `counted`: the connection holds one of its peer's places in the guard until its request is read.
  DeadlineStream(socket_t sock, ConnectionGuard& guard, std::string peer, bool counted)
      : sock_(sock), guard_(guard), peer_(std::move(peer)),
        deadline_(Clock::now() + guard.limits().request_timeout), counted_(counted) {}
  ~DeadlineStream() override {
    header_read();
    if (current_ == this) current_ = nullptr;
  }

  /// The stream this thread serves now (one connection a thread).
  static thread_local DeadlineStream* current_;

  /// The peer's place is given back; the deadline still holds until the answer begins.
  void header_read() {
    if (!counted_) return;
    counted_ = false;
    guard_.end_reading(peer_);
  }

  bool is_readable() const override { return wait(POLLIN, read_wait()); }
  bool is_writable() const override { return wait(POLLOUT, guard_.limits().write_timeout); }

  ssize_t read(char* ptr, size_t size) override {
    if (begin_ == end_) {
      if (!wait(POLLIN, read_wait())) {
        if (reading_ && !timed_out_) {
          timed_out_ = true;
          guard_.count_timeout();
        }
        return -1;
      }
      ssize_t n;
      do n = ::recv(sock_, buffer_, sizeof buffer_, 0); while (n < 0 && errno == EINTR);
      if (n <= 0) return n;
      begin_ = 0;
      end_ = static_cast<std::size_t>(n);
    }
    const std::size_t taken = std::min(size, end_ - begin_);
    std::copy_n(buffer_ + begin_, taken, ptr);
    begin_ += taken;
    return static_cast<ssize_t>(taken);
  }

  ssize_t write(const char* ptr, size_t size) override {
    request_read();
    if (!is_writable()) return -1;
    ssize_t n;
    do n = ::send(sock_, ptr, size, MSG_NOSIGNAL); while (n < 0 && errno == EINTR);
    return n;
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (::getpeername(sock_, reinterpret_cast<sockaddr*>(&address), &length) == 0) address_of(address, ip, port);
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (::getsockname(sock_, reinterpret_cast<sockaddr*>(&address), &length) == 0) address_of(address, ip, port);
  }
  socket_t socket() const override { return sock_; }

 private:
  /// The request is read (the answer begins) or the connection ends: no deadline any more.
  void request_read() {
    header_read();
    reading_ = false;
  }
  std::chrono::milliseconds read_wait() const {
    if (!reading_) return guard_.limits().read_timeout;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - Clock::now());
    return std::max(std::chrono::milliseconds(0), std::min(left, guard_.limits().read_timeout));
  }
  bool wait(short events, std::chrono::milliseconds timeout) const {
    pollfd fd{sock_, events, 0};
    int n;
    do n = ::poll(&fd, 1, static_cast<int>(timeout.count())); while (n < 0 && errno == EINTR);
    return n > 0 && (fd.revents & (events | POLLHUP | POLLERR)) != 0;
  }

  socket_t sock_;
  ConnectionGuard& guard_;
  std::string peer_;
  Clock::time_point deadline_;
  bool counted_, reading_ = true, timed_out_ = false;
  char buffer_[4096];
  std::size_t begin_ = 0, end_ = 0;
};

thread_local DeadlineStream* DeadlineStream::current_ = nullptr;

std::string peer_of(socket_t sock) {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  std::string ip;
  int port = 0;
  if (::getpeername(sock, reinterpret_cast<sockaddr*>(&address), &length) == 0) address_of(address, ip, port);
  return ip;
}

/// Whether the connection's whole request is already waiting in its socket: a head (at most
/// httplib's 8 kB) that has ended and announces no body. Such a connection is no longer sending,
/// so it takes none of its peer's places: its thread is busy for the answer only, as a counted
/// connection's is once read. (A burst of complete requests from one address, a proxy's or a
/// loaded client's, is served; a connection still sending its head or a body is not.)
bool whole_request_arrived(socket_t sock) {
  char head[CPPHTTPLIB_HEADER_MAX_LENGTH];
  const ssize_t n = ::recv(sock, head, sizeof head, MSG_PEEK | MSG_DONTWAIT);
  if (n <= 0) return false;
  std::string text(head, static_cast<std::size_t>(n));
  const std::size_t end = text.find("\r\n\r\n");
  if (end == std::string::npos) return false;
  text.resize(end + 2);
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (text.find("\ntransfer-encoding:") != std::string::npos) return false;
  const std::size_t length = text.find("\ncontent-length:");
  if (length == std::string::npos) return true;
  if (text.find("\ncontent-length:", length + 1) != std::string::npos) return false;   // two: not ours to judge
  const std::size_t value = text.find_first_not_of(" \t", length + 16);
  return value != std::string::npos && text.compare(value, 3, "0\r\n") == 0;
}

void close_socket(socket_t sock) {
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
}

}  // namespace

bool GuardedHttpServer::process_and_close_socket(socket_t sock) {
  const std::string peer = peer_of(sock);
  const bool counted = guard_.begin_reading(peer);
  if (!counted && !whole_request_arrived(sock)) {
    // Told, not just dropped, so a proxy or a user sees why; without waiting for the request.
    static constexpr char kTooMany[] =
        "HTTP/1.1 429 Too Many Requests\r\nRetry-After: 5\r\nContent-Length: 0\r\n"
        "Connection: close\r\n\r\n";
    guard_.count_peer_limit();
    ::send(sock, kTooMany, sizeof kTooMany - 1, MSG_NOSIGNAL | MSG_DONTWAIT);
    close_socket(sock);
    return false;
  }
  bool ok = false;
  {
    DeadlineStream stream(sock, guard_, peer, counted);
    DeadlineStream::current_ = &stream;
    bool closed = false;
    // One request per connection (keep-alive off, as set_keep_alive_max_count(1) did).
    ok = process_request(stream, /*close_connection=*/true, closed, nullptr);
  }
  close_socket(sock);
  return ok;
}

void GuardedHttpServer::widen_backlog(int backlog) {
  const socket_t sock = svr_sock_;
  if (sock != INVALID_SOCKET) ::listen(sock, backlog);   // Linux takes a new length for a listening socket
}

void GuardedHttpServer::header_read() {
  if (DeadlineStream::current_ != nullptr) DeadlineStream::current_->header_read();
}

}  // namespace gc::dashboard
