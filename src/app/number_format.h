// How the panel writes a number: with enough significant digits that a light particle's mass
// (0.00407 g) or a small damping (0.00025 N s/m) reads as itself, not "0.00" or "0.0003" (a
// fixed "%.2f" or "%.4f" rounded them away). ImGui-free, so it is tested; the panel hands the
// format to its sliders.
#pragma once

#include <string>
#include <string_view>

namespace weft::app {

// The printf format that writes `value` with `significant` significant digits, chosen from
// its magnitude: fixed notation ("%.5f" for 0.00407, "%.0f" for 12345: never an exponent
// for a number a slider spans), exponent notation ("%.3g") only below 1e-4 or from 1e9 on,
// where fixed notation would be a row of zeros. Never fewer than `least_decimals` decimals
// in fixed notation, nor fewer than that many significant digits in exponent notation: a
// logarithmic slider in Dear ImGui 1.86 reads the format's precision as the smallest step
// it can reach (10^-precision), so the format must resolve the slider's low end. `suffix`
// follows the number ("%.2f x rest"); a '%' in it is written as "%%".
std::string significant_format(double value, int significant, int least_decimals = 0,
                               std::string_view suffix = "");

// The decimals a logarithmic slider's format needs to reach `low` (> 0): 4 for 1e-4, 0 for
// 1 and above.
int decimals_to_reach(double low);

// `value` written by significant_format (without a suffix): "0.00407", "0.000250", "800".
std::string significant_text(double value, int significant, int least_decimals = 0);

}  // namespace weft::app
