// Compiled by tests/packaging/pkg_config_test.sh with only
// `pkg-config --cflags --libs gearcoupling-client` against the installed package (no Cyclone
// flags: the client's header needs none). Run with CYCLONEDDS_URI unset on a domain with no
// service: the call times out, and the error names the installed Cyclone configuration, which
// the installed library found beside itself.
//   pkg_config_client DOMAIN EXPECTED_CONFIGURATION_URI
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "client/client.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: pkg_config_client DOMAIN EXPECTED_CONFIGURATION_URI\n");
    return 2;
  }
  gc::client::Client client({.domain = std::atoi(argv[1]), .timeout = std::chrono::milliseconds(300)});
  try {
    client.call<gc::protocol::Calculation::kJamAngle>({gc::protocol::CatalogueName{"nrel_upwind"}});
  } catch (const gc::client::Timeout& timeout) {
    std::printf("%s\n", timeout.what());
    return std::string(timeout.what()).find(std::string("DDS configuration: ") + argv[2] +
                                            " (installed") == std::string::npos;
  }
  std::fprintf(stderr, "pkg_config_client: a service answered on a domain that should have none\n");
  return 1;
}
