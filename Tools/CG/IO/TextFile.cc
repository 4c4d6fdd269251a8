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

bool toReal(std::string_view token, double& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error == std::errc::result_out_of_range) {
        // Subnormal numbers (a 1e-320 overlap) are numbers: read them as the stream would.
        value = std::strtod(std::string(token).c_str(), nullptr);
        return end == token.data() + token.size();
    }
    return error == std::errc() && end == token.data() + token.size() && !token.empty();
}

bool toInteger(std::string_view token, long& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    return error == std::errc() && end == token.data() + token.size() && !token.empty();
}

double parseReal(std::string_view token, const TextFile& file, const std::string& what) {
    double value = 0;
    if (!toReal(token, value)) file.fail("bad number '" + std::string(token) + "' for " + what);
    return value;
}

long parseInteger(std::string_view token, const TextFile& file, const std::string& what) {
    long value = 0;
    if (!toInteger(token, value)) file.fail("bad integer '" + std::string(token) + "' for " + what);
    return value;
}

}  // namespace talus::cg
