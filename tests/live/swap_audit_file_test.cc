// The audit trail on disk (live/swap_audit_file.h): what a monitor wrote, the next one loads, as
// it was; the after-figures of a swap still followed are written at a bounded rate and a kill
// leaves them marked interrupted; a later line replaces, never duplicates, its swap; damaged and
// torn lines are skipped; the file stays within its bound and a swap still followed is carried
// across rotations; a directory that is not there is refused by name. Damaged files are also
// tested against the real monitor (robustness_test.cc).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/model_error.h"
#include "live/swap_audit.h"
#include "live/swap_audit_file.h"
#include "tests/cli/run_process.h"

namespace gc::live {
namespace {

/// A path of its own in the test process's scratch directory (removed at exit), not made.
std::filesystem::path temp_path(const std::string& stem) { return cli::testing::temp_path(stem); }

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
  EXPECT_FALSE(got.after_interrupted);   // the monitor stopped: its final after line
  EXPECT_STREQ(after_state_text(got), "final");
  EXPECT_EQ(loaded.entries()[1].by, "");
  EXPECT_FALSE(loaded.entries()[1].after_interrupted);   // final too, without a sample after it
  EXPECT_TRUE(loaded.contains(want.writer, want.written_ns));
  EXPECT_FALSE(loaded.contains(want.writer, want.written_ns - 1));
}

/// The lines of `file` that start with `v1 ` and hold ` KIND ` (swap, after).
std::size_t lines_of_kind(const std::filesystem::path& file, const std::string& kind) {
  std::ifstream in(file);
  std::size_t count = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v1 ", 0) == 0 && line.find(" " + kind + " ", 19) == 19) ++count;
  }
  return count;
}

HealthReport health_of(const std::string& model, double msy_nm, double msz_nm, std::uint64_t samples) {
  HealthReport health;
  health.model.model_name = model;
  health.model.channels[0].rmse_nm = msy_nm;
  health.model.channels[1].rmse_nm = msz_nm;
  health.window_samples = samples;
  return health;
}

// A swap followed for 8 s, its health every 0.5 s: its after-figures are written at the first
// health with samples, then 1 s, 2 s and 4 s later (t = 0, 1, 3, 7 s), not at every health; at
// t = 20 s, past the next due time, figures equal to those written are not written again. The
// monitor is then killed (no close(): no final line), and the next one loads the figures last
// written, marked interrupted, as one entry.
TEST(SwapAuditFile, FollowedFiguresAreWrittenAtABoundedRateAndOutliveAKillMarkedInterrupted) {
  const auto dir = new_state_dir("audit_followed");
  const auto t0 = std::chrono::steady_clock::time_point(std::chrono::hours(1));
  {
    SwapAudit audit(dir);
    SwapEntry swap = swap_of("dyno1", 1, "alice@bench");
    swap.model_after = "dyno1_eccentric";
    audit.add(swap);
    audit.follow("dyno1", health_of("dyno1_eccentric", 0.0, 0.0, 0), t0);   // no sample yet: nothing
    for (int half_s = 0; half_s <= 16; ++half_s) {
      const double rmse = 2000.0 + half_s;   // changes at every health
      audit.follow("dyno1", health_of("dyno1_eccentric", rmse, rmse + 0.5, 100 * (half_s + 1)),
                   t0 + std::chrono::milliseconds(500 * half_s));
    }
    EXPECT_EQ(lines_of_kind(dir / "swap_audit.log", "after"), 4u);
    EXPECT_EQ(audit.entries().back().after_samples, 1700u);   // in memory, every health
    audit.follow("dyno1", health_of("dyno1_eccentric", 2014.0, 2014.5, 1500), t0 + std::chrono::seconds(20));
    EXPECT_EQ(lines_of_kind(dir / "swap_audit.log", "after"), 4u);
  }   // killed: gone without close()
  SwapAudit loaded(dir);
  ASSERT_EQ(loaded.entries().size(), 1u);
  const SwapEntry& got = loaded.entries()[0];
  EXPECT_EQ(got.after_samples, 1500u);   // written at t = 7 s (half_s 14), the last write
  EXPECT_EQ(got.after_rmse_nm[0], 2014.0);
  EXPECT_EQ(got.after_rmse_nm[1], 2014.5);
  EXPECT_TRUE(got.after_frozen);        // nobody follows it now
  EXPECT_TRUE(got.after_interrupted);
  EXPECT_STREQ(after_state_text(got), "interrupted");
}

// One swap's records as a file may hold them: its swap line, after lines while followed, the
// same swap again (carried into a newer file), then a damaged after line, one of an unknown
// state and a torn last one (a kill in the middle of a write). One entry, with the figures of
// the last whole after line; the bad lines are skipped, the torn one cut off the file.
TEST(SwapAuditFile, AnAfterLineReplacesItsSwapsFiguresAndBadOrTornLinesAreSkipped) {
  const auto dir = new_state_dir("audit_replaces");
  SwapEntry swap = swap_of("dyno1", 7, "alice@bench");
  auto after = [&swap](double msy, std::uint64_t samples, AfterState state) {
    swap.after_rmse_nm[0] = msy;
    swap.after_rmse_nm[1] = msy + 1.0;
    swap.after_samples = samples;
    return audit_line(after_record_payload(swap, state));
  };
  const std::string first = audit_line(swap_record_payload(swap));
  std::string following = after(1900.0, 100, AfterState::following);
  following += after(1800.0, 200, AfterState::following);   // in this order: `after` sets `swap`
  const std::string carried = audit_line(swap_record_payload(swap));   // with 1800 / 200
  std::string damaged = after(1700.0, 300, AfterState::following);
  damaged[damaged.find("1700")] = '9';
  std::string unknown_state = "after " + std::string(16 - 1, '0') + "7 1650 1651 350 halfway";
  unknown_state = audit_line(unknown_state);
  const std::string whole = first + following + carried + damaged + unknown_state;
  const std::string torn_final = after(1600.0, 400, AfterState::final);
  std::ofstream(dir / "swap_audit.log", std::ios::binary) << whole << torn_final.substr(0, torn_final.size() - 3);

  SwapAudit loaded(dir);
  ASSERT_EQ(loaded.entries().size(), 1u);   // replaced, not duplicated
  const SwapEntry& got = loaded.entries()[0];
  EXPECT_EQ(got.id, 7u);
  EXPECT_EQ(got.after_rmse_nm[0], 1800.0);
  EXPECT_EQ(got.after_rmse_nm[1], 1801.0);
  EXPECT_EQ(got.after_samples, 200u);
  EXPECT_TRUE(got.after_interrupted);   // the final line was torn
  std::ifstream in(dir / "swap_audit.log", std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), whole);
}

TEST(SwapAuditFile, AFinalAfterLineMarksTheFollowingCompleteAndAnOlderMonitorsLineIsFinal) {
  const auto dir = new_state_dir("audit_final");
  SwapEntry swap = swap_of("dyno1", 3, "bob");
  const std::string first = audit_line(swap_record_payload(swap));
  swap.after_samples = 500;
  const std::string final_line = audit_line(after_record_payload(swap, AfterState::final));
  SwapEntry older = swap_of("dyno2", 4, "carol");
  older.after_samples = 600;
  std::string older_after = after_record_payload(older, AfterState::final);
  older_after.resize(older_after.rfind(' '));   // "after ID MSY MSZ SAMPLES": no state
  std::ofstream(dir / "swap_audit.log", std::ios::binary)
      << first << final_line << audit_line(swap_record_payload(older)) << audit_line(older_after);
  SwapAudit loaded(dir);
  ASSERT_EQ(loaded.entries().size(), 2u);
  EXPECT_EQ(loaded.entries()[0].after_samples, 500u);
  EXPECT_STREQ(after_state_text(loaded.entries()[0]), "final");
  EXPECT_EQ(loaded.entries()[1].after_samples, 600u);
  EXPECT_STREQ(after_state_text(loaded.entries()[1]), "final");
}

// A swap followed while 400 others of another cell rotate the file (at 32 kB here) again and
// again: the file it was first written in is gone, yet it loads first (the oldest), with its
// figures, because each rotation kept it (the latest of its cell) and carried it into the new file.
TEST(SwapAuditFile, ASwapStillFollowedIsCarriedAcrossRotations) {
  const auto dir = new_state_dir("audit_carried");
  constexpr std::uintmax_t kBound = 32 * 1024;
  {
    SwapAudit audit(dir, kBound);
    SwapEntry followed = swap_of("dyno1", 1, "alice@bench");
    followed.model_after = "dyno1_eccentric";
    audit.add(followed);
    audit.follow("dyno1", health_of("dyno1_eccentric", 1900.0, 2000.0, 500), std::chrono::steady_clock::now());
    for (std::uint64_t i = 2; i <= 401; ++i) audit.add(swap_of("dyno2", i, "bob@bench"));
  }
  std::size_t files = 0;
  for (const auto& file : std::filesystem::directory_iterator(dir)) {
    EXPECT_LE(file.file_size(), kBound) << file.path();
    ++files;
  }
  EXPECT_EQ(files, 2u);
  SwapAudit loaded(dir);
  ASSERT_GE(loaded.entries().size(), 3u);
  const SwapEntry& got = loaded.entries().front();
  EXPECT_EQ(got.id, 1u);
  EXPECT_EQ(got.after_samples, 500u);
  EXPECT_EQ(got.after_rmse_nm[1], 2000.0);
  EXPECT_TRUE(got.after_interrupted);
  EXPECT_EQ(loaded.entries()[1].id, loaded.entries()[2].id - 1);
  EXPECT_GT(loaded.entries()[1].id, 2u);   // the first swaps of dyno2 went with the rotations
  EXPECT_EQ(loaded.entries().back().id, 401u);
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

// 600 swaps of one cell (lines of about 300 bytes) against a bound of 64 kB: rotated, at most
// two files of at most the bound stay, and the latest kKept swaps load from them in order.
TEST(SwapAuditFile, RotatesAtItsBoundAndLoadsAcrossTheTwoFiles) {
  const auto dir = new_state_dir("audit_rotation");
  constexpr std::uintmax_t kBound = 64 * 1024;
  {
    SwapAudit audit(dir, kBound);
    for (std::uint64_t i = 1; i <= 600; ++i) audit.add(swap_of("dyno1", i, "bob"));
  }
  std::uintmax_t total = 0;
  std::size_t files = 0;
  for (const auto& file : std::filesystem::directory_iterator(dir)) {
    EXPECT_LE(file.file_size(), kBound) << file.path();
    total += file.file_size();
    ++files;
  }
  EXPECT_EQ(files, 2u);
  EXPECT_LE(total, 2 * kBound);
  SwapAudit loaded(dir);
  ASSERT_EQ(loaded.entries().size(), SwapAudit::kKept);
  for (std::size_t i = 0; i < loaded.entries().size(); ++i) {
    EXPECT_EQ(loaded.entries()[i].id, 600 - SwapAudit::kKept + 1 + i);
  }
}

/// Every swap of `cell` on disk, oldest first: what the files hold, whatever kKept loads.
std::vector<std::uint64_t> ids_on_disk(const std::filesystem::path& dir, const std::string& cell) {
  std::vector<std::uint64_t> ids;
  SwapAuditFile file(dir);
  for (const SwapEntry& e : file.load(1'000'000)) {
    if (e.test_cell == cell) ids.push_back(e.id);
  }
  return ids;
}

// Issue 38, finding 3: two swaps of cell d with 1.1 MB names (model, by, source) rotated the
// file twice, deleting 4 of cell c's 5 earlier swaps, and left a swap_audit.log.1 of 2.26 MB.
// Now every text field is cut (a line is at most kMaxLineBytes) and nothing of c is lost.
TEST(SwapAuditFile, LongNamesNeitherPushAnotherCellsSwapsOutNorTakeTheFilesBeyondTheirBound) {
  const auto dir = new_state_dir("audit_long_names");
  const std::string huge(1'100'000, 'n');
  {
    SwapAudit audit(dir);
    for (std::uint64_t i = 1; i <= 5; ++i) audit.add(swap_of("c", i, "alice@bench"));
    for (std::uint64_t i = 6; i <= 7; ++i) {
      SwapEntry e = swap_of("d", i, huge);
      e.source = huge;
      e.model_after = huge;
      audit.add(e);
    }
  }
  std::uintmax_t total = 0;
  for (const auto& file : std::filesystem::directory_iterator(dir)) {
    EXPECT_LE(file.file_size(), SwapAuditFile::kRotateBytes) << file.path();
    total += file.file_size();
  }
  EXPECT_LE(total, 2 * SwapAuditFile::kRotateBytes);
  std::ifstream in(dir / "swap_audit.log");
  for (std::string line; std::getline(in, line);) EXPECT_LE(line.size() + 1, SwapAuditFile::kMaxLineBytes);
  EXPECT_EQ(ids_on_disk(dir, "c"), (std::vector<std::uint64_t>{1, 2, 3, 4, 5}));
  const std::vector<std::uint64_t> d = ids_on_disk(dir, "d");
  ASSERT_EQ(d.size(), 2u);
  SwapAudit loaded(dir);
  EXPECT_EQ(loaded.entries().back().model_after.substr(0, 3), "nnn");
  EXPECT_LE(loaded.entries().back().model_after.size(), SwapAuditFile::kMaxFieldBytes);
}

// Issue 38, finding 3: one cell's swaps, however many, never push another cell's latest
// kKeptPerCell swaps off the disk: 1,000 swaps of cell d (about ten rotations at a bound of 32 kB)
// after 5 of cell c and 20 of cell e leave c's 5 and e's latest 8, and the files within 2 bounds.
TEST(SwapAuditFile, ARotationKeepsEachCellsLatestSwapsWhateverAnotherCellSwaps) {
  const auto dir = new_state_dir("audit_per_cell");
  constexpr std::uintmax_t kBound = 32 * 1024;
  {
    SwapAudit audit(dir, kBound);
    std::uint64_t id = 1;
    for (int i = 0; i < 5; ++i) audit.add(swap_of("c", id++, "alice@bench"));
    for (int i = 0; i < 20; ++i) audit.add(swap_of("e", id++, "carol@bench"));
    for (int i = 0; i < 1000; ++i) audit.add(swap_of("d", id++, "mallory@elsewhere"));
    // The trail the status shows (kKept swaps) keeps c's and e's too: d gives up its oldest.
    const auto of = [&](const std::string& cell) {
      return std::count_if(audit.entries().begin(), audit.entries().end(),
                           [&](const SwapEntry& e) { return e.test_cell == cell; });
    };
    EXPECT_EQ(of("c"), 5);
    EXPECT_EQ(of("e"), 20);
    EXPECT_EQ(audit.entries().back().id, 1025u);
  }
  SwapAudit loaded(dir);   // and so does the trail a restarted monitor loads
  EXPECT_EQ(std::count_if(loaded.entries().begin(), loaded.entries().end(),
                          [](const SwapEntry& e) { return e.test_cell == "c"; }), 5);
  std::uintmax_t total = 0;
  for (const auto& file : std::filesystem::directory_iterator(dir)) {
    EXPECT_LE(file.file_size(), kBound) << file.path();
    total += file.file_size();
  }
  EXPECT_LE(total, 2 * kBound);
  EXPECT_EQ(ids_on_disk(dir, "c"), (std::vector<std::uint64_t>{1, 2, 3, 4, 5}));
  const std::vector<std::uint64_t> e = ids_on_disk(dir, "e");
  ASSERT_GE(e.size(), SwapAuditFile::kKeptPerCell);
  EXPECT_EQ(e.back(), 25u);
  EXPECT_EQ(e[e.size() - SwapAuditFile::kKeptPerCell], 25u - SwapAuditFile::kKeptPerCell + 1);
  const std::vector<std::uint64_t> d = ids_on_disk(dir, "d");
  ASSERT_GE(d.size(), SwapAuditFile::kKeptPerCell);
  EXPECT_EQ(d.back(), 1025u);
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
