// Text the user wrote that is not in the expected format: a batch CSV header, an --add effect
// spec. The message names what was written and what is accepted; the CLI exits with 2, as for
// a bad flag.
#pragma once

#include <stdexcept>

namespace gc::analysis {

class FormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace gc::analysis
