// Numbers in human text in engineering notation: three significant digits and an SI prefix
// that is a power of 1000 ("1.50 MN·m", "20.0 kN·m", "251 N·m"), so that every summary,
// verdict and report quotes moments and torques alike (docs/cli.md). Pure text, no locale.
#pragma once

#include <string>
#include <string_view>

namespace gc {

/// `value` in `unit` (SI, e.g. "N·m", "rad", "s"), prefixed: engineering_text(2.04e4, "N·m") is
/// "20.4 kN·m". Units without prefixes ("deg", "-", "") get three significant digits only, and
/// "-" (dimensionless) is not written.
/// Non-finite values are written as such ("nan N·m").
std::string engineering_text(double value, std::string_view unit);

/// `value` with the prefix and decimals `reference` would get, for numbers read side by side:
/// engineering_text(251, "N·m", 2.04e4) is "0.251 kN·m".
std::string engineering_text(double value, std::string_view unit, double reference);

/// "1.50-1.80 MN·m" (one prefix, from the larger magnitude), or "1.50 MN·m" when both ends read
/// the same.
std::string engineering_range(double lower, double upper, std::string_view unit);

/// The range under the prefix `scale` takes (1e3: "k"), three significant digits for the larger
/// end: engineering_range(0.625e6, 2.2e6, "N·m", 1e3) is "625-2200 kN·m".
std::string engineering_range(double lower, double upper, std::string_view unit, double scale);

}  // namespace gc
