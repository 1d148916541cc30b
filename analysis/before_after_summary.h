// validate --add: the model before and after the added effect, side by side per channel, overall
// and in every bin of every input (the bins of both runs are the same, diagnosis/validation/error_bins.h).
#pragma once

#include <cstdio>

#include "idl/validation.pb.h"

namespace gc::analysis {

/// Compares result.models(0) (before) with each later model (after). Nothing for one model.
void print_before_after(const gearcoupling::v1::ValidationResult& result, std::FILE* out);

}  // namespace gc::analysis
