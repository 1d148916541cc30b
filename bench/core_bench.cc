// Google Benchmark of the core on the NREL upwind coupling (100 teeth): one tooth contact plus
// induced moments at 1.5 MN·m, 0.4 deg, mu 0.1 (issue 40's target: 0.5 us), returned by value
// and into a caller's ToothContact (what a loop over many points does: no allocation), with and
// without the table of teeth, the contact alone, and building a CouplingGeometry (validation plus the jam angle, eqs 23-35).
#include <cmath>
#include <string>

#include <benchmark/benchmark.h>

#include "codec/coupling_catalog.h"
#include "codec/coupling_file.h"
#include "core/coupling_geometry.h"
#include "core/induced_moments.h"
#include "core/tooth_contact.h"

namespace {

const std::string kUpwindFile = std::string(GC_BUNDLED_CATALOG_DIR) + "/nrel_upwind.textproto";

const gc::CouplingGeometry& upwind() {
  static const gc::CouplingGeometry geometry = gc::codec::load_coupling_geometry(kUpwindFile);
  return geometry;
}

constexpr gc::OperatingPoint kPoint{.torque_nm = 1.5e6,
                                    .misalignment_rad = 0.4 * M_PI / 180.0,
                                    .direction_rad = 0.0,
                                    .friction_coefficient = 0.1};

void BM_ToothContactAndInducedMoments(benchmark::State& state) {
  const gc::CouplingGeometry& coupling = upwind();
  for (auto _ : state) {
    const gc::ToothContact contact = gc::tooth_contact(coupling, kPoint);
    benchmark::DoNotOptimize(gc::induced_moments(coupling, kPoint, contact));
  }
}
BENCHMARK(BM_ToothContactAndInducedMoments);

void BM_ToothContactAndInducedMomentsIntoOneContact(benchmark::State& state) {
  const gc::CouplingGeometry& coupling = upwind();
  const gc::ContactOptions options;
  gc::ToothContact contact;
  for (auto _ : state) {
    gc::tooth_contact(coupling, kPoint, options, contact);
    benchmark::DoNotOptimize(gc::induced_moments(coupling, kPoint, contact));
  }
}
BENCHMARK(BM_ToothContactAndInducedMomentsIntoOneContact);

// A load case as batch, the service's load cases and Python's induced_moments_many need it: the
// contact's summary (q, loads, zones at the edge, stress) and the moments, without the table of
// N teeth (list_teeth() derives it on request): induced_moments(coupling, point, options, contact).
void BM_ToothContactWithoutTeethAndInducedMoments(benchmark::State& state) {
  const gc::CouplingGeometry& coupling = upwind();
  const gc::ContactOptions options;
  for (auto _ : state) {
    gc::ToothContact contact;
    benchmark::DoNotOptimize(gc::induced_moments(coupling, kPoint, options, contact));
  }
}
BENCHMARK(BM_ToothContactWithoutTeethAndInducedMoments);

void BM_ToothContactWithoutTeethAndInducedMomentsIntoOneContact(benchmark::State& state) {
  const gc::CouplingGeometry& coupling = upwind();
  const gc::ContactOptions options;
  gc::ToothContact contact;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gc::induced_moments(coupling, kPoint, options, contact));
  }
}
BENCHMARK(BM_ToothContactWithoutTeethAndInducedMomentsIntoOneContact);

void BM_ToothContact(benchmark::State& state) {
  const gc::CouplingGeometry& coupling = upwind();
  for (auto _ : state) benchmark::DoNotOptimize(gc::tooth_contact(coupling, kPoint));
}
BENCHMARK(BM_ToothContact);

// CouplingGeometry's constructor validates the definition and solves eq 23 for the jam angle.
void BM_JamAngleGeometryConstruction(benchmark::State& state) {
  const gc::CouplingDefinition definition = gc::codec::load_coupling_file(kUpwindFile);
  for (auto _ : state) {
    const gc::CouplingGeometry geometry(definition);
    benchmark::DoNotOptimize(geometry.jam_angle().angle_rad);
  }
}
BENCHMARK(BM_JamAngleGeometryConstruction);

}  // namespace

BENCHMARK_MAIN();
