#include "clients/python/errors.h"

#include <string>

#include "analysis/format_error.h"
#include "clients/python/bindings.h"
#include "core/model_error.h"
#ifdef GC_PYTHON_REMOTE
#include "client/client_error.h"
#include "protocol/reply_status.h"
#endif

namespace py = pybind11;

namespace gc::python {
namespace {

// The exception classes, made once at import (module state lives as long as the interpreter).
struct ErrorTypes {
  py::object model_error, invalid_input, not_converged, timeout;
};

ErrorTypes& types() {
  static ErrorTypes* types = new ErrorTypes();  // never destroyed: outlives the interpreter's teardown
  return *types;
}

py::object new_exception_type(py::module_& m, const char* name, py::tuple bases, const char* doc) {
  const std::string qualified = std::string("gearcoupling.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (type == nullptr) throw py::error_already_set();
  py::object object = py::reinterpret_steal<py::object>(type);
  m.attr(name) = object;
  return object;
}

// The Python type and the message for `error`; `field` is set for InvalidInput.
py::object classify(const std::exception_ptr& error, std::string& message, py::object& field) {
  try {
    std::rethrow_exception(error);
  } catch (const InvalidInput& e) {
    message = e.what();
    field = py::str(e.field());
    return types().invalid_input;
#ifdef GC_PYTHON_REMOTE
  } catch (const protocol::ServiceError& e) {  // the service's own refusal (unknown coupling, ...)
    message = e.what();
    if (!e.field().empty()) field = py::str(e.field());
    return types().model_error;
#endif
  } catch (const NotConverged& e) {
    message = e.what();
    return types().not_converged;
  } catch (const ModelError& e) {
    message = e.what();
    return types().model_error;
  } catch (const analysis::FormatError& e) {
    message = e.what();
    return py::reinterpret_borrow<py::object>(PyExc_ValueError);
#ifdef GC_PYTHON_REMOTE
  } catch (const client::Timeout& e) {
    message = e.what();
    return types().timeout;
#endif
  } catch (const py::error_already_set&) {
    throw;
  } catch (const py::builtin_exception&) {  // pybind11's own (TypeError, ...): its translator
    throw;
  } catch (const std::exception& e) {
    message = e.what();
    return py::reinterpret_borrow<py::object>(PyExc_RuntimeError);
  }
}

}  // namespace

void set_python_error(const std::exception_ptr& error, std::optional<std::size_t> index) {
  std::string message;
  py::object field = py::none();
  py::object type = classify(error, message, field);
  if (index) message = "case " + std::to_string(*index) + ": " + message;
  py::object exception = type(message);
  exception.attr("field") = field;  // None where the error names no field
  if (index) exception.attr("index") = *index;
  PyErr_SetObject(type.ptr(), exception.ptr());
}

void bind_errors(py::module_& m) {
  ErrorTypes& t = types();
  t.model_error = new_exception_type(
      m, "ModelError", py::make_tuple(py::reinterpret_borrow<py::object>(PyExc_Exception)),
      "Base of every error the model raises (gc::ModelError).");
  t.invalid_input = new_exception_type(
      m, "InvalidInput",
      py::make_tuple(t.model_error, py::reinterpret_borrow<py::object>(PyExc_ValueError)),
      "An input outside its physical range; .field names it as written "
      "(e.g. 'operating_point.misalignment_rad'), the message gives the value and the allowed range.");
  t.not_converged = new_exception_type(m, "NotConverged", py::make_tuple(t.model_error),
                                       "An iteration (eqs 20-22, eq 23's root) stopped before "
                                       "meeting its tolerance.");
  t.timeout = new_exception_type(
      m, "Timeout", py::make_tuple(py::reinterpret_borrow<py::object>(PyExc_TimeoutError)),
      "No reply from gearcoupling-service within the client's timeout.");
  py::register_exception_translator([](std::exception_ptr error) {
    if (error) set_python_error(error);
  });
}

}  // namespace gc::python
