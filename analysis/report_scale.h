// One colour scale for every error map of the HTML report. Each map coloured against its own
// worst cell painted a corrected model at the noise level (2 kN·m) as deep red as the 20 kN·m
// failure beside it; on one absolute scale, with the noise level marked, the two read apart.
#pragma once

#include "idl/validation.pb.h"

namespace gc::analysis {

/// The worst cell RMSE of every model's map, both channels [N·m]; 0 when no cell has samples.
double colour_scale_max_nm(const gearcoupling::v1::ValidationResult& result);

/// The recording's noise level [N·m]: the median of the noise estimates of every model and
/// channel that compared samples (they see the same measurement noise); 0 when none did.
double noise_level_nm(const gearcoupling::v1::ValidationResult& result);

}  // namespace gc::analysis
