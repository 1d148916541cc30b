// Ids for clients and service instances: 64 random bits, never 0.
#pragma once

#include <cstdint>

namespace gc::protocol {

/// A fresh non-zero id from std::random_device (so two processes started in the same
/// microsecond still differ).
std::uint64_t random_id();

/// `prefix` in the top 32 bits and 32 random non-zero bits below; random_id() when `prefix` is
/// 0. A client's DDS Security permissions allow it the reply partitions of ids with its
/// certificate's prefix only (docs/security.md).
std::uint64_t random_id_with_prefix(std::uint32_t prefix);

}  // namespace gc::protocol
