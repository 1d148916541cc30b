// The upper tail of a Beta distribution fitted by its moments: the chance that a share explained
// (a statistic in [0, 1], such as R^2, which for Gaussian noise is Beta(p/2, (n - p)/2) exactly)
// reaches `observed`, given the mean and variance of shares drawn under the null.
#pragma once

namespace gc {

/// I_x(a, b), the regularized incomplete beta function, for x in [0, 1] and a, b > 0 (the continued
/// fraction of Numerical Recipes 6.4, evaluated by the modified Lentz method).
double regularized_incomplete_beta(double x, double a, double b);

/// P(share >= observed) for the Beta distribution with `mean` and `variance` (method of moments);
/// 1 when the moments admit no Beta (variance at least mean (1 - mean)) or `observed` is not above
/// the mean.
double beta_upper_tail(double observed, double mean, double variance);

}  // namespace gc
