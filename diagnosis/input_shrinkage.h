// The inputs read back toward their own centred average: what a model fed noisy input sensors
// should have been fed. A torque transducer's or a proximity probe's noise e enters the model's
// prediction as dM/dx e, which the bridges never saw; the measured moments then look less
// sensitive to the inputs than the model (errors in the variables attenuate every slope), and any
// effect that lowers the model's sensitivity (a compliance, an offset of the misalignment) fits
// that attenuation with a real held-out gain and no physics. The Wiener estimate of an input
// whose truth moves slowly beside fast noise is its local mean plus a share of its departure from
// it:
//
//   x'(t) = m_W(t) + keep (x(t) - m_W(t)),   m_W(t) = the mean of x over [t - W/2, t + W/2],
//
// keep in [0, 1] (0: the local mean alone; 1: the input as recorded). Centred, so it smooths
// without shifting anything in time; per channel, because each sensor has its own noise.
//
// Or the local median in the place of the mean, for torque and misalignment: a programme's steps
// and ramps pass a centred median unchanged (the median of a monotone stretch is its centre row),
// where a mean smears a torque staircase over the window. A mean had to stay shorter than the
// stairs, too short to average a transducer's noise, and the model fed a noisy torque held next to
// one of its jumps (the integer quarter sums of eqs 13 and 42-43: two more teeth in contact, 2 kN·m
// more moment, within a kN·m of torque) flipped across it; an effect that took the bias this left
// was claimed on noise alone.
#pragma once

#include <cstddef>
#include <map>
#include <span>
#include <tuple>
#include <vector>

#include "core/recorded_sample.h"

namespace gc {

struct InputShrink {
  double window_s = 0.0;  ///< W, the centred window [s]
  double keep = 1.0;      ///< the share of the departure from the window's mean kept, in [0, 1]
  bool median = false;    ///< the window's median in the place of its mean (torque, misalignment)
  bool none() const { return window_s <= 0.0 || keep >= 1.0; }
};

/// One shrink per input channel the paper's model reads.
struct InputShrinks {
  InputShrink torque;        ///< T
  InputShrink misalignment;  ///< zeta
  InputShrink direction;     ///< beta, averaged as a unit vector and kept along the shorter arc
  bool none() const { return torque.none() && misalignment.none() && direction.none(); }
};

/// `observations` with the inputs of `rows` (positions in time order; the windows run over them
/// only, so excluded rows neither feed nor receive an average) read back by `shrinks`. Derived
/// inputs (rates, loading and travel direction) are left as recorded: they are already averaged
/// over half a second. Rows not listed are copied unchanged.
/// `at`: the rows (ascending, a subset of `rows`) whose inputs are wanted; the others are copied
/// unchanged. Empty: all of `rows`.
std::vector<RecordedSample> with_shrunk_inputs(std::span<const RecordedSample> observations,
                                               std::span<const std::size_t> rows, const InputShrinks& shrinks,
                                               std::span<const std::size_t> at = {});

/// The median of `value` over the centred window of `window_s` (as a median read-back's) about each
/// of `at` (ascending, a subset of `rows`), in the order of `at`: no copy of the recording.
std::vector<double> centred_medians(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                    double window_s, std::span<const std::size_t> at,
                                    double (*value)(const MeasurementSample&));

/// with_shrunk_inputs for one trial of shrinks after another (a search over windows and keeps):
/// the recording is copied once, each trial rewrites only the three inputs, and the centred means
/// (or medians) of each channel and window are made once. The same values as with_shrunk_inputs,
/// to the bit.
class InputShrinker {
 public:
  /// Both must outlive the shrinker. `at`: as with_shrunk_inputs' (the centres are made there only).
  InputShrinker(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                std::span<const std::size_t> at = {});
  /// with_shrunk_inputs(observations, rows, shrinks, at), valid until the next call.
  std::span<const RecordedSample> shrunk(const InputShrinks& shrinks);
  /// The same at the listed rows `read` (some of `at`); the others hold whatever an earlier
  /// call left. For a caller that reads no other row (a model predicting those rows alone,
  /// CouplingModel::reads_other_samples): a long recording's 1,500 search rows, not all of it.
  std::span<const RecordedSample> shrunk(const InputShrinks& shrinks, std::span<const std::size_t> read);

 private:
  enum Channel { kTorque, kMisalignment, kDirectionCos, kDirectionSin };
  const std::vector<double>& centres(Channel channel, const InputShrink& shrink);
  /// Each shrunk channel's centred means or medians (null for a channel left as recorded).
  struct Centres {
    const double* torque = nullptr;
    const double* misalignment = nullptr;
    const double* direction_cos = nullptr;
    const double* direction_sin = nullptr;
  };
  Centres centres_for(const InputShrinks& shrinks);
  /// Writes the three inputs of observation rows_[k] by `shrinks`.
  void write(const InputShrinks& shrinks, const Centres& m, std::size_t k);

  std::span<const RecordedSample> observations_;
  std::span<const std::size_t> rows_;
  std::vector<bool> wanted_;  ///< per position of rows_: one of `at`
  std::vector<RecordedSample> buffer_;
  std::vector<std::size_t> position_;  ///< of each observation in rows_ (rows_.size() for none)
  std::map<std::tuple<Channel, double, bool>, std::vector<double>> centres_;
};

}  // namespace gc
