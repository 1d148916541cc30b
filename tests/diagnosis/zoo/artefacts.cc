#include "tests/diagnosis/zoo/artefacts.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {
namespace {

std::vector<double>& col(Channels& c, int k) {
  std::vector<double>* cols[kColumns] = {&c.time_s, &c.torque_nm, &c.zeta_rad, &c.beta_rad,
                                         &c.speed_rpm, &c.temperature_c, &c.msy_nm, &c.msz_nm};
  return *cols[k];
}

ArtefactTruth truth(const Channels& c, int k, const char* kind, std::size_t a, std::size_t b, std::string detail = {}) {
  return {c.rows(), column_name(k), kind, a, b, std::move(detail)};
}

std::pair<double, double> range(const std::vector<double>& v) {
  double lo = 1e300, hi = -1e300;
  for (double x : v) {
    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  }
  return {lo, hi};
}

// Robust sample-to-sample noise of a channel: 1.4826 MAD of first differences / sqrt(2).
double difference_noise(const std::vector<double>& v) {
  std::vector<double> d;
  for (std::size_t i = 1; i < v.size(); ++i) d.push_back(std::abs(v[i] - v[i - 1]));
  if (d.empty()) return 0.0;
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  return 1.4826 * d[d.size() / 2] / std::sqrt(2.0);
}

std::size_t pick_row(Rng& rng, std::size_t lo, std::size_t hi) {  // in [lo, hi]
  return lo + static_cast<std::size_t>(rng.uniform() * static_cast<double>(hi - lo + 1)) % (hi - lo + 1);
}

}  // namespace

std::vector<ArtefactTruth> clip_at_rail(Channels& rec, int k, Rng& rng) {
  auto& v = col(rec, k);
  const auto [lo, hi] = range(v);
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  const bool upper = rng.chance(0.5);
  const double rail = mid + (upper ? 1 : -1) * rng.uniform(0.6, 0.9) * half;
  std::vector<ArtefactTruth> out;
  std::size_t start = 0;
  bool in = false;
  for (std::size_t i = 0; i <= v.size(); ++i) {
    const bool beyond = i < v.size() && (upper ? v[i] >= rail : v[i] <= rail);
    if (beyond) v[i] = rail;
    if (beyond && !in) start = i, in = true;
    if (!beyond && in) {
      out.push_back(truth(rec, k, "clipped", start, i - 1, format("rail %.6g", rail)));
      in = false;
    }
  }
  return out;
}

std::vector<ArtefactTruth> stuck_value(Channels& rec, int k, Rng& rng) {
  auto& v = col(rec, k);
  const std::size_t n = v.size();
  const auto len = static_cast<std::size_t>(std::clamp(rng.log_uniform(20.0, 2000.0), 2.0, std::max(2.0, 0.1 * n)));
  const std::size_t a = pick_row(rng, 1, n - len - 1);
  for (std::size_t i = a; i < a + len; ++i) v[i] = v[a];
  return {truth(rec, k, "stuck", a, a + len - 1, format("held %.6g", v[a]))};
}

std::vector<ArtefactTruth> dropout(Channels& rec, std::set<std::pair<std::size_t, int>>& empty, int k, Rng& rng) {
  auto& v = col(rec, k);
  const std::size_t n = v.size();
  const auto len = static_cast<std::size_t>(std::clamp(rng.log_uniform(1.0, 200.0), 1.0, std::max(1.0, 0.05 * n)));
  const std::size_t a = pick_row(rng, 1, n - len - 1);
  const int style = rng.integer(0, 2);
  for (std::size_t i = a; i < a + len; ++i) {
    if (style == 0) empty.insert({i, k});
    if (style == 1) v[i] = std::nan("");
    if (style == 2) v[i] = 0.0;
  }
  static const char* kinds[] = {"dropout_empty", "dropout_nan", "dropout_zero"};
  return {truth(rec, k, kinds[style], a, a + len - 1)};
}

std::vector<ArtefactTruth> time_gap(Channels& rec, Rng& rng) {
  const std::size_t n = rec.rows();
  const double period = (rec.time_s.back() - rec.time_s.front()) / static_cast<double>(n - 1);
  const double gap = rng.log_uniform(5.0, 500.0) * period;
  const std::size_t a = pick_row(rng, 1, n - 2);
  for (std::size_t i = a; i < n; ++i) rec.time_s[i] += gap;
  return {truth(rec, kTime, "time_gap", a, a, format("gap %.6g s", gap))};
}

std::vector<ArtefactTruth> polarity_flip(Channels& rec, int k, Rng& rng) {
  auto& v = col(rec, k);
  const std::size_t a = pick_row(rng, v.size() / 10, v.size() * 9 / 10);
  for (std::size_t i = a; i < v.size(); ++i) v[i] = -v[i];
  return {truth(rec, k, "polarity_flip", a, v.size() - 1)};
}

std::vector<ArtefactTruth> coarse_quantisation(Channels& rec, int k, Rng& rng) {
  auto& v = col(rec, k);
  const auto [lo, hi] = range(v);
  const double step = rng.uniform(0.02, 0.1) * std::max(hi - lo, 1e-12);
  for (double& x : v) x = step * std::round(x / step);
  return {truth(rec, k, "coarse_quantisation", 0, v.size() - 1, format("step %.6g", step))};
}

std::vector<ArtefactTruth> stamp_jitter_artefact(Channels& rec, Rng& rng) {
  const std::size_t n = rec.rows();
  const double period = (rec.time_s.back() - rec.time_s.front()) / static_cast<double>(n - 1);
  const double sd = rng.uniform(0.05, 0.4) * period;
  for (std::size_t i = 0; i < n; ++i) {
    rec.time_s[i] += sd * rng.normal();
    if (i > 0) rec.time_s[i] = std::max(rec.time_s[i], rec.time_s[i - 1]);
  }
  return {truth(rec, kTime, "stamp_jitter", 0, n - 1, format("sd %.3g s", sd))};
}

std::vector<ArtefactTruth> duplicate_stamps(Channels& rec, Rng& rng) {
  const std::size_t n = rec.rows();
  const int count = rng.integer(1, 20);
  std::set<std::size_t> rows;
  while (static_cast<int>(rows.size()) < count) rows.insert(pick_row(rng, 1, n - 1));
  std::vector<ArtefactTruth> out;
  for (std::size_t i : rows) {
    rec.time_s[i] = rec.time_s[i - 1];
    out.push_back(truth(rec, kTime, "duplicate_stamp", i, i));
  }
  return out;
}

std::vector<ArtefactTruth> backwards_stamp(Channels& rec, Rng& rng) {
  const std::size_t n = rec.rows();
  const double period = (rec.time_s.back() - rec.time_s.front()) / static_cast<double>(n - 1);
  const std::size_t i = pick_row(rng, 2, n - 2);
  rec.time_s[i] = rec.time_s[i - 1] - rng.uniform(0.5, 3.0) * period;
  return {truth(rec, kTime, "backwards_stamp", i, i, format("%.6g s after %.6g s", rec.time_s[i], rec.time_s[i - 1]))};
}

namespace {
double spike_size(const std::vector<double>& v, Rng& rng) {
  const auto [lo, hi] = range(v);
  return std::max(rng.uniform(10.0, 40.0) * difference_noise(v), rng.uniform(0.03, 0.1) * (hi - lo));
}
}  // namespace

std::vector<ArtefactTruth> isolated_spikes_artefact(Channels& rec, int k, Rng& rng) {
  auto& v = col(rec, k);
  const double size = spike_size(v, rng);
  const int count = rng.integer(3, 20);
  std::set<std::size_t> rows;
  for (int tries = 0; static_cast<int>(rows.size()) < count && tries < 1000; ++tries) {
    const std::size_t i = pick_row(rng, 1, v.size() - 2);
    if (!rows.count(i - 1) && !rows.count(i + 1)) rows.insert(i);  // isolated: no neighbour spiked
  }
  std::vector<ArtefactTruth> out;
  for (std::size_t i : rows) {
    const double s = (rng.chance(0.5) ? 1 : -1) * size * rng.uniform(0.8, 1.2);
    v[i] += s;
    out.push_back(truth(rec, k, "spike", i, i, format("%+.6g", s)));
  }
  return out;
}

std::vector<ArtefactTruth> large_run(Channels& rec, int k, Rng& rng) {
  auto& v = col(rec, k);
  const double size = (rng.chance(0.5) ? 1 : -1) * spike_size(v, rng);
  const auto len = static_cast<std::size_t>(rng.integer(5, 60));
  const std::size_t a = pick_row(rng, 1, v.size() - len - 1);
  for (std::size_t i = a; i < a + len; ++i) v[i] += size;
  return {truth(rec, k, "large_run", a, a + len - 1, format("%+.6g", size))};
}

std::vector<ArtefactTruth> ringing_after_torque_steps(Channels& rec, Rng& rng) {
  const std::size_t n = rec.rows();
  const double period = (rec.time_s.back() - rec.time_s.front()) / static_cast<double>(n - 1);
  const double fn = rng.uniform(0.05, 0.25) / period, damping = rng.uniform(0.01, 0.1);
  const double share = rng.uniform(0.05, 0.3);
  const double wn = 2 * std::numbers::pi * fn, wd = wn * std::sqrt(1 - damping * damping);
  const auto [tlo, thi] = range(rec.torque_nm);
  const auto ring_rows = static_cast<std::size_t>(std::ceil(std::log(50.0) / (damping * wn) / period));
  std::vector<ArtefactTruth> out;
  const Channels before = rec;
  for (std::size_t i = 1; i < n; ++i) {
    if (std::abs(before.torque_nm[i] - before.torque_nm[i - 1]) <= 0.05 * (thi - tlo)) continue;
    for (int k : {kMsy, kMsz}) {
      const auto& b = col(const_cast<Channels&>(before), k);
      const double amp = share * (b[i] - b[i - 1]);
      const std::size_t last = std::min(n - 1, i + ring_rows);
      for (std::size_t j = i; j <= last; ++j) {
        const double t = static_cast<double>(j - i) * period;
        col(rec, k)[j] += amp * std::exp(-damping * wn * t) * std::cos(wd * t);
      }
      out.push_back(truth(rec, k, "ringing", i, last, format("fn %.4g Hz damping %.3f amplitude %.6g", fn, damping, amp)));
    }
  }
  return out;
}

const std::vector<std::string>& artefact_kinds() {
  static const std::vector<std::string> kinds = {
      "clipped", "stuck", "dropout_empty", "dropout_nan", "dropout_zero", "time_gap", "polarity_flip",
      "coarse_quantisation", "stamp_jitter", "duplicate_stamp", "backwards_stamp", "spike", "large_run", "ringing"};
  return kinds;
}

ArtefactRecording apply_artefact(const Channels& clean, const std::string& kind, std::uint64_t seed) {
  ArtefactRecording r{clean, {}, {}};
  Rng rng(seed);
  const int moment = rng.chance(0.5) ? kMsy : kMsz;
  const int any[] = {kTorque, kZeta, kBeta, kMsy, kMsz};
  const int channel = any[rng.integer(0, 4)];
  if (kind == "clipped") r.truths = clip_at_rail(r.rec, moment, rng);
  else if (kind == "stuck") r.truths = stuck_value(r.rec, channel, rng);
  else if (kind.rfind("dropout", 0) == 0) {
    // A named style is kept by redrawing until the generator picks it (it draws one of three).
    for (std::uint64_t s = seed;; ++s) {
      ArtefactRecording t{clean, {}, {}};
      Rng g(s);
      t.truths = dropout(t.rec, t.empty, channel, g);
      if (kind == "dropout" || t.truths.front().kind == kind) return t;
    }
  } else if (kind == "time_gap") r.truths = time_gap(r.rec, rng);
  else if (kind == "polarity_flip") r.truths = polarity_flip(r.rec, moment, rng);
  else if (kind == "coarse_quantisation") r.truths = coarse_quantisation(r.rec, channel, rng);
  else if (kind == "stamp_jitter") r.truths = stamp_jitter_artefact(r.rec, rng);
  else if (kind == "duplicate_stamp") r.truths = duplicate_stamps(r.rec, rng);
  else if (kind == "backwards_stamp") r.truths = backwards_stamp(r.rec, rng);
  else if (kind == "spike") r.truths = isolated_spikes_artefact(r.rec, moment, rng);
  else if (kind == "large_run") r.truths = large_run(r.rec, moment, rng);
  else if (kind == "ringing") r.truths = ringing_after_torque_steps(r.rec, rng);
  else throw std::invalid_argument("unknown artefact kind " + kind);
  return r;
}

}  // namespace gc::zoo
