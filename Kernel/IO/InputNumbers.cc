#include "IO/InputNumbers.h"

#include "Error.h"

namespace talus {

void InputPlace::fail(const std::string& problem) const {
    throw Error(file_ + " line " + std::to_string(line) + ": " + problem);
}

double InputPlace::real(std::string_view word, std::string_view what) const {
    double x = 0;
    if (const std::string problem = formats::readReal(word, what, x); !problem.empty()) fail(problem);
    return x;
}

std::int64_t InputPlace::integer(std::string_view word, std::string_view what, std::int64_t min,
                                 std::int64_t max) const {
    std::int64_t n = 0;
    if (const std::string problem = formats::readInteger(word, what, n, min, max); !problem.empty()) fail(problem);
    return n;
}

std::uint64_t InputPlace::count(std::string_view word, std::string_view what, std::uint64_t max) const {
    std::uint64_t n = 0;
    if (const std::string problem = formats::readCount(word, what, n, max); !problem.empty()) fail(problem);
    return n;
}

}  // namespace talus
