#include "IO/LammpsDataFile.h"

#include <fstream>
#include <sstream>
#include <unordered_map>

#include "Error.h"

namespace talus {

namespace {

// The words of a line without its comment (LAMMPS comments start with #).
std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line.substr(0, line.find('#')));
    std::vector<std::string> result;
    for (std::string w; in >> w;) result.push_back(w);
    return result;
}

}  // namespace

LammpsData readLammpsData(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot open LAMMPS data file " + path);
    LammpsData data;
    std::size_t declaredAtoms = 0;
    int lineNumber = 0;
    std::string line;
    auto fail = [&](const std::string& what) -> Error {
        return Error("LAMMPS data file " + path + " line " + std::to_string(lineNumber) + ": " + what);
    };
    auto number = [&](const std::string& word, const char* what) {
        std::size_t used = 0;
        double x = 0;
        try {
            x = std::stod(word, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != word.size() || !std::isfinite(x)) throw fail("bad number '" + word + "' for " + what);
        return x;
    };
    auto integer = [&](const std::string& word, const char* what) {
        const double x = number(word, what);
        if (x != std::floor(x) || x < 0) throw fail("'" + word + "' for " + what + " is not a non-negative integer");
        return static_cast<std::uint64_t>(x);
    };

    std::getline(in, line);  // the first line is a title
    ++lineNumber;
    std::string section;
    std::unordered_map<std::uint64_t, std::size_t> indexOf;
    bool sawAtoms = false;
    while (std::getline(in, line)) {
        ++lineNumber;
        const auto w = words(line);
        if (w.empty()) continue;
        if (w.size() == 1 && (w[0] == "Atoms" || w[0] == "Velocities")) {
            section = w[0];
            continue;
        }
        if (section.empty()) {  // header keywords
            if (w.size() == 2 && w[1] == "atoms") declaredAtoms = integer(w[0], "the atom count");
            else if (w.size() == 3 && w[1] == "atom" && w[2] == "types") data.types = static_cast<int>(integer(w[0], "the type count"));
            else if (w.size() == 4 && w[2].size() == 3 && w[3].size() == 3 && w[2][1] == 'l' && w[3][1] == 'h') {
                const int axis = w[2][0] - 'x';
                if (axis < 0 || axis > 2 || w[2].substr(1) != "lo" || w[3].substr(1) != "hi")
                    throw fail("unknown box line '" + line + "'");
                data.lo[axis] = number(w[0], "the box");
                data.hi[axis] = number(w[1], "the box");
                if (!(data.hi[axis] > data.lo[axis])) throw fail("empty box along " + std::string(1, "xyz"[axis]));
            } else if (w.size() == 2 && w[1] == "types") {
                throw fail("unsupported header line '" + line + "'");
            } else if (w.size() >= 2 && (w[1] == "bonds" || w[1] == "angles")) {
                throw fail("molecular data files are not supported");
            } else {
                throw fail("unknown header line '" + line + "'");
            }
            continue;
        }
        if (section == "Atoms") {
            sawAtoms = true;
            // atom style sphere: id type diameter density x y z [ix iy iz]
            if (w.size() != 7 && w.size() != 10)
                throw fail("an atom line (style sphere) has 7 or 10 words: id type diameter density x y z [ix iy iz]");
            LammpsAtom a;
            a.id = integer(w[0], "the atom id");
            a.type = static_cast<int>(integer(w[1], "the atom type"));
            if (a.type < 1 || a.type > data.types) throw fail("atom type " + w[1] + " is not in 1.." + std::to_string(data.types));
            a.diameter = number(w[2], "the diameter");
            a.density = number(w[3], "the density");
            if (!(a.diameter > 0)) throw fail("the diameter must be positive");
            if (!(a.density > 0)) throw fail("the density must be positive");
            for (int k = 0; k < 3; ++k) a.position[k] = number(w[4 + k], "the position");
            if (w.size() == 10)
                for (int k = 0; k < 3; ++k) a.position[k] += static_cast<double>(std::stol(w[7 + k])) * (data.hi[k] - data.lo[k]);
            if (!indexOf.emplace(a.id, data.atoms.size()).second) throw fail("atom id " + w[0] + " appears twice");
            data.atoms.push_back(a);
        } else {  // Velocities: id vx vy vz wx wy wz
            if (w.size() != 7) throw fail("a velocity line has 7 words: id vx vy vz wx wy wz");
            const auto it = indexOf.find(integer(w[0], "the atom id"));
            if (it == indexOf.end()) throw fail("velocity of unknown atom id " + w[0]);
            LammpsAtom& a = data.atoms[it->second];
            for (int k = 0; k < 3; ++k) a.velocity[k] = number(w[1 + k], "the velocity");
            for (int k = 0; k < 3; ++k) a.angularVelocity[k] = number(w[4 + k], "the angular velocity");
        }
    }
    if (!sawAtoms) throw Error("LAMMPS data file " + path + ": no Atoms section");
    if (data.atoms.size() != declaredAtoms)
        throw Error("LAMMPS data file " + path + ": the header declares " + std::to_string(declaredAtoms) +
                    " atoms, the Atoms section has " + std::to_string(data.atoms.size()));
    return data;
}

}  // namespace talus
