#include "core/effects/expression.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "core/effects/expression_terms.h"
#include "core/model_error.h"

namespace gc {
namespace {

/// The EffectInfo over `terms`, each found by `find` (interned or owned).
template <typename Find>
EffectInfo make_info(const std::vector<std::string>& terms, Find find) {
  EffectInfo info{kExpressionEffect,
                  "A formula for what the library's effects do not explain: a sum of terms built from the "
                  "model's inputs and outputs (docs/diagnosis.md), found by diagnose or written by hand.",
                  "none: a discrepancy term (Kennedy and O'Hagan's model discrepancy)",
                  {}};
  for (const std::string& name : terms) {
    const ExpressionTerm* term = find(name);
    if (!term) {
      std::string known;
      for (const ExpressionTerm& t : expression_terms()) known += (known.empty() ? "" : ", ") + t.name;
      throw InvalidInput(std::string("effects.") + kExpressionEffect + "." + name,
                         "unknown term; the terms are: " + known +
                             ", time_cycle_<P>s_<sin|cos>_on_<y|z> for a period P of 0.0001 to 1000000 s, step_at_<t>s_on_<y|z>, "
                             "[torque_]mesh_order_<N>[_plus_<j>|_minus_<j>]_<sin_on_y|...|backward_sin> for a coupling "
                             "of N teeth (j = 1, 2), and ringing_<f_n>Hz_zeta<zeta>_on_<y|z>");
    }
    info.parameters.push_back({term->name, term->coefficient_unit, term->formula, -term->bound, term->bound, 0.0, 0.0, {}});
  }
  return info;
}

/// Catalogue order, so that {a, b} and {b, a} are one expression.
std::vector<std::string> in_catalogue_order(const std::vector<std::string>& terms) {
  std::vector<std::string> ordered;
  for (const ExpressionTerm& t : expression_terms()) {
    for (const std::string& name : terms) if (name == t.name) { ordered.push_back(name); break; }
  }
  // Then the time_cycle terms (made on use, not in the catalogue) and unknown names (make_info
  // names them), sorted.
  std::vector<std::string> rest;
  for (const std::string& name : terms) {
    if (std::find(ordered.begin(), ordered.end(), name) == ordered.end()) rest.push_back(name);
  }
  std::sort(rest.begin(), rest.end());
  ordered.insert(ordered.end(), rest.begin(), rest.end());
  return ordered;
}

/// What an expression made from a model's values owns: its EffectInfo and the terms made on
/// use (time_cycle, step), freed with it. A base before Effect, so it is made first.
struct OwnedTerms {
  std::vector<std::unique_ptr<const ExpressionTerm>> made;
  std::unique_ptr<const EffectInfo> info;
};

class Expression final : private OwnedTerms, public Effect {
 public:
  /// Over interned terms and info (fits: expression_registration).
  Expression(const EffectInfo& info, const ParameterValues& values) : Effect(info, values) {
    for (const ParameterSpec& p : info.parameters) terms_.push_back(find_expression_term(p.name));
  }
  /// Owning its info and terms (a model's: make_expression).
  Expression(OwnedTerms owned, const ParameterValues& values)
      : OwnedTerms(std::move(owned)), Effect(*OwnedTerms::info, values) {
    for (const ParameterSpec& p : OwnedTerms::info->parameters) {
      for (const auto& term : made) {
        if (term->name == p.name) terms_.push_back(term.get());
      }
    }
  }

  void adjust_outputs(const MeasurementSample& sample, const ModelContext&, const ModelState&,
                      SensorMoments& moments) const override {
    const SensorMoments model = moments;  // every term sees the model before the formula
    for (std::size_t k = 0; k < terms_.size(); ++k) {
      const std::optional<Eigen::Vector2d> v = terms_[k]->value(sample, model);
      if (!v) {
        throw InvalidInput(std::string("effects.") + kExpressionEffect + "." + terms_[k]->name,
                           "needs an input this sample lacks (" + terms_[k]->formula + ")");
      }
      moments.y_nm += values()[k] * v->x();
      moments.z_nm += values()[k] * v->y();
    }
  }

  // A ringing term's transient, from the torque before the sample (its value() at a sample alone is
  // the steady state, zero).
  void adjust_outputs_in_history(const InputHistory& history, SensorMoments& moments) const override {
    for (std::size_t k = 0; k < terms_.size(); ++k) {
      if (!terms_[k]->reads_history()) continue;
      const Eigen::Vector2d v = terms_[k]->history_value(history);
      moments.y_nm += values()[k] * v.x();
      moments.z_nm += values()[k] * v.y();
    }
  }

  // The same, term by term over the rows: each row's sum takes the terms in the same order.
  void adjust_outputs_in_history_at(std::span<const RecordedSample> recording, std::span<const std::size_t> rows,
                                    std::span<SensorMoments> moments) const override {
    for (std::size_t k = 0; k < terms_.size(); ++k) {
      if (!terms_[k]->reads_history()) continue;
      const std::vector<double> r = terms_[k]->history_values_at(recording, rows);
      const Eigen::Vector2d channel = terms_[k]->history_channel();
      for (std::size_t j = 0; j < rows.size(); ++j) {
        const Eigen::Vector2d v = r[j] * channel;
        moments[j].y_nm += values()[k] * v.x();
        moments[j].z_nm += values()[k] * v.y();
      }
    }
  }

  bool reads_history() const override {
    return std::any_of(terms_.begin(), terms_.end(), [](const ExpressionTerm* t) { return t->reads_history(); });
  }

  double history_s() const override {
    double longest = 0.0;
    for (const ExpressionTerm* term : terms_) longest = std::max(longest, term->history_s());
    return longest;
  }

 private:
  std::vector<const ExpressionTerm*> terms_;
};

}  // namespace

const EffectInfo& expression_info(const std::vector<std::string>& terms) {
  static std::mutex mutex;
  static std::map<std::vector<std::string>, std::unique_ptr<const EffectInfo>> interned;
  const std::vector<std::string> key = in_catalogue_order(terms);
  std::lock_guard lock(mutex);
  auto& slot = interned[key];
  if (!slot) slot = std::make_unique<const EffectInfo>(make_info(key, find_expression_term));
  return *slot;
}

std::shared_ptr<const Effect> make_expression(const ParameterValues& coefficients) {
  if (coefficients.empty()) {
    throw InvalidInput(std::string("effects.") + kExpressionEffect, "give at least one term and its coefficient");
  }
  std::vector<std::string> terms;
  for (const auto& [name, value] : coefficients) {
    require_finite(std::string("effects.") + kExpressionEffect + "." + name, value);
    terms.push_back(name);
  }
  // Not interned: a model's expression owns what it needs, so a model from the network (a live
  // swap of terms no one used before) leaves nothing behind when it goes.
  OwnedTerms owned;
  const EffectInfo info = make_info(in_catalogue_order(terms), [&owned](const std::string& name) -> const ExpressionTerm* {
    std::optional<ExpressionTerm> term = make_expression_term(name);
    if (!term) return nullptr;
    owned.made.push_back(std::make_unique<const ExpressionTerm>(std::move(*term)));
    return owned.made.back().get();
  });
  owned.info = std::make_unique<const EffectInfo>(info);
  return std::make_shared<const Expression>(std::move(owned), coefficients);
}

EffectRegistration expression_registration(const std::vector<std::string>& terms) {
  // Fits keep the interned info (they may point at it), as the diagnosis' term sets are few.
  return {&expression_info(terms), [](const ParameterValues& values) -> std::shared_ptr<const Effect> {
            if (values.empty()) return make_expression(values);   // its error
            std::vector<std::string> names;
            for (const auto& [name, value] : values) {
              require_finite(std::string("effects.") + kExpressionEffect + "." + name, value);
              names.push_back(name);
            }
            return std::make_shared<const Expression>(expression_info(names), values);
          }};
}

}  // namespace gc
