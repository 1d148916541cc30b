#include "protocol/random_id.h"

#include <random>

namespace gc::protocol {

std::uint64_t random_id() {
  std::random_device device;
  std::uint64_t id = 0;
  while (id == 0) id = (std::uint64_t{device()} << 32) ^ device();
  return id;
}

std::uint64_t random_id_with_prefix(std::uint32_t prefix) {
  if (prefix == 0) return random_id();
  std::random_device device;
  std::uint32_t low = 0;
  while (low == 0) low = device();
  return (std::uint64_t{prefix} << 32) | low;
}

}  // namespace gc::protocol
