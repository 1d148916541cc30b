#include "tests/diagnosis/zoo/rng.h"

#include <cmath>
#include <numbers>

namespace gc::zoo {

namespace {
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
}  // namespace

std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t salt) {
  return mix(seed + 0x9e3779b97f4a7c15ULL * (salt + 1) + mix(salt ^ 0x5851f42d4c957f2dULL));
}

std::uint64_t derive_seed(std::uint64_t seed, std::string_view salt) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a
  for (const char c : salt) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return derive_seed(seed, h);
}

std::uint64_t Rng::bits() { return mix(state_ += 0x9e3779b97f4a7c15ULL); }

double Rng::uniform() { return (static_cast<double>(bits() >> 11) + 0.5) * 0x1.0p-53; }

double Rng::uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

double Rng::log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }

int Rng::integer(int lo, int hi) {
  const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
  return lo + static_cast<int>(bits() % span);
}

bool Rng::chance(double p) { return uniform() < p; }

double Rng::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double r = std::sqrt(-2.0 * std::log(uniform()));
  const double a = 2.0 * std::numbers::pi * uniform();
  spare_ = r * std::sin(a);
  has_spare_ = true;
  return r * std::cos(a);
}

double Rng::chi2(int dof) {
  double s = 0.0;
  for (int k = 0; k < dof; ++k) {
    const double n = normal();
    s += n * n;
  }
  return s;
}

double Rng::student_t(double dof) {
  // Z / sqrt(V / dof), V ~ chi2(dof) = Gamma(dof / 2, 2); a non-integer dof by Marsaglia-Tsang.
  const double shape = dof / 2.0;
  const double d = (shape < 1.0 ? shape + 1.0 : shape) - 1.0 / 3.0, c = 1.0 / std::sqrt(9.0 * d);
  double g = 0.0;
  for (;;) {
    double x, v;
    do {
      x = normal();
      v = 1.0 + c * x;
    } while (v <= 0.0);
    v = v * v * v;
    const double u = uniform();
    if (std::log(u) < 0.5 * x * x + d - d * v + d * std::log(v)) {
      g = d * v;
      break;
    }
  }
  if (shape < 1.0) g *= std::pow(uniform(), 1.0 / shape);
  return normal() / std::sqrt(2.0 * g / dof);
}

double Rng::laplace() {
  const double u = uniform() - 0.5;
  return (u < 0 ? 1.0 : -1.0) * std::log(1.0 - 2.0 * std::abs(u));
}

double Rng::exponential() { return -std::log(uniform()); }

}  // namespace gc::zoo
