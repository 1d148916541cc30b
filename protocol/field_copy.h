// The two directions of a field-list conversion between core value types and IDL samples:
// wire_inputs.cc and wire_results.cc list each type's fields once, in a template taking
// `copy(core_field, wire_field)`, and pass one of these to go either way.
#pragma once

namespace gc::protocol {

inline constexpr auto kToWire = [](const auto& core, auto& wire) { wire = core; };
inline constexpr auto kFromWire = [](auto& core, const auto& wire) { core = wire; };

}  // namespace gc::protocol
