// Strict reading of the numbers in Talus's file formats and flags, shared by the kernel's readers
// (Kernel/IO/InputNumbers.h) and the coarse-graining tool's (Tools/CG/IO/TextFile.h): the whole
// word must be the number (no trailing text), reals must be finite (no nan, no inf, no overflow),
// integers whole decimal numbers in range ("1.7" and "1e30" are not integers).
//
// The library throws nothing: each reading returns the problem as text, which the reader puts after
// its file and line ("restart file run.restart line 12: bad number 'x' for the radius") and throws
// as its own error type (talus::Error in the kernel, cg::InputError in talus-cg).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace talus::formats {

// The conversions alone: false when `word` is not such a number (value is then unspecified). A
// leading '+' is allowed, and hexadecimal reals (0x1p-3); subnormal reals read exactly, reals below
// them read as 0.
bool toFiniteReal(std::string_view word, double& value);
bool toInteger(std::string_view word, std::int64_t& value);
bool toCount(std::string_view word,
             std::uint64_t& value);  // no sign but '+': "-0" is not a count

// The same readings with the reason: empty when `word` is the number (`value` holds it), else the
// problem, naming the word and `what` it was due to be ("'1.7' for the atom id is not a whole
// number", "the image flag 2000000000 is out of range (-1 to 1)").
std::string readReal(std::string_view word, std::string_view what, double& value);
std::string readInteger(std::string_view word, std::string_view what, std::int64_t& value,
                        std::int64_t min = std::numeric_limits<std::int64_t>::min(),
                        std::int64_t max = std::numeric_limits<std::int64_t>::max());
std::string readCount(std::string_view word, std::string_view what, std::uint64_t& value,
                      std::uint64_t max = std::numeric_limits<std::uint64_t>::max());

}  // namespace talus::formats
