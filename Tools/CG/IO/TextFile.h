// Line-by-line reading of a text file with the line number kept, and strict number parsing:
// every reader of the CG tool reports problems as "FILE line L: PROBLEM".
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace talus::cg {

class TextFile {
public:
    // Throws InputError "cannot open PATH" when the file cannot be read.
    explicit TextFile(std::string path);

    // Reads the next line into `line` (without the newline, a trailing '\r' removed);
    // false at the end of the file.
    bool nextLine(std::string& line);
    // Makes the next nextLine() return the line just read again (one line of look-ahead).
    void pushBack();

    long lineNumber() const { return lineNumber_; }
    const std::string& path() const { return path_; }
    // Bytes read so far and the file size: for progress estimates.
    std::uintmax_t bytesRead();
    std::uintmax_t size() const { return size_; }

    // Throws InputError "PATH line L: PROBLEM" for the line read last.
    [[noreturn]] void fail(const std::string& problem) const;
    [[noreturn]] void failAtLine(long line, const std::string& problem) const;

private:
    std::string path_;
    std::ifstream stream_;
    std::string last_;
    bool pushedBack_ = false;
    long lineNumber_ = 0;
    std::uintmax_t size_ = 0;
};

// Splits a line at blanks (spaces, tabs) into `fields` (views into `line`).
void splitFields(std::string_view line, std::vector<std::string_view>& fields);

// Strict conversions (Formats/Numbers.h, the same as the kernel's; `what` a view, so that the
// readers name a column without building a string per number): the whole token must be a
// finite number (no nan, inf or overflow), an integer a whole one ("1.7" and "1e30" are not);
// otherwise file.fail names `what`.
double parseReal(std::string_view token, const TextFile& file, std::string_view what);
long parseInteger(std::string_view token, const TextFile& file, std::string_view what);
// An integer that counts something: not negative.
long parseCount(std::string_view token, const TextFile& file, std::string_view what);
// The same for program options and other strings: nullopt-like failure as a bool.
bool toReal(std::string_view token, double& value);
bool toInteger(std::string_view token, long& value);

}  // namespace talus::cg
