// Publishes ModelSwap samples (a model file's text for a test cell) on the model topic, as a
// dashboard, a script or `gearcoupling swap-model` does.
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstdint>
#include <string>

#include "protocol/dds_entity.h"

namespace gc::live {

class ModelSwapPublisher {
 public:
  explicit ModelSwapPublisher(dds_entity_t participant);
  /// Publishes `model_text` (empty: only the decimation) for `test_cell`; `residual_decimation`
  /// 0 keeps the monitor's. Throws InvalidInput naming "test_cell" for a bad name.
  void publish(const std::string& test_cell, const std::string& model_text,
               std::uint32_t residual_decimation = 0);
  bool wait_for_readers(std::uint32_t readers, std::chrono::milliseconds timeout) const;

 private:
  protocol::Entity publisher_, topic_, writer_;
};

}  // namespace gc::live
