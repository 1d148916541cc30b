// The plain-language verdict of one diagnosis round.
#pragma once

#include <string>

namespace gc {

struct DiagnosisRound;
struct EffectFit;

/// e.g. "Round 1: the residual in Msz' is explained by friction (...): mu0 = 0.06 (+/- 0.002) -,
/// ...; held-out RMSE falls 71 % (12.3 kN·m to 3.6 kN·m; noise 3.4 kN·m)."
std::string round_verdict(int number, const DiagnosisRound& round);

/// "name = value (+/- error) unit" for every parameter, held ones marked.
std::string fitted_parameters_text(const EffectFit& fit);

/// A number to 3 significant digits.
std::string short_number(double value);

}  // namespace gc
