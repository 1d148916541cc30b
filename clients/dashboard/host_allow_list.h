// Which Host and Origin the dashboard answers (issue 38, finding 4): a page of another site
// whose name an attacker re-points at this dashboard's address (DNS rebinding) is, to the
// browser, of the attacker's origin, and sends the attacker's name as Host and Origin. Only the
// dashboard's own names are answered: an IP literal (no DNS, so no rebinding), "localhost",
// the address it listens on, and the names given with --allow-host.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gc::dashboard {

class HostAllowList {
 public:
  /// `listen_host` as given to --listen; `names`: --allow-host (e.g. "dyno-hall.example").
  HostAllowList(std::string listen_host, std::vector<std::string> names);

  /// Whether a Host header ("name", "name:port", "[v6]:port", "1.2.3.4:8080") names this
  /// dashboard. Names compare without case; the port is not checked (a rebinding page is on
  /// the dashboard's port anyway).
  bool host_allowed(std::string_view host) const;
  /// Whether an Origin header ("http://name:port") is of a name host_allowed accepts; "null"
  /// and anything not of that form are not.
  bool origin_allowed(std::string_view origin) const;

  /// "localhost, <listen_host>, <names...> or an IP address": for the refusal's text.
  std::string describe() const;

 private:
  std::vector<std::string> names_;   // lower case
};

}  // namespace gc::dashboard
