// Names of the live test-cell topics (docs/protocol.md, "The live test cell").
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gc::live {

inline constexpr const char* kMeasurementTopic = "gearcoupling/live/measurement";
inline constexpr const char* kResidualTopic = "gearcoupling/live/residual";
inline constexpr const char* kHealthTopic = "gearcoupling/live/health";
inline constexpr const char* kModelTopic = "gearcoupling/live/model";
/// The monitor's proposals (one per test cell) and its own status with the audit trail of swaps.
inline constexpr const char* kProposalTopic = "gearcoupling/live/proposal";
inline constexpr const char* kMonitorTopic = "gearcoupling/live/monitor";
/// Health and residuals; and measurements and model swaps of publishers older than per-cell
/// partitions (still read in plain mode; under DDS Security no grant lets anyone publish them here).
inline constexpr const char* kLivePartition = "gearcoupling.live";
/// Measurements and model swaps of test cell CELL are published in partition
/// kCellPartitionPrefix + CELL, so DDS Security can grant a cell identity, or an operator, its
/// own test cells only (permissions restrict partitions, not key values; docs/security.md).
inline constexpr const char* kCellPartitionPrefix = "gearcoupling.live.cell.";
/// What the monitor's readers ask for: every test cell's partition.
inline constexpr const char* kEveryCellPartition = "gearcoupling.live.cell.*";
/// An operator identity operator-NAME writes its model swaps also in partition
/// kOperatorPartitionPrefix + NAME, which only its DDS Security grant allows: the monitor reads
/// the writer's partitions and so learns which operator identity swapped, authenticated by the
/// access control (Cyclone 0.10's API does not give it a remote participant's certificate;
/// docs/security.md, "Who swapped: what the audit trail proves").
inline constexpr const char* kOperatorPartitionPrefix = "gearcoupling.live.operator.";
inline constexpr const char* kOperatorIdentityPrefix = "operator-";

/// Most samples in one MeasurementBatch.
inline constexpr std::size_t kMaxBatchSamples = 4096;

/// Throws InvalidInput naming "test_cell" unless `name` is 1 to 64 characters of
/// [A-Za-z0-9._-] (it names a DDS instance, a file and a dashboard panel).
void require_test_cell_name(std::string_view name);

/// "gearcoupling.live.cell.<test_cell>" (test_cell checked as require_test_cell_name).
std::string cell_partition(std::string_view test_cell);

/// "gearcoupling.live.operator.<operator_name>"; throws InvalidInput naming "operator" unless the
/// name is an identity name of deploy/security/make-security.sh (1 to 32 of a-z 0-9 _ -,
/// starting with a letter or digit).
std::string operator_partition(std::string_view operator_name);
/// NAME when $GC_IDENTITY (the DDS Security identity the configuration names) is operator-NAME,
/// else "": the operator partition a swap writer of this process adds.
std::string operator_of_identity();
/// "operator-NAME" for the first partition of `writer_partitions` that is an operator's, else "".
std::string operator_identity_of(const std::vector<std::string>& writer_partitions);

/// Whether a sample for `test_cell` may come from a writer in `writer_partitions`: its own cell's
/// partition, or the shared kLivePartition of older publishers. A writer in another test cell's
/// partition may not speak for this one.
bool partitions_speak_for(const std::vector<std::string>& writer_partitions,
                          std::string_view test_cell);

}  // namespace gc::live
