// The core holds no shared mutable state: results computed on 8 threads at once, on different
// inputs and one shared CouplingGeometry, equal the single-threaded results bit for bit.
// CI also runs this under ThreadSanitizer (.ci/run).
#include <gtest/gtest.h>

#include <cstring>
#include <thread>
#include <vector>

#include "core/coupling_geometry.h"
#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "core/effects/expression.h"
#include "core/induced_moments.h"
#include "core/restoring_torque.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::deg;

struct Evaluation {
  double q, max_load, moment_y, moment_z, stress, jam, restoring;
};

bool bitwise_equal(const Evaluation& a, const Evaluation& b) {
  return std::memcmp(&a, &b, sizeof(Evaluation)) == 0;
}

Evaluation evaluate(const CouplingGeometry& shared, int i) {
  // Alternate between the shared geometry and one built on this thread.
  const CouplingGeometry own(i % 2 ? testing::nrel_downwind() : testing::nrel_upwind());
  const CouplingGeometry& g = i % 3 ? shared : own;
  const OperatingPoint p{2e5 + 1e4 * i, g.jam_angle().angle_rad * (i % 97) / 100.0,
                         deg(3.7 * i), 0.01 * (i % 15)};
  const ToothContact c = tooth_contact(g, p);
  const InducedMoments m = induced_moments(g, p, c);
  return {c.load_sharing.q, c.max_tooth_load_n, m.moment_y_nm, m.moment_z_nm,
          c.max_stress.contact_stress_pa, g.jam_angle().angle_rad, restoring_torque(g).torque_nm};
}

TEST(Reentrancy, EightThreadsMatchSingleThreadedResultsBitForBit) {
  const CouplingGeometry shared(testing::nrel_upwind());
  constexpr int kCases = 800;
  constexpr int kThreads = 8;
  std::vector<Evaluation> serial(kCases);
  for (int i = 0; i < kCases; ++i) serial[i] = evaluate(shared, i);

  std::vector<Evaluation> parallel(kCases);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int i = t; i < kCases; i += kThreads) parallel[i] = evaluate(shared, i);
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int i = 0; i < kCases; ++i) EXPECT_TRUE(bitwise_equal(serial[i], parallel[i])) << i;
}

TEST(Reentrancy, ModelWithEveryEffectOnMatchesSerialResultsBitForBit) {
  std::vector<std::shared_ptr<const Effect>> effects;
  for (const EffectRegistration& r : effect_registry()) {
    // Defaults; the formula needs its terms: one of each kind of input it reads.
    effects.push_back(r.info->name != kExpressionEffect
                          ? r.make({})
                          : make_expression({{"travel_sign_along_moment", 3e3}, {"torque_misalignment_along_misalignment", 0.02},
                                             {"model_z_on_y", 0.01}}));
  }
  const CouplingModel model(testing::nrel_downwind(), effects);
  const auto predict = [&model](int i) {
    MeasurementSample s;
    s.torque_nm = 1e5 + 2e4 * i;
    s.misalignment_rad = deg(1.2) * (i % 50) / 50.0;
    s.direction_rad = deg(7.0 * i);
    s.loading_direction = i % 3 - 1;
    return model.predict(s).moments;
  };
  constexpr int kCases = 400;
  std::vector<SensorMoments> serial(kCases), parallel(kCases);
  for (int i = 0; i < kCases; ++i) serial[i] = predict(i);
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&, t] {
      for (int i = t; i < kCases; i += 8) parallel[i] = predict(i);
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int i = 0; i < kCases; ++i) {
    EXPECT_EQ(std::memcmp(&serial[i], &parallel[i], sizeof(SensorMoments)), 0) << i;
  }
}

}  // namespace
}  // namespace gc
