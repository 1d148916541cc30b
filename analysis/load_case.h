// One load case's result, as the batch CSV writes it and a Calculator returns it.
#pragma once

#include "core/induced_moments.h"
#include "core/tooth_contact.h"

namespace gc::analysis {

/// Tooth contact and the moments computed from it (eqs 5-48), for one load case.
struct LoadCase {
  ToothContact contact;
  InducedMoments moments;
};

}  // namespace gc::analysis
