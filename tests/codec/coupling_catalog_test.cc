#include "codec/coupling_catalog.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/model_error.h"

namespace gc::codec {
namespace {

namespace fs = std::filesystem;

// A fresh directory under the test's temporary directory.
fs::path scratch_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("gc_catalog_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(CouplingCatalog, BundledCatalogHoldsBothNrelCouplings) {
  const auto catalog = load_coupling_catalog(GC_BUNDLED_CATALOG_DIR);
  ASSERT_EQ(catalog.size(), 2u);
  EXPECT_EQ(catalog.at("nrel_upwind").teeth(), 100);
  EXPECT_TRUE(catalog.contains("nrel_downwind"));
  // Both jam angles are well inside (0, 2 deg): the geometry was derived, not defaulted.
  for (const auto& [name, geometry] : catalog) {
    EXPECT_GT(geometry.jam_angle().angle_rad, 0.0) << name;
    EXPECT_LT(geometry.jam_angle().angle_rad, 2.0 * M_PI / 180.0) << name;
  }
}

TEST(CouplingCatalog, DuplicateNamesAreAnError) {
  const fs::path dir = scratch_dir("duplicate");
  fs::copy_file(fs::path(GC_BUNDLED_CATALOG_DIR) / "nrel_upwind.textproto", dir / "a.textproto");
  fs::copy_file(fs::path(GC_BUNDLED_CATALOG_DIR) / "nrel_upwind.textproto", dir / "b.textproto");
  try {
    load_coupling_catalog(dir);
    FAIL() << "duplicate accepted";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "coupling.name");
    EXPECT_NE(std::string(error.what()).find("a.textproto and b.textproto"), std::string::npos);
  }
}

TEST(CouplingCatalog, UnphysicalCouplingNamesFieldAndFile) {
  const fs::path dir = scratch_dir("unphysical");
  std::ifstream in(fs::path(GC_BUNDLED_CATALOG_DIR) / "nrel_upwind.textproto");
  std::ofstream out(dir / "negative.textproto");
  std::string line;
  while (std::getline(in, line)) {
    out << (line.rfind("backlash_m", 0) == 0 ? "backlash_m: -0.001" : line) << "\n";
  }
  out.close();
  try {
    load_coupling_catalog(dir);
    FAIL() << "negative backlash accepted";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "coupling.backlash_m");
    // The core's message whole, with the file: not "coupling.backlash_m:  = -0.001".
    EXPECT_STREQ(error.what(), "coupling.backlash_m = -0.001 is out of range: allowed a finite "
                               "value > 0 (in negative.textproto)");
  }
}

TEST(CouplingCatalog, AngleOutOfRangeNamesTheFilesDegreeField) {
  const fs::path dir = scratch_dir("angle");
  std::ifstream in(fs::path(GC_BUNDLED_CATALOG_DIR) / "nrel_upwind.textproto");
  std::ofstream out(dir / "steep.textproto");
  std::string line;
  while (std::getline(in, line)) {
    out << (line.rfind("pressure_angle_deg", 0) == 0 ? "pressure_angle_deg: 60" : line) << "\n";
  }
  out.close();
  try {
    load_coupling_geometry(dir / "steep.textproto");
    FAIL() << "60 deg pressure angle accepted";
  } catch (const InvalidInput& error) {
    // Checked in the file's terms before the core's radians (codec/coupling_file.cc).
    EXPECT_EQ(error.field(), "coupling.pressure_angle_deg");
    EXPECT_STREQ(error.what(), "coupling.pressure_angle_deg = 60 is out of range: allowed "
                               "[5.002, 45] deg (in steep.textproto)");
  }
}

TEST(CouplingCatalog, MissingDirectoryIsAnError) {
  EXPECT_THROW(load_coupling_catalog("/nonexistent/catalog"), InvalidInput);
}

TEST(CouplingCatalog, EnvironmentOverridesDefaultDirectory) {
  ::setenv("GEARCOUPLING_CATALOG", "/some/where", 1);
  EXPECT_EQ(default_catalog_dir(), fs::path("/some/where"));
  ::unsetenv("GEARCOUPLING_CATALOG");
  EXPECT_TRUE(fs::exists(default_catalog_dir() / "nrel_upwind.textproto"));
}

}  // namespace
}  // namespace gc::codec
