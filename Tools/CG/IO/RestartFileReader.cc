#include "IO/RestartFileReader.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <utility>

#include "Formats/RestartFormat.h"
#include "IO/InputError.h"
#include "IO/TextFile.h"

namespace talus::cg {

namespace restart = formats::restart;  // the keys and the fields read by position

namespace {

// A 0 or 1 flag.
bool parseFlag(std::string_view token, const TextFile& file, const std::string& what) {
    const long value = parseCount(token, file, what);
    if (value > 1) file.fail(what + " must be 0 or 1, found " + std::string(token));
    return value == 1;
}

// How many entries to reserve for `count` particle lines of at least 46 bytes (23 fields): no
// more than the file can hold, so that a corrupt count does not reserve gigabytes.
std::size_t reservable(long count, const TextFile& file) {
    return static_cast<std::size_t>(
        std::min<std::uintmax_t>(static_cast<std::uintmax_t>(count), file.size() / (2 * restart::sphereFields)));
}

// Talus restart formats 4 to 7 (restart.md; the fields by the names of Formats/RestartFormat.h):
// `domain lo(3) hi(3) px py pz`, `species S` + S lines `name density law...`, `walls W` + W
// lines, `shapes S Q`, `particles N nextId` + N lines of 23 fields (spheres only).
RestartInfo readTalusRestart(TextFile& file) {
    RestartInfo info;
    info.writer = "Talus";
    std::string line;
    std::vector<std::string_view> fields;
    bool sawDomain = false, sawSpecies = false, sawParticles = false;
    while (file.nextLine(line)) {
        splitFields(line, fields);
        if (fields.empty()) continue;
        if (fields[0] == restart::key::time && fields.size() > 1 + restart::time) {
            info.time = parseReal(fields[1 + restart::time], file, "the time");
        } else if (fields[0] == restart::key::domain) {
            if (fields.size() != 1 + restart::domainFields)
                file.fail("expected 'domain' with " + std::to_string(restart::domainFields) + " values, found " +
                          std::to_string(fields.size() - 1));
            for (int k = 0; k < 3; ++k)
                info.periodic[k] = parseFlag(fields[1 + restart::periodic + k], file, "a periodic flag");
            sawDomain = true;
        } else if (fields[0] == restart::key::species) {
            if (fields.size() != 2) file.fail("expected 'species COUNT'");
            const long count = parseCount(fields[1], file, "the species count");
            for (long s = 0; s < count; ++s) {
                if (!file.nextLine(line)) file.failAtLine(file.lineNumber() + 1, "file ends inside the species list (truncated file?)");
                splitFields(line, fields);
                if (fields.size() < restart::speciesFieldsAtLeast)
                    file.fail("expected 'name density law ...' for species " + std::to_string(s));
                const double density = parseReal(fields[restart::density], file, "the density of species " + std::to_string(s));
                if (!(density > 0)) file.fail("density of species " + std::to_string(s) + " must be positive");
                info.speciesDensity.push_back(density);
            }
            sawSpecies = true;
        } else if (fields[0] == restart::key::walls && fields.size() == 2) {
            // restart.md: per wall normal (3; a cylinder's axis direction), point (3; a point of
            // its axis), species, motion index, radius (0: a plane).
            const long count = parseCount(fields[1], file, "the wall count");
            for (long w = 0; w < count; ++w) {
                if (!file.nextLine(line)) file.failAtLine(file.lineNumber() + 1, "file ends inside the wall list (truncated file?)");
                splitFields(line, fields);
                if (fields.size() != restart::wallFields)
                    file.fail("expected " + std::to_string(restart::wallFields) + " fields for a wall, found " +
                              std::to_string(fields.size()));
                CylinderWall wall;
                for (int k = 0; k < 3; ++k) {
                    wall.axisDirection[k] = parseReal(fields[restart::wallNormal + k], file, "the wall normal");
                    wall.axisPoint[k] = parseReal(fields[restart::wallPoint + k], file, "the wall point");
                }
                wall.radius = parseReal(fields[restart::wallRadius], file, "the wall radius");
                if (wall.radius < 0) file.fail("the wall radius must be 0 (a plane) or positive (a cylinder)");
                if (wall.radius > 0 && wall.axisDirection == std::array<double, 3>{0, 0, 0})
                    file.fail("a cylinder wall needs an axis direction (its normal), found 0 0 0");
                if (wall.radius > 0) info.cylinders.push_back(wall);
            }
        } else if (fields[0] == restart::key::shapes) {
            // Restart format 5: `shapes S Q`, S = 1 when the scene has superquadric particles. The
            // fields here treat every particle as a sphere of its .data radius (mass, volume, the
            // branch vectors of the contact stress), which for a superquadric is its bounding
            // radius: refused rather than silently wrong.
            if (fields.size() != 1 + restart::shapesFields) file.fail("expected 'shapes FLAG COUNT'");
            if (parseFlag(fields[1 + restart::shapesFlag], file, "the shapes flag"))
                file.fail("the run has superquadric particles (Documentation/Superquadrics/Superquadrics.md); "
                          "talus-cg coarse-grains spheres only so far");
        } else if (fields[0] == restart::key::particles) {
            if (fields.size() != 1 + restart::particlesFields) file.fail("expected 'particles COUNT NEXTID'");
            const long count = parseCount(fields[1 + restart::particleCount], file, "the particle count");
            std::vector<std::pair<long, bool>> idFixed;
            idFixed.reserve(reservable(count, file));
            for (long p = 0; p < count; ++p) {
                if (!file.nextLine(line)) file.failAtLine(file.lineNumber() + 1, "file ends inside the particle list (truncated file?)");
                splitFields(line, fields);
                if (fields.size() != restart::sphereFields)
                    file.fail("expected " + std::to_string(restart::sphereFields) + " fields for a particle, found " +
                              std::to_string(fields.size()));
                idFixed.emplace_back(parseCount(fields[restart::id], file, "the particle id"),
                                     parseFlag(fields[restart::fixed], file, "the fixed flag"));
            }
            // .data lines are in ascending id (data.md).
            std::sort(idFixed.begin(), idFixed.end());
            for (const auto& [id, fixed] : idFixed) info.fixed.push_back(fixed);
            sawParticles = true;
        }
    }
    if (!sawDomain || !sawSpecies || !sawParticles) {
        throw InputError(file.path() + ": not a complete Talus restart file (missing " +
                         std::string(!sawDomain ? "'domain'" : !sawSpecies ? "'species'" : "'particles'") +
                         " section)");
    }
    return info;
}

// The value after `key` on a MercuryDPM line of `key value` pairs.
bool valueAfter(const std::vector<std::string_view>& fields, std::string_view key, std::string_view& value) {
    for (std::size_t k = 0; k + 1 < fields.size(); ++k) {
        if (fields[k] == key) {
            value = fields[k + 1];
            return true;
        }
    }
    return false;
}

// MercuryDPM restart: `Species S` then species lines with `id K density D` (mixed species have
// idA/idB and no density), `PeriodicBoundary ... normal nx ny nz`, `Particles N` then lines
// `BaseParticle id K ... invMass X` (X = 0 for fixed particles).
RestartInfo readMercuryRestart(TextFile& file) {
    RestartInfo info;
    info.writer = "MercuryDPM";
    std::string line;
    std::vector<std::string_view> fields;
    std::string_view value;
    bool sawParticles = false;
    while (file.nextLine(line)) {
        splitFields(line, fields);
        if (fields.empty()) continue;
        if (fields[0] == "timeStep" && valueAfter(fields, "time", value)) {
            info.time = parseReal(value, file, "the time");
        } else if (fields[0].ends_with("Species") && !fields[0].ends_with("MixedSpecies") &&
                   valueAfter(fields, "density", value)) {
            std::string_view id;
            if (!valueAfter(fields, "id", id)) file.fail("species line without 'id'");
            const long s = parseInteger(id, file, "the species id");
            if (s < 0 || s > 100000) file.fail("species id " + std::to_string(s) + " out of range");
            if (static_cast<long>(info.speciesDensity.size()) <= s) info.speciesDensity.resize(s + 1, 0.0);
            info.speciesDensity[s] = parseReal(value, file, "the density of species " + std::to_string(s));
        } else if (fields[0] == "PeriodicBoundary") {
            if (!valueAfter(fields, "normal", value)) file.fail("PeriodicBoundary without 'normal'");
            const auto at = std::find(fields.begin(), fields.end(), std::string_view("normal")) - fields.begin();
            if (at + 3 >= static_cast<long>(fields.size())) file.fail("PeriodicBoundary normal needs 3 values");
            int axis = -1;
            for (int k = 0; k < 3; ++k) {
                const double n = parseReal(fields[at + 1 + k], file, "the periodic normal");
                if (std::abs(n) > 1e-12) axis = (axis == -1) ? k : 3;
            }
            if (axis < 0 || axis > 2) file.fail("periodic boundary normal is not along x, y or z");
            info.periodic[axis] = true;
        } else if (fields[0] == "Particles" && fields.size() == 2) {
            const long count = parseCount(fields[1], file, "the particle count");
            for (long p = 0; p < count; ++p) {
                if (!file.nextLine(line)) file.failAtLine(file.lineNumber() + 1, "file ends inside the particle list (truncated file?)");
                splitFields(line, fields);
                if (!valueAfter(fields, "invMass", value)) file.fail("particle line without 'invMass'");
                info.fixed.push_back(parseReal(value, file, "the inverse mass") == 0.0);
            }
            sawParticles = true;
        }
    }
    if (info.speciesDensity.empty() || !sawParticles) {
        throw InputError(file.path() + ": not a complete MercuryDPM restart file (no species densities or no particles)");
    }
    for (std::size_t s = 0; s < info.speciesDensity.size(); ++s) {
        if (!(info.speciesDensity[s] > 0)) throw InputError(file.path() + ": species " + std::to_string(s) + " has no positive density");
    }
    return info;
}

}  // namespace

RestartInfo readRestartFile(const std::string& path) {
    TextFile file(path);
    std::string first;
    if (!file.nextLine(first)) throw InputError(path + ": empty restart file");
    std::vector<std::string_view> words;
    splitFields(first, words);
    if (words.size() >= 2 && words[0] == restart::magicWords[0] && words[1] == restart::magicWords[1])
        return readTalusRestart(file);
    if (first.starts_with("MercuryDPM")) return readMercuryRestart(file);
    file.fail("not a restart file of Talus ('Talus restart ...') or MercuryDPM ('MercuryDPM ...')");
}

}  // namespace talus::cg
