#include "clients/python/coupling_argument.h"

#include <map>
#include <mutex>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "calculators/coupling_reference.h"
#include "clients/python/bindings.h"
#include "clients/python/typed_objects.h"
#include "codec/coupling_catalog.h"
#include "codec/coupling_file.h"
#include "core/model_error.h"

namespace py = pybind11;

namespace gc::python {
namespace {

using Catalogue = std::map<std::string, std::shared_ptr<const Coupling>, std::less<>>;

// The catalogue, read on first use and kept (as the CLI's InProcessCalculator does).
const Catalogue& catalogue() {
  static std::once_flag once;
  static Catalogue* loaded = nullptr;
  std::call_once(once, [] {
    auto couplings = std::make_unique<Catalogue>();
    for (auto& [name, geometry] : codec::load_coupling_catalog(codec::default_catalog_dir())) {
      couplings->emplace(name, std::make_shared<const Coupling>(
                                   Coupling{name, std::make_shared<const CouplingGeometry>(std::move(geometry))}));
    }
    loaded = couplings.release();
  });
  return *loaded;
}

std::shared_ptr<const Coupling> from_catalogue(const std::string& name) {
  const Catalogue& couplings = catalogue();
  const auto found = couplings.find(name);
  if (found != couplings.end()) return found->second;
  std::string known;
  for (const auto& [known_name, coupling] : couplings) known += (known.empty() ? "" : ", ") + known_name;
  throw InvalidInput("coupling", "no coupling named \"" + name + "\" in " +
                                     codec::default_catalog_dir().string() + " (known: " + known + ")");
}

std::shared_ptr<const Coupling> from_definition(CouplingDefinition definition) {
  return std::make_shared<const Coupling>(
      Coupling{"", std::make_shared<const CouplingGeometry>(std::move(definition))});
}

std::shared_ptr<const Coupling> from_dict(py::handle dict) {
  const std::string json = py::str(py::module_::import("json").attr("dumps")(dict));
  return from_definition(codec::parse_coupling_json(json, "coupling dict"));
}

bool is_path(py::handle argument) {
  return py::isinstance(argument, py::module_::import("os").attr("PathLike"));
}

}  // namespace

std::shared_ptr<const Coupling> coupling_argument(py::handle argument) {
  if (py::isinstance<Coupling>(argument)) return argument.cast<std::shared_ptr<Coupling>>();
  if (py::isinstance<py::dict>(argument)) return from_dict(argument);
  if (is_path(argument)) {
    return from_definition(codec::load_coupling_file(argument.cast<std::filesystem::path>()));
  }
  if (py::isinstance<py::str>(argument)) {
    const std::string text = argument.cast<std::string>();
    if (calculators::is_file_reference(text)) return from_definition(codec::load_coupling_file(text));
    return from_catalogue(text);
  }
  throw py::type_error("coupling: a gearcoupling.Coupling, a catalogue name, a coupling file or a dict, not " +
                       std::string(py::str(py::type::of(argument))));
}

RemoteCoupling remote_coupling_argument(py::handle argument) {
  if (py::isinstance<py::str>(argument) && !calculators::is_file_reference(argument.cast<std::string>())) {
    const std::string name = argument.cast<std::string>();
    return {name, nullptr, name};
  }
  std::shared_ptr<const Coupling> coupling = coupling_argument(argument);
  if (!coupling->catalogue_name.empty()) {
    return {coupling->catalogue_name, nullptr, coupling->catalogue_name};
  }
  return {std::nullopt, coupling, coupling->geometry->name()};
}

void bind_couplings(py::module_& m) {
  py::class_<Coupling, std::shared_ptr<Coupling>>(
      m, "Coupling",
      "A validated coupling: from the catalogue by name, from a coupling file, or from a dict with "
      "the coupling file's fields (idl/coupling.proto; angles in degrees as in the files).")
      .def(py::init([](const CouplingArgument& argument) {
             return std::const_pointer_cast<Coupling>(coupling_argument(argument));
           }),
           py::arg("source"),
           "A catalogue name ('nrel_upwind'), a coupling file (.textproto), or a dict.")
      .def_property_readonly("name", [](const Coupling& c) { return c.geometry->name(); },
                             "The coupling's name (its definition's).")
      .def_property_readonly("catalogue_name",
                             [](const Coupling& c) -> std::optional<std::string> {
                               if (c.catalogue_name.empty()) return std::nullopt;
                               return c.catalogue_name;
                             },
                             "The catalogue name it was loaded by; None for a file or a dict.")
      .def_property_readonly("teeth", [](const Coupling& c) { return c.geometry->teeth(); },
                             "N, teeth [-].")
      .def_property_readonly("pitch_radius_m", [](const Coupling& c) { return c.geometry->pitch_radius_m(); },
                             "R, pitch radius (eq 8) [m].")
      .def_property_readonly("crown_radius_m", [](const Coupling& c) { return c.geometry->crown_radius_m(); },
                             "R_F, crown radius [m].")
      .def_property_readonly("mesh_stiffness_n_per_m",
                             [](const Coupling& c) { return c.geometry->mesh_stiffness_n_per_m(); },
                             "C, single-pair mesh stiffness (eqs 5-6) [N/m].")
      .def_property_readonly("jam_angle_rad", [](const Coupling& c) { return c.geometry->jam_angle().angle_rad; },
                             "xi, the jam angle (eqs 23-35) [rad].")
      .def("__repr__", [](const Coupling& c) { return "<gearcoupling.Coupling '" + c.geometry->name() + "'>"; });
  m.def("catalogue", [] {
        std::vector<std::string> names;
        for (const auto& [name, coupling] : catalogue()) names.push_back(name);
        return names;
      },
      "The names of the catalogue's couplings ($GEARCOUPLING_CATALOG, else the bundled ones).");
}

}  // namespace gc::python
