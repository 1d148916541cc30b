#include "tests/service/scaled_coupling.h"

#include <cmath>

#include "codec/coupling_catalog.h"

namespace gc::test {

CouplingDefinition scaled_coupling(int teeth) {
  CouplingDefinition d = codec::load_coupling_catalog(codec::default_catalog_dir())
                             .at("nrel_upwind")
                             .definition();
  const double addendum = d.outer_diameter_m - d.pitch_diameter_m;
  const double dedendum = d.pitch_diameter_m - d.root_diameter_m;
  d.name = "scaled";
  d.teeth = teeth;
  d.pitch_diameter_m = d.teeth * d.module_m;
  d.base_diameter_m = d.pitch_diameter_m * std::cos(d.pressure_angle_rad);
  d.outer_diameter_m = d.pitch_diameter_m + addendum;
  d.root_diameter_m = d.pitch_diameter_m - dedendum;
  d.sleeve_root_diameter_m.reset();
  return d;
}

}  // namespace gc::test
