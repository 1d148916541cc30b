// A formula added to the model without recompiling: the sum of catalogue terms
// (core/effects/expression_terms.h) times their coefficients, added to the sensor moments after
// every other effect:  M += sum_k c_k term_k(sample, M).
// In a model file: effects { name: "expression" parameters { name: "<term>" value: <c> } ... }; each
// parameter names a term and gives its coefficient in the term's unit, finite and within its
// bound. `diagnose --write-model` writes it, `validate --add expression=<term>=<c>,...` takes it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/effects/effect_registry.h"

namespace gc {

inline constexpr const char* kExpressionEffect = "expression";

/// The EffectInfo of an expression over exactly these terms (catalogue order), interned: the same
/// term set gives the same object for the life of the process, so fits may point at it.
const EffectInfo& expression_info(const std::vector<std::string>& terms);

/// The expression with these coefficients, owning its EffectInfo and the terms it made (not
/// interned: a model's expression leaves nothing behind when the model goes, issue 38). Throws
/// InvalidInput naming "effects.expression.<term>"
/// for an unknown term (listing the catalogue) or a coefficient that is not finite or beyond its
/// bound, and "effects.expression" for no term at all.
std::shared_ptr<const Effect> make_expression(const ParameterValues& coefficients);

/// Registration for fitting an expression over these terms (values: their coefficients); what it
/// makes points at the interned expression_info of its values' terms.
EffectRegistration expression_registration(const std::vector<std::string>& terms);

}  // namespace gc
