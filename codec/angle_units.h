// Degrees at the human-facing edges, radians everywhere inside (style: SI at every interface).
#pragma once

#include <numbers>

namespace gc::codec {

constexpr double radians_from_degrees(double degrees) { return degrees * std::numbers::pi / 180.0; }
constexpr double degrees_from_radians(double radians) { return radians * 180.0 / std::numbers::pi; }

}  // namespace gc::codec
