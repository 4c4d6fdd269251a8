// A compile-time check that a printf line format has one conversion per described column, so
// that a column added to a format's description without its conversion (or the reverse) does
// not compile.
#pragma once

#include <cstddef>
#include <string_view>

namespace talus::formats {

// Number of conversions ('%' not followed by '%') in a printf format.
constexpr int conversions(std::string_view format) {
    int n = 0;
    for (std::size_t k = 0; k < format.size(); ++k) {
        if (format[k] != '%') continue;
        if (k + 1 < format.size() && format[k + 1] == '%') {
            ++k;
            continue;
        }
        ++n;
    }
    return n;
}

}  // namespace talus::formats
