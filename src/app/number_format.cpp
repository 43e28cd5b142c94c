#include "app/number_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace weft::app {

std::string significant_format(double value, int significant, int least_decimals,
                               std::string_view suffix) {
    significant = std::max(significant, 1);
    least_decimals = std::max(least_decimals, 0);
    std::string escaped;
    for (char c : suffix) escaped += c == '%' ? std::string("%%") : std::string(1, c);
    char format[32];
    const double magnitude = std::fabs(value);
    if (!std::isfinite(value) || magnitude == 0.0) {
        std::snprintf(format, sizeof format, "%%.%df", least_decimals);
        return format + escaped;
    }
    // The power of ten of the leading digit: -3 for 0.00407, 4 for 12345.
    const int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
    if (exponent < -4 || exponent >= 9) {
        std::snprintf(format, sizeof format, "%%.%dg", std::max(significant, least_decimals));
        return format + escaped;
    }
    const int decimals = std::max({significant - 1 - exponent, least_decimals, 0});
    std::snprintf(format, sizeof format, "%%.%df", decimals);
    return format + escaped;
}

int decimals_to_reach(double low) {
    if (!(low > 0.0) || low >= 1.0 || !std::isfinite(low)) return 0;
    // A hair of slack, so 1e-4 (a little above or below in binary) needs 4, not 5.
    return static_cast<int>(std::ceil(-std::log10(low) - 1e-9));
}

std::string significant_text(double value, int significant, int least_decimals) {
    char text[64];
    std::snprintf(text, sizeof text, significant_format(value, significant, least_decimals).c_str(),
                  value);
    return text;
}

}  // namespace weft::app
