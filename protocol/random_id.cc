#include "protocol/random_id.h"

#include <random>

namespace gc::protocol {

std::uint64_t random_id() {
  std::random_device device;
  std::uint64_t id = 0;
  while (id == 0) id = (std::uint64_t{device()} << 32) ^ device();
  return id;
}

}  // namespace gc::protocol
