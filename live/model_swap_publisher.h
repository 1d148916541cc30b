// Publishes ModelSwap samples (a model file's text for a test cell) on the model topic, as a
// dashboard, a script or `gearcoupling swap-model` does.
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "protocol/dds_entity.h"

namespace gc::live {

class ModelSwapPublisher {
 public:
  /// One writer per test cell of `test_cells`, each in that cell's own partition
  /// (cell_partition): under DDS Security an operator identity may create writers only for the
  /// cells it is granted (creating another fails, NOT_ALLOWED_BY_SECURITY). Throws InvalidInput
  /// naming "test_cell" for a bad name.
  /// `user_data`, "by=WHO;source=WHAT", goes in every writer's USER_DATA: the monitor's audit
  /// trail names who swapped and from what (a proposal, a file); "" says nothing.
  /// `operator_name` NAME (an operator identity operator-NAME, live::operator_of_identity())
  /// puts every writer in partition operator_partition(NAME) too, which under DDS Security only
  /// that identity's grant allows: the audit trail then names it, authenticated (live_names.h).
  /// When the permissions do not allow it (made by a make-security.sh before it), the writers
  /// are made without it, and a warning says so. Throws InvalidInput naming "operator" for a
  /// bad name.
  ModelSwapPublisher(dds_entity_t participant, const std::vector<std::string>& test_cells,
                     const std::string& user_data = "", const std::string& operator_name = "");
  /// Publishes `model_text` (empty: only the decimation) for `test_cell`, one of the
  /// constructor's; `residual_decimation` 0 keeps the monitor's. Throws InvalidInput naming
  /// "test_cell" for a bad name or one not given to the constructor.
  void publish(const std::string& test_cell, const std::string& model_text,
               std::uint32_t residual_decimation = 0);
  /// Waits until every cell's writer has at least `readers` matched readers.
  bool wait_for_readers(std::uint32_t readers, std::chrono::milliseconds timeout) const;

 private:
  struct CellWriter {
    protocol::Entity publisher, writer;
  };
  protocol::Entity topic_;
  std::map<std::string, CellWriter> writers_;
};

}  // namespace gc::live
