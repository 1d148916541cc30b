#include "core/effects/ringing_response.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <complex>
#include <numbers>
#include <type_traits>

namespace gc {

RingingPole::RingingPole(const RingingMode& m) {
  const double wn = 2.0 * std::numbers::pi * m.natural_frequency_hz;
  const double root = std::sqrt(1.0 - m.damping_ratio * m.damping_ratio);
  s_ = {-m.damping_ratio * wn, wn * root};
  a_ = {-1.0, m.damping_ratio / root};
  gaps_.fill(std::numeric_limits<double>::quiet_NaN());
}

namespace {

/// Where a change is forgotten: e^{-zeta w_n tau} below this.
constexpr double kForgotten = 1e-6;

}  // namespace

std::vector<double> ringing_sequence(std::span<const double> times_s, std::span<const double> inputs,
                                     const RingingMode& mode) {
  RingingPole pole(mode);
  std::vector<double> r(inputs.size(), 0.0);
  std::complex<double> sum = 0.0;
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    r[i] = pole.next(sum, times_s[i] - times_s[i - 1], inputs[i] - inputs[i - 1]);
  }
  return r;
}

double ringing_memory_s(const RingingMode& mode) {
  // -Re s of RingingPole, written out: a pole fills its 64-gap cache.
  return -std::log(kForgotten) / (mode.damping_ratio * (2.0 * std::numbers::pi * mode.natural_frequency_hz));
}

namespace {

/// Blocks a memory long: a row pays up to a block past its memory for sharing the block's pass
/// (1.5 memories on average, alone), and a pass over every row steps each sample twice. Shorter
/// blocks cost a lone row less and a pass more (a quarter: 1.125 and 5).
constexpr double kBlocksPerMemory = 1.0;

/// The inputs of sample k of a recording or a sequence.
template <class Samples>
const MeasurementSample& input(const Samples& samples, std::size_t k) {
  if constexpr (std::is_same_v<Samples, InputHistory>) {
    return samples.at(k);
  } else {
    return samples[k].input;
  }
}

/// Where the pass for sample i starts: the last sample k <= i at or before a memory before the
/// start of i's block (0 when none). A search by time over [0, i].
template <class Samples>
std::size_t anchor_of(const Samples& samples, std::size_t i, double memory_s) {
  const double block_s = memory_s / kBlocksPerMemory;
  const double before_s = std::floor(input(samples, i).time_s / block_s) * block_s - memory_s;
  std::size_t lo = 0, hi = i + 1;  // the first k with t_k > before_s lies in [lo, hi]
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (input(samples, mid).time_s > before_s) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return lo == 0 ? 0 : lo - 1;
}

/// S stepped from `from` (its value there) over the changes of samples from + 1 .. to.
template <class Samples>
std::complex<double> stepped(const Samples& samples, std::size_t from, std::size_t to, std::complex<double> sum,
                             RingingPole& pole) {
  if (to <= from) return sum;
  double t = input(samples, from).time_s, u = input(samples, from).torque_nm;  // sample k - 1's
  for (std::size_t k = from + 1; k <= to; ++k) {
    const MeasurementSample& now = input(samples, k);
    pole.next(sum, now.time_s - t, now.torque_nm - u);
    t = now.time_s;
    u = now.torque_nm;
  }
  return sum;
}

}  // namespace

double ringing_history_s(const RingingMode& mode) {
  return ringing_memory_s(mode) * (1.0 + 1.0 / kBlocksPerMemory);
}

double torque_ringing_at(const InputHistory& history, const RingingMode& mode) {
  RingingPole pole(mode);
  const std::size_t i = history.index();
  return stepped(history, anchor_of(history, i, ringing_memory_s(mode)), i, 0.0, pole).real();
}

std::vector<double> torque_ringing_at_rows(std::span<const RecordedSample> recording,
                                           std::span<const std::size_t> rows, const RingingMode& mode) {
  RingingPole pole(mode);
  const double memory_s = ringing_memory_s(mode);
  std::vector<double> r(rows.size());
  std::size_t anchor = 0, at = 0;  // the pass: from `anchor`, S at sample `at`
  std::complex<double> sum = 0.0;
  bool open = false;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::size_t i = rows[k];
    const std::size_t a = anchor_of(recording, i, memory_s);
    if (!open || a != anchor || i < at) {  // a new block, or a row out of time order
      anchor = at = a;
      sum = 0.0;
      open = true;
    }
    sum = stepped(recording, at, i, sum, pole);
    at = i;
    r[k] = sum.real();
  }
  return r;
}

}  // namespace gc
