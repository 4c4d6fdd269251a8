// The restart file's tokens (IO/RestartFile.cc): a writer of keys and numbers (doubles with 17
// significant digits, so that a restart continues to the bit) and a reader of whitespace-separated
// tokens that knows the line of each, for messages naming the file and line. Only the restart
// file's reader and writer include this.
#pragma once

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <istream>
#include <ostream>
#include <string>

#include "IO/InputNumbers.h"
#include "Math/Vector.h"

namespace talus::restartio {

class Writer {
public:
    explicit Writer(std::ostream& out) : out_(out) {}
    Writer& key(const char* k) { out_ << k; return *this; }
    Writer& operator<<(double x) {
        char b[40];
        std::snprintf(b, sizeof b, " %.17g", x);
        out_ << b;
        return *this;
    }
    Writer& operator<<(std::uint64_t x) { out_ << ' ' << x; return *this; }
    Writer& operator<<(std::int64_t x) { out_ << ' ' << x; return *this; }
    Writer& operator<<(const std::string& s) { out_ << ' ' << s; return *this; }
    Writer& operator<<(const Vec3& v) { return *this << v.x() << v.y() << v.z(); }
    void end() { out_ << '\n'; }

private:
    std::ostream& out_;
};

// Reads whitespace-separated tokens, remembering the line of each for error messages; numbers
// are read strictly (IO/InputNumbers.h).
class Reader {
public:
    Reader(std::istream& in, const std::string& path) : in_(in), place_("restart file " + path) {}

    [[noreturn]] void fail(const std::string& what) const { place_.fail(what); }
    std::string token(const char* what) {
        std::string t;
        for (;;) {
            int c = in_.get();
            if (c == EOF) {
                if (t.empty()) fail(std::string("file ends while reading ") + what + " (truncated file?)");
                return t;
            }
            if (c == '\n') {
                if (!t.empty()) { in_.unget(); return t; }
                ++place_.line;
                continue;
            }
            if (std::isspace(c)) {
                if (!t.empty()) return t;
                continue;
            }
            t.push_back(static_cast<char>(c));
        }
    }
    void expect(const char* keyword) {
        const std::string t = token(keyword);
        if (t != keyword) fail("expected '" + std::string(keyword) + "', found '" + t + "'");
    }
    double real(const char* what) { return place_.real(token(what), what); }
    Vec3 vec(const char* what) {
        Vec3 v;
        for (int a = 0; a < 3; ++a) v[a] = real(what);
        return v;
    }
    std::uint64_t count(const char* what, std::uint64_t max = ~std::uint64_t{0}) {
        return place_.count(token(what), what, max);
    }
    // An index into a list of `size` things (of none when size is 0).
    std::uint64_t index(const char* what, std::uint64_t size) {
        const std::string t = token(what);
        const std::uint64_t k = place_.count(t, what);
        if (k >= size)
            fail(std::string(what) + " " + t + " is out of range (" +
                 (size == 0 ? std::string("there are none") : "at most " + std::to_string(size - 1)) + ")");
        return k;
    }
    std::int64_t integer(const char* what) { return place_.integer(token(what), what); }
    bool flag(const char* what) { return count(what, 1) == 1; }
    bool atEnd() {
        int c;
        while ((c = in_.get()) != EOF) {
            if (c == '\n') ++place_.line;
            if (!std::isspace(c)) {
                in_.unget();
                return false;
            }
        }
        return true;
    }
    std::istream& stream() { return in_; }

private:
    std::istream& in_;
    InputPlace place_;
};

}  // namespace talus::restartio
