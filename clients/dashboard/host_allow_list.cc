#include "clients/dashboard/host_allow_list.h"

#include <arpa/inet.h>

#include <algorithm>
#include <cctype>

namespace gc::dashboard {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

/// The name of "name", "name:port", "[v6]", "[v6]:port"; "" when malformed.
std::string name_of(std::string_view host) {
  if (!host.empty() && host.front() == '[') {
    const std::size_t close = host.find(']');
    if (close == std::string_view::npos) return "";
    const std::string_view rest = host.substr(close + 1);
    if (!rest.empty() && rest.front() != ':') return "";
    return std::string(host.substr(1, close - 1));
  }
  const std::size_t colon = host.find(':');
  if (colon != host.rfind(':')) return "";   // a bare v6 address is written in brackets
  return std::string(host.substr(0, colon));
}

bool ip_literal(const std::string& name) {
  unsigned char buffer[16];
  return inet_pton(AF_INET, name.c_str(), buffer) == 1 || inet_pton(AF_INET6, name.c_str(), buffer) == 1;
}

}  // namespace

HostAllowList::HostAllowList(std::string listen_host, std::vector<std::string> names) {
  names_.push_back("localhost");
  names_.push_back(lower(listen_host));
  for (const std::string& name : names) names_.push_back(lower(name));
}

bool HostAllowList::host_allowed(std::string_view host) const {
  const std::string name = lower(name_of(host));
  if (name.empty()) return false;
  if (ip_literal(name)) return true;
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

bool HostAllowList::origin_allowed(std::string_view origin) const {
  for (std::string_view scheme : {"http://", "https://"}) {
    if (origin.substr(0, scheme.size()) != scheme) continue;
    const std::string_view rest = origin.substr(scheme.size());
    if (rest.find('/') != std::string_view::npos) return false;   // an origin has no path
    return host_allowed(rest);
  }
  return false;
}

std::string HostAllowList::describe() const {
  std::string out;
  std::vector<std::string> shown;
  for (const std::string& name : names_) {
    if (name.empty() || ip_literal(name) ||
        std::find(shown.begin(), shown.end(), name) != shown.end()) {
      continue;
    }
    shown.push_back(name);
    out += (out.empty() ? "" : ", ") + name;
  }
  return out + (out.empty() ? "" : " or ") + "an IP address";
}

}  // namespace gc::dashboard
