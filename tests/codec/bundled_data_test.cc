// Where programs find the bundled couplings and models. The installed layout (share/gearcoupling
// beside the installed library) is tested by tests/packaging on a real install and a real .deb.
#include "codec/bundled_data.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "codec/coupling_catalog.h"

namespace gc::codec {
namespace {

namespace fs = std::filesystem;

TEST(BundledData, FromTheBuildTreeIsTheSourceTreesDataFolder) {
  // This test links libgearcoupling-codec in the build folder, beside which nothing is
  // installed: the source tree's data/ is next in line.
  EXPECT_TRUE(fs::equivalent(bundled_data_dir("couplings"), GC_BUNDLED_CATALOG_DIR));
  EXPECT_TRUE(fs::equivalent(bundled_data_dir("models"), GC_SOURCE_DIR "/data/models"));
}

TEST(BundledData, CatalogueDefaultIsTheBundledCouplingsWithoutTheEnvironment) {
  ::unsetenv("GEARCOUPLING_CATALOG");
  EXPECT_EQ(default_catalog_dir(), bundled_data_dir("couplings"));
}

TEST(BundledData, WhenNothingExistsTheConfiguredInstallFolderIsNamed) {
  // The last place looked at, named in the error that reading it gives.
  const fs::path dir = bundled_data_dir("no_such_kind");
  EXPECT_EQ(dir.filename(), "no_such_kind");
  EXPECT_EQ(dir.parent_path().filename(), "gearcoupling");
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace gc::codec
