// Strict parsing of numeric command-line values: the whole text must be one number in range,
// or the caller gets a message saying why. atoi and atof would turn "abc" into 0 and "1x"
// into 1 without a word, and a study would then run with a value nobody asked for.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <system_error>

namespace weft::bench {

// An integer in [low, high], or nothing with `why` set.
inline std::optional<long long> parse_integer(const std::string& text, long long low,
                                              long long high, std::string& why) {
    long long value = 0;
    const char* end = text.data() + text.size();
    const auto [stop, status] = std::from_chars(text.data(), end, value);
    if (text.empty() || status == std::errc::invalid_argument || stop != end) {
        why = "'" + text + "' is not an integer";
        return std::nullopt;
    }
    if (status == std::errc::result_out_of_range || value < low || value > high) {
        why = "'" + text + "' is out of range (" + std::to_string(low) + " to " +
              std::to_string(high) + ")";
        return std::nullopt;
    }
    return value;
}

// A finite number strictly greater than `above`, or nothing with `why` set.
inline std::optional<double> parse_number_above(const std::string& text, double above,
                                                std::string& why) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [stop, status] = std::from_chars(text.data(), end, value);
    if (text.empty() || status == std::errc::invalid_argument || stop != end) {
        why = "'" + text + "' is not a number";
        return std::nullopt;
    }
    if (status == std::errc::result_out_of_range || !std::isfinite(value) || !(value > above)) {
        char bound[32];
        std::snprintf(bound, sizeof bound, "%g", above);
        why = "'" + text + "' must be a finite number > " + bound;
        return std::nullopt;
    }
    return value;
}

}  // namespace weft::bench
