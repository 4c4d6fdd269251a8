#include "IO/TextFile.h"

#include <cstdio>
#include <filesystem>
#include <limits>

#include "Formats/Numbers.h"
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

// The conversions and the wording of their problems: Formats/Numbers.h, shared with the kernel.
bool toReal(std::string_view token, double& value) { return formats::toFiniteReal(token, value); }

bool toInteger(std::string_view token, long& value) {
    std::int64_t n = 0;
    if (!formats::toInteger(token, n)) return false;
    value = static_cast<long>(n);
    return true;
}

double parseReal(std::string_view token, const TextFile& file, std::string_view what) {
    double value = 0;
    if (const std::string problem = formats::readReal(token, what, value); !problem.empty()) file.fail(problem);
    return value;
}

long parseInteger(std::string_view token, const TextFile& file, std::string_view what) {
    std::int64_t value = 0;
    const std::string problem = formats::readInteger(token, what, value, std::numeric_limits<long>::min(),
                                                     std::numeric_limits<long>::max());
    if (!problem.empty()) file.fail(problem);
    return static_cast<long>(value);
}

long parseCount(std::string_view token, const TextFile& file, std::string_view what) {
    std::uint64_t value = 0;
    const std::string problem =
        formats::readCount(token, what, value, static_cast<std::uint64_t>(std::numeric_limits<long>::max()));
    if (!problem.empty()) file.fail(problem);
    return static_cast<long>(value);
}

}  // namespace talus::cg
