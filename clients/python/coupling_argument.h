// How the Python functions take a coupling: a gearcoupling.Coupling, a catalogue name ("nrel_upwind"),
// a coupling file (a str containing '/' or ending in ".textproto", or an os.PathLike), or a dict
// with the coupling file's fields (idl/coupling.proto, angles in _deg as in the files).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "core/coupling_definition.h"
#include "core/coupling_geometry.h"

namespace gc::python {

/// gearcoupling.Coupling: a validated coupling, immutable, shared by any number of threads.
struct Coupling {
  /// The catalogue name it was loaded by; empty for a file or a dict (sent inline to a service).
  std::string catalogue_name;
  std::shared_ptr<const CouplingGeometry> geometry;
};

/// The coupling for an argument, loading a catalogue name from the catalogue directory
/// (codec::default_catalog_dir(), read once) and a file or a dict each time. Throws
/// gc::InvalidInput naming "coupling" or the field.
std::shared_ptr<const Coupling> coupling_argument(pybind11::handle argument);

/// What a service is asked about: a catalogue name as is (the service's catalogue), any other
/// coupling as its definition. `name` is the coupling's name for the results.
struct RemoteCoupling {
  std::optional<std::string> catalogue_name;
  std::shared_ptr<const Coupling> inline_coupling;
  std::string name;
};
RemoteCoupling remote_coupling_argument(pybind11::handle argument);

}  // namespace gc::python
