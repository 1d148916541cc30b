#include "tests/diagnosis/zoo/csv.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace gc::zoo {

const char* column_name(int column) {
  static const char* names[] = {"time", "torque", "misalignment", "direction", "speed", "temperature", "msy", "msz"};
  return column >= 0 && column < kColumns ? names[column] : "?";
}

std::string CsvStyle::describe() const {
  if (time == "s" && torque == "nm" && angle == "rad" && moment == "nm" && !extra_column) return "SI";
  return time + "," + torque + "," + angle + "," + moment + (extra_column ? ",+Ch9" : "");
}

CsvStyle draw_style(Rng& rng) {
  CsvStyle s;
  if (!rng.chance(0.25)) return s;
  s.time = rng.chance(0.5) ? "ms" : "s";
  const char* torques[] = {"nm", "knm", "mnm"};
  const char* angles[] = {"rad", "deg", "mrad"};
  const char* moments[] = {"nm", "knm"};
  s.torque = torques[rng.integer(0, 2)];
  s.angle = angles[rng.integer(0, 2)];
  s.moment = moments[rng.integer(0, 1)];
  s.extra_column = rng.chance(0.5);
  return s;
}

namespace {
double factor(const std::string& unit) {  // SI value -> value in `unit`
  if (unit == "ms") return 1e3;
  if (unit == "knm") return 1e-3;
  if (unit == "mnm") return 1e-6;
  if (unit == "deg") return 180.0 / std::numbers::pi;
  if (unit == "mrad") return 1e3;
  return 1.0;
}
void append(std::string& s, double v) {
  if (std::isnan(v)) {
    s += "nan";
    return;
  }
  char buf[32];
  const int n = std::snprintf(buf, sizeof buf, "%.12g", v);
  s.append(buf, static_cast<std::size_t>(n));
}
}  // namespace

std::string write_csv(const Channels& c, const CsvStyle& st, const std::set<std::pair<std::size_t, int>>& empty,
                      std::uint64_t extra_seed) {
  std::string s;
  s.reserve(c.rows() * 110 + 200);
  s += "time_" + st.time + ",torque_" + st.torque + ",misalignment_" + st.angle + ",direction_" + st.angle +
       ",speed_rpm,temperature_c,msy_" + st.moment + ",msz_" + st.moment + (st.extra_column ? ",Ch9_V" : "") + "\n";
  const double f[kColumns] = {factor(st.time), factor(st.torque), factor(st.angle), factor(st.angle), 1.0, 1.0,
                              factor(st.moment), factor(st.moment)};
  const std::vector<double>* cols[kColumns] = {&c.time_s, &c.torque_nm, &c.zeta_rad, &c.beta_rad,
                                               &c.speed_rpm, &c.temperature_c, &c.msy_nm, &c.msz_nm};
  Rng extra(extra_seed);
  for (std::size_t i = 0; i < c.rows(); ++i) {
    for (int k = 0; k < kColumns; ++k) {
      if (k) s += ',';
      if (!empty.empty() && empty.count({i, k})) continue;
      append(s, (*cols[k])[i] * f[k]);
    }
    if (st.extra_column) {
      s += ',';
      append(s, 2.5 + 0.01 * extra.normal());
    }
    s += '\n';
  }
  return s;
}

}  // namespace gc::zoo
