// An input error whose message the codec writes whole, in the file's terms (the file, its field
// names and units, both fields of a consistency check), rather than the core's "field: message".
// Still a gc::InvalidInput naming one field, so every edge that catches those reports it as before.
#pragma once

#include <string>
#include <utility>

#include "core/model_error.h"

namespace gc::codec {

class FileInputError : public InvalidInput {
 public:
  FileInputError(std::string field, std::string message)
      : InvalidInput(field, message), message_(std::move(message)) {}
  const char* what() const noexcept override { return message_.c_str(); }

 private:
  std::string message_;
};

}  // namespace gc::codec
