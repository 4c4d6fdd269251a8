// Strict reading of numbers from the words of input files and flags, for every reader of the
// kernel. The conversions and the wording of their problems live in the formats library
// (Formats/Numbers.h), shared with talus-cg; here readers say where a word comes from with an
// InputPlace, so that every failure is a talus::Error "<file description> line <L>: <problem>".
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "Formats/Numbers.h"

namespace talus {

using formats::toCount;
using formats::toFiniteReal;
using formats::toInteger;

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
