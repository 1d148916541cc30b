// A bracketed scalar root finder (Illinois variant of regula falsi): never leaves the bracket,
// converges superlinearly on smooth functions. Used by eq 23 and its inverse.
#pragma once

#include <cmath>
#include <optional>

namespace gc {

/// Root of `f` in [lo, hi] to within `tolerance` in x, or empty when f(lo) and f(hi) have the
/// same sign. `f` must be continuous on the bracket.
template <typename Function>
std::optional<double> find_bracketed_root(const Function& f, double lo, double hi,
                                          double tolerance, int max_iterations = 200) {
  double f_lo = f(lo);
  double f_hi = f(hi);
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if ((f_lo < 0.0) == (f_hi < 0.0)) return std::nullopt;
  int side = 0;  // which end was kept last time, for the Illinois halving
  double x = lo;
  for (int i = 0; i < max_iterations && hi - lo > tolerance; ++i) {
    x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double f_x = f(x);
    if (f_x == 0.0) return x;
    if ((f_x < 0.0) == (f_lo < 0.0)) {
      lo = x;
      f_lo = f_x;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = x;
      f_hi = f_x;
      if (side == +1) f_lo *= 0.5;
      side = +1;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace gc
