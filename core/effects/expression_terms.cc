#include "core/effects/expression_terms.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <tuple>

namespace gc {
namespace {

/// The scalar factor of a term: what it is, its unit, its coefficient's bound when it multiplies a
/// unit direction, and the mechanisms it usually stands for.
struct Scalar {
  const char* name;
  const char* formula;
  const char* along_unit;  ///< of a coefficient times a unit direction: N·m per unit of the scalar
  const char* times_unit;  ///< of a coefficient times the model's moment: per unit of the scalar
  double bound;            ///< |coefficient| times a unit direction [along_unit]
  const char* mechanisms;
  std::optional<double> (*read)(const MeasurementSample&);
};

const Scalar kScalars[] = {
    {"constant", "1", "N·m", "-", 1e7,
     "a constant moment: a bridge zero offset, the weight of a part the model leaves out, or (along the "
     "model's moment) a friction moment that does not grow with torque, i.e. friction rising at low torque "
     "(eq 37's mu T with mu ~ 1/T)",
     [](const MeasurementSample&) { return std::optional(1.0); }},
    {"torque", "T", "N·m/N·m", "1/(N·m)", 1.0,
     "a moment in proportion to torque: torque cross-talk into the bending bridge, or a torque-dependent "
     "offset of the shaft",
     [](const MeasurementSample& s) { return std::optional(s.torque_nm); }},
    {"inverse_torque", "1/T", "N·m²", "N·m", 1e13,
     "a moment that grows as torque falls: friction rising at low torque (eq 37 with mu ~ 1/T), or the hub "
     "resting eccentric on the sleeve below the restoring torque (eqs 49-53)",
     [](const MeasurementSample& s) { return s.torque_nm != 0.0 ? std::optional(1.0 / s.torque_nm) : std::nullopt; }},
    {"misalignment", "zeta", "N·m/rad", "1/rad", 1e9,
     "a moment in proportion to misalignment: a misalignment the sensors mis-scale (scale error of the "
     "displacement sensors), or a coupling stiffer or softer in bending than modelled (compliance)",
     [](const MeasurementSample& s) { return std::optional(s.misalignment_rad); }},
    {"misalignment_squared", "zeta^2", "N·m/rad²", "1/rad²", 1e11,
     "a moment growing with the square of misalignment: a contact zone or crowning that differs from the "
     "model's, or a misalignment the coupling sees more of than measured",
     [](const MeasurementSample& s) { return std::optional(s.misalignment_rad * s.misalignment_rad); }},
    {"torque_misalignment", "T zeta", "1/rad", "1/(N·m·rad)", 1e3,
     "a moment in proportion to torque times misalignment, the scale of the induced moment itself: a "
     "friction coefficient or mesh stiffness different from the model's, or a misalignment scale error",
     [](const MeasurementSample& s) { return std::optional(s.torque_nm * s.misalignment_rad); }},
    {"travel_sign", "sign(dzeta/dt)", "N·m", "-", 1e7,
     "a moment whose sign follows the direction of travel of the misalignment, and holds it when the "
     "misalignment stops: Coulomb friction in the loading mechanism or the spline (locked on the side "
     "of the last move), or hysteresis (a lag of the coupling behind the measured misalignment)",
     [](const MeasurementSample& s) { return std::optional<double>(s.travel_direction); }},
    {"torque_travel_sign", "T sign(dzeta/dt)", "N·m/N·m", "1/(N·m)", 1.0,
     "a moment that flips with the direction of travel of the misalignment and grows with torque: Coulomb "
     "friction between the spline's teeth (mu times the tooth forces, which torque sets), a hysteresis of "
     "the coupling that grows with load",
     [](const MeasurementSample& s) { return std::optional<double>(s.torque_nm * s.travel_direction); }},
    {"time", "t", "N·m/s", "1/s", 1e4,
     "a moment that changes with time alone: zero drift of the strain-gauge bridge (its temperature), or "
     "a slow change of the rig during the test",
     [](const MeasurementSample& s) { return std::optional(s.time_s); }},
    {"time_squared", "t^2", "N·m/s²", "1/s²", 1e4,
     "a moment that changes smoothly with time alone, bending: zero drift of the strain-gauge bridge as it "
     "warms, or a slow change of the rig during the test",
     [](const MeasurementSample& s) { return std::optional(s.time_s * s.time_s); }},
    {"time_cubed", "t^3", "N·m/s³", "1/s³", 1e4,
     "a moment that changes smoothly with time alone, turning: zero drift of the strain-gauge bridge, or a "
     "slow change of the rig during the test",
     [](const MeasurementSample& s) { return std::optional(s.time_s * s.time_s * s.time_s); }},
    {"misalignment_rate", "dzeta/dt", "N·m/(rad/s)", "1/(rad/s)", 1e10,
     "a moment in proportion to how fast the misalignment changes: viscous damping of the spline's oil "
     "film, or a coupling that lags the measured misalignment by a time (M(t - tau) ~ M - tau dM/dt: a "
     "hysteresis that grows with the speed of travel)",
     [](const MeasurementSample& s) { return s.misalignment_rate_rad_s; }},
    {"torque_rate", "dT/dt", "N·m/(N·m/s)", "1/(N·m/s)", 1e3,
     "a moment in proportion to how fast the torque changes: the drivetrain's torsional inertia or "
     "damping, or the moment channels sampled at another time than the torque channel (a DAQ skew)",
     [](const MeasurementSample& s) { return s.torque_rate_nm_s; }},
    {"speed", "n", "N·m/rpm", "1/rpm", 1e6,
     "a moment in proportion to shaft speed: viscous drag (oil shear in the spline, windage), or bearing "
     "drag",
     [](const MeasurementSample& s) { return s.speed_rpm; }},
    {"temperature", "theta", "N·m/deg C", "1/deg C", 1e6,
     "a moment that changes with oil temperature: viscosity changing friction, or thermal drift of the "
     "bridge",
     [](const MeasurementSample& s) { return s.temperature_c; }},
};

/// The direction factor of a term.
struct Frame {
  const char* name;
  const char* formula;
  const char* mechanisms;
};

const Frame kFrames[] = {
    {"on_y", "(1, 0)", "on M_sy' alone, so more likely a sensor (bridge, calibration) than the coupling"},
    {"on_z", "(0, 1)", "on M_sz' alone, so more likely a sensor (bridge, calibration) than the coupling"},
    {"along_moment", "M/|M| (the model's moment direction)", "along the model's moment, so in the coupling's own mechanics"},
    {"normal_to_moment", "the model's moment direction turned by +90 deg",
     "normal to the model's moment: the moment turned, as by a pressure-angle shift (eqs 44-45) or a sensor frame "
     "rotated against the model's"},
    {"along_misalignment", "(cos beta, sin beta)", "along the misalignment direction, in the coupling's frame"},
    {"normal_to_misalignment", "(-sin beta, cos beta)", "normal to the misalignment direction, in the coupling's frame"},
    {"times_moment", "M (the model's moment)",
     "in proportion to the model's own moment, i.e. the moment scaled: a misalignment scale error (the coupling "
     "sees a share more or less misalignment than measured), a friction coefficient or mesh stiffness different "
     "from the model's, or a gain error of both bridges"},
    {"times_moment_turned", "M turned by +90 deg",
     "in proportion to the model's own moment turned by 90 deg, i.e. the moment rotated by a small angle: a "
     "pressure-angle shift of the moment direction (eqs 44-45) that differs from the model's, or bridges whose "
     "frame is rotated against the model's"},
};

constexpr int kScalarCount = static_cast<int>(std::size(kScalars));
constexpr int kFrameCount = static_cast<int>(std::size(kFrames));
constexpr int kTimesMoment = kFrameCount - 2;  ///< this and the next scale with the model's moment
// Terms past the scalar-times-frame products: the model's own moments, and the rotation phase.
constexpr int kGainYY = 0, kGainZZ = 1, kCrossZY = 2, kCrossYZ = 3, kSinY = 4, kCosY = 5, kSinZ = 6, kCosZ = 7;
// A moment vector turning at the order's angle, seen by the stationary bridges, both channels in
// one term with the phase between them fixed: forward, with the shaft (y toward z), (cos, sin) and
// its quadrature (-sin, cos); backward, against it, (cos, -sin) and (sin, cos). Order analysis's
// full spectrum: forward and backward whirl together span the four one-channel terms.
constexpr int kForwardCos = 8, kForwardSin = 9, kBackwardCos = 10, kBackwardSin = 11;
// The time_cycle terms: scalar kCycle, frame the same four (sin/cos on y/z) as the revolution's;
// the shaft orders: scalar kOrder, the same frames; the steps: scalar kStep, frame on_y or on_z.
// The ringing terms: scalar kRinging, frame kSinY (on M_sy') or kSinZ (on M_sz').
constexpr int kCycle = -2, kOrder = -3, kStep = -4, kRinging = -5;
// 10 kHz (a 20 kHz DAQ's Nyquist: a 1 kHz recording found a 100 Hz cycle that its name could not
// carry, and the diagnosis stopped) to 11 days.
constexpr double kShortestCycleS = 1e-4, kLongestCycleS = 1e6;
constexpr double kSlowCycleS = 10.0;  // from here on a cycle is a slow drift of the zero, below an interference
constexpr double kLatestStepS = 1e9;  // the recording reader's time range

Eigen::Vector2d direction(int frame, const MeasurementSample& s, const SensorMoments& m) {
  const Eigen::Vector2d moment(m.y_nm, m.z_nm);
  const double size = moment.norm();
  const Eigen::Vector2d along = size > 0.0 ? Eigen::Vector2d(moment / size) : Eigen::Vector2d::Zero();
  switch (frame) {
    case 0: return {1.0, 0.0};
    case 1: return {0.0, 1.0};
    case 2: return along;
    case 3: return {-along.y(), along.x()};
    case 4: return {std::cos(s.direction_rad), std::sin(s.direction_rad)};
    case 5: return {-std::sin(s.direction_rad), std::cos(s.direction_rad)};
    case 6: return moment;  // not a unit vector: the coefficient is per unit of M
    default: return {-moment.y(), moment.x()};
  }
}

/// The eight terms of shaft order k (sin and cos on each channel, forward and backward whirls),
/// named "<order_name>_sin_on_y" ..., their amplitude scaled as `modulation` says (a "torque_" or
/// "speed_squared_" prefix).
std::vector<ExpressionTerm> order_terms(int k, const std::string& order_name, const std::string& mechanisms,
                                        ExpressionTerm::Modulation modulation) {
  using M = ExpressionTerm::Modulation;
  const std::string prefix = modulation == M::torque ? "torque_" : modulation == M::speed_squared ? "speed_squared_" : "";
  const std::string factor = modulation == M::torque ? "T " : modulation == M::speed_squared ? "n^2 " : "";
  const std::string unit = modulation == M::torque ? "N·m/N·m" : modulation == M::speed_squared ? "N·m/rpm²" : "N·m";
  const double bound = modulation == M::torque ? 1.0 : modulation == M::speed_squared ? 1e5 : 1e7;
  const std::string angle = k == 1 ? "phi_rot" : std::to_string(k) + " phi_rot";
  const std::string grows = modulation == M::torque ? ", growing with torque" : "";
  const std::string c = "cos(" + angle + ")", s = "sin(" + angle + ")";
  const std::tuple<const char*, int, std::string> parts[] = {
      {"_sin_on_y", kSinY, s + " on M_sy'"},
      {"_cos_on_y", kCosY, c + " on M_sy'"},
      {"_sin_on_z", kSinZ, s + " on M_sz'"},
      {"_cos_on_z", kCosZ, c + " on M_sz'"},
      {"_forward_cos", kForwardCos, "(" + c + ", " + s + ")"},
      {"_forward_sin", kForwardSin, "(-" + s + ", " + c + ")"},
      {"_backward_cos", kBackwardCos, "(" + c + ", -" + s + ")"},
      {"_backward_sin", kBackwardSin, "(" + s + ", " + c + ")"}};
  std::vector<ExpressionTerm> terms;
  for (const auto& [suffix, frame, formula] : parts) {
    const std::string where =
        frame >= kBackwardCos ? "; a moment vector turning against the shaft: a fixed load that the rotor's "
                                "out-of-roundness modulates, or a phase counted against the turn"
        : frame >= kForwardCos ? "; a moment vector turning with the shaft: a part of the rotor"
                               : "; on one channel";
    ExpressionTerm term{prefix + order_name + suffix, factor + formula, unit, bound, mechanisms + grows + where,
                        kOrder, frame};
    term.order = k;
    term.modulation = modulation;
    terms.push_back(std::move(term));
  }
  return terms;
}

/// The terms of shaft order k in the catalogue: "revolution_..." for k = 1, "order_<k>_..." above.
void add_order_terms(std::vector<ExpressionTerm>& terms, int k, const std::string& mechanisms,
                     ExpressionTerm::Modulation modulation) {
  for (ExpressionTerm& t : order_terms(k, k == 1 ? "revolution" : "order_" + std::to_string(k), mechanisms, modulation)) {
    terms.push_back(std::move(t));
  }
}

std::vector<ExpressionTerm> make_terms() {
  std::vector<ExpressionTerm> terms;
  for (int i = 0; i < kScalarCount; ++i) {
    for (int f = 0; f < kFrameCount; ++f) {
      const Scalar& s = kScalars[i];
      // Along a unit direction the coefficient is N·m per unit of the scalar; times the model's
      // moment it is a share of that moment per unit of the scalar (bounded for moments to 1e7 N·m).
      const bool scaled = f >= kTimesMoment;
      const std::string unit = scaled ? s.times_unit : s.along_unit;
      terms.push_back({std::string(s.name) + "_" + kFrames[f].name, std::string(s.formula) + " " + kFrames[f].formula,
                       unit, scaled ? s.bound / 1e7 : s.bound, std::string(s.mechanisms) + "; " + kFrames[f].mechanisms, i, f});
    }
  }
  const char* gain = "a gain (calibration slope) error of that channel, or a coupling stiffer or softer than modelled";
  const char* cross = "cross-talk between the two bending bridges, or a sensor frame rotated against the model's";
  const char* revolution =
      "once per revolution: runout or an eccentric hub, an unbalance, or a gauge on the rotating shaft "
      "seeing a fixed load";
  terms.push_back({"model_y_on_y", "M_sy' (model) on M_sy'", "-", 1.0, gain, -1, kGainYY});
  terms.push_back({"model_z_on_z", "M_sz' (model) on M_sz'", "-", 1.0, gain, -1, kGainZZ});
  terms.push_back({"model_z_on_y", "M_sz' (model) on M_sy'", "-", 1.0, cross, -1, kCrossZY});
  terms.push_back({"model_y_on_z", "M_sy' (model) on M_sz'", "-", 1.0, cross, -1, kCrossYZ});
  add_order_terms(terms, 1, revolution, ExpressionTerm::Modulation::none);
  const char* order_mechanisms[] = {
      "",
      "",
      "twice per revolution: an oval (out-of-round) sleeve or hub, a bent shaft's second harmonic, or a "
      "misalignment that the rotating gauges see twice a turn",
      "three times per revolution: a three-lobed (triangular) sleeve or hub from machining or clamping, or a "
      "three-point support",
      "four times per revolution: a four-lobed sleeve or hub, or the bolts of a four-bolt flange"};
  for (int k = 2; k <= kHighestShaftOrder; ++k) add_order_terms(terms, k, order_mechanisms[k], ExpressionTerm::Modulation::none);
  // Ripples whose amplitude follows an input: the same orders scaled by torque (an out-of-round
  // sleeve or a runout shares the tooth load unevenly, in proportion to the load), and the
  // revolution scaled by the speed squared (an unbalance: m e omega^2).
  add_order_terms(terms, 1, revolution, ExpressionTerm::Modulation::torque);
  for (int k = 2; k <= kHighestShaftOrder; ++k) add_order_terms(terms, k, order_mechanisms[k], ExpressionTerm::Modulation::torque);
  add_order_terms(terms, 1,
                  "once per revolution, growing with the square of speed: an unbalance of the shaft, hub or a part "
                  "on it (its centrifugal force m e omega^2), or a bent shaft whirling",
                  ExpressionTerm::Modulation::speed_squared);
  return terms;
}

/// sin or cos of `angle` on one channel (kSinY .. kCosZ), or the vector turning with it
/// (kForwardCos .. kBackwardSin), as `frame` says.
Eigen::Vector2d harmonic(int frame, double angle) {
  switch (frame) {
    case kForwardCos: return Eigen::Vector2d(std::cos(angle), std::sin(angle));
    case kForwardSin: return Eigen::Vector2d(-std::sin(angle), std::cos(angle));
    case kBackwardCos: return Eigen::Vector2d(std::cos(angle), -std::sin(angle));
    case kBackwardSin: return Eigen::Vector2d(std::sin(angle), std::cos(angle));
    case kSinY: return Eigen::Vector2d(std::sin(angle), 0.0);
    case kCosY: return Eigen::Vector2d(std::cos(angle), 0.0);
    case kSinZ: return Eigen::Vector2d(0.0, std::sin(angle));
    default: return Eigen::Vector2d(0.0, std::cos(angle));
  }
}

constexpr std::string_view kCyclePrefix = "time_cycle_";
constexpr std::pair<std::string_view, int> kCycleSuffixes[] = {
    {"s_sin_on_y", kSinY}, {"s_cos_on_y", kCosY}, {"s_sin_on_z", kSinZ}, {"s_cos_on_z", kCosZ}};

/// A number in at most 6 significant digits, without exponent or trailing zeros: "70", "2.50137".
std::string number_text(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  std::string text(buffer);
  if (text.find('e') != std::string::npos) {  // %g chose an exponent: write it out in full
    std::snprintf(buffer, sizeof buffer, "%.6f", value);
    text = buffer;
    if (text.find('.') != std::string::npos) {
      text.erase(text.find_last_not_of('0') + 1);
      if (text.back() == '.') text.pop_back();
    }
  }
  return text;
}

std::string period_text(double period_s) { return number_text(period_s); }

/// The number at the start of `text` if it is written as number_text writes it (one spelling a
/// value, so one term a period or a time); the rest of `text` in `rest`.
std::optional<double> leading_number(std::string_view text, std::string_view& rest) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end == text.data() || !std::isfinite(value)) return std::nullopt;
  const std::string_view written(text.data(), static_cast<std::size_t>(end - text.data()));
  if (written != number_text(value)) return std::nullopt;
  rest = std::string_view(end, static_cast<std::size_t>(text.data() + text.size() - end));
  return value;
}

ExpressionTerm cycle_term(double period_s, std::string_view suffix, int frame) {
  const bool sine = suffix.find("sin") != std::string_view::npos;
  const std::string channel = frame <= kCosY ? "M_sy'" : "M_sz'";
  const std::string mechanisms =
      period_s >= kSlowCycleS
          ? "a moment that swings with time alone on a slow cycle: zero drift of the strain-gauge bridge with the "
            "cell's temperature control (the air or oil cycling about its set point), or a slow rig oscillation"
          : "a periodic component at " + number_text(1.0 / period_s) + " Hz that no input explains: electrical "
            "pickup from a pump, fan or converter, a structural resonance of the rig excited by the cell, or a "
            "beat between the DAQ's and the telemetry's clocks";
  return {std::string(kCyclePrefix) + period_text(period_s) + std::string(suffix),
          std::string(sine ? "sin" : "cos") + "(2 pi t / " + period_text(period_s) + " s) on " + channel,
          "N·m", 1e7, mechanisms + "; on one channel, so more likely a sensor than the coupling", kCycle, frame, period_s};
}

/// The time_cycle term `name` stands for, or nullopt: "time_cycle_<period>s_<sin|cos>_on_<y|z>".
std::optional<ExpressionTerm> parse_cycle_term(std::string_view name) {
  if (name.substr(0, kCyclePrefix.size()) != kCyclePrefix) return std::nullopt;
  name.remove_prefix(kCyclePrefix.size());
  std::string_view suffix;
  const std::optional<double> p = leading_number(name, suffix);
  if (!p || *p < kShortestCycleS || *p > kLongestCycleS) return std::nullopt;
  for (const auto& [s, frame] : kCycleSuffixes) if (suffix == s) return cycle_term(*p, s, frame);
  return std::nullopt;
}

constexpr std::string_view kStepPrefix = "step_at_";

ExpressionTerm step_term(double time_s, int frame) {
  const std::string channel = frame == kSinY ? "M_sy'" : "M_sz'";
  ExpressionTerm term{std::string(kStepPrefix) + number_text(time_s) + (frame == kSinY ? "s_on_y" : "s_on_z"),
                      "(t >= " + number_text(time_s) + " s) on " + channel, "N·m", 1e7,
                      "a step of one channel's zero at that time: a bridge re-zeroed or re-balanced, a gauge or "
                      "amplifier replaced, a connector reseated, or a bolt that slipped",
                      kStep, frame};
  term.step_time_s = time_s;
  return term;
}

/// The step term `name` stands for, or nullopt: "step_at_<time>s_on_<y|z>".
std::optional<ExpressionTerm> parse_step_term(std::string_view name) {
  if (name.substr(0, kStepPrefix.size()) != kStepPrefix) return std::nullopt;
  name.remove_prefix(kStepPrefix.size());
  std::string_view suffix;
  const std::optional<double> t = leading_number(name, suffix);
  if (!t || std::abs(*t) > kLatestStepS) return std::nullopt;
  if (suffix == "s_on_y") return step_term(*t, kSinY);
  if (suffix == "s_on_z") return step_term(*t, kSinZ);
  return std::nullopt;
}

constexpr std::string_view kMeshPrefix = "mesh_order_";
constexpr int kMostTeeth = 10000;

/// The name of the mesh order of `teeth` teeth shifted by `sideband` orders: "mesh_order_56",
/// "mesh_order_56_plus_1", "mesh_order_56_minus_2".
std::string mesh_order_name(int teeth, int sideband) {
  const std::string mesh = std::string(kMeshPrefix) + std::to_string(teeth);
  if (sideband == 0) return mesh;
  return mesh + (sideband > 0 ? "_plus_" : "_minus_") + std::to_string(std::abs(sideband));
}

/// What a term at the mesh order (sideband 0) or beside it usually means.
std::string mesh_mechanisms(int teeth, int sideband) {
  if (sideband == 0) {
    return "the tooth-mesh order (N = " + std::to_string(teeth) +
           " teeth, once per tooth pass): tooth-mesh excitation, spacing (pitch) errors between the teeth, or a "
           "tooth-to-tooth stiffness variation as the teeth take and give up the load";
  }
  const std::string times = std::abs(sideband) == 1 ? "once" : "twice";
  return "a sideband of the tooth-mesh order (N " + std::string(sideband > 0 ? "+ " : "- ") +
         std::to_string(std::abs(sideband)) + " = " + std::to_string(teeth + sideband) + "): the mesh modulated " + times +
         " per revolution, by a runout or eccentricity of the hub or sleeve (an oval one at 2) that loads the teeth "
         "unevenly around the turn";
}

/// The mesh term `name` stands for, or nullopt: "[torque_]mesh_order_<N>[_plus_<j>|_minus_<j>]_<part>".
std::optional<ExpressionTerm> parse_mesh_term(std::string_view name) {
  using M = ExpressionTerm::Modulation;
  const bool scaled = name.substr(0, 7) == "torque_";
  std::string_view rest = scaled ? name.substr(7) : name;
  if (rest.substr(0, kMeshPrefix.size()) != kMeshPrefix) return std::nullopt;
  rest.remove_prefix(kMeshPrefix.size());
  int teeth = 0;
  const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), teeth);
  if (error != std::errc() || teeth < 1 + kMeshSidebands || teeth > kMostTeeth) return std::nullopt;
  for (int sideband = -kMeshSidebands; sideband <= kMeshSidebands; ++sideband) {
    for (ExpressionTerm& term : order_terms(teeth + sideband, mesh_order_name(teeth, sideband),
                                            mesh_mechanisms(teeth, sideband), scaled ? M::torque : M::none)) {
      if (term.name == name) return std::move(term);
    }
  }
  return std::nullopt;
}

constexpr std::string_view kRingingPrefix = "ringing_";
constexpr double kHighestRingingHz = 1e4;

ExpressionTerm ringing_term(const RingingMode& mode, int frame) {
  const std::string f = number_text(mode.natural_frequency_hz), zeta = number_text(mode.damping_ratio);
  const bool y = frame == kSinY;
  ExpressionTerm term{std::string(kRingingPrefix) + f + "Hz_zeta" + zeta + (y ? "_on_y" : "_on_z"),
                      "(h * T - T) on " + std::string(y ? "M_sy'" : "M_sz'") + ", h the second-order response of f_n = " +
                          f + " Hz, zeta = " + zeta,
                      "N·m/N·m", 1.0,
                      "the rig ringing after a change of the load, at " + f + " Hz with a damping ratio of " + zeta +
                          ": a structural resonance of the rig excited by load changes, a stiff-shaft mode, or the "
                          "dynamometer's torsional mode; filter the moment channels below it, or model the rig's "
                          "dynamics; on one channel",
                      kRinging, frame};
  term.ringing = mode;
  return term;
}

/// The ringing term `name` stands for, or nullopt: "ringing_<f_n>Hz_zeta<zeta>_on_<y|z>".
std::optional<ExpressionTerm> parse_ringing_term(std::string_view name) {
  if (name.substr(0, kRingingPrefix.size()) != kRingingPrefix) return std::nullopt;
  name.remove_prefix(kRingingPrefix.size());
  std::string_view rest;
  const std::optional<double> f = leading_number(name, rest);
  if (!f || !(*f > 0.0) || *f > kHighestRingingHz || rest.substr(0, 7) != "Hz_zeta") return std::nullopt;
  rest.remove_prefix(7);
  std::string_view suffix;
  const std::optional<double> zeta = leading_number(rest, suffix);
  if (!zeta || !(*zeta > 0.0) || !(*zeta < 1.0)) return std::nullopt;
  if (suffix == "_on_y") return ringing_term({*f, *zeta}, kSinY);
  if (suffix == "_on_z") return ringing_term({*f, *zeta}, kSinZ);
  return std::nullopt;
}

/// `value` rounded to 3 significant digits: a mode's frequency and damping are known to a few %.
double three_digits(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return std::stod(buffer);
}

}  // namespace

std::optional<Eigen::Vector2d> ExpressionTerm::value(const MeasurementSample& sample, const SensorMoments& model) const {
  if (scalar >= 0) {
    const std::optional<double> s = kScalars[scalar].read(sample);
    if (!s) return std::nullopt;
    return *s * direction(frame, sample, model);
  }
  if (scalar == kCycle) return harmonic(frame, 2.0 * std::numbers::pi * sample.time_s / period_s);
  if (scalar == kRinging) return Eigen::Vector2d::Zero();
  if (scalar == kStep) {
    const double on = sample.time_s >= step_time_s ? 1.0 : 0.0;
    return frame == kSinY ? Eigen::Vector2d(on, 0.0) : Eigen::Vector2d(0.0, on);
  }
  switch (frame) {
    case kGainYY: return Eigen::Vector2d(model.y_nm, 0.0);
    case kGainZZ: return Eigen::Vector2d(0.0, model.z_nm);
    case kCrossZY: return Eigen::Vector2d(model.z_nm, 0.0);
    case kCrossYZ: return Eigen::Vector2d(0.0, model.y_nm);
    default: break;
  }
  if (!sample.rotation_phase_rad) return std::nullopt;
  const Eigen::Vector2d wave = harmonic(frame, (scalar == kOrder ? order : 1) * *sample.rotation_phase_rad);
  switch (modulation) {
    case Modulation::torque: return sample.torque_nm * wave;
    case Modulation::speed_squared:
      if (!sample.speed_rpm) return std::nullopt;
      return *sample.speed_rpm * *sample.speed_rpm * wave;
    case Modulation::none: break;
  }
  return wave;
}

Eigen::Vector2d ExpressionTerm::history_value(const InputHistory& history) const {
  if (!reads_history()) return Eigen::Vector2d::Zero();
  return torque_ringing_at(history, ringing) * history_channel();
}

std::vector<double> ExpressionTerm::history_values_at(std::span<const RecordedSample> recording,
                                                     std::span<const std::size_t> rows) const {
  if (!reads_history()) return std::vector<double>(rows.size(), 0.0);
  return torque_ringing_at_rows(recording, rows, ringing);
}

Eigen::Vector2d ExpressionTerm::history_channel() const {
  if (!reads_history()) return Eigen::Vector2d::Zero();
  return frame == kSinY ? Eigen::Vector2d(1.0, 0.0) : Eigen::Vector2d(0.0, 1.0);
}

double ExpressionTerm::frequency_hz(const MeasurementSample& sample) const {
  if (scalar == kCycle) return 1.0 / period_s;
  if (scalar == kRinging) return ringing.natural_frequency_hz;
  if (scalar == kOrder && sample.speed_rpm) return order * std::abs(*sample.speed_rpm) / 60.0;
  return 0.0;
}

const std::vector<ExpressionTerm>& expression_terms() {
  static const std::vector<ExpressionTerm> terms = make_terms();
  return terms;
}

const ExpressionTerm* find_expression_term(std::string_view name) {
  for (const ExpressionTerm& t : expression_terms()) if (t.name == name) return &t;
  // Terms made for a value in their name: a period, a time, a tooth count, a mode.
  std::optional<ExpressionTerm> term = make_expression_term(name);
  if (!term) return nullptr;
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<const ExpressionTerm>, std::less<>> made;
  std::lock_guard lock(mutex);
  auto& slot = made[term->name];
  if (!slot) slot = std::make_unique<const ExpressionTerm>(std::move(*term));
  return slot.get();
}

std::optional<ExpressionTerm> make_expression_term(std::string_view name) {
  for (const ExpressionTerm& t : expression_terms()) if (t.name == name) return t;
  // Terms made for a value in their name: a period, a time, a tooth count, a mode.
  std::optional<ExpressionTerm> made = parse_cycle_term(name);
  if (!made) made = parse_step_term(name);
  if (!made) made = parse_mesh_term(name);
  if (!made) made = parse_ringing_term(name);
  return made;
}

std::vector<std::string> cycle_term_names(double period_s) {
  const double p = std::stod(number_text(std::clamp(period_s, kShortestCycleS, kLongestCycleS)));
  std::vector<std::string> names;
  for (const auto& [suffix, frame] : kCycleSuffixes) names.push_back(cycle_term(p, suffix, frame).name);
  return names;
}

std::vector<std::string> step_term_names(double time_s) {
  const double t = std::stod(number_text(std::clamp(time_s, -kLatestStepS, kLatestStepS)));
  return {step_term(t, kSinY).name, step_term(t, kSinZ).name};
}

std::vector<std::string> mesh_term_names(int teeth) {
  std::vector<std::string> names;
  if (teeth < 1 + kMeshSidebands || teeth > kMostTeeth) return names;
  for (const ExpressionTerm::Modulation m : {ExpressionTerm::Modulation::none, ExpressionTerm::Modulation::torque}) {
    for (int sideband = -kMeshSidebands; sideband <= kMeshSidebands; ++sideband) {
      for (const ExpressionTerm& t : order_terms(teeth + sideband, mesh_order_name(teeth, sideband), "", m)) {
        names.push_back(t.name);
      }
    }
  }
  return names;
}

std::vector<std::string> ringing_term_names(const RingingMode& mode) {
  const RingingMode written{three_digits(std::clamp(mode.natural_frequency_hz, 1e-3, kHighestRingingHz)),
                            three_digits(std::clamp(mode.damping_ratio, 1e-3, 0.99))};
  return {ringing_term(written, kSinY).name, ringing_term(written, kSinZ).name};
}

}  // namespace gc
