// Which Cyclone configuration the clients join with (protocol/dds_config.h) and the "no instance"
// message that names it: pure functions, no DDS traffic.
#include "protocol/dds_config.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <unistd.h>

namespace gc::protocol {
namespace {

namespace fs = std::filesystem;

// A temporary folder with an installed-looking etc/gearcoupling/cyclonedds.xml.
class DdsConfigChoice : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("gc_dds_config_" + std::to_string(::getpid()));
    fs::create_directories(root_ / "etc/gearcoupling");
    installed_ = root_ / "etc/gearcoupling/cyclonedds.xml";
    std::ofstream(installed_) << "<CycloneDDS/>\n";
    missing_ = root_ / "nowhere/cyclonedds.xml";
  }
  void TearDown() override { fs::remove_all(root_); }

  fs::path root_, installed_, missing_;
};

TEST_F(DdsConfigChoice, TheEnvironmentWinsOverAnInstalledFile) {
  const DdsConfig config = choose_dds_config("file:///mine.xml", {installed_});
  EXPECT_EQ(config.source, DdsConfigSource::kEnvironment);
  EXPECT_EQ(config.uri, "file:///mine.xml");
  EXPECT_EQ(describe(config), "CYCLONEDDS_URI=file:///mine.xml");
}

TEST_F(DdsConfigChoice, UnsetEnvironmentAndAnInstalledFileGiveTheFile) {
  for (const char* unset : {static_cast<const char*>(nullptr), ""}) {
    const DdsConfig config = choose_dds_config(unset, {missing_, installed_});
    EXPECT_EQ(config.source, DdsConfigSource::kInstalled);
    EXPECT_EQ(config.uri, "file://" + installed_.string());
    EXPECT_EQ(describe(config),
              "file://" + installed_.string() + " (installed; CYCLONEDDS_URI unset)");
  }
}

TEST_F(DdsConfigChoice, NeitherGivesCyclonesDefault) {
  for (const std::vector<fs::path>& paths :
       {std::vector<fs::path>{}, std::vector<fs::path>{missing_, root_ / "etc"}}) {
    const DdsConfig config = choose_dds_config(nullptr, paths);
    EXPECT_EQ(config.source, DdsConfigSource::kCycloneDefault);
    EXPECT_EQ(config.uri, "");
    EXPECT_EQ(describe(config), "Cyclone's default (CYCLONEDDS_URI unset)");
  }
}

TEST(DdsConfigPaths, AnInstallTreesConfigurationIsFoundFromItsLibdirOrBindir) {
  // The .deb: /usr's configuration is in /etc, as cmake/install_system_files.cmake installs it.
  EXPECT_EQ(install_tree_dds_config(fs::path("/usr") / GC_INSTALL_LIBDIR),
            fs::path("/etc/gearcoupling/cyclonedds.xml"));
  EXPECT_EQ(install_tree_dds_config("/usr/bin"), fs::path("/etc/gearcoupling/cyclonedds.xml"));
  // Another prefix: <prefix>/etc/gearcoupling.
  EXPECT_EQ(install_tree_dds_config(fs::path("/opt/gc") / GC_INSTALL_LIBDIR),
            fs::path("/opt/gc/etc/gearcoupling/cyclonedds.xml"));
  EXPECT_EQ(install_tree_dds_config("/opt/gc/bin"),
            fs::path("/opt/gc/etc/gearcoupling/cyclonedds.xml"));
  // A build tree is no install tree.
  EXPECT_EQ(install_tree_dds_config("/work/build/clients/cli"), std::nullopt);
  EXPECT_EQ(install_tree_dds_config(""), std::nullopt);
}

TEST(DdsConfigPaths, ABuildTreeBinaryLooksOnlyUnderTheConfiguredPrefix) {
  // This test runs from the build tree: only the configured prefix's file is a candidate, so
  // without an install there it behaves as before (Cyclone's default or CYCLONEDDS_URI).
  EXPECT_EQ(installed_dds_config_paths(),
            std::vector<fs::path>{fs::path(GC_INSTALLED_DDS_CONFIG)});
}

TEST(NoInstanceMessage, NamesTheDomainTheConfigurationAndHowToStartAService) {
  const std::string message = no_instance_message(
      7, std::chrono::milliseconds(3000), "Cyclone's default (CYCLONEDDS_URI unset)", 0);
  EXPECT_EQ(message,
            "no gearcoupling-service instance ready on domain 7 within 3000 ms (0 instance(s) "
            "discovered; DDS configuration: Cyclone's default (CYCLONEDDS_URI unset)); start one "
            "with `systemctl start gearcoupling-service` or `gearcoupling-service --domain 7`, on "
            "the same configuration and domain");
  EXPECT_EQ(no_instance_message(0, std::chrono::milliseconds(500), "CYCLONEDDS_URI=file:///x.xml"),
            "no gearcoupling-service instance ready on domain 0 within 500 ms (DDS configuration: "
            "CYCLONEDDS_URI=file:///x.xml); start one with `systemctl start gearcoupling-service` "
            "or `gearcoupling-service --domain 0`, on the same configuration and domain");
}

}  // namespace
}  // namespace gc::protocol
