// Fitting one library effect's parameters to a recording, on top of a base model: bounded
// Levenberg-Marquardt on the parameters scaled by their bounds, from several starts; parameters
// the data cannot determine are held (and say why); uncertainties from the Jacobian at the
// optimum, in physical units.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "diagnosis/bounded_least_squares.h"
#include "diagnosis/parameter_box.h"
#include "core/recorded_sample.h"
#include "diagnosis/parallel_for.h"
#include "core/effects/effect_registry.h"

namespace gc {

struct ParameterEstimate {
  std::string name;
  std::string unit;
  double value = 0.0;           ///< fitted (or held) value [unit]
  /// One standard error [unit], s^2 (J'J)^-1 over the fitted parameters; nullopt when held.
  std::optional<double> standard_error;
  bool held = false;            ///< true when the data could not determine it
  std::string note;             ///< why it was held, or that it sits at a bound
  /// Inside the parameter's plausible range for this coupling (ParameterSpec::plausible) and not on
  /// a physical bound. Advice: an effect best by held-out error stays the answer outside it.
  bool plausible = true;
  /// On a physical bound other than the neutral value: the truth may lie beyond what the effect can
  /// say, so the effect only partly explains.
  bool at_bound = false;
};

struct EffectFit {
  const EffectInfo* info = nullptr;
  std::shared_ptr<const Effect> effect;  ///< with the fitted values
  std::vector<ParameterEstimate> parameters;
  Eigen::VectorXd unit_values;           ///< the fitted values in the unit box
  std::vector<double> box_lower, box_upper;  ///< the box searched, per parameter [unit]
  std::vector<bool> free;                ///< which were fitted (the others were held)
  double sum_of_squares = 0.0;           ///< over both channels of the rows fitted [N²·m²]
  std::size_t rows = 0;
  int evaluations = 0;                   ///< model evaluations over all rows (cost measure)
  /// Every fitted parameter inside its plausible range and none on a physical bound.
  bool plausible() const;
  /// Some fitted parameter on a physical bound (ParameterEstimate::at_bound).
  bool at_bound() const;
  /// The box the fit searched, for a refit.
  ParameterBox box() const;
};

struct FitSettings {
  LeastSquaresOptions least_squares;
  /// Starts from the data beside the generic ones (e.g. a skew by cross-correlation,
  /// delay_estimate.h), each for the effect whose parameters it names; the others at their defaults.
  std::vector<ParameterValues> hints;
  int probe_points = 8;  ///< Halton points whose cost picks the starts
  int starts = 2;        ///< Levenberg-Marquardt runs from the best probes, and the best near neutral
  int scan_points = 101;  ///< a lone free parameter's grid over its box (effect_fit.cc, scanned_start)
  int profile_points = 9;  ///< a profiled parameter's grid over its box (ParameterSpec::profiled)
};

/// The base model with `registration`'s effect at `values`.
CouplingModel model_with(const CouplingModel& base, const EffectRegistration& registration,
                         const ParameterValues& values);

/// Fits the effect to `rows` from several starts and holds unidentifiable parameters. The search
/// box is the plausible range for the base model's coupling (holding `current`'s values, the
/// effect the model has now when this is a refinement), widened to the physical bounds for a
/// parameter that ends on its edge. Returns nullopt when no start can be evaluated (the effect
/// jams every candidate on these rows).
std::optional<EffectFit> fit_effect(const CouplingModel& base, const EffectRegistration& registration,
                                    std::span<const RecordedSample> observations,
                                    std::span<const std::size_t> rows, const ParallelFor& parallel,
                                    const FitSettings& settings, const Effect* current = nullptr);

/// Refits from `start` (held parameters stay held) with at most `iterations` steps: the cheap
/// fit of a cross-validation fold, or the final fit on all rows after a search on a subsample.
std::optional<EffectFit> refit_effect(const CouplingModel& base, const EffectRegistration& registration,
                                      const EffectFit& start, std::span<const RecordedSample> observations,
                                      std::span<const std::size_t> rows, const ParallelFor& parallel,
                                      int iterations, bool with_uncertainty);

}  // namespace gc
