// validate's HTML report in a real browser: headless Chromium runs the page's scripts, dumps
// the DOM and takes a screenshot. Asserts that every error map shares one absolute colour scale
// (the noise level marked on it), that charts of an input the recording holds constant are left
// out with a note, and that the page renders to a non-blank picture. Skips, saying why, where
// Debian's chromium is not installed (deploy/install-deps.sh installs it).
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "run_process.h"

namespace gc::cli::testing {
namespace {

const std::string kRecordings = GC_BUNDLED_RECORDINGS_DIR;

std::string find_chromium() {
  for (const char* name : {"chromium", "chromium-browser"}) {
    for (const char* dir : {"/usr/bin", "/usr/local/bin", "/snap/bin"}) {
      const std::filesystem::path path = std::filesystem::path(dir) / name;
      if (std::filesystem::exists(path)) return path.string();
    }
  }
  return "";
}

// Headless, offline, in a fresh profile: nothing from earlier runs, nothing fetched.
std::string chromium_command(const std::string& chromium, const std::string& profile,
                             const std::string& what) {
  return "timeout 120 " + chromium +
         " --headless --no-sandbox --disable-gpu --disable-background-networking"
         " --disable-component-update --disable-sync --no-first-run --user-data-dir=" + profile +
         " " + what + " 2>/dev/null";
}

std::string run_command(const std::string& command, int& status) {
  std::string out;
  std::FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return out;
  std::array<char, 65536> buffer;
  while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
  status = pclose(pipe);
  return out;
}

double attribute(const std::string& dom, const std::string& element_id, const std::string& name) {
  std::smatch match;
  const std::regex pattern("id=\"" + element_id + "\"[^>]*" + name + "=\"([^\"]*)\"");
  if (!std::regex_search(dom, match, pattern)) {
    ADD_FAILURE() << "no " << name << " on #" << element_id;
    return -1.0;
  }
  return std::stod(match[1]);
}

class ReportInBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    chromium_ = find_chromium();
    if (chromium_.empty()) {
      GTEST_SKIP() << "chromium is not installed (Debian package chromium; deploy/install-deps.sh "
                      "installs it): the report is not checked in a browser";
    }
    // Before and after on a torque ramp: the paper's model 2-9 kN·m off, with eccentricity
    // close to the 2 kN·m noise.
    html_ = temp_path("gc_browser_report") + ".html";
    const ProcessResult run = run_gearcoupling(
        {"validate", "--data", kRecordings + "/hidden_eccentricity_torque_ramp.csv", "--model",
         "paper", "--add", "eccentricity", "--html", html_});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    profile_ = temp_path("gc_chromium_profile");
  }
  void TearDown() override {
    std::error_code ignored;
    if (!profile_.empty()) std::filesystem::remove_all(profile_, ignored);
  }

  std::string chromium_, html_, profile_;
};

TEST_F(ReportInBrowser, EveryErrorMapSharesOneAbsoluteScaleWithTheNoiseMarked) {
  int status = -1;
  const std::string dom = run_command(chromium_command(chromium_, profile_, "--dump-dom file://" + html_), status);
  if (dom.find("<html") == std::string::npos) GTEST_SKIP() << "chromium did not run (status " << status << ")";
  const double scale_max = attribute(dom, "colour-scale", "data-scale-max-nm");
  const double noise = attribute(dom, "colour-scale", "data-noise-level-nm");
  EXPECT_NEAR(noise, 2000.0, 300.0);   // make_recordings.sh adds 2 kN·m of noise
  EXPECT_GT(scale_max, 3.0 * noise);

  // Each coloured cell's opacity follows its RMSE on that one scale; the worst per model.
  const std::regex map_pattern(R"re(<table class="map" data-model="([^"]*)"[^>]*>([\s\S]*?)</table>)re");
  const std::regex cell_pattern(R"re(data-rmse-nm="([^"]*)" data-alpha="([^"]*)")re");
  std::map<std::string, double> worst_alpha;
  int cells = 0;
  for (auto map = std::sregex_iterator(dom.begin(), dom.end(), map_pattern); map != std::sregex_iterator(); ++map) {
    const std::string model = (*map)[1], body = (*map)[2];
    for (auto cell = std::sregex_iterator(body.begin(), body.end(), cell_pattern); cell != std::sregex_iterator(); ++cell) {
      const double rmse = std::stod((*cell)[1]), alpha = std::stod((*cell)[2]);
      EXPECT_NEAR(alpha, 0.05 + 0.85 * std::min(1.0, rmse / scale_max), 6e-4) << model << " " << rmse;
      worst_alpha[model] = std::max(worst_alpha[model], alpha);
      ++cells;
    }
  }
  EXPECT_GT(cells, 8);
  ASSERT_EQ(worst_alpha.size(), 2u);
  // Coloured by its own worst cell, the corrected model was as deep red (0.9) as the paper's.
  EXPECT_NEAR(worst_alpha["paper"], 0.9, 1e-3);
  EXPECT_LT(worst_alpha["paper + eccentricity"], 0.6);
}

// A torque ramp at one misalignment and direction: those charts would be single stripes.
TEST_F(ReportInBrowser, ChartsOfAnInputHeldConstantAreLeftOutWithANote) {
  int status = -1;
  const std::string dom = run_command(chromium_command(chromium_, profile_, "--dump-dom file://" + html_), status);
  if (dom.find("<html") == std::string::npos) GTEST_SKIP() << "chromium did not run (status " << status << ")";
  std::smatch match;
  ASSERT_TRUE(std::regex_search(dom, match, std::regex(R"re(id="left-out" data-left-out="([^"]*)")re"))) << dom.substr(0, 2000);
  const std::string left_out = match[1];
  for (const char* chart : {"model against measurement by misalignment", "residual against misalignment",
                            "residual against misalignment direction", "RMSE by misalignment", "RMSE by direction"}) {
    EXPECT_NE(left_out.find(chart), std::string::npos) << chart << " not in " << left_out;
  }
  EXPECT_EQ(left_out.find("torque"), std::string::npos) << left_out;   // torque varies: drawn
  EXPECT_NE(dom.find("Left out, as this recording holds the input constant"), std::string::npos);
  // Moments in one unit: no chart axis or table in % of T_ref.
  EXPECT_EQ(dom.find("% of T_ref]"), std::string::npos);
  EXPECT_EQ(dom.find("RMSE % T_ref"), std::string::npos);
}

TEST_F(ReportInBrowser, RendersToAScreenshot) {
  const std::string png = temp_path("gc_report_screenshot") + ".png";
  int status = -1;
  run_command(chromium_command(chromium_, profile_,
                               "--window-size=1400,5000 --screenshot=" + png + " file://" + html_), status);
  if (!std::filesystem::exists(png)) GTEST_SKIP() << "chromium did not run (status " << status << ")";
  // A blank page of that size compresses to a few kB; the charts and maps take hundreds.
  EXPECT_GT(std::filesystem::file_size(png), 100000u);
  std::printf("screenshot: %s\n", png.c_str());
}

}  // namespace
}  // namespace gc::cli::testing
