// libFuzzer target: a coupling file (protobuf text format, idl/coupling.proto) through
// codec::load_coupling_geometry, the function the CLI and the service's catalogue read couplings
// with: text -> CouplingDefinition -> validated CouplingGeometry (jam angle included). A
// coupling that validates is then run as `contact`, `moments` and `restoring-torque` run it.
//
// Checks: loading throws nothing but InvalidInput naming a field; an accepted coupling has a
// finite, positive jam angle; its calculations return finite results or throw InvalidInput or
// NotConverged (calculator.h).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <system_error>

#include "codec/coupling_catalog.h"
#include "core/induced_moments.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"
#include "fuzz/fuzz_checks.h"
#include "fuzz/scratch_file.h"
#include "fuzz/load_cases.h"

namespace {

void run_load_case(const gc::CouplingGeometry& coupling, const gc::OperatingPoint& point) {
  gc::fuzz::expect_result_or<gc::InvalidInput, gc::NotConverged>([&] {
    const gc::ToothContact contact = gc::tooth_contact(coupling, point, {});
    gc::fuzz::check(contact, coupling.teeth());
    gc::fuzz::check(gc::induced_moments(coupling, point, contact));
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const gc::fuzz::ScratchFile scratch("gc_coupling_fuzz", ".textproto", data, size);
  const std::filesystem::path& input = scratch.path();
  std::optional<gc::CouplingGeometry> coupling;
  gc::fuzz::expect_result_or<gc::InvalidInput>(
      [&] { coupling.emplace(gc::codec::load_coupling_geometry(input)); });
  if (!coupling) return 0;
  gc::fuzz::check(coupling->jam_angle());
  gc::fuzz::check_finite("crown_radius_m", coupling->crown_radius_m());
  gc::fuzz::check_finite("mesh_stiffness_n_per_m", coupling->mesh_stiffness_n_per_m());
  gc::fuzz::expect_result_or<gc::InvalidInput, gc::NotConverged>(
      [&] { gc::fuzz::check(gc::restoring_torque(*coupling)); });
  for (const gc::OperatingPoint& point : gc::fuzz::load_cases(*coupling)) {
    run_load_case(*coupling, point);
  }
  return 0;
}
