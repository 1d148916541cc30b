// The parts of the gearcoupling Python module (docs/python.md), each bound by its own file.
#pragma once

#include <pybind11/pybind11.h>

namespace gc::python {

void bind_errors(pybind11::module_& m);         // errors.cc
void bind_couplings(pybind11::module_& m);      // coupling_argument.cc
void bind_calculations(pybind11::module_& m);   // calculations.cc
void bind_case_arrays(pybind11::module_& m);    // case_arrays.cc
void bind_models(pybind11::module_& m);         // model_argument.cc
void bind_recordings(pybind11::module_& m);     // recording_argument.cc
void bind_measurement(pybind11::module_& m);    // measurement.cc
void bind_client(pybind11::module_& m);         // remote_client.cc (with the service only)

}  // namespace gc::python
