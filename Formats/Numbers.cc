#include "Formats/Numbers.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace talus::formats {

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

RealWord classifyReal(std::string_view word, double& value) {
    if (!dropPlus(word)) return RealWord::notANumber;
    const char* end = word.data() + word.size();
    // Hexadecimal reals (0x1p-3: a value to the bit) as strtod takes them; from_chars wants them
    // without the 0x and its sign.
    const bool negative = word.front() == '-';
    const std::string_view digits = word.substr(negative);
    const bool hex =
        digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X') && digits[2] != '-';
    const auto [stop, error] = hex ? std::from_chars(digits.data() + 2, end, value, std::chars_format::hex)
                                   : std::from_chars(word.data(), end, value);
    if (hex && negative) value = -value;
    if (stop != end) return RealWord::notANumber;
    if (error == std::errc::result_out_of_range) {
        // Underflow below the subnormals (1e-400) reads as 0, as strtod reads it; overflow is no
        // number.
        value = std::strtod(std::string(word).c_str(), nullptr);
        return std::isfinite(value) ? RealWord::finite : RealWord::overflow;
    }
    if (error != std::errc()) return RealWord::notANumber;
    return std::isfinite(value) ? RealWord::finite : RealWord::nonFinite;
}

// "'WORD' for WHAT" (appended: GCC 12 warns falsely on "'" + std::string(word)).
std::string wordFor(std::string_view word, std::string_view what) {
    std::string text = "'";
    text.append(word).append("' for ").append(what);
    return text;
}

std::string outOfRange(std::string_view word, std::string_view what, const std::string& range) {
    std::string text(what);
    text.append(" ").append(word).append(" is out of range (").append(range).append(")");
    return text;
}

}  // namespace

bool toFiniteReal(std::string_view word, double& value) { return classifyReal(word, value) == RealWord::finite; }

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

std::string readReal(std::string_view word, std::string_view what, double& value) {
    switch (classifyReal(word, value)) {
        case RealWord::finite:
            return {};
        case RealWord::nonFinite:
            return wordFor(word, what) + " is not a finite number";
        case RealWord::overflow:
            return "bad number " + wordFor(word, what) + " (too large)";
        case RealWord::notANumber:
            break;
    }
    return "bad number " + wordFor(word, what);
}

std::string readInteger(std::string_view word, std::string_view what, std::int64_t& value, std::int64_t min,
                        std::int64_t max) {
    const bool read = toInteger(word, value);
    if (!read && !wholeDecimal(word)) {
        double x = 0;
        if (toFiniteReal(word, x)) return wordFor(word, what) + " is not an integer";
        return "bad integer " + wordFor(word, what);
    }
    if (!read || value < min || value > max)  // (not read: digits beyond 64 bits)
        return outOfRange(word, what, std::to_string(min) + " to " + std::to_string(max));
    return {};
}

std::string readCount(std::string_view word, std::string_view what, std::uint64_t& value, std::uint64_t max) {
    const bool read = toCount(word, value);
    if (!read && wholeDecimal(word) && word.front() == '-') {
        std::string text(what);
        return text.append(" must not be negative, found ").append(word);
    }
    if (!read && !wholeDecimal(word)) {
        double x = 0;
        if (toFiniteReal(word, x) && x >= 0) return wordFor(word, what) + " is not a whole number";
        return "bad count " + wordFor(word, what);
    }
    if (!read || value > max)  // (not read: digits beyond 64 bits)
        return outOfRange(word, what, "at most " + std::to_string(max));
    return {};
}

}  // namespace talus::formats
