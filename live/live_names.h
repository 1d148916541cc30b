// Names of the live test-cell topics (docs/protocol.md, "The live test cell").
#pragma once

#include <string_view>

namespace gc::live {

inline constexpr const char* kMeasurementTopic = "gearcoupling/live/measurement";
inline constexpr const char* kResidualTopic = "gearcoupling/live/residual";
inline constexpr const char* kHealthTopic = "gearcoupling/live/health";
inline constexpr const char* kModelTopic = "gearcoupling/live/model";
inline constexpr const char* kLivePartition = "gearcoupling.live";

/// Most samples in one MeasurementBatch.
inline constexpr std::size_t kMaxBatchSamples = 4096;

/// Throws InvalidInput naming "test_cell" unless `name` is 1 to 64 characters of
/// [A-Za-z0-9._-] (it names a DDS instance, a file and a dashboard panel).
void require_test_cell_name(std::string_view name);

}  // namespace gc::live
