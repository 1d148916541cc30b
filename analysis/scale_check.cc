#include "analysis/scale_check.h"

#include <array>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/engineering_text.h"
#include "core/model_error.h"

namespace gc::analysis {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
constexpr std::array<double, 4> kUnitSlips{10.0, 100.0, 1000.0, kDegreesPerRadian};
// A factor of 1000 is a kilo prefix slipped: never a model that wrong.
constexpr double kRefusedSlip = 1000.0;
// Within a factor of 1.5 of a slip: 10 matches 6.7-15, 57.3 matches 38-86. A model wrong by
// 3-5 times (no unit at fault) matches none.
constexpr double kSlipTolerance = 1.5;
// Plausible misalignments in jam angles: a test cell runs within the jam angle.
constexpr double kPlausibleLow = 0.1, kPlausibleHigh = 3.0;

std::string_view channel_hint(double ratio) {
  return ratio > 1.0 ? "too large" : "too small";
}

}  // namespace

std::optional<double> unit_slip_factor(double ratio) {
  if (!(ratio > 0.0) || !std::isfinite(ratio)) return std::nullopt;
  const double distance_to_one = std::abs(std::log(ratio));
  std::optional<double> nearest;
  double nearest_distance = std::log(kSlipTolerance);
  for (double slip : kUnitSlips) {
    const double distance = std::abs(distance_to_one - std::log(slip));
    if (distance < nearest_distance) {
      nearest = slip;
      nearest_distance = distance;
    }
  }
  return nearest;
}

void MomentScale::add(const SensorMoments& measured, const SensorMoments& predicted) {
  measured_y_ += measured.y_nm * measured.y_nm;
  measured_z_ += measured.z_nm * measured.z_nm;
  model_y_ += predicted.y_nm * predicted.y_nm;
  model_z_ += predicted.z_nm * predicted.z_nm;
  ++count_;
}

std::vector<std::string> MomentScale::warnings(std::string_view model_name) const {
  std::vector<std::string> warnings;
  for (ChannelSlip& slip : slips(model_name)) warnings.push_back(std::move(slip.warning));
  return warnings;
}

std::optional<std::string> MomentScale::refusal(std::string_view model_name) const {
  for (ChannelSlip& slip : slips(model_name)) {
    if (slip.factor == kRefusedSlip) return std::move(slip.warning);
  }
  return std::nullopt;
}

std::string unit_slip_error(std::string_view source, std::string_view refusal, UnitFix fix) {
  std::string_view remedy;
  switch (fix) {
    case UnitFix::cli:
      remedy = "give the column its unit (rename it in the file, or --columns msy_knm=HEADER), "
               "or --force-scale to run anyway";
      break;
    case UnitFix::python:
      remedy = "give the column its unit (rename it, or columns={'msy_knm': 'HEADER'}), or "
               "force_scale=True to run anyway";
      break;
    case UnitFix::stream:
      remedy = "the publisher must send N·m (the measurement's _nm members; kN·m x 1000); no "
               "diagnosis meanwhile";
      break;
  }
  return fmt::format("{}: unit error: {}; a fit to moments 1000 times off says nothing: {}",
                     source, refusal, remedy);
}

void refuse_unit_slip(std::string_view source, const std::optional<std::string>& refusal,
                      UnitFix fix) {
  if (!refusal) return;
  throw InvalidInput("recording", unit_slip_error(source, *refusal, fix));
}

std::vector<MomentScale::ChannelSlip> MomentScale::slips(std::string_view model_name) const {
  std::vector<ChannelSlip> warnings;
  if (count_ == 0) return warnings;
  const double n = static_cast<double>(count_);
  const double model_y = std::sqrt(model_y_ / n), model_z = std::sqrt(model_z_ / n);
  const struct {
    std::string_view name, column;
    double measured, model, other_model;
  } channels[] = {{"M_sy'", "msy", std::sqrt(measured_y_ / n), model_y, model_z},
                  {"M_sz'", "msz", std::sqrt(measured_z_ / n), model_z, model_y}};
  for (const auto& c : channels) {
    if (!(c.model > 0.1 * c.other_model) || c.model <= 0.0) continue;
    const double ratio = c.measured / c.model;
    const std::optional<double> slip = unit_slip_factor(ratio);
    if (!slip) continue;
    warnings.push_back({*slip, fmt::format(
        "{} measured RMS {} is {:.4g} times the model {}'s {}, {} by about {:g}: "
        "check the unit of the {} column (N·m under _knm? kN·m under _nm?{})",
        c.name, engineering_text(c.measured, "N·m"), ratio, model_name,
        engineering_text(c.model, "N·m"), channel_hint(ratio), *slip, c.column,
        *slip == kUnitSlips.back() ? " or degrees and radians in the misalignment's" : "")});
  }
  return warnings;
}

std::optional<std::string> torque_scale_warning(double largest_torque_nm, double reference_torque_nm) {
  if (!(largest_torque_nm > 0.0) || !(reference_torque_nm > 0.0)) return std::nullopt;
  const double share = largest_torque_nm / reference_torque_nm;
  const bool plausible_in_knm = share * kRefusedSlip >= kPlausibleLow && share * kRefusedSlip <= kPlausibleHigh;
  if (share >= 0.01 || !plausible_in_knm) return std::nullopt;
  return fmt::format("torque reaches only {}, {:.3g} of T_ref ({}): kN·m under a _nm header? "
                     "(1000 times too small: give the column its unit, torque_knm)",
                     engineering_text(largest_torque_nm, "N·m"), share,
                     engineering_text(reference_torque_nm, "N·m"));
}

std::optional<std::string> misalignment_scale_warning(double largest_misalignment_rad,
                                                      double jam_angle_rad) {
  if (!(largest_misalignment_rad > 0.0) || !(jam_angle_rad > 0.0)) return std::nullopt;
  const double in_jam_angles = largest_misalignment_rad / jam_angle_rad;
  const auto plausible = [](double x) { return x >= kPlausibleLow && x <= kPlausibleHigh; };
  if (in_jam_angles > kPlausibleHigh && plausible(in_jam_angles / kDegreesPerRadian)) {
    return fmt::format("misalignment reaches {}, {:.3g} times the jam angle ({}): "
                       "degrees under a _rad header? (57.3 times too large)",
                       engineering_text(largest_misalignment_rad, "rad"), in_jam_angles,
                       engineering_text(jam_angle_rad, "rad"));
  }
  if (in_jam_angles < kPlausibleLow && plausible(in_jam_angles * kDegreesPerRadian)) {
    return fmt::format("misalignment reaches only {}, {:.3g} of the jam angle ({}): "
                       "radians under a _deg header? (57.3 times too small; ignore this if the "
                       "test ran that close to aligned)",
                       engineering_text(largest_misalignment_rad, "rad"), in_jam_angles,
                       engineering_text(jam_angle_rad, "rad"));
  }
  return std::nullopt;
}

}  // namespace gc::analysis
