// validate's terminal output: per model and channel the error metrics, the worst region of
// every input in words, the samples the model refused, the rows excluded from the file, the
// columns ignored and the scale warnings.
// Several models (before/after) print side by side, one row each.
#pragma once

#include <cstdio>

#include "idl/validation.pb.h"

namespace gc::analysis {

/// A region is named where its RMSE is at least this many times that of the rest of the
/// recording (validate's summary, the monitor's health).
inline constexpr double kNotableContrast = 1.2;

void print_validation_summary(const gearcoupling::v1::ValidationResult& result, std::FILE* out);

/// The recording's ignored columns and scale warnings (analysis/scale_check.h), when any; the
/// diagnosis summary prints them too.
void print_input_notes(const google::protobuf::RepeatedPtrField<std::string>& warnings,
                       const google::protobuf::RepeatedPtrField<std::string>& ignored_columns,
                       std::FILE* out);

}  // namespace gc::analysis
