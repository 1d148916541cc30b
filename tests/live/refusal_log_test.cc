// The monitor's refusals (live/refusal_log.h, issue 38 finding 7): every one counted by kind;
// the log gets a kind's first with its reason, then at most one summary a second, whatever the
// rate; odd bytes of a sample are shown escaped. Time is given to the log, not waited for.
#include <gtest/gtest.h>

#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>

#include <memory>
#include <string>
#include <vector>

#include "live/refusal_log.h"

namespace gc::live {
namespace {

using namespace std::chrono_literals;

/// spdlog's default logger into a ring buffer for the test's life.
class CapturedLog {
 public:
  CapturedLog() : sink_(std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(100'000)), previous_(spdlog::default_logger()) {
    spdlog::set_default_logger(std::make_shared<spdlog::logger>("captured", sink_));
  }
  ~CapturedLog() { spdlog::set_default_logger(previous_); }
  std::vector<std::string> lines() const { return sink_->last_formatted(); }

 private:
  std::shared_ptr<spdlog::sinks::ringbuffer_sink_mt> sink_;
  std::shared_ptr<spdlog::logger> previous_;
};

// The finding: a batch whose test-cell name has odd bytes wrote a warning line per batch (4.5 MB
// of log in 0.4 s). 100,000 such refusals in 0.4 s now write one line; they are all counted.
TEST(RefusalLog, AFloodOfOneKindWritesItsFirstLineThenAtMostOneSummaryASecond) {
  CapturedLog log;
  RefusalLog refusals;
  const auto t0 = RefusalLog::Clock::now();
  for (int i = 0; i < 100'000; ++i) {
    refusals.refuse(Refusal::batch_bad_name, "measurement batch refused: '\x01\xff'", 1, t0 + i * 4us);
  }
  EXPECT_EQ(refusals.count(Refusal::batch_bad_name), 100'000u);
  EXPECT_EQ(refusals.samples(Refusal::batch_bad_name), 100'000u);
  ASSERT_EQ(log.lines().size(), 1u);
  EXPECT_NE(log.lines()[0].find("'\\x01\\xff'"), std::string::npos) << log.lines()[0];
  EXPECT_NE(log.lines()[0].find("batch_bad_name"), std::string::npos) << log.lines()[0];

  // The burst ends: the next flush a second after the first line tells the rest, once.
  refusals.flush(t0 + 500ms);
  EXPECT_EQ(log.lines().size(), 1u);
  refusals.flush(t0 + 1s);
  ASSERT_EQ(log.lines().size(), 2u);
  EXPECT_NE(log.lines()[1].find("99999 more refusals batch_bad_name"), std::string::npos) << log.lines()[1];
  refusals.flush(t0 + 5s);
  EXPECT_EQ(log.lines().size(), 2u);

  // Ten seconds of one refusal a millisecond: one summary a second, not 10,000 lines.
  for (int i = 0; i < 10'000; ++i) refusals.refuse(Refusal::batch_bad_name, "again", 1, t0 + 5s + i * 1ms);
  EXPECT_LE(log.lines().size(), 2u + 10u);
  EXPECT_GE(log.lines().size(), 2u + 9u);
  EXPECT_EQ(refusals.lines(), log.lines().size());
}

TEST(RefusalLog, EachKindIsCountedAndLoggedOnItsOwn) {
  CapturedLog log;
  RefusalLog refusals;
  const auto t0 = RefusalLog::Clock::now();
  refusals.refuse(Refusal::batch_oversized, "5000 samples", 5000, t0);
  refusals.refuse(Refusal::swap_bad_model, "model.coupling_file: refused", 0, t0);
  refusals.refuse(Refusal::swap_bad_model, "model.coupling_file: refused", 0, t0 + 1ms);
  EXPECT_EQ(refusals.count(Refusal::batch_oversized), 1u);
  EXPECT_EQ(refusals.samples(Refusal::batch_oversized), 5000u);
  EXPECT_EQ(refusals.count(Refusal::swap_bad_model), 2u);
  EXPECT_EQ(refusals.count(Refusal::batch_foreign), 0u);
  EXPECT_EQ(log.lines().size(), 2u);
  for (std::size_t k = 0; k < kRefusalKinds; ++k) {
    EXPECT_STRNE(refusal_kind(static_cast<Refusal>(k)), "unknown");
  }
}

TEST(RefusalLog, PrintableEscapesOddBytesAndBoundsTheLength) {
  EXPECT_EQ(printable("dyno\n\x7f\xc3"), "dyno\\x0a\\x7f\\xc3");
  const std::string shown = printable(std::string(10'000, 'x'), 100);
  EXPECT_EQ(shown.size(), 103u);
  EXPECT_EQ(shown.substr(100), "...");
}

}  // namespace
}  // namespace gc::live
