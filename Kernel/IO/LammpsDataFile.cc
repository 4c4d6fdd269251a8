#include "IO/LammpsDataFile.h"

#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <unordered_map>

#include "Error.h"
#include "IO/InputNumbers.h"

namespace talus {

namespace {

// The words of a line before its comment (LAMMPS comments start with #), and the comment's first
// word (an Atoms section header names its atom style there: "Atoms # sphere").
std::vector<std::string> words(const std::string& line, std::string* commentWord = nullptr) {
    const std::size_t hash = line.find('#');
    std::istringstream in(line.substr(0, hash));
    std::vector<std::string> result;
    for (std::string w; in >> w;) result.push_back(w);
    if (commentWord) {
        commentWord->clear();
        if (hash != std::string::npos) std::istringstream(line.substr(hash + 1)) >> *commentWord;
    }
    return result;
}

std::string joined(const std::vector<std::string>& w) {
    std::string s;
    for (const std::string& x : w) s += (s.empty() ? "" : " ") + x;
    return s;
}

}  // namespace

LammpsData readLammpsData(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot open LAMMPS data file " + path);
    InputPlace place("LAMMPS data file " + path);
    LammpsData data;
    std::uint64_t declaredAtoms = 0;
    std::set<std::string> headerSeen;          // each header line once
    std::array<bool, 3> boxGiven{false, false, false};
    std::string section, line, style;
    std::set<std::string> sectionsSeen;        // each section once
    long atomsLine = 0;
    std::unordered_map<std::uint64_t, std::size_t> indexOf;
    std::vector<bool> velocityGiven;

    std::getline(in, line);  // the first line is a title
    place.line = 1;
    while (std::getline(in, line)) {
        ++place.line;
        const auto w = words(line, &style);
        if (w.empty()) continue;
        if (std::isalpha(static_cast<unsigned char>(w[0][0])) && !(section.empty() && w.size() > 1)) {
            // A section header (atom and velocity lines start with an id, header lines with a number).
            if (w.size() != 1 || (w[0] != "Atoms" && w[0] != "Velocities"))
                place.fail("unsupported section '" + joined(w) + "' (this reader takes Atoms and Velocities)");
            if (!sectionsSeen.insert(w[0]).second) place.fail("a second " + w[0] + " section");
            if (w[0] == "Atoms") {
                if (!style.empty() && style != "sphere")
                    place.fail("atom style '" + style + "': this reader takes atom style sphere only");
                if (data.types < 1) place.fail("the Atoms section comes before an 'atom types' header line");
                for (int axis = 0; axis < 3; ++axis)
                    if (!boxGiven[axis]) place.fail(std::string("no ") + "xyz"[axis] + "lo " + "xyz"[axis] + "hi line in the header");
                atomsLine = place.line;
            } else if (atomsLine == 0) {
                place.fail("the Velocities section comes before the Atoms section");
            }
            section = w[0];
            continue;
        }
        if (section.empty()) {  // header keywords
            // The words after the number(s): "atoms", "atom types", "xlo xhi", ...
            const bool boxLine = w.size() == 4 && (w[2] + w[3] == "xloxhi" || w[2] + w[3] == "yloyhi" || w[2] + w[3] == "zlozhi");
            const std::string key = joined(std::vector<std::string>(w.begin() + (boxLine ? 2 : 1), w.end()));
            if (!headerSeen.insert(key).second) place.fail("a second '" + key + "' header line");
            if (key == "atoms") {
                declaredAtoms = place.count(w[0], "the atom count");
            } else if (key == "atom types") {
                data.types = static_cast<int>(place.count(w[0], "the type count", 1u << 20));
            } else if (boxLine) {
                const int axis = w[2][0] - 'x';
                data.lo[axis] = place.real(w[0], "the box");
                data.hi[axis] = place.real(w[1], "the box");
                if (!(data.hi[axis] > data.lo[axis])) place.fail("empty box along " + std::string(1, "xyz"[axis]));
                boxGiven[axis] = true;
            } else if (w.size() >= 2 && (w[1] == "bonds" || w[1] == "angles")) {
                place.fail("molecular data files are not supported");
            } else {
                place.fail("unknown or unsupported header line '" + joined(w) + "'");
            }
            continue;
        }
        if (section == "Atoms") {
            // atom style sphere: id type diameter density x y z [ix iy iz]
            if (w.size() != 7 && w.size() != 10)
                place.fail("an atom line (style sphere) has 7 or 10 words: id type diameter density x y z [ix iy iz]");
            LammpsAtom a;
            a.id = place.count(w[0], "the atom id");
            if (a.id == 0) place.fail("atom id 0: LAMMPS atom ids start at 1");
            a.type = static_cast<int>(place.integer(w[1], "the atom type"));
            if (a.type < 1 || a.type > data.types) place.fail("atom type " + w[1] + " is not in 1.." + std::to_string(data.types));
            a.diameter = place.real(w[2], "the diameter");
            a.density = place.real(w[3], "the density");
            if (!(a.diameter > 0)) place.fail("the diameter must be positive");
            if (!(a.density > 0)) place.fail("the density must be positive");
            for (int k = 0; k < 3; ++k) a.position[k] = place.real(w[4 + k], "the position");
            if (w.size() == 10) {
                // Image flags: how many box lengths the atom has crossed a periodic side.
                for (int k = 0; k < 3; ++k)
                    a.position[k] += static_cast<double>(place.integer(w[7 + k], "the image flag", -(1 << 30), 1 << 30)) *
                                     (data.hi[k] - data.lo[k]);
                if (!a.position.allFinite()) place.fail("the image flags take the atom beyond the largest number");
            }
            if (!indexOf.emplace(a.id, data.atoms.size()).second) place.fail("atom id " + w[0] + " appears twice");
            data.atoms.push_back(a);
            velocityGiven.push_back(false);
        } else {  // Velocities: id vx vy vz wx wy wz
            if (w.size() != 7) place.fail("a velocity line has 7 words: id vx vy vz wx wy wz");
            const auto it = indexOf.find(place.count(w[0], "the atom id"));
            if (it == indexOf.end()) place.fail("velocity of unknown atom id " + w[0]);
            if (velocityGiven[it->second]) place.fail("a second velocity of atom id " + w[0]);
            velocityGiven[it->second] = true;
            LammpsAtom& a = data.atoms[it->second];
            for (int k = 0; k < 3; ++k) a.velocity[k] = place.real(w[1 + k], "the velocity");
            for (int k = 0; k < 3; ++k) a.angularVelocity[k] = place.real(w[4 + k], "the angular velocity");
        }
    }
    if (in.bad()) throw Error("LAMMPS data file " + path + ": read error");
    if (atomsLine == 0) throw Error("LAMMPS data file " + path + ": no Atoms section");
    if (data.atoms.size() != declaredAtoms) {
        place.line = atomsLine;
        place.fail("the header declares " + std::to_string(declaredAtoms) + " atoms, the Atoms section has " +
                   std::to_string(data.atoms.size()));
    }
    return data;
}

}  // namespace talus
