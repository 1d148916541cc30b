// An upper bound on any test's power in one power-mode draw: the detectability of the hidden
// effect by an oracle that knows its exact signal on the moments and the noise's spectrum.
//
// For Gaussian noise n of covariance Sigma and a known signal s, the Neyman-Pearson test of
// "r = n" against "r = s + n" is linear in r and its statistic, standardised, moves by
//   d = sqrt(s' Sigma^-1 s)
// under the effect. At size alpha (one-sided) its power is Phi(d - z_alpha); no test of that size
// does better, and a diagnosis that must also fit the effect's parameters, choose it among many
// and beat every other explanation does worse. At 1 % and 90 % power, d >= 2.326 + 1.282 = 3.61.
//
// Sigma is the draw's own noise (what the recording holds beside the effect, read against the
// model fed the logged inputs, so input-sensor noise carried through the model counts), taken as
// stationary: each channel is whitened by an autoregression fitted to it by Burg's method
// (order by AIC, at most 64), s' Sigma^-1 s ~ the whitened signal's sum of squares over the
// innovations' covariance, the two channels' innovations correlated at lag 0 (a common-mode
// noise; their cross-correlation at other lags is not modelled). For noise that is not
// Gaussian (spikes, steps, a variance that moves) this is the bound for Gaussian noise of the
// same spectrum, an indication, not a proof.
#pragma once

#include <string>
#include <vector>

namespace gc::zoo {

struct OracleBound {
  double d = 0.0;       ///< sqrt(s' Sigma^-1 s) over both channels; NaN where a channel has no noise
  double power = 0.0;   ///< Phi(d - z_0.01): the best power of any one-sided 1 % test
  int order_y = 0, order_z = 0;   ///< the autoregressions' orders
};

/// signal_*: the effect's change of each moment channel [N·m]; noise_*: the rest of the residual
/// [N·m]; all of one length >= 64 and finite (std::invalid_argument otherwise).
OracleBound oracle_bound(const std::vector<double>& signal_y, const std::vector<double>& signal_z,
                         const std::vector<double>& noise_y, const std::vector<double>& noise_z);

/// An autoregression x_t + a_1 x_{t-1} + ... + a_p x_{t-p} = e_t and its innovations' variance.
struct Autoregression {
  std::vector<double> a;
  double innovation_variance = 0.0;
};

/// The whitening above as a linear map: each channel through the autoregression fitted to its
/// noise (Burg, order by AIC, at most 64 or n/10), then the two innovations decorrelated at lag 0
/// (u1 = e_y / sqrt(c_yy), u2 = (e_z - c_yz / c_yy e_y) / sqrt(det / c_yy), so u1^2 + u2^2 =
/// e' C^-1 e). apply(s) has s' Sigma^-1 s as its sum of squares. The identity oracle
/// (identity_oracle.h) measures its distances in it too.
class Whitening {
 public:
  /// noise_*: one length, mean removed here.
  Whitening(const std::vector<double>& noise_y, const std::vector<double>& noise_z);
  /// False where a channel has no noise (no bound).
  bool ok() const { return ok_; }
  /// The whitened vector's length: both channels, less the autoregressions' start-up rows.
  std::size_t size() const { return 2 * (n_ - from_); }
  /// y, z of the noise's length, whitened into out (resized to size()).
  void apply(const std::vector<double>& y, const std::vector<double>& z, std::vector<double>& out) const;
  int order_y() const { return static_cast<int>(ar_y_.a.size()); }
  int order_z() const { return static_cast<int>(ar_z_.a.size()); }

 private:
  Autoregression ar_y_, ar_z_;
  std::size_t from_ = 0, n_ = 0;
  double sy_ = 0.0, rho_ = 0.0, sz_ = 0.0;
  bool ok_ = false;
};

/// The bounds' inputs: std::invalid_argument, naming `who`, unless the four series have one
/// length >= 64 and are finite.
void check_signal_and_noise(const std::string& who, const std::vector<double>& signal_y, const std::vector<double>& signal_z,
                            const std::vector<double>& noise_y, const std::vector<double>& noise_z);

/// Phi(d - z_0.01): the power of a one-sided 1 % test whose statistic moves by d.
double power_at_one_percent(double d);

/// Burg's autoregression of x (mean removed): coefficients a_1..a_p with
/// x_t + a_1 x_{t-1} + ... + a_p x_{t-p} = e_t, and the innovations' variance.
Autoregression burg(const std::vector<double>& x, int order);

}  // namespace gc::zoo
