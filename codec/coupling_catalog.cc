#include "codec/coupling_catalog.h"

#include <algorithm>
#include <cstdlib>
#include <system_error>
#include <vector>

#include "codec/bundled_data.h"
#include "codec/coupling_file.h"
#include "codec/file_input_error.h"
#include "core/model_error.h"

namespace gc::codec {
namespace {

// The core names angles in radians; the file states them in degrees under a _deg name.
std::string file_units_note(const std::string& field) {
  if (!field.ends_with("_rad")) return "";
  const std::string name = field.substr(field.rfind('.') + 1);
  return ", where it is " + name.substr(0, name.size() - 4) + "_deg in degrees";
}

std::vector<std::filesystem::path> coupling_files(const std::filesystem::path& dir) {
  std::error_code error;
  std::filesystem::directory_iterator entries(dir, error);
  if (error) {
    throw InvalidInput("catalog", "cannot read coupling catalogue " + dir.string() + ": " +
                                      error.message());
  }
  std::vector<std::filesystem::path> files;
  for (const auto& entry : entries) {
    if (entry.is_regular_file() && entry.path().extension() == ".textproto") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());  // deterministic order for the duplicate message
  return files;
}

}  // namespace

CouplingGeometry load_coupling_geometry(const std::filesystem::path& file) {
  CouplingDefinition definition = load_coupling_file(file);
  try {
    return CouplingGeometry(std::move(definition));
  } catch (const InvalidInput& error) {
    // The core names the field; the user also needs the file it came from.
    // The core's message whole ("coupling.x = 1 is out of range: ..."): cutting the field off
    // and letting InvalidInput put it back as "field: " left "coupling.x:  = 1".
    const std::string where =
        " (in " + file.filename().string() + file_units_note(error.field()) + ")";
    throw FileInputError(error.field(), error.what() + where);
  }
}

std::map<std::string, CouplingGeometry> load_coupling_catalog(const std::filesystem::path& dir) {
  std::map<std::string, CouplingGeometry> catalog;
  std::map<std::string, std::string> file_of_name;
  for (const auto& file : coupling_files(dir)) {
    CouplingGeometry geometry = load_coupling_geometry(file);
    const std::string name = geometry.name();
    const auto [previous, inserted] = file_of_name.emplace(name, file.filename().string());
    if (!inserted) {
      throw InvalidInput("coupling.name", "\"" + name + "\" is defined twice, in " +
                                              previous->second + " and " +
                                              file.filename().string());
    }
    catalog.emplace(name, std::move(geometry));
  }
  return catalog;
}

std::filesystem::path default_catalog_dir() {
  const char* from_environment = std::getenv("GEARCOUPLING_CATALOG");
  if (from_environment != nullptr && *from_environment != '\0') return from_environment;
  return bundled_data_dir("couplings");
}

}  // namespace gc::codec
