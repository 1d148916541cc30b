#include "tests/diagnosis/zoo/zoo.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "core/coupling_geometry.h"
#include "tests/diagnosis/zoo/families.h"
#include "tests/diagnosis/zoo/hidden_effects.h"
#include "tests/diagnosis/zoo/identity_oracle.h"
#include "tests/diagnosis/zoo/oracle.h"
#include "tests/diagnosis/zoo/programme.h"
#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {
namespace {

double three_digits(double x) {
  const double p = std::pow(10.0, std::floor(std::log10(x)) - 2.0);
  return std::round(x / p) * p;
}

// The model's prediction at the true inputs, on two threads for long records.
void predict(const CouplingModel& model, Channels& c) {
  const std::size_t n = c.rows();
  auto part = [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) {
      const SensorMoments m = model.predict(c.sample(i)).moments;
      c.msy_nm[i] = m.y_nm;
      c.msz_nm[i] = m.z_nm;
    }
  };
  if (n < 20000) return part(0, n);
  std::thread t(part, n / 2, n);
  part(0, n / 2);
  t.join();
}

double spread(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

// The identity bound (identity_oracle.h) beside the detection bound: the effect's signal against
// every rival family's nearest member, on at most kIdentityRows of the rows the oracle read (every
// k-th), each family evaluated on the effect-free truth at those rows, the distance scaled to all
// rows by the detection d. `kept`: the rows the oracle read (indices into truth).
constexpr std::size_t kIdentityRows = 2000;

void set_identity_bound(const std::string& effect, const CouplingModel& model, double jam, const Channels& truth,
                        const std::vector<double>& clean_y, const std::vector<double>& clean_z, const std::vector<std::size_t>& kept,
                        const std::vector<double>& sy, const std::vector<double>& sz, const std::vector<double>& ny,
                        const std::vector<double>& nz, ZooDraw& d) {
  if (!std::isfinite(d.oracle_d)) return;
  Channels clean = truth;
  clean.msy_nm = clean_y;
  clean.msz_nm = clean_z;
  const std::vector<std::size_t> at = thinned_rows(kept.size(), kIdentityRows);
  std::vector<std::size_t> rows;
  std::vector<double> ty, tz, my, mz;
  for (std::size_t k : at) {
    rows.push_back(kept[k]);
    ty.push_back(sy[k]), tz.push_back(sz[k]), my.push_back(ny[k]), mz.push_back(nz[k]);
  }
  if (rows.size() < 64) return;
  std::vector<SignalFamily> rivals;
  for (const std::string& name : identity_rivals(effect)) rivals.push_back(signal_family(name, model, jam, clean, rows));
  IdentityOptions options;
  options.seed = derive_seed(d.seed, "identity");
  const IdentityBound bound = identity_bound(ty, tz, my, mz, d.oracle_d, rivals, options);
  d.identity_d = bound.d;
  d.identity_power = bound.power;
  d.identity_rival = bound.rival;
}

// The oracle's bound (oracle.h): the effect's signal is what it added to the true moments; the
// noise is the rest of what diagnose's residual holds, the logged moments less the model fed the
// logged inputs, less that signal. Then the identity bound on the same rows.
void set_oracle_bound(const std::string& effect, const CouplingModel& model, double jam, const Channels& truth,
                      const Channels& logged, const std::vector<double>& clean_y, const std::vector<double>& clean_z, ZooDraw& d) {
  const std::size_t n = truth.rows();
  if (logged.rows() != n || n < 64) return;
  // A row whose logged inputs the model refuses is left out, as diagnose leaves it out; beyond
  // 5 % of the rows there is no bound.
  std::vector<double> sy, sz, ny, nz;
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < n; ++i) {
    SensorMoments read;
    try {
      read = model.predict(logged.sample(i)).moments;
    } catch (const std::exception&) {
      continue;
    }
    kept.push_back(i);
    sy.push_back(truth.msy_nm[i] - clean_y[i]);
    sz.push_back(truth.msz_nm[i] - clean_z[i]);
    ny.push_back(logged.msy_nm[i] - read.y_nm - sy.back());
    nz.push_back(logged.msz_nm[i] - read.z_nm - sz.back());
  }
  if (sy.size() < n - n / 20) return;
  try {
    const OracleBound bound = oracle_bound(sy, sz, ny, nz);
    d.oracle_d = bound.d;
    d.oracle_power = bound.power;
    set_identity_bound(effect, model, jam, truth, clean_y, clean_z, kept, sy, sz, ny, nz, d);
  } catch (const std::invalid_argument&) {
    // a value not finite (a dropout written as NaN): no bound for this draw
  }
}

}  // namespace

std::uint64_t draw_seed(std::uint64_t master, std::size_t k) { return derive_seed(master, static_cast<std::uint64_t>(k)); }

ZooDraw draw(std::uint64_t seed, const DrawLimits& lim) {
  ZooDraw d;
  d.seed = seed;
  Rng sizes(derive_seed(seed, "sizes"));
  d.rows = static_cast<std::size_t>(std::lround(sizes.log_uniform(static_cast<double>(lim.min_rows), static_cast<double>(lim.max_rows))));
  d.rows = std::clamp(d.rows, lim.min_rows, lim.max_rows);
  d.fs_hz = three_digits(sizes.log_uniform(lim.min_rate_hz, lim.max_rate_hz));
  d.level_share = sizes.log_uniform(lim.min_level, lim.max_level);

  Rng model_rng(derive_seed(seed, "model"));
  d.model = draw_model(model_rng, lim.bundled_share);
  const auto model = load_choice(d.model);
  const double jam = model->geometry().jam_angle().angle_rad;

  Rng prog_rng(derive_seed(seed, "programme"));
  ProgrammeLimits pl;
  pl.torque_min_nm = 0.1e6 * d.model.torque_scale;
  pl.torque_max_nm = prog_rng.uniform(1.5e6, 2.6e6) * d.model.torque_scale;
  pl.zeta_max_rad = prog_rng.uniform(0.3, 0.6) * jam;
  pl.zeta_min_rad = prog_rng.uniform(0.03, 0.1) * jam;
  if (!lim.effect_truth.empty()) {
    const ProgrammeNeeds needs = hidden_effect_programme(lim.effect_truth);
    pl.first_block = needs.first_block;
    pl.vary_speed = needs.vary_speed;
  }
  Programme prog = draw_programme(d.rows, d.fs_hz, pl, prog_rng);
  Channels& truth = prog.truth;
  predict(*model, truth);

  const double ry = spread(truth.msy_nm), rz = spread(truth.msz_nm);
  double peak = 0.0;
  for (std::size_t i = 0; i < truth.rows(); ++i) peak = std::max({peak, std::abs(truth.msy_nm[i]), std::abs(truth.msz_nm[i])});
  d.moment_range_nm = std::max({ry, rz, 0.1 * peak});
  d.level_nm = d.level_share * d.moment_range_nm;
  std::string hidden;
  const std::vector<double> clean_y = truth.msy_nm, clean_z = truth.msz_nm;
  if (!lim.effect_truth.empty()) {
    Rng effect_rng(derive_seed(seed, "effect"));
    hidden = "HIDDEN " + add_hidden_effect(lim.effect_truth, lim.effect_snr, d.level_nm, *model, jam, truth, effect_rng) + "; ";
  }

  // The families: 1-3 distinct, at least one on the moments (a bridge always has some noise).
  Rng pick(derive_seed(seed, "families"));
  std::vector<const Family*> chosen;
  if (!lim.only_families.empty()) {
    for (const auto& name : lim.only_families) {
      const Family* f = find_family(name);
      if (!f) throw std::invalid_argument("unknown noise family " + name);
      chosen.push_back(f);
    }
  } else {
    const int k = pick.integer(lim.min_families, lim.max_families);
    const auto& all = all_families();
    while (static_cast<int>(chosen.size()) < k) {
      const Family* f = &all[static_cast<std::size_t>(pick.integer(0, static_cast<int>(all.size()) - 1))];
      if (std::find(chosen.begin(), chosen.end(), f) == chosen.end()) chosen.push_back(f);
    }
  }
  if (std::none_of(chosen.begin(), chosen.end(), [](const Family* f) { return f->kind == FamilyKind::moment; })) {
    chosen.push_back(find_family("white"));
  }
  std::stable_sort(chosen.begin(), chosen.end(), [](const Family* a, const Family* b) {
    auto rank = [](FamilyKind k) { return k == FamilyKind::input ? 0 : k == FamilyKind::moment ? 1 : 2; };
    return rank(a->kind) < rank(b->kind);
  });
  // The moment level split among the moment families (their RMS add in quadrature to level_nm).
  std::vector<double> weight(chosen.size(), 0.0);
  double wsum = 0.0;
  for (std::size_t j = 0; j < chosen.size(); ++j) {
    if (chosen[j]->kind == FamilyKind::moment) wsum += (weight[j] = pick.uniform(0.2, 1.0));
  }

  Channels logged = truth;
  NoiseContext ctx;
  ctx.truth = &truth;
  ctx.fs_hz = d.fs_hz;
  ctx.moment_range_nm = d.moment_range_nm;
  ctx.torque_span_nm = std::max(spread(truth.torque_nm), 0.1 * pl.torque_max_nm);
  ctx.jam_rad = jam;
  std::string fams;
  for (std::size_t j = 0; j < chosen.size(); ++j) {
    ctx.level_nm = chosen[j]->kind == FamilyKind::moment ? d.level_nm * std::sqrt(weight[j] / wsum) : d.level_nm;
    Rng frng(derive_seed(seed, std::string("family:") + chosen[j]->name));
    const std::string params = chosen[j]->apply(ctx, frng, logged);
    d.families.push_back(chosen[j]->name);
    fams += (fams.empty() ? "" : "; ") + std::string(chosen[j]->name) + "(" + params + ")";
  }

  if (!lim.effect_truth.empty()) set_oracle_bound(lim.effect_truth, *model, jam, truth, logged, clean_y, clean_z, d);

  Rng style_rng(derive_seed(seed, "style"));
  const CsvStyle style = style_rng.chance(lim.style_share) ? draw_style(style_rng) : CsvStyle{};
  d.csv = write_csv(logged, style, {}, derive_seed(seed, "extra"));
  d.description = format("seed %016llx: %zu rows at %g Hz (%.4g s), %s, %s, level %.2f%% of %.4g kN·m = %.3g kN·m, units %s: ",
                         static_cast<unsigned long long>(seed), d.rows, d.fs_hz, d.rows / d.fs_hz, d.model.description.c_str(),
                         prog.description.c_str(), 100 * d.level_share, d.moment_range_nm / 1e3, d.level_nm / 1e3,
                         style.describe().c_str()) +
                  hidden + fams;
  if (lim.keep_channels) {
    d.truth = std::move(truth);
    d.logged = std::move(logged);
  }
  return d;
}

}  // namespace gc::zoo
