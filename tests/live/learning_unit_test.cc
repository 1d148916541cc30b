// The learning loop's parts without DDS: the rolling window (live/sample_window.h), the proposal
// a diagnosis makes (live/proposal.h), the worker's bounds (live/diagnosis_worker.h) and the
// audit trail (live/swap_audit.h).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "analysis/recording_csv.h"
#include "codec/bundled_data.h"
#include "core/model_error.h"
#include "live/cell_model.h"
#include "live/diagnosis_worker.h"
#include "live/proposal.h"
#include "live/sample_window.h"
#include "live/swap_audit.h"

namespace gc::live {
namespace {

using namespace std::chrono_literals;

CellModel paper() {
  return load_cell_model("paper", codec::bundled_data_dir("models"),
                         codec::bundled_data_dir("couplings"));
}

std::vector<RecordedSample> hidden_eccentricity() {
  return analysis::read_recording(GC_SOURCE_DIR "/data/recordings/hidden_eccentricity_torque_ramp.csv").samples;
}

RecordedSample at(double t) {
  RecordedSample s;
  s.input.time_s = t;
  return s;
}

TEST(SampleWindow, KeepsEverySampleWhileThereIsRoom) {
  SampleWindow window(100, 1.0);
  for (int i = 0; i < 50; ++i) window.add(at(0.001 * i));
  EXPECT_EQ(window.size(), 50u);
  EXPECT_EQ(window.stride(), 1u);
}

TEST(SampleWindow, ThinsAFastStreamToSpanItsTimeInBoundedMemory) {
  SampleWindow window(100, 1.0);
  for (int i = 0; i < 100000; ++i) window.add(at(1e-4 * i));   // 10 s at 10 kHz
  EXPECT_LE(window.size(), 100u);
  const auto samples = window.samples();
  EXPECT_GE(samples.back().input.time_s - samples.front().input.time_s, 1.0);
  EXPECT_NEAR(samples.back().input.time_s, 9.9999, 0.1);   // the latest, not the first
  EXPECT_GT(window.stride(), 1u);
  for (std::size_t i = 1; i < samples.size(); ++i) {
    EXPECT_GT(samples[i].input.time_s, samples[i - 1].input.time_s);
  }
}

TEST(SampleWindow, SlidesWhenFullAndSpanningItsTime) {
  SampleWindow window(10, 1.0);
  for (int i = 0; i < 100; ++i) window.add(at(1.0 * i));
  EXPECT_EQ(window.size(), 10u);
  EXPECT_EQ(window.stride(), 1u);
  EXPECT_EQ(window.samples().front().input.time_s, 90.0);
  window.clear();
  EXPECT_EQ(window.size(), 0u);
}

TEST(SampleWindow, RefusesABadSizeNamingIt) {
  try {
    SampleWindow window(1, 1.0);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "diagnosis_samples");
  }
  EXPECT_THROW(SampleWindow(10, 0.0), InvalidInput);
}

TEST(Proposal, TheDiagnosisOfTheHiddenEffectProposesItWithTheModelText) {
  const auto samples = hidden_eccentricity();
  const DiagnosisOutcome outcome = run_job({"cell", 1, paper(), samples, std::nullopt});
  ASSERT_TRUE(outcome.proposal.has_value()) << outcome.note;
  const Proposal& p = *outcome.proposal;
  EXPECT_EQ(p.effects, "eccentricity");
  EXPECT_EQ(p.kind, "addition");
  EXPECT_EQ(p.outcome, "effect_found");
  EXPECT_EQ(p.base_model, "paper");
  EXPECT_EQ(p.model_name, "paper_diagnosed");
  EXPECT_EQ(p.window_samples, samples.size());
  EXPECT_NEAR(p.reduction(), 0.6, 0.1);   // diagnose: 4.86 to 1.96 kN·m
  EXPECT_GT(outcome.cpu_s, 0.0);
  ASSERT_FALSE(p.parameters.empty());
  EXPECT_EQ(p.parameters[0].effect, "eccentricity");
  // The text is a model file the monitor takes, and with it the error falls to the noise.
  const CellModel proposed = parse_cell_model(p.model_text, "proposal", codec::bundled_data_dir("couplings"));
  EXPECT_EQ(proposed.name, "paper_diagnosed");
  const double before = *pooled_rmse(*paper().model, samples);
  const double after = *pooled_rmse(*proposed.model, samples);
  EXPECT_LT(after, 0.5 * before);
  EXPECT_LT(after, 1.1 * p.noise_nm);
}

TEST(Proposal, NothingIsProposedForNoise) {
  const auto samples = analysis::read_recording(GC_SOURCE_DIR "/data/recordings/paper_torque_ramp.csv").samples;
  const DiagnosisOutcome outcome = run_job({"cell", 1, paper(), samples, std::nullopt});
  EXPECT_FALSE(outcome.proposal.has_value());
  EXPECT_NE(outcome.note.find("the residual is noise"), std::string::npos) << outcome.note;
}

TEST(Proposal, ARecheckComparesBothModelsOnTheNewerSamples) {
  const auto samples = hidden_eccentricity();
  Proposal standing;
  standing.model = paper().model;   // a "proposal" no better than the model: not below it
  const DiagnosisOutcome outcome = run_job({"cell", 1, paper(), samples, standing});
  ASSERT_TRUE(outcome.rechecked.has_value());
  ASSERT_TRUE(outcome.base_rmse_nm && outcome.proposed_rmse_nm);
  EXPECT_DOUBLE_EQ(*outcome.base_rmse_nm, *outcome.proposed_rmse_nm);
}

TEST(Proposal, ReplacesOnlyWhenItRemovesMoreOfTheError) {
  Proposal standing, better, worse;
  standing.before_rmse_nm = better.before_rmse_nm = worse.before_rmse_nm = 100.0;
  standing.after_rmse_nm = 50.0;
  better.after_rmse_nm = 40.0;
  worse.after_rmse_nm = 60.0;
  EXPECT_TRUE(replaces(better, standing));
  EXPECT_FALSE(replaces(worse, standing));
  standing.state = ProposalState::withdrawn;
  EXPECT_TRUE(replaces(worse, standing));
}

TEST(DiagnosisWorker, OneJobPerCellAndABoundedQueue) {
  std::atomic<int> done{0};
  DiagnosisWorker worker(2, 0, 1.0, [&] { ++done; });
  const CellModel model = paper();
  const auto samples = hidden_eccentricity();
  Proposal recheck;
  recheck.model = model.model;
  // a: a diagnosis, seconds long, so still queued or running when a is submitted again.
  EXPECT_TRUE(worker.submit({"a", 1, model, samples, std::nullopt}));
  EXPECT_FALSE(worker.submit({"a", 1, model, samples, recheck}));
  EXPECT_TRUE(worker.busy("a"));
  EXPECT_TRUE(worker.submit({"b", 2, model, samples, recheck}));
  // At most 2 waiting: a third cell is refused unless a's job has started.
  const bool c = worker.submit({"c", 3, model, samples, recheck});
  std::vector<DiagnosisOutcome> outcomes;
  const auto until = std::chrono::steady_clock::now() + 60s;
  while (outcomes.size() < (c ? 3u : 2u) && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(10ms);
    for (auto& o : worker.take_outcomes()) outcomes.push_back(std::move(o));
  }
  ASSERT_EQ(outcomes.size(), c ? 3u : 2u);
  EXPECT_EQ(outcomes[0].test_cell, "a");   // one at a time, in order
  EXPECT_EQ(outcomes[1].test_cell, "b");
  EXPECT_EQ(done.load(), static_cast<int>(outcomes.size()));
  EXPECT_FALSE(worker.busy("a"));
}

TEST(DiagnosisWorker, StoppingCancelsTheRunningDiagnosisAndDropsItsOutcome) {
  std::atomic<int> done{0};
  {
    DiagnosisWorker worker(1, 19, 0.25, [&] { ++done; });
    ASSERT_TRUE(worker.submit({"a", 1, paper(), hidden_eccentricity(), std::nullopt}));
    std::this_thread::sleep_for(50ms);   // running, seconds from its end
  }
  EXPECT_EQ(done.load(), 0);
}

TEST(SwapAudit, KeepsTheLatestSwapsAndFollowsTheModelInForce) {
  SwapAudit audit;
  for (std::size_t i = 0; i < SwapAudit::kKept + 3; ++i) {
    SwapEntry entry;
    entry.test_cell = i % 2 == 0 ? "cell0" : "cell1";
    entry.model_after = "m";
    entry.model_after += std::to_string(i);
    audit.add(entry);
  }
  EXPECT_EQ(audit.entries().size(), SwapAudit::kKept);
  EXPECT_EQ(audit.total(), SwapAudit::kKept + 3);
  const std::string latest = audit.entries().back().model_after;
  HealthReport health;
  health.model.model_name = latest;
  health.model.channels[0].rmse_nm = 1.0;
  health.model.channels[1].rmse_nm = 2.0;
  health.window_samples = 10;
  audit.follow(audit.entries().back().test_cell, health);
  EXPECT_EQ(audit.entries().back().after_rmse_nm[1], 2.0);
  EXPECT_EQ(audit.entries().back().after_samples, 10u);
  // Frozen once the cell is gone: later health changes nothing.
  audit.freeze(audit.entries().back().test_cell);
  health.model.channels[1].rmse_nm = 5.0;
  audit.follow(audit.entries().back().test_cell, health);
  EXPECT_EQ(audit.entries().back().after_rmse_nm[1], 2.0);
}

}  // namespace
}  // namespace gc::live
