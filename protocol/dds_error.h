// The error a failed DDS call throws, without Cyclone's headers: public headers (the client's)
// name it, and a program using them need not see Cyclone's C types.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace gc::protocol {

/// A DDS call failed. what() names the call and Cyclone's return code text.
class DdsError : public std::runtime_error {
 public:
  DdsError(const std::string& call, std::int32_t code);  ///< `code`: Cyclone's return code
  std::int32_t code() const noexcept { return code_; }

 private:
  std::int32_t code_;
};

}  // namespace gc::protocol
