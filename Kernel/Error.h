// The one exception type of Talus: every bad input and every detected blow-up ends here,
// with a message that names the parameter, file and line, or the particle and time.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace talus {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// Throws Error(message) unless condition holds. Used for argument checks in setters.
inline void require(bool condition, const std::string& message) {
    if (!condition) throw Error(message);
}

// A number as messages show it (shortest form, as std::ostream writes it: 0.1, 1e-05, nan).
inline std::string str(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

}  // namespace talus
