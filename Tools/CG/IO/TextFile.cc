#include "IO/TextFile.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "IO/InputError.h"

namespace talus::cg {

std::string str(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", value);
    return buffer;
}

TextFile::TextFile(std::string path) : path_(std::move(path)), stream_(path_) {
    std::error_code error;
    if (!stream_ || std::filesystem::is_directory(path_, error)) {
        throw InputError("cannot open " + path_);
    }
    size_ = std::filesystem::file_size(path_, error);
    if (error) size_ = 0;
}

bool TextFile::nextLine(std::string& line) {
    if (pushedBack_) {
        pushedBack_ = false;
        line = last_;
        ++lineNumber_;
        return true;
    }
    if (!std::getline(stream_, line)) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    last_ = line;
    ++lineNumber_;
    return true;
}

void TextFile::pushBack() {
    pushedBack_ = true;
    --lineNumber_;
}

std::uintmax_t TextFile::bytesRead() {
    const auto position = stream_.tellg();
    return position < 0 ? size_ : static_cast<std::uintmax_t>(position);
}

void TextFile::fail(const std::string& problem) const { failAtLine(lineNumber_, problem); }

void TextFile::failAtLine(long line, const std::string& problem) const {
    throw InputError(path_ + " line " + std::to_string(line) + ": " + problem);
}

void splitFields(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
        if (j > i) fields.push_back(line.substr(i, j - i));
        i = j;
    }
}

namespace {

// Drops one leading '+', which from_chars does not take; "+-1" stays no number.
bool dropPlus(std::string_view& token) {
    if (!token.empty() && token.front() == '+') {
        token.remove_prefix(1);
        return !token.empty() && token.front() != '-';
    }
    return !token.empty();
}

// A token that is a whole number but not a finite one: nan, inf, or beyond the largest double.
bool nonFiniteNumber(std::string_view token) {
    double value = 0;
    if (!dropPlus(token)) return false;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    return end == token.data() + token.size() && (error == std::errc::result_out_of_range || !std::isfinite(value));
}

// "'TOKEN' for WHAT", for messages (appended: GCC 12 warns falsely on "'" + std::string(token)).
std::string tokenFor(std::string_view token, const std::string& what) {
    std::string text = "'";
    text.append(token).append("' for ").append(what);
    return text;
}

}  // namespace

bool toReal(std::string_view token, double& value) {
    if (!dropPlus(token)) return false;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (end != token.data() + token.size()) return false;
    if (error == std::errc::result_out_of_range) {
        // Below the subnormals (1e-400) the number reads as 0, as the stream would read it; beyond
        // the largest double it is no number.
        value = std::strtod(std::string(token).c_str(), nullptr);
        return std::isfinite(value);
    }
    return error == std::errc() && std::isfinite(value);
}

bool toInteger(std::string_view token, long& value) {
    if (!dropPlus(token)) return false;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    return error == std::errc() && end == token.data() + token.size();
}

double parseReal(std::string_view token, const TextFile& file, const std::string& what) {
    double value = 0;
    if (!toReal(token, value)) {
        if (nonFiniteNumber(token)) file.fail(tokenFor(token, what) + " is not a finite number");
        file.fail("bad number " + tokenFor(token, what));
    }
    return value;
}

long parseInteger(std::string_view token, const TextFile& file, const std::string& what) {
    long value = 0;
    if (!toInteger(token, value)) {
        double real = 0;
        if (toReal(token, real)) file.fail(tokenFor(token, what) + " is not an integer");
        file.fail("bad integer " + tokenFor(token, what));
    }
    return value;
}

long parseCount(std::string_view token, const TextFile& file, const std::string& what) {
    const long value = parseInteger(token, file, what);
    if (value < 0) file.fail(what + " must not be negative, found " + std::string(token));
    return value;
}

}  // namespace talus::cg
