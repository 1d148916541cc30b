// gc_noise_zoo: the false-claim rate of `gearcoupling diagnose` on noise-only recordings, like a
// statistical test's size (tests/diagnosis/zoo/). Each draw is a random coupling, test programme,
// sample rate, length and mix of noise families on the model's own prediction; diagnose is run on
// it as a user runs it, with the same model. Any claim is false.
//
//   gc_noise_zoo --gearcoupling build/clients/cli/gearcoupling --draws 40 --seed 1 [--jobs 2]
//                [--max-rows R] [--min-rows R] [--keep DIR] [--only K] [--families a,b]
//                [--diagnose-threads T] [--effect-truth NAME --snr X]
//   gc_noise_zoo --gearcoupling PATH --power [--effects a,b] [--snrs 0.75,1.5,3] [--draws N]
//                [--deadline-min M] ...
//
// Power mode (--effect-truth NAME --snr X, NAME one of hidden_effect_table(): torque_gain,
// misalignment_offset, twice_per_rev, weight, or an effect's truth): the same draws with a hidden
// effect of X times the noise level (tests/diagnosis/zoo/hidden_effects.h); the share of draws
// whose first claim names it. Every truth but the two additive signals (twice_per_rev, weight),
// torque gain and misalignment offset included, is the model's moments at the effect's size,
// solved for the SNR (int(qN/4) steps with torque and misalignment: no change is scaled).
//
// Power table (--power): every hidden effect (or --effects) at every SNR (--snrs, default
// 0.75,1.5,3), draws 0..N-1 of the master seed each (the same noise draws for every effect), in
// the order draw, SNR, effect, so a run stopped by --deadline-min (no task started after M minutes)
// keeps its counts even; a markdown table of the share named first with a 95 % Wilson interval,
// and the same share among the draws where a detection oracle reaches 90 % (zoo/oracle.h) and
// where the truth is also identifiable, told apart from every rival effect's nearest member with
// identity and detection d >= 3.61 (zoo/identity_oracle.h).
//
// A draw's seed is derived from the master seed and its index (gc::zoo::draw_seed), so
// `--seed S --only K` reruns draw K alone. The default master seed comes from the clock, printed.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <unistd.h>

#include "tests/diagnosis/zoo/families.h"
#include "tests/diagnosis/zoo/harness.h"
#include "tests/diagnosis/zoo/hidden_effects.h"
#include "tests/diagnosis/zoo/text.h"
#include <regex>
#include "tests/diagnosis/zoo/zoo.h"

namespace {

using namespace gc::zoo;

struct Options {
  std::string gearcoupling;
  std::size_t draws = 40;
  bool draws_given = false;
  std::uint64_t seed = 0;
  bool seed_given = false;
  int jobs = 2;
  std::size_t max_rows = 200000, min_rows = 1000;
  std::string keep;
  long only = -1;
  int diagnose_threads = -1;  // -1: 1 when jobs > 1 (so at most `jobs` busy threads), else diagnose's default
  std::vector<std::string> families;
  std::string effect_truth;
  double snr = 1.0;
  bool power = false;
  std::vector<std::string> effects;
  std::vector<double> snrs = {0.75, 1.5, 3.0};
  double deadline_min = 0.0;  // 0: none
};

std::vector<std::string> split(const std::string& v) {
  std::vector<std::string> out;
  for (std::size_t p = 0; p != std::string::npos;) {
    const std::size_t q = v.find(',', p);
    out.push_back(v.substr(p, q == std::string::npos ? q : q - p));
    p = q == std::string::npos ? q : q + 1;
  }
  return out;
}

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr,
               "gc_noise_zoo: %s\nusage: gc_noise_zoo --gearcoupling PATH [--draws N] [--seed S] [--jobs J (1-2)] "
               "[--max-rows R] [--min-rows R] [--keep DIR] [--only K] [--families a,b] [--diagnose-threads T] [--effect-truth NAME --snr X] [--power [--effects a,b] [--snrs 0.75,1.5,3] [--deadline-min M]]\n",
               why);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(("missing value for " + a).c_str());
      return argv[++i];
    };
    if (a == "--gearcoupling") o.gearcoupling = value();
    else if (a == "--draws") o.draws = std::stoul(value()), o.draws_given = true;
    else if (a == "--seed") o.seed = std::stoull(value(), nullptr, 0), o.seed_given = true;
    else if (a == "--jobs") o.jobs = std::stoi(value());
    else if (a == "--max-rows") o.max_rows = std::stoul(value());
    else if (a == "--min-rows") o.min_rows = std::stoul(value());
    else if (a == "--keep") o.keep = value();
    else if (a == "--only") o.only = std::stol(value());
    else if (a == "--diagnose-threads") o.diagnose_threads = std::stoi(value());
    else if (a == "--effect-truth") o.effect_truth = value();
    else if (a == "--snr") o.snr = std::stod(value());
    else if (a == "--power") o.power = true;
    else if (a == "--effects") o.effects = split(value());
    else if (a == "--snrs") {
      o.snrs.clear();
      for (const auto& x : split(value())) o.snrs.push_back(std::stod(x));
    } else if (a == "--deadline-min") o.deadline_min = std::stod(value());
    else if (a == "--families") {
      std::string v = value();
      for (std::size_t p = 0; p != std::string::npos;) {
        const std::size_t q = v.find(',', p);
        o.families.push_back(v.substr(p, q == std::string::npos ? q : q - p));
        p = q == std::string::npos ? q : q + 1;
      }
      for (const auto& f : o.families) {
        if (!find_family(f)) usage(("unknown family " + f).c_str());
      }
    } else if (a == "--help" || a == "-h") usage("help");
    else usage(("unknown flag " + a).c_str());
  }
  if (o.gearcoupling.empty()) usage("--gearcoupling is required");
  if (!o.effect_truth.empty()) {
    bool known = false;
    for (const auto& n : hidden_effect_names()) known = known || n == o.effect_truth;
    if (!known) usage(("unknown --effect-truth " + o.effect_truth).c_str());
  }
  if (o.power && !o.draws_given) o.draws = 10;
  if (o.power && o.effects.empty()) o.effects = hidden_effect_names();
  for (const auto& e : o.effects) {
    bool known = false;
    for (const auto& n : hidden_effect_names()) known = known || n == e;
    if (!known) usage(("unknown effect in --effects: " + e).c_str());
  }
  if (o.jobs < 1 || o.jobs > 2) usage("--jobs must be 1 or 2 (the machine is shared)");
  if (o.min_rows < 10 || o.max_rows < o.min_rows) usage("rows: 10 <= --min-rows <= --max-rows");
  if (!o.seed_given) o.seed = static_cast<std::uint64_t>(std::chrono::system_clock::now().time_since_epoch().count());
  if (o.diagnose_threads < 0) o.diagnose_threads = o.jobs > 1 ? 1 : 0;
  return o;
}

struct Result {
  std::size_t k = 0;
  ZooDraw draw;  // csv dropped after writing
  DiagnoseOutcome outcome;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::min<double>(v.size() - 1, std::floor(q * (v.size() - 1) + 0.5)))];
}

// 95 % Wilson score interval of k of n.
std::pair<double, double> wilson(std::size_t k, std::size_t n, double z = 1.959964) {
  if (n == 0) return {0.0, 1.0};
  const double p = static_cast<double>(k) / n, nn = static_cast<double>(n), z2 = z * z;
  const double c = (p + z2 / (2 * nn)) / (1 + z2 / nn);
  const double h = z * std::sqrt(p * (1 - p) / nn + z2 / (4 * nn * nn)) / (1 + z2 / nn);
  return {std::max(0.0, c - h), std::min(1.0, c + h)};
}

/// The share named first and its 95 % interval by the noise draws (a ratio estimator's standard
/// error over the draws k as clusters): every effect at draw k shares its noise, so one noise the
/// diagnosis cannot see through misses most of its row together, and Wilson's interval, which
/// takes the draws as independent, is too narrow (fresh seed 20261314: three slow AR(1)s under
/// white noise made 35 of the 58 misses).
std::tuple<double, double, double> share_by_clusters(const std::vector<std::pair<std::size_t, std::size_t>>& hits_of) {
  double hits = 0, n = 0;
  for (const auto& [h, m] : hits_of) hits += static_cast<double>(h), n += static_cast<double>(m);
  if (n == 0 || hits_of.size() < 2) return {NAN, NAN, NAN};
  const double p = hits / n;
  double ss = 0;
  for (const auto& [h, m] : hits_of) ss += std::pow(static_cast<double>(h) - p * static_cast<double>(m), 2);
  const double k = static_cast<double>(hits_of.size());
  const double se = std::sqrt(k / (k - 1) * ss) / n;
  return {p, std::max(0.0, p - 1.959964 * se), std::min(1.0, p + 1.959964 * se)};
}

/// Per noise draw k: its families, how many effects were named first, and of the identifiable
/// ones; then the share with its interval by draws.
template <typename Task, typename Identifiable>
void print_by_noise_draw(const std::vector<Task>& tasks, Identifiable identifiable) {
  std::map<std::size_t, std::vector<const Task*>> by_k;
  for (const Task& t : tasks) if (t.done && !t.error) by_k[t.k].push_back(&t);
  std::printf("\n| noise draw k | noise families | named first | identifiable: named first |\n|---|---|---|---|\n");
  std::vector<std::pair<std::size_t, std::size_t>> all, id;
  for (const auto& [k, ts] : by_k) {
    std::size_t hits = 0, id_hits = 0, id_n = 0;
    for (const Task* t : ts) {
      hits += t->hit;
      if (identifiable(*t)) ++id_n, id_hits += t->hit;
    }
    std::string families;
    for (const std::string& f : ts.front()->families) families += (families.empty() ? "" : ", ") + f;
    std::printf("| %zu | %s | %zu of %zu | %zu of %zu |\n", k, families.c_str(), hits, ts.size(), id_hits, id_n);
    all.push_back({hits, ts.size()});
    id.push_back({id_hits, id_n});
  }
  const auto [p, lo, hi] = share_by_clusters(all);
  const auto [p_id, lo_id, hi_id] = share_by_clusters(id);
  std::printf("\nby noise draw (each draw's effects share its noise; 95 %% interval over the %zu draws as clusters): named "
              "first %.0f %% (%.0f-%.0f %%); identifiable: %.0f %% (%.0f-%.0f %%)\n",
              by_k.size(), 100 * p, 100 * lo, 100 * hi, 100 * p_id, 100 * lo_id, 100 * hi_id);
}

int power_table(const Options& o) {
  struct Task {
    std::size_t k;
    double snr;
    std::string effect;
    bool done = false, hit = false, claim = false, error = false;
    std::string first;  // the first claim's first name, "noise" when nothing claimed
    double wall_s = 0;
    std::size_t rows = 0;
    double touch_up = 1.0;  // the generator's linear scaling past the effect's physical bounds (1: none)
    double oracle_power = std::numeric_limits<double>::quiet_NaN();  // zoo/oracle.h
    double oracle_d = std::numeric_limits<double>::quiet_NaN();
    double identity_d = std::numeric_limits<double>::quiet_NaN();    // zoo/identity_oracle.h
    std::vector<std::string> families;  // the noise drawn (the same for every effect at draw k)
  };
  // Draws where a test that knew the effect and the noise's spectrum reaches 90 % at 1 % (d >= 3.61).
  const auto oracle_can = [](const Task& t) { return t.oracle_power >= 0.9; };
  // Draws where the truth can be told apart from every rival effect too (zoo/identity_oracle.h):
  // identity and detection d >= 3.61.
  const auto identifiable = [](const Task& t) { return t.identity_d >= 3.61 && t.oracle_d >= 3.61; };
  // Within the library: the generator reached the SNR with the effect's own parameters, its linear
  // touch-up within 25 % (past a physical bound, a touch-up of x2 is a truth no fit can express).
  const auto within_library = [](const Task& t) { return t.touch_up >= 0.8 && t.touch_up <= 1.25; };
  std::vector<Task> tasks;
  for (std::size_t k = 0; k < o.draws; ++k)
    for (double snr : o.snrs)
      for (const auto& e : o.effects) {
        Task t;
        t.k = k, t.snr = snr, t.effect = e;
        tasks.push_back(t);
      }
  const auto root = std::filesystem::temp_directory_path() / ("gc_noise_zoo_power_" + std::to_string(::getpid()));
  std::printf("noise zoo power table: master seed %llu, %zu effect(s) x %zu SNR(s) x %zu draw(s), jobs %d, rows %zu-%zu%s\n",
              static_cast<unsigned long long>(o.seed), o.effects.size(), o.snrs.size(), o.draws, o.jobs, o.min_rows, o.max_rows,
              o.deadline_min > 0 ? format(", deadline %.0f min", o.deadline_min).c_str() : "");
  std::fflush(stdout);
  const auto start = std::chrono::steady_clock::now();
  std::atomic<std::size_t> next{0};
  std::mutex print;
  auto worker = [&]() {
    for (;;) {
      const std::size_t j = next++;
      if (j >= tasks.size()) return;
      if (o.deadline_min > 0 &&
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > 60.0 * o.deadline_min) {
        return;
      }
      Task& t = tasks[j];
      DrawLimits lim;
      lim.max_rows = o.max_rows;
      lim.min_rows = std::min(o.min_rows, o.max_rows);
      lim.only_families = o.families;
      lim.effect_truth = t.effect;
      lim.effect_snr = t.snr;
      ZooDraw d = draw(draw_seed(o.seed, t.k), lim);
      const auto dir = root / ("task_" + std::to_string(j));
      const auto model = write_choice(d.model, dir);
      const auto csv = dir / "recording.csv";
      std::ofstream(csv, std::ios::binary) << d.csv;
      const DiagnoseOutcome out = run_diagnose(o.gearcoupling, csv, model, o.diagnose_threads);
      std::filesystem::remove_all(dir);
      const std::regex re(hidden_effect_pattern(t.effect));
      t.error = out.error;
      t.claim = out.claim;
      t.hit = !out.error && std::any_of(out.first_claim.begin(), out.first_claim.end(),
                                        [&](const std::string& nm) { return std::regex_search(nm, re); });
      t.first = out.error ? "error" : out.first_claim.empty() ? (out.claim ? "(claim, unnamed)" : "noise") : out.first_claim.front();
      t.wall_s = out.wall_s;
      t.rows = d.rows;
      t.oracle_power = d.oracle_power;
      t.oracle_d = d.oracle_d;
      t.identity_d = d.identity_d;
      t.families = d.families;
      std::smatch touch;
      if (std::regex_search(d.description, touch, std::regex("touch-up x([0-9.]+)"))) t.touch_up = std::stod(touch[1]);
      t.done = true;
      std::string names;
      for (const auto& c : out.first_claim) names += (names.empty() ? "" : ",") + c;
      std::lock_guard lock(print);
      std::printf("[k=%zu snr=%.2f %s] %s first=%s outcomes=%s (%zu rows, diagnose %.1f s; oracle d %.1f, power %.0f %%; identity d %.1f vs %s)%s\n  %s\n",
                  t.k, t.snr, t.effect.c_str(), t.error ? "ERROR" : t.hit ? "HIT" : "miss", names.empty() ? "-" : names.c_str(),
                  out.outcomes.c_str(), d.rows, out.wall_s, d.oracle_d, 100 * d.oracle_power, d.identity_d,
                  d.identity_rival.empty() ? "-" : d.identity_rival.c_str(),
                  t.error ? (" " + out.stderr_tail).c_str() : "", d.description.c_str());
      std::fflush(stdout);
    }
  };
  std::vector<std::thread> pool;
  for (int i = 0; i < o.jobs; ++i) pool.emplace_back(worker);
  for (auto& th : pool) th.join();
  std::filesystem::remove_all(root);

  std::printf("\n## Power table: master seed %llu (gc_noise_zoo --power --seed %llu --max-rows %zu --min-rows %zu)\n\n",
              static_cast<unsigned long long>(o.seed), static_cast<unsigned long long>(o.seed), o.max_rows, o.min_rows);
  std::printf("| hidden effect | names that count | SNR | draws | named first | share | 95 %% Wilson | any claim | errors | within the library: named first | where an oracle reaches 90 %%: named first | where the truth is identifiable (identity and detection d >= 3.61): named first | first claim when missed |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::size_t all_n = 0, all_hits = 0, in_n = 0, in_hits = 0, can_n = 0, can_hits = 0, id_n = 0, id_hits = 0;
  for (const auto& e : o.effects) {
    std::string counts;
    for (const auto& info : hidden_effect_table()) if (info.name == e) counts = info.counts;
    for (double snr : o.snrs) {
      std::size_t n = 0, hits = 0, claims = 0, errors = 0, n_in = 0, hits_in = 0, n_can = 0, hits_can = 0, n_id = 0, hits_id = 0;
      std::map<std::string, int> instead;
      for (const auto& t : tasks) {
        if (!t.done || t.effect != e || t.snr != snr) continue;
        if (t.error) { ++errors; continue; }
        ++n, hits += t.hit, claims += t.claim;
        if (within_library(t)) ++n_in, hits_in += t.hit;
        if (oracle_can(t)) ++n_can, hits_can += t.hit;
        if (identifiable(t)) ++n_id, hits_id += t.hit;
        if (!t.hit) ++instead[t.first];
      }
      all_n += n, all_hits += hits, in_n += n_in, in_hits += hits_in, can_n += n_can, can_hits += hits_can;
      id_n += n_id, id_hits += hits_id;
      std::vector<std::pair<int, std::string>> v;
      for (const auto& [name, c] : instead) v.push_back({-c, name});
      std::sort(v.begin(), v.end());
      std::string miss;
      for (const auto& [c, name] : v) miss += (miss.empty() ? "" : ", ") + name + " " + std::to_string(-c);
      const auto [lo, hi] = wilson(hits, n);
      std::printf("| %s | %s | %.2f | %zu | %zu | %.0f %% | %.0f-%.0f %% | %zu | %zu | %zu of %zu | %zu of %zu | %zu of %zu | %s |\n", e.c_str(),
                  counts.c_str(), snr, n, hits, n ? 100.0 * hits / n : 0.0, 100 * lo, 100 * hi, claims, errors, hits_in, n_in,
                  hits_can, n_can, hits_id, n_id, miss.empty() ? "-" : miss.c_str());
    }
  }
  std::printf("\nnamed first: %zu of %zu; within the library (the generator's touch-up x0.8-1.25): %zu of %zu; where a test "
              "that knew the effect and the noise's spectrum reaches 90 %% at 1 %% (zoo/oracle.h, d >= 3.61): %zu of %zu\n",
              all_hits, all_n, in_hits, in_n, can_hits, can_n);
  std::printf("where the truth can also be told apart from every rival effect's nearest member (zoo/identity_oracle.h, identity "
              "and detection d >= 3.61): %zu of %zu\n",
              id_hits, id_n);
  print_by_noise_draw(tasks, identifiable);
  std::vector<double> wall;
  for (const auto& t : tasks) if (t.done) wall.push_back(t.wall_s);
  std::printf("\ndiagnose wall time: median %.1f s, max %.1f s over %zu runs; %.1f min in all\n", quantile(wall, 0.5),
              quantile(wall, 1.0), wall.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  if (o.power) return power_table(o);
  DrawLimits lim;
  lim.max_rows = o.max_rows;
  lim.min_rows = std::min(o.min_rows, o.max_rows);
  lim.only_families = o.families;
  lim.effect_truth = o.effect_truth;
  lim.effect_snr = o.snr;
  std::vector<std::size_t> todo;
  if (o.only >= 0) todo.push_back(static_cast<std::size_t>(o.only));
  else for (std::size_t k = 0; k < o.draws; ++k) todo.push_back(k);

  const std::filesystem::path root = o.keep.empty()
      ? std::filesystem::temp_directory_path() / ("gc_noise_zoo_" + std::to_string(::getpid()))
      : std::filesystem::path(o.keep);
  std::printf("noise zoo: master seed %llu, %zu draw(s), jobs %d, rows %zu-%zu, diagnose %s\n",
              static_cast<unsigned long long>(o.seed), todo.size(), o.jobs, lim.min_rows, lim.max_rows,
              o.diagnose_threads > 0 ? ("-j " + std::to_string(o.diagnose_threads)).c_str() : "(default threads)");
  std::fflush(stdout);

  std::vector<Result> results(todo.size());
  std::atomic<std::size_t> next{0};
  std::mutex print;
  auto worker = [&]() {
    for (;;) {
      const std::size_t j = next++;
      if (j >= todo.size()) return;
      Result& r = results[j];
      r.k = todo[j];
      const auto t0 = std::chrono::steady_clock::now();
      r.draw = draw(draw_seed(o.seed, r.k), lim);
      const double gen_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const auto dir = root / ("draw_" + std::to_string(r.k));
      const auto model = write_choice(r.draw.model, dir);
      const auto csv = dir / "recording.csv";
      std::ofstream(csv, std::ios::binary) << r.draw.csv;
      std::ofstream(dir / "description.txt") << r.draw.description << "\n";
      r.draw.csv.clear();
      r.draw.csv.shrink_to_fit();
      r.outcome = run_diagnose(o.gearcoupling, csv, model, o.diagnose_threads);
      if (o.keep.empty()) std::filesystem::remove_all(dir);
      std::lock_guard lock(print);
      std::printf("[%zu] %s -> %s%s (diagnose %.1f s, generate %.1f s)\n  %s\n", r.k,
                  r.outcome.error ? "ERROR" : r.outcome.claim ? "CLAIM" : "noise", r.outcome.outcomes.c_str(),
                  r.outcome.error ? (" exit " + std::to_string(r.outcome.exit_code) + ": " + r.outcome.stderr_tail).c_str() : "",
                  r.outcome.wall_s, gen_s, r.draw.description.c_str());
      std::fflush(stdout);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < o.jobs; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (o.keep.empty()) std::filesystem::remove_all(root);

  // The rate, with a 95 % Clopper-Pearson interval's upper end.
  std::size_t claims = 0, errors = 0;
  for (const auto& r : results) claims += r.outcome.claim, errors += r.outcome.error;
  const std::size_t n = results.size() - errors;
  std::printf("\n## Noise zoo%s: master seed %llu\n\n", o.effect_truth.empty() ? "" : " (power mode: claims are wanted)", static_cast<unsigned long long>(o.seed));
  std::printf("draws %zu (errors %zu, not counted); false claims %zu of %zu = %.1f %% (95 %% Clopper-Pearson upper bound %.1f %%)\n",
              results.size(), errors, claims, n, n ? 100.0 * claims / n : 0.0, 100.0 * clopper_pearson_upper(claims, n));

  std::printf("\n| family | draws | claims | errors |\n|---|---|---|---|\n");
  std::map<std::string, std::array<std::size_t, 3>> per;
  for (const auto& f : all_families()) per[f.name] = {0, 0, 0};
  for (const auto& r : results) {
    for (const auto& f : r.draw.families) {
      auto& p = per[f];
      ++p[0];
      p[1] += r.outcome.claim;
      p[2] += r.outcome.error;
    }
  }
  for (const auto& f : all_families()) {
    const auto& p = per[f.name];
    std::printf("| %s | %zu | %zu | %zu |\n", f.name, p[0], p[1], p[2]);
  }

  std::printf("\n### Claimed draws (rerun one: --seed %llu --only K)\n", static_cast<unsigned long long>(o.seed));
  for (const auto& r : results) {
    if (!r.outcome.claim) continue;
    std::string names;
    for (const auto& c : r.outcome.claimed) names += (names.empty() ? "" : ", ") + c;
    std::printf("- K=%zu %s\n  outcomes: %s\n  claimed: %s\n  numbers: %s\n", r.k, r.draw.description.c_str(),
                r.outcome.outcomes.c_str(), names.empty() ? "(none named)" : names.c_str(), r.outcome.numbers.c_str());
  }
  if (errors) {
    std::printf("\n### Errors\n");
    for (const auto& r : results) {
      if (r.outcome.error) std::printf("- K=%zu exit %d: %s\n  %s\n", r.k, r.outcome.exit_code, r.outcome.stderr_tail.c_str(), r.draw.description.c_str());
    }
  }

  if (!o.effect_truth.empty()) {
    const std::regex re(hidden_effect_pattern(o.effect_truth));
    std::size_t hits = 0;
    for (const auto& r : results) {
      const bool hit = !r.outcome.first_claim.empty() &&
                       std::any_of(r.outcome.first_claim.begin(), r.outcome.first_claim.end(),
                                   [&](const std::string& nm) { return std::regex_search(nm, re); });
      hits += hit;
    }
    std::printf("\npower: hidden %s at %.2fx the noise: named first in %zu of %zu draws (%.1f %%); any claim in %zu\n",
                o.effect_truth.c_str(), o.snr, hits, n, n ? 100.0 * hits / n : 0.0, claims);
  }

  // Diagnose's wall time against rows.
  std::vector<double> all;
  std::map<int, std::vector<double>> by_bucket;
  const std::size_t edges[] = {1000, 3000, 10000, 30000, 100000, 1000000};
  for (const auto& r : results) {
    all.push_back(r.outcome.wall_s);
    int b = 0;
    while (b < 5 && r.draw.rows >= edges[b + 1]) ++b;
    by_bucket[b].push_back(r.outcome.wall_s);
  }
  std::printf("\ndiagnose wall time: median %.1f s, p90 %.1f s, max %.1f s\n\n| rows | draws | median s | p90 s | max s |\n|---|---|---|---|---|\n",
              quantile(all, 0.5), quantile(all, 0.9), quantile(all, 1.0));
  for (const auto& [b, v] : by_bucket) {
    std::printf("| %zu-%zu | %zu | %.1f | %.1f | %.1f |\n", edges[b], edges[b + 1], v.size(), quantile(v, 0.5), quantile(v, 0.9),
                quantile(v, 1.0));
  }
  return 0;
}
