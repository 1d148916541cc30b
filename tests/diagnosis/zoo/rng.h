// The zoo's random numbers: SplitMix64 (Steele, Lea, Flood 2014) with the distributions the noise
// families draw from. Portable (same numbers on every platform), seeded, and cheap to fork: a
// draw's sub-streams are derived from its seed by derive_seed, so one part of a draw (e.g. the
// noise of one family) does not shift when another part draws more or fewer numbers.
#pragma once

#include <cstdint>
#include <string_view>

namespace gc::zoo {

/// Mixes `seed` and a salt into an independent seed (a SplitMix64 step of their combination).
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t salt);
/// The same with a text salt (FNV-1a of it), e.g. a family's name.
std::uint64_t derive_seed(std::uint64_t seed, std::string_view salt);

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t bits();
  double uniform();                        ///< in (0, 1)
  double uniform(double lo, double hi);    ///< in (lo, hi)
  double log_uniform(double lo, double hi);///< log-uniform in (lo, hi), lo > 0
  int integer(int lo, int hi);             ///< uniform in [lo, hi]
  bool chance(double p);                   ///< true with probability p
  double normal();                         ///< N(0, 1), Box-Muller (both values used)
  double student_t(double dof);            ///< Student-t, unit scale (not unit variance)
  double laplace();                        ///< Laplace, unit scale b = 1 (variance 2)
  double chi2(int dof);                    ///< sum of dof squared normals
  double exponential();                    ///< Exp(1)

 private:
  std::uint64_t state_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace gc::zoo
