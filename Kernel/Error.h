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

// An error that every rank of an MPI run throws at the same step (Parallel/DomainSplit.h), so
// that all of them stop cleanly. The rank that found the problem carries the message; the others
// are silent (their message only says which rank found it), and Simulation::solve prints only
// the first kind.
class CollectiveError : public Error {
public:
    CollectiveError(const std::string& message, bool silent) : Error(message), silent_(silent) {}
    bool silent() const { return silent_; }

private:
    bool silent_;
};

// Throws Error(message) unless condition holds. Used for argument checks in setters.
inline void require(bool condition, const std::string& message) {
    if (!condition) throw Error(message);
}

// Throws unless `word` is one word (not empty, no white space): names that files write
// between spaces (a run's name, a species').
inline void requireWord(const std::string& word, const std::string& what) {
    require(!word.empty() && word.find_first_of(" \t\n\r") == std::string::npos,
            what + " must be one word without spaces, got '" + word + "'");
}

// A number as messages show it (shortest form, as std::ostream writes it: 0.1, 1e-05, nan).
inline std::string str(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

}  // namespace talus
