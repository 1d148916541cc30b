#include "live/live_names.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/model_error.h"

namespace gc::live {

void require_test_cell_name(std::string_view name) {
  const auto allowed = [](unsigned char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           c == '.' || c == '_' || c == '-';
  };
  if (name.empty() || name.size() > 64 || !std::all_of(name.begin(), name.end(), allowed)) {
    std::string shown;
    for (unsigned char c : name.substr(0, 64)) shown += (c >= 0x20 && c < 0x7f) ? char(c) : '?';
    throw InvalidInput("test_cell", "'" + shown + "' (" + std::to_string(name.size()) +
                                        " bytes) is not a test cell name: 1 to 64 characters "
                                        "of A-Z a-z 0-9 . _ -");
  }
}

std::string cell_partition(std::string_view test_cell) {
  require_test_cell_name(test_cell);
  return kCellPartitionPrefix + std::string(test_cell);
}

std::string operator_partition(std::string_view operator_name) {
  const auto allowed = [](unsigned char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  };
  if (operator_name.empty() || operator_name.size() > 32 || operator_name[0] == '_' ||
      operator_name[0] == '-' || !std::all_of(operator_name.begin(), operator_name.end(), allowed)) {
    throw InvalidInput("operator", "'" + std::string(operator_name.substr(0, 32)) +
                                       "' is not an operator name: 1 to 32 of a-z 0-9 _ -, "
                                       "starting with a letter or digit");
  }
  return kOperatorPartitionPrefix + std::string(operator_name);
}

std::string operator_of_identity() {
  const char* identity = std::getenv("GC_IDENTITY");
  const std::string_view prefix = kOperatorIdentityPrefix;
  if (identity == nullptr || std::string_view(identity).substr(0, prefix.size()) != prefix) return "";
  return identity + prefix.size();
}

std::string operator_identity_of(const std::vector<std::string>& writer_partitions) {
  const std::string_view prefix = kOperatorPartitionPrefix;
  for (const std::string& p : writer_partitions) {
    if (p.size() > prefix.size() && p.compare(0, prefix.size(), prefix) == 0) {
      return kOperatorIdentityPrefix + p.substr(prefix.size());
    }
  }
  return "";
}

bool partitions_speak_for(const std::vector<std::string>& writer_partitions,
                          std::string_view test_cell) {
  const std::string own = kCellPartitionPrefix + std::string(test_cell);
  return std::any_of(writer_partitions.begin(), writer_partitions.end(),
                     [&](const std::string& p) { return p == own || p == kLivePartition; });
}

}  // namespace gc::live
