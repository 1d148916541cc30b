// The core's errors as Python exceptions: gearcoupling.ModelError, InvalidInput (also a
// ValueError, with .field), NotConverged; Timeout (a TimeoutError) from the service client.
#pragma once

#include <cstddef>
#include <exception>
#include <optional>

#include <pybind11/pybind11.h>

namespace gc::python {

/// Sets the Python error for `error` (one of the core's, the client's, or any std::exception);
/// with `index`, the message starts "case <index>: " and the exception has .index: the load case
/// of a vectorised call that failed. Needs the GIL.
void set_python_error(const std::exception_ptr& error, std::optional<std::size_t> index = {});

}  // namespace gc::python
