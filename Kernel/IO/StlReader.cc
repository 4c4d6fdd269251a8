#include "IO/StlReader.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "Error.h"
#include "IO/DurableFile.h"
#include "IO/InputNumbers.h"

namespace talus {

namespace {

constexpr std::size_t binaryHeaderBytes = 84;  // 80 bytes of header, a 32-bit triangle count
constexpr std::size_t binaryTriangleBytes = 50;

std::string wholeFile(const std::string& path, const std::string& what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open " + what + " " + path);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad()) throw Error(what + " " + path + ": read error");
    return bytes.str();
}

void checkScale(double scale, const std::string& path) {
    require(std::isfinite(scale) && scale > 0, "the scale of " + path + " must be positive, got " + str(scale));
}

std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> result;
    std::size_t at = 0;
    while (true) {
        at = line.find_first_not_of(" \t\r\v\f", at);
        if (at == std::string_view::npos) return result;
        const std::size_t end = std::min(line.find_first_of(" \t\r\v\f", at), line.size());
        result.push_back(line.substr(at, end - at));
        at = end;
    }
}

std::string lowercase(std::string_view word) {
    std::string s(word);
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Calls each(line) for every line of `text` (without its end), counting them in place.line.
template <class Each>
void forEachLine(const std::string& text, InputPlace& place, Each each) {
    place.line = 0;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        ++place.line;
        each(std::string_view(text).substr(at, end - at));
        at = end + 1;
    }
}

std::uint32_t uint32At(const std::string& bytes, std::size_t at) {
    std::uint32_t u = 0;
    for (int k = 3; k >= 0; --k) u = u << 8 | static_cast<unsigned char>(bytes[at + k]);  // little-endian
    return u;
}

bool startsWithSolid(const std::string& bytes) {
    const std::size_t at = bytes.find_first_not_of(" \t\r\n");
    if (at == std::string::npos || lowercase(std::string_view(bytes).substr(at, 5)) != "solid") return false;
    return at + 5 == bytes.size() || std::isspace(static_cast<unsigned char>(bytes[at + 5]));
}

bool looksBinary(const std::string& bytes) {
    if (bytes.size() >= binaryHeaderBytes &&
        bytes.size() == binaryHeaderBytes + binaryTriangleBytes * std::uint64_t(uint32At(bytes, 80)))
        return true;
    return bytes.find('\0') != std::string::npos || !startsWithSolid(bytes);
}

TriangleMesh readBinaryStl(const std::string& path, const std::string& bytes, double scale) {
    MeshSource source{"binary STL file " + path, "triangle", {}};
    if (bytes.size() < binaryHeaderBytes)
        throw Error(source.name + ": " + std::to_string(bytes.size()) +
                    " bytes, shorter than the 84 bytes of header and triangle count (and no ASCII STL file, which "
                    "starts with 'solid')");
    const std::uint64_t count = uint32At(bytes, 80);
    const std::uint64_t expected = binaryHeaderBytes + binaryTriangleBytes * count;
    const std::string sizes = std::to_string(bytes.size()) + " bytes, but its count of " + std::to_string(count) +
                              " triangles takes " + std::to_string(expected);
    if (bytes.size() < expected)
        throw Error(source.name + " " +
                    source.place((bytes.size() - binaryHeaderBytes) / binaryTriangleBytes) +
                    ": the file ends inside this triangle (" + sizes + ")");
    if (bytes.size() > expected)
        throw Error(source.name + ": " + sizes + " (a wrong count, or no STL file)");
    std::vector<TriangleCorners> triangles(count);
    for (std::size_t t = 0; t < count; ++t) {
        // Past the 12 bytes of the normal: three corners of three 32-bit floats.
        const std::size_t at = binaryHeaderBytes + binaryTriangleBytes * t + 12;
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a)
                triangles[t][k][a] = double(std::bit_cast<float>(uint32At(bytes, at + 12 * k + 4 * a))) * scale;
    }
    return TriangleMesh(triangles, std::move(source));
}

TriangleMesh readAsciiStl(const std::string& path, const std::string& text, double scale) {
    MeshSource source{"ASCII STL file " + path, "line", {}};
    InputPlace place(source.name);
    std::vector<TriangleCorners> triangles;
    enum class Expect { solid, facet, outerLoop, vertex, endfacet } expect = Expect::solid;
    TriangleCorners corners;
    int vertices = 0;
    long facetLine = 0;
    forEachLine(text, place, [&](std::string_view line) {
        const std::vector<std::string_view> w = words(line);
        if (w.empty()) return;
        const std::string keyword = lowercase(w[0]);
        auto expectForm = [&](bool matches, const std::string& expected) {
            if (matches) return;
            std::string found;
            for (const std::string_view word : w) found.append(found.empty() ? "" : " ").append(word);
            place.fail("expected " + expected + ", found '" + found + "'");
        };
        switch (expect) {
            case Expect::solid:
                expectForm(keyword == "solid", "'solid'");
                expect = Expect::facet;
                break;
            case Expect::facet:
                if (keyword == "endsolid") {
                    expect = Expect::solid;
                    break;
                }
                expectForm(keyword == "facet" && w.size() == 5 && lowercase(w[1]) == "normal",
                        "'facet normal nx ny nz' or 'endsolid'");
                for (int a = 0; a < 3; ++a) place.real(w[2 + a], "the facet normal");
                facetLine = place.line;
                expect = Expect::outerLoop;
                break;
            case Expect::outerLoop:
                expectForm(keyword == "outer" && w.size() == 2 && lowercase(w[1]) == "loop", "'outer loop'");
                vertices = 0;
                expect = Expect::vertex;
                break;
            case Expect::vertex:
                if (keyword == "endloop") {
                    if (vertices != 3)
                        place.fail("the facet has " + std::to_string(vertices) +
                                   " vertices; STL facets are triangles (3 vertices)");
                    expect = Expect::endfacet;
                    break;
                }
                expectForm(keyword == "vertex", "'vertex x y z' or 'endloop'");
                if (vertices == 3) place.fail("a fourth vertex: STL facets are triangles (3 vertices)");
                expectForm(w.size() == 4, "'vertex x y z'");
                for (int a = 0; a < 3; ++a)
                    corners[vertices][a] = place.real(w[1 + a], std::string("the ") + "xyz"[a] + " of a vertex") * scale;
                ++vertices;
                break;
            case Expect::endfacet:
                expectForm(keyword == "endfacet", "'endfacet'");
                triangles.push_back(corners);
                source.places.push_back(facetLine);
                expect = Expect::facet;
                break;
        }
    });
    if (expect == Expect::facet) place.fail("the file ends without 'endsolid'");
    if (expect != Expect::solid) {
        place.line = facetLine;
        place.fail("the file ends inside the facet that starts on this line");
    }
    return TriangleMesh(triangles, std::move(source));
}

void putUint32(std::ostream& out, std::uint32_t u) {
    for (int k = 0; k < 4; ++k) out.put(static_cast<char>(u >> 8 * k & 0xff));  // little-endian
}

void putFloats(std::ostream& out, const Vec3& x) {
    for (int a = 0; a < 3; ++a) putUint32(out, std::bit_cast<std::uint32_t>(static_cast<float>(x[a])));
}

void writeBinaryStl(std::ostream& out, const TriangleMesh& mesh, const std::string& solidName) {
    // (A binary header must not start with "solid", which readers take for ASCII.)
    std::string header = "binary STL written by Talus: " + solidName;
    header.resize(80, ' ');
    out.write(header.data(), 80);
    putUint32(out, static_cast<std::uint32_t>(mesh.triangleCount()));
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        putFloats(out, mesh.normal(t));
        for (int k = 0; k < 3; ++k) putFloats(out, mesh.corner(t, k));
        out.put(0).put(0);  // the attribute
    }
}

void writeAsciiStl(std::ostream& out, const TriangleMesh& mesh, const std::string& solidName) {
    out.precision(17);  // every double to the bit
    auto put = [&](const Vec3& x) { out << x.x() << ' ' << x.y() << ' ' << x.z() << '\n'; };
    out << "solid " << solidName << '\n';
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        out << "  facet normal ";
        put(mesh.normal(t));
        out << "    outer loop\n";
        for (int k = 0; k < 3; ++k) {
            out << "      vertex ";
            put(mesh.corner(t, k));
        }
        out << "    endloop\n  endfacet\n";
    }
    out << "endsolid " << solidName << '\n';
}

}  // namespace

TriangleMesh readStl(const std::string& path, double scale) {
    checkScale(scale, path);
    const std::string bytes = wholeFile(path, "STL file");
    if (bytes.empty()) throw Error("STL file " + path + " is empty");
    return looksBinary(bytes) ? readBinaryStl(path, bytes, scale) : readAsciiStl(path, bytes, scale);
}

TriangleMesh readTriangleTable(const std::string& path, double scale) {
    checkScale(scale, path);
    const std::string text = wholeFile(path, "triangle table");
    MeshSource source{"triangle table " + path, "line", {}};
    if (text.empty()) throw Error(source.name + " is empty");
    InputPlace place(source.name);
    std::vector<TriangleCorners> triangles;
    forEachLine(text, place, [&](std::string_view line) {
        const std::vector<std::string_view> w = words(line);
        double first = 0;
        if (w.empty() || (place.line == 1 && !toFiniteReal(w[0], first))) return;  // (the header)
        if (w.size() != 9)
            place.fail("a triangle is 9 numbers (x y z of each of its three corners), found " +
                       std::to_string(w.size()) + " words");
        TriangleCorners corners;
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a)
                corners[k][a] =
                    place.real(w[3 * k + a], std::string("the ") + "xyz"[a] + " of corner " + std::to_string(k + 1)) *
                    scale;
        triangles.push_back(corners);
        source.places.push_back(place.line);
    });
    return TriangleMesh(triangles, std::move(source));
}

void writeStl(const std::string& path, const TriangleMesh& mesh, StlEncoding encoding, const std::string& solidName) {
    requireWord(solidName, "the solid name of an STL file");
    replaceFile(path, [&](std::ostream& out) {
        if (encoding == StlEncoding::binary)
            writeBinaryStl(out, mesh, solidName);
        else
            writeAsciiStl(out, mesh, solidName);
    });
}

}  // namespace talus
