// Test couplings of any size: nrel_upwind with `teeth` teeth of the same module and tooth, so the
// same jam angle on a proportionally larger pitch diameter.
#pragma once

#include "core/coupling_definition.h"

namespace gc::test {

/// nrel_upwind's definition with `teeth` teeth, named "scaled".
CouplingDefinition scaled_coupling(int teeth);

}  // namespace gc::test
