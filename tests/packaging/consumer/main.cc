// A downstream program built against the installed package: one jam angle through
// gearcoupling-service with gearcoupling::client, checked against the same core run in process
// on the catalogue installed with the package (gearcoupling::codec finds it).
//   consumer DOMAIN     (CYCLONEDDS_URI set by the caller; exit 0 when the answers agree)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "client/client.h"
#include "codec/coupling_catalog.h"
#include "core/jam_angle.h"

int main(int argc, char** argv) {
  using gc::protocol::Calculation;
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer DOMAIN\n");
    return 2;
  }
  try {
    gc::client::Client client({.domain = std::atoi(argv[1]), .timeout = std::chrono::seconds(30)});
    const gc::protocol::JamAngleResult remote =
        client.call<Calculation::kJamAngle>({gc::protocol::CatalogueName{"nrel_upwind"}});

    const auto catalogue_dir = gc::codec::default_catalog_dir();
    const gc::JamAngle local =
        gc::codec::load_coupling_catalog(catalogue_dir).at("nrel_upwind").jam_angle();

    const double remote_deg = remote.jam.angle_rad * 180.0 / M_PI;
    std::printf("catalogue %s\njam angle nrel_upwind: %.6f deg (service), %.6f deg (in process)\n",
                catalogue_dir.c_str(), remote_deg, local.angle_rad * 180.0 / M_PI);
    // The service runs the same core on the same file: bit for bit. 0.7509 deg: eq 23 with the
    // derived crown radius (tests/core/jam_angle_test.cc).
    if (remote.jam.angle_rad != local.angle_rad || std::abs(remote_deg - 0.7509) > 5e-4) {
      std::fprintf(stderr, "consumer: the answers disagree\n");
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
