// validate's terminal output: per model and channel the error metrics, the worst region of
// every input in words, the samples the model refused and the rows excluded from the file.
// Several models (before/after) print side by side, one row each.
#pragma once

#include <cstdio>

#include "idl/validation.pb.h"

namespace gc::analysis {

void print_validation_summary(const gearcoupling::v1::ValidationResult& result, std::FILE* out);

}  // namespace gc::analysis
