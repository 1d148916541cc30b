// The audit trail on disk (live/swap_audit_file.h): what a monitor wrote, the next one loads, as
// it was; the file stays within its bound; a directory that is not there is refused by name.
// Damaged files are tested against the real monitor (robustness_test.cc).
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>

#include "core/model_error.h"
#include "live/swap_audit.h"
#include "live/swap_audit_file.h"

namespace gc::live {
namespace {

/// A path of its own under the temporary directory, not made.
std::filesystem::path temp_path(const std::string& stem) {
  static std::atomic<int> counter{0};
  return std::filesystem::temp_directory_path() /
         (stem + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
}

std::filesystem::path new_state_dir(const std::string& stem) {
  const std::filesystem::path dir = temp_path(stem);
  std::filesystem::create_directories(dir);
  return dir;
}

SwapEntry swap_of(const std::string& test_cell, std::uint64_t id, const std::string& by) {
  SwapEntry e;
  e.id = id;
  e.test_cell = test_cell;
  e.at = std::chrono::system_clock::time_point(std::chrono::seconds(1'790'000'000) + std::chrono::microseconds(id));
  e.by = by;
  e.source = "file /srv/models/dyno 1 100%.textproto";   // a space and a '%' to encode
  e.proposal_id = id * 0x1000001;
  e.model_before = "paper";
  e.model_after.assign(1, '-');                      // "-", the empty text's spelling
  e.before_rmse_nm[0] = 6612.5;
  e.before_rmse_nm[1] = 1.0 / 3.0;                         // round trip to the last bit
  e.writer = "0110fa3c00000002000000000000d03";
  e.written_ns = 1'790'000'000'123'456'789 + static_cast<std::int64_t>(id);
  return e;
}

TEST(SwapAuditFile, WhatOneMonitorWroteTheNextLoadsAsItWas) {
  const auto dir = new_state_dir("audit_round_trip");
  {
    SwapAudit audit(dir);
    audit.add(swap_of("dyno1", 1, "alice@bench"));
    audit.add(swap_of("dyno2", 2, ""));
    HealthReport health;
    health.model.model_name = "-";
    health.model.channels[0].rmse_nm = 1900.25;
    health.model.channels[1].rmse_nm = 2100.5;
    health.window_samples = 1000;
    audit.follow("dyno1", health);
    audit.close();   // the monitor stops: the after-figures go to the file
  }
  SwapAudit loaded(dir);
  ASSERT_EQ(loaded.entries().size(), 2u);
  EXPECT_EQ(loaded.total(), 0u);   // swaps of this monitor: none yet
  const SwapEntry want = swap_of("dyno1", 1, "alice@bench");
  const SwapEntry& got = loaded.entries()[0];
  EXPECT_EQ(got.id, want.id);
  EXPECT_EQ(got.test_cell, "dyno1");
  EXPECT_EQ(got.at, want.at);
  EXPECT_EQ(got.by, "alice@bench");
  EXPECT_EQ(got.source, want.source);
  EXPECT_EQ(got.proposal_id, want.proposal_id);
  EXPECT_EQ(got.model_before, "paper");
  EXPECT_EQ(got.model_after, "-");
  EXPECT_EQ(got.before_rmse_nm[0], 6612.5);
  EXPECT_EQ(got.before_rmse_nm[1], 1.0 / 3.0);
  EXPECT_EQ(got.after_rmse_nm[0], 1900.25);
  EXPECT_EQ(got.after_rmse_nm[1], 2100.5);
  EXPECT_EQ(got.after_samples, 1000u);
  EXPECT_TRUE(got.after_frozen);
  EXPECT_EQ(loaded.entries()[1].by, "");
  EXPECT_TRUE(loaded.contains(want.writer, want.written_ns));
  EXPECT_FALSE(loaded.contains(want.writer, want.written_ns - 1));
}

TEST(SwapAuditFile, LoadsTheLatestKeptSwaps) {
  const auto dir = new_state_dir("audit_kept");
  {
    SwapAudit audit(dir);
    for (std::uint64_t i = 1; i <= SwapAudit::kKept + 6; ++i) audit.add(swap_of("dyno1", i, "bob"));
  }
  SwapAudit loaded(dir);
  ASSERT_EQ(loaded.entries().size(), SwapAudit::kKept);
  EXPECT_EQ(loaded.entries().front().id, 7u);
  EXPECT_EQ(loaded.entries().back().id, SwapAudit::kKept + 6);
}

// 130 swaps of 20 kB each (a long "by") are 2.6 MB: rotated twice, at most two files of at most
// kRotateBytes stay, and the latest kKept swaps load from them in order.
TEST(SwapAuditFile, RotatesAtItsBoundAndLoadsAcrossTheTwoFiles) {
  const auto dir = new_state_dir("audit_rotation");
  const std::string long_by(20'000, 'x');
  {
    SwapAudit audit(dir);
    for (std::uint64_t i = 1; i <= 130; ++i) audit.add(swap_of("dyno1", i, long_by));
  }
  std::uintmax_t total = 0;
  std::size_t files = 0;
  for (const auto& file : std::filesystem::directory_iterator(dir)) {
    EXPECT_LE(file.file_size(), SwapAuditFile::kRotateBytes) << file.path();
    total += file.file_size();
    ++files;
  }
  EXPECT_EQ(files, 2u);
  EXPECT_LE(total, 2 * SwapAuditFile::kRotateBytes);
  SwapAudit loaded(dir);
  ASSERT_EQ(loaded.entries().size(), SwapAudit::kKept);
  for (std::size_t i = 0; i < loaded.entries().size(); ++i) {
    EXPECT_EQ(loaded.entries()[i].id, 130 - SwapAudit::kKept + 1 + i);
  }
}

TEST(SwapAuditFile, ADirectoryThatIsNotThereIsRefusedNamingTheFlag) {
  try {
    SwapAudit audit(temp_path("absent_state_dir"));
    FAIL() << "no error";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "--state-dir");
    EXPECT_NE(std::string(error.what()).find("absent_state_dir"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace gc::live
