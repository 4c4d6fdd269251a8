#include "IO/InputNumbers.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "Error.h"

namespace talus {

namespace {

// Drops one leading '+', which from_chars does not take; "+-1" stays no number.
bool dropPlus(std::string_view& word) {
    if (!word.empty() && word.front() == '+') {
        word.remove_prefix(1);
        return !word.empty() && word.front() != '-';
    }
    return !word.empty();
}


// A whole decimal number, perhaps too large for any integer type.
bool wholeDecimal(std::string_view word) {
    if (!word.empty() && (word.front() == '+' || word.front() == '-')) word.remove_prefix(1);
    return !word.empty() && word.find_first_not_of("0123456789") == std::string_view::npos;
}

// What a word is as a real number.
enum class RealWord { finite, nonFinite, overflow, notANumber };

RealWord readReal(std::string_view word, double& value) {
    if (!dropPlus(word)) return RealWord::notANumber;
    const char* end = word.data() + word.size();
    // Hexadecimal reals (0x1p-3: a value to the bit) as strtod takes them; from_chars wants them
    // without the 0x and its sign.
    const bool negative = word.front() == '-';
    const std::string_view digits = word.substr(negative);
    const bool hex = digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X') && digits[2] != '-';
    const auto [stop, error] = hex ? std::from_chars(digits.data() + 2, end, value, std::chars_format::hex)
                                   : std::from_chars(word.data(), end, value);
    if (hex && negative) value = -value;
    if (stop != end) return RealWord::notANumber;
    if (error == std::errc::result_out_of_range) {
        // Underflow below the subnormals (1e-400) reads as 0, as strtod reads it; overflow is no number.
        value = std::strtod(std::string(word).c_str(), nullptr);
        return std::isfinite(value) ? RealWord::finite : RealWord::overflow;
    }
    if (error != std::errc()) return RealWord::notANumber;
    return std::isfinite(value) ? RealWord::finite : RealWord::nonFinite;
}

}  // namespace

bool toFiniteReal(std::string_view word, double& value) { return readReal(word, value) == RealWord::finite; }

bool toInteger(std::string_view word, std::int64_t& value) {
    if (!dropPlus(word)) return false;
    const char* end = word.data() + word.size();
    const auto [stop, error] = std::from_chars(word.data(), end, value);
    return error == std::errc() && stop == end;
}

bool toCount(std::string_view word, std::uint64_t& value) {
    if (!dropPlus(word) || word.front() == '-') return false;
    const char* end = word.data() + word.size();
    const auto [stop, error] = std::from_chars(word.data(), end, value);
    return error == std::errc() && stop == end;
}

void InputPlace::fail(const std::string& problem) const {
    throw Error(file_ + " line " + std::to_string(line) + ": " + problem);
}

double InputPlace::real(std::string_view word, std::string_view what) const {
    double x = 0;
    switch (readReal(word, x)) {
        case RealWord::finite: return x;
        case RealWord::nonFinite: fail("'" + std::string(word) + "' for " + std::string(what) + " is not a finite number");
        case RealWord::overflow: fail("bad number '" + std::string(word) + "' for " + std::string(what) + " (too large)");
        case RealWord::notANumber: break;
    }
    fail("bad number '" + std::string(word) + "' for " + std::string(what));
}

std::int64_t InputPlace::integer(std::string_view word, std::string_view what, std::int64_t min, std::int64_t max) const {
    std::int64_t n = 0;
    const bool read = toInteger(word, n);
    if (!read && !wholeDecimal(word)) {
        double x = 0;
        if (toFiniteReal(word, x)) fail("'" + std::string(word) + "' for " + std::string(what) + " is not an integer");
        fail("bad integer '" + std::string(word) + "' for " + std::string(what));
    }
    if (!read || n < min || n > max)  // (not read: digits beyond 64 bits)
        fail(std::string(what) + " " + std::string(word) + " is out of range (" + std::to_string(min) + " to " +
             std::to_string(max) + ")");
    return n;
}

std::uint64_t InputPlace::count(std::string_view word, std::string_view what, std::uint64_t max) const {
    std::uint64_t n = 0;
    const bool read = toCount(word, n);
    if (!read && !(wholeDecimal(word) && word.front() != '-')) {
        double x = 0;
        if (toFiniteReal(word, x) && x >= 0)
            fail("'" + std::string(word) + "' for " + std::string(what) + " is not a whole number");
        fail("bad count '" + std::string(word) + "' for " + std::string(what));
    }
    if (!read || n > max)  // (not read: digits beyond 64 bits)
        fail(std::string(what) + " " + std::string(word) + " is out of range (at most " + std::to_string(max) + ")");
    return n;
}

}  // namespace talus
