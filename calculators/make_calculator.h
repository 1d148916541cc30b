// The Calculator an edge asks for: in process on a catalogue directory, or gearcoupling-service
// over DDS. The edge turns its own flags into CalculatorSettings (the CLI: clients/cli/
// make_calculator.h).
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>

#include "calculators/calculator.h"

namespace gc::calculators {

struct CalculatorSettings {
  bool remote = false;                 ///< gearcoupling-service instead of the core in process
  std::filesystem::path catalog_dir;   ///< in process: the catalogue (*.textproto by name)
  int domain = 0;                      ///< remote: DDS domain id
  /// remote: the longest any call waits, discovery included.
  std::chrono::milliseconds timeout{10000};
  /// remote: `timeout` bounds every call together, from make_calculator on (a command's
  /// deadline: `--timeout-s 2` ends a command of several requests within 2 s), not each call
  /// (RemoteCalculator).
  bool timeout_is_deadline = false;
  std::uint32_t client_id_prefix = 0;  ///< remote, under DDS Security (client_id_prefix.h)
};

/// Throws std::invalid_argument for `remote` in a build without the service (GC_BUILD_SERVICE).
std::unique_ptr<Calculator> make_calculator(const CalculatorSettings& settings);

}  // namespace gc::calculators
