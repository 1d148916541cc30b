#include "tests/diagnosis/independent/test_cell_noise.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gc::independent {
namespace {

// Distinct seeds for the two channels so that y and z noise are independent.
constexpr std::uint64_t kChannelZSalt = 0x632be59bd9b4e019ULL;

ChannelNoise zeros(std::size_t count) { return ChannelNoise(count, SensorMoments{0.0, 0.0}); }

}  // namespace

std::uint64_t NoiseStream::next_bits() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double NoiseStream::uniform() {
  // 53 random bits, shifted away from zero so that log() stays finite.
  return (static_cast<double>(next_bits() >> 11) + 1.0) * 0x1.0p-53;
}

double NoiseStream::standard_normal() {
  const double u1 = uniform();
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

ChannelNoise white_noise(std::size_t count, double sigma_nm, std::uint64_t seed) {
  NoiseStream y(seed), z(seed ^ kChannelZSalt);
  ChannelNoise noise = zeros(count);
  for (SensorMoments& n : noise) {
    n.y_nm = sigma_nm * y.standard_normal();
    n.z_nm = sigma_nm * z.standard_normal();
  }
  return noise;
}

ChannelNoise ar1_noise(std::size_t count, double phi, double sigma_nm, std::uint64_t seed) {
  if (!(std::abs(phi) < 1.0)) throw std::invalid_argument("ar1_noise: |phi| must be below 1");
  NoiseStream y(seed), z(seed ^ kChannelZSalt);
  const double innovation = sigma_nm * std::sqrt(1.0 - phi * phi);
  ChannelNoise noise = zeros(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (i == 0) {
      noise[i] = {sigma_nm * y.standard_normal(), sigma_nm * z.standard_normal()};
    } else {
      noise[i].y_nm = phi * noise[i - 1].y_nm + innovation * y.standard_normal();
      noise[i].z_nm = phi * noise[i - 1].z_nm + innovation * z.standard_normal();
    }
  }
  return noise;
}

ChannelNoise spiky_noise(std::size_t count, double sigma_nm, double outlier_share,
                         double outlier_sigmas, std::uint64_t seed) {
  ChannelNoise noise = white_noise(count, sigma_nm, seed);
  NoiseStream y(seed + 1), z((seed + 1) ^ kChannelZSalt);
  const auto spike = [&](NoiseStream& s) {
    if (s.uniform() > outlier_share) return 0.0;
    return (s.uniform() < 0.5 ? -1.0 : 1.0) * outlier_sigmas * sigma_nm;
  };
  for (SensorMoments& n : noise) {
    n.y_nm += spike(y);
    n.z_nm += spike(z);
  }
  return noise;
}

ChannelNoise random_walk_drift(std::size_t count, double step_nm, std::uint64_t seed, bool y,
                               bool z) {
  NoiseStream sy(seed), sz(seed ^ kChannelZSalt);
  ChannelNoise noise = zeros(count);
  SensorMoments level{0.0, 0.0};
  for (SensorMoments& n : noise) {
    level.y_nm += step_nm * sy.standard_normal();
    level.z_nm += step_nm * sz.standard_normal();
    n = {y ? level.y_nm : 0.0, z ? level.z_nm : 0.0};
  }
  return noise;
}

ChannelNoise sine_drift(const std::vector<double>& times_s, double amplitude_nm, double period_s,
                        std::uint64_t seed, bool y, bool z) {
  NoiseStream s(seed);
  const double phase = 2.0 * std::numbers::pi * s.uniform();
  ChannelNoise noise = zeros(times_s.size());
  for (std::size_t i = 0; i < times_s.size(); ++i) {
    const double v = amplitude_nm * std::sin(2.0 * std::numbers::pi * times_s[i] / period_s + phase);
    noise[i] = {y ? v : 0.0, z ? v : 0.0};
  }
  return noise;
}

ChannelNoise operator+(const ChannelNoise& a, const ChannelNoise& b) {
  if (a.size() != b.size()) throw std::invalid_argument("noise lengths differ");
  ChannelNoise sum = a;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sum[i].y_nm += b[i].y_nm;
    sum[i].z_nm += b[i].z_nm;
  }
  return sum;
}

}  // namespace gc::independent
