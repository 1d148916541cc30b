// Errors of the remote client that are not the model's: no service answered in time.
#pragma once

#include <stdexcept>
#include <string>

namespace gc::client {

/// No reply within the call's timeout, or no service instance ready to take the request. what()
/// says which calculation, which request, which instance and how long was waited.
class Timeout : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The client was destroyed with the request still pending.
class ClientClosed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace gc::client
