#include "tests/diagnosis/zoo/harness.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <google/protobuf/util/json_util.h>

#include "idl/diagnosis.pb.h"
#include "tests/diagnosis/zoo/text.h"

extern char** environ;

namespace gc::zoo {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string candidate_text(const gearcoupling::v1::CandidateRecord& c) {
  return format("%s held-out %.4g N·m, reduction %.2f%%, t %.2f", c.effect().c_str(), c.held_out_rmse_nm(),
                100 * c.reduction(), c.t());
}

}  // namespace

void read_diagnosis_json(const std::string& json, DiagnoseOutcome& out) {
  gearcoupling::v1::DiagnosisResult r;
  google::protobuf::util::JsonParseOptions opt;
  opt.ignore_unknown_fields = true;  // diagnose grows fields while the zoo runs
  if (!google::protobuf::util::JsonStringToMessage(json, &r, opt).ok()) {
    out.error = true;
    out.stderr_tail = "JSON does not parse: " + json.substr(0, 300);
    return;
  }
  std::set<std::string> seen;
  auto name = [&](const std::string& n) {
    if (!n.empty() && seen.insert(n).second) out.claimed.push_back(n);
  };
  for (int i = 0; i < r.rounds_size(); ++i) {
    const auto& round = r.rounds(i);
    out.outcomes += (i ? "; " : "") + round.outcome();
    if (round.outcome() == "noise") continue;
    const bool first = !out.claim;
    out.claim = true;
    std::vector<std::string> names = {round.claimed().effect()};
    for (const auto& p : round.claimed().parameters()) names.push_back(p.name());
    if (round.formula_chosen() || round.outcome() == "formula_proposed") {
      names.push_back(round.formula().effect());
      for (const auto& p : round.formula().parameters()) names.push_back(p.name());
    }
    for (const auto& n : names) {
      if (n.empty()) continue;
      name(n);
      if (first) out.first_claim.push_back(n);
    }
    std::string n = format("round %d %s: rmse %.4g N·m, noise %.4g N·m (phi %.2f/%.2f)", i + 1, round.outcome().c_str(),
                           round.rmse_nm(), round.noise_rmse_nm(), round.noise_phi_y(), round.noise_phi_z());
    if (round.ranking_size() > 0) n += "; best " + candidate_text(round.ranking(0));
    if (round.has_formula()) n += "; formula " + candidate_text(round.formula());
    out.numbers += (out.numbers.empty() ? "" : " | ") + n;
  }
  if (r.rounds_size() == 0) out.outcomes = "(no round)";
  for (const auto& a : r.add_flags()) {
    out.claim = true;
    name("add:" + a);
  }
}

DiagnoseOutcome run_diagnose(const std::string& gearcoupling, const std::filesystem::path& csv,
                             const std::filesystem::path& model, int threads) {
  const auto out_path = csv.parent_path() / "diagnose.json", err_path = csv.parent_path() / "diagnose.err";
  std::vector<std::string> args = {gearcoupling, "diagnose", "--data", csv.string(), "--model", model.string(), "--json"};
  if (threads > 0) args.insert(args.end(), {"-j", std::to_string(threads)});
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, gearcoupling.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot start " + gearcoupling);
  int status = 0;
  ::waitpid(pid, &status, 0);
  DiagnoseOutcome o;
  o.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  const std::string err = slurp(err_path);
  o.stderr_tail = err.size() > 600 ? err.substr(err.size() - 600) : err;
  if (o.exit_code != 0) {
    o.error = true;
    return o;
  }
  read_diagnosis_json(slurp(out_path), o);
  return o;
}

namespace {
// Regularised incomplete beta I_x(a, b) by Lentz's continued fraction (Numerical Recipes 6.4).
double betacf(double a, double b, double x) {
  const double tiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  d = 1.0 / (std::abs(d) < tiny ? tiny : d);
  double h = d;
  for (int m = 1; m <= 500; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((a - 1.0 + m2) * (a + m2));
    d = 1.0 + aa * d, c = 1.0 + aa / c;
    d = 1.0 / (std::abs(d) < tiny ? tiny : d), c = std::abs(c) < tiny ? tiny : c;
    h *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + 1.0 + m2));
    d = 1.0 + aa * d, c = 1.0 + aa / c;
    d = 1.0 / (std::abs(d) < tiny ? tiny : d), c = std::abs(c) < tiny ? tiny : c;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) < 1e-14) break;
  }
  return h;
}
double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log(1.0 - x));
  return x < (a + 1.0) / (a + b + 2.0) ? front * betacf(a, b, x) / a : 1.0 - front * betacf(b, a, 1.0 - x) / b;
}
}  // namespace

double clopper_pearson_upper(std::size_t k, std::size_t n, double alpha) {
  if (n == 0) return 1.0;
  if (k >= n) return 1.0;
  // Upper bound p: P(X <= k | p) = alpha / 2, i.e. I_p(k + 1, n - k) = 1 - alpha / 2.
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (incomplete_beta(k + 1.0, static_cast<double>(n - k), mid) < 1.0 - alpha / 2 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace gc::zoo
