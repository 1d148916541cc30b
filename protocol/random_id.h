// Ids for clients and service instances: 64 random bits, never 0.
#pragma once

#include <cstdint>

namespace gc::protocol {

/// A fresh non-zero id from std::random_device (so two processes started in the same
/// microsecond still differ).
std::uint64_t random_id();

}  // namespace gc::protocol
