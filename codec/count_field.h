// Counts in gearcoupling.v1 messages are uint32, so that protobuf's JSON mapping writes them as
// numbers (it writes 64-bit integers as strings). A count past uint32 is refused, never wrapped.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "core/model_error.h"

namespace gc::codec {

/// `count` as a message's uint32. Throws InvalidInput naming `field` beyond 4294967295.
inline std::uint32_t count_field(std::size_t count, std::string_view field) {
  if (count > std::numeric_limits<std::uint32_t>::max()) {
    throw InvalidInput(std::string(field),
                       std::to_string(count) + " is beyond the messages' count range [0, 4294967295]");
  }
  return static_cast<std::uint32_t>(count);
}

}  // namespace gc::codec
