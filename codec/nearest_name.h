// "did you mean ...": the known name nearest a misspelt one, for the errors of every edge (an
// unknown field of a coupling or model file, a bundled model or catalogue name).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gc::codec {

/// Edits (insert, delete, substitute, swap two neighbours) from `a` to `b`, ignoring ASCII case:
/// the optimal string alignment distance.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The name of `known` nearest `typed` when it is near enough to be a typo of it: at most 1 edit
/// for up to 4 characters, 2 for up to 8, 3 beyond; the first such in `known`'s order on a tie.
/// "" when none is, or when `typed` is itself in `known`.
std::string nearest_name(std::string_view typed, const std::vector<std::string>& known);

/// "; did you mean 'NAME'?" for nearest_name, "" when there is none: to append to an error.
std::string did_you_mean(std::string_view typed, const std::vector<std::string>& known);

/// did_you_mean among the effects of the library (core/effects/effect_registry.h): for a model
/// file's effect or validate --add.
std::string did_you_mean_effect(std::string_view typed);

}  // namespace gc::codec
