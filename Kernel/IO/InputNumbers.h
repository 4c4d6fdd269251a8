// Strict reading of numbers from the words of input files and flags, shared by every reader of
// the kernel: the whole word must be the number (no trailing text), reals must be finite (no
// nan, no inf, no overflow), integers must be whole decimal numbers in range ("1.7" and "1e30"
// are not integers). Readers say where a word comes from with an InputPlace, so that every
// failure is a talus::Error "<file description> line <L>: <problem>".
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace talus {

// The conversions alone: false when `word` is not such a number (value is then unspecified).
// A leading '+' is allowed, and hexadecimal reals (0x1p-3); subnormal reals read exactly, reals
// below them read as 0.
bool toFiniteReal(std::string_view word, double& value);
bool toInteger(std::string_view word, std::int64_t& value);
bool toCount(std::string_view word, std::uint64_t& value);  // no sign but '+': "-0" is not a count

// A line of an input file, for messages ("restart file run.restart line 12: ..."), and the
// conversions that name it, and what the word was due to be, when a word is not that number.
class InputPlace {
public:
    // `file` describes the file, e.g. "restart file run.restart".
    explicit InputPlace(std::string file) : file_(std::move(file)) {}

    long line = 1;

    [[noreturn]] void fail(const std::string& problem) const;
    double real(std::string_view word, std::string_view what) const;
    std::int64_t integer(std::string_view word, std::string_view what,
                         std::int64_t min = std::numeric_limits<std::int64_t>::min(),
                         std::int64_t max = std::numeric_limits<std::int64_t>::max()) const;
    std::uint64_t count(std::string_view word, std::string_view what,
                        std::uint64_t max = std::numeric_limits<std::uint64_t>::max()) const;

private:
    std::string file_;
};

}  // namespace talus
