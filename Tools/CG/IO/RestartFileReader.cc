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

// `shapes FLAG Q` (restart format 5 on) and its Q lines `a b c e1 e2`: FLAG 1 when the scene has
// superquadric particles, the one kind of shape the format knows. Returns FLAG.
bool readShapes(TextFile& file, std::vector<std::string_view>& fields, RestartInfo& info) {
    if (fields.size() != 1 + restart::shapesFields) file.fail("expected 'shapes FLAG COUNT'");
    const long flag = parseCount(fields[1 + restart::shapesFlag], file, "the shapes flag");
    if (flag > 1)
        file.fail("shapes flag " + std::to_string(flag) + ": an unknown kind of shapes (0: spheres only, 1: superquadrics)");
    const long count = parseCount(fields[1 + restart::shapeCount], file, "the shape count");
    std::string line;
    for (long k = 0; k < count; ++k) {
        if (!file.nextLine(line)) file.failAtLine(file.lineNumber() + 1, "file ends inside the shape list (truncated file?)");
        splitFields(line, fields);
        if (fields.size() != restart::shapeFields)
            file.fail("expected a superquadric 'a b c e1 e2' (" + std::to_string(restart::shapeFields) + " numbers) for shape " +
                      std::to_string(k) + ", found " + std::to_string(fields.size()) + " fields: an unknown kind of shape");
        SuperquadricShape shape;
        for (int axis = 0; axis < 3; ++axis) {
            shape.semiAxes[axis] = parseReal(fields[restart::semiAxes + axis], file, "a semi-axis of shape " + std::to_string(k));
            if (!(shape.semiAxes[axis] > 0)) file.fail("the semi-axes of shape " + std::to_string(k) + " must be positive");
        }
        shape.e1 = parseReal(fields[restart::blockiness], file, "the blockiness e1 of shape " + std::to_string(k));
        shape.e2 = parseReal(fields[restart::blockiness + 1], file, "the blockiness e2 of shape " + std::to_string(k));
        // Theory/Superquadrics.md eq. (1): convex for 0 < e1, e2 <= 1, the shapes the kernel simulates.
        if (!(shape.e1 > 0 && shape.e1 <= 1 && shape.e2 > 0 && shape.e2 <= 1))
            file.fail("the blockiness e1 = " + str(shape.e1) + ", e2 = " + str(shape.e2) + " of shape " + std::to_string(k) +
                      " is outside (0, 1]: not a convex superquadric");
        info.shapes.push_back(shape);
    }
    return flag == 1;
}

// The orientation and shape index of a particle line of a scene with shapes; the mass the kernel
// gave a superquadric is its density times the shape's volume (Kernel/Scene/Scene.cc
// addSuperquadric), the same expression as SuperquadricShape::volume: a file whose masses
// disagree is not one the kernel wrote.
void readShapedParticle(const TextFile& file, const std::vector<std::string_view>& fields, const RestartInfo& info,
                        RestartParticle& particle) {
    const std::string which = "particle id " + std::to_string(particle.id);
    double norm2 = 0;
    for (int k = 0; k < 4; ++k) {
        particle.orientation[k] = parseReal(fields[restart::orientation + k], file, "the orientation of " + which);
        norm2 += particle.orientation[k] * particle.orientation[k];
    }
    // (Particles/RigidBodyRotation.h: the kernel's orientations are normalised to 1e-6.)
    if (!(std::abs(std::sqrt(norm2) - 1) <= 1e-6))
        file.fail("the orientation quaternion of " + which + " has length " + str(std::sqrt(norm2)) + ", not 1");
    const long shape = parseInteger(fields[restart::shape], file, "the shape index of " + which);
    if (shape < -1 || shape >= static_cast<long>(info.shapes.size()))
        file.fail(which + " has shape " + std::to_string(shape) + ", which is no shape of the file (it has " +
                  std::to_string(info.shapes.size()) + "; -1: a sphere)");
    particle.shape = static_cast<int>(shape);
    if (shape < 0) return;
    const double mass = info.speciesDensity[particle.species] * info.shapes[particle.shape].volume();
    if (!(std::abs(particle.mass - mass) <= 1e-12 * mass))
        file.fail("the mass " + str(particle.mass) + " of " + which + " is not its species' density times the volume of its shape " +
                  std::to_string(shape) + " (" + str(mass) + ")");
}

// `particles N nextId` and its N lines (23 fields, 34 in a scene with shapes: Formats/RestartFormat.h),
// kept in ascending id, the order of the .data lines (data.md).
void readParticles(TextFile& file, std::vector<std::string_view>& fields, bool shaped, RestartInfo& info) {
    if (fields.size() != 1 + restart::particlesFields) file.fail("expected 'particles COUNT NEXTID'");
    const long count = parseCount(fields[1 + restart::particleCount], file, "the particle count");
    const std::size_t expected = shaped ? restart::shapedFields : restart::sphereFields;
    std::vector<std::pair<RestartParticle, bool>> particles;  // (particle, fixed)
    particles.reserve(reservable(count, file));
    std::string line;
    for (long p = 0; p < count; ++p) {
        if (!file.nextLine(line)) file.failAtLine(file.lineNumber() + 1, "file ends inside the particle list (truncated file?)");
        splitFields(line, fields);
        if (fields.size() != expected)
            file.fail("expected " + std::to_string(expected) + " fields for a particle" + (shaped ? " of a scene with shapes" : "") +
                      ", found " + std::to_string(fields.size()));
        RestartParticle particle;
        particle.id = parseCount(fields[restart::id], file, "the particle id");
        const std::string which = "particle id " + std::to_string(particle.id);
        particle.radius = parseReal(fields[restart::radius], file, "the radius");
        particle.mass = parseReal(fields[restart::mass], file, "the mass");
        if (!(particle.radius > 0 && particle.mass > 0)) file.fail("the radius and mass of " + which + " must be positive");
        const long species = parseCount(fields[restart::particleSpecies], file, "the species");
        if (species >= static_cast<long>(info.speciesDensity.size()))
            file.fail(which + ": species " + std::to_string(species) + " is not in the species list (" +
                      std::to_string(info.speciesDensity.size()) + " species)");
        particle.species = static_cast<int>(species);
        if (shaped) readShapedParticle(file, fields, info, particle);
        particles.emplace_back(particle, parseFlag(fields[restart::fixed], file, "the fixed flag"));
    }
    std::sort(particles.begin(), particles.end(), [](const auto& a, const auto& b) { return a.first.id < b.first.id; });
    for (const auto& [particle, fixed] : particles) {
        info.particles.push_back(particle);
        info.fixed.push_back(fixed);
    }
}

// Talus restart formats 4 to 8 (restart.md; the fields by the names of Formats/RestartFormat.h):
// `domain lo(3) hi(3) px py pz`, `species S` + S lines `name density law...`, `walls W` + W
// lines, `shapes FLAG Q` + Q lines, `particles N nextId` + N lines.
RestartInfo readTalusRestart(TextFile& file) {
    RestartInfo info;
    info.writer = "Talus";
    std::string line;
    std::vector<std::string_view> fields;
    bool sawDomain = false, sawSpecies = false, sawParticles = false, shaped = false;
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
            // its axis), species, motion index, radius (0: a plane); from version 8 a revolved
            // segment's profile and joints, which coarse graining does not use.
            const long count = parseCount(fields[1], file, "the wall count");
            for (long w = 0; w < count; ++w) {
                if (!file.nextLine(line)) file.failAtLine(file.lineNumber() + 1, "file ends inside the wall list (truncated file?)");
                splitFields(line, fields);
                if (fields.size() != restart::wallFields && fields.size() != restart::wallFieldsBeforeVersion8)
                    file.fail("expected " + std::to_string(restart::wallFields) + " fields for a wall (" +
                              std::to_string(restart::wallFieldsBeforeVersion8) + " before version 8), found " +
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
            shaped = readShapes(file, fields, info);
        } else if (fields[0] == restart::key::particles) {
            readParticles(file, fields, shaped, info);
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

// A MercuryDPM particle line starts with its kind; those of a sphere's shape are read (mass from
// the .data radius). A SuperQuadricParticle (`axes a b c exp1 e1 exp2 e2`) would be coarse-grained
// as the sphere of its .data radius, a bounding radius: refused, as is a kind this reader does not
// know.
void requireSphericalKind(const TextFile& file, const std::vector<std::string_view>& fields) {
    static constexpr std::string_view spheres[] = {"BaseParticle", "SphericalParticle", "LiquidFilmParticle", "ThermalParticle"};
    const std::string_view kind = fields.empty() ? std::string_view() : fields[0];
    if (std::find(std::begin(spheres), std::end(spheres), kind) != std::end(spheres)) return;
    if (kind == "SuperQuadricParticle")
        file.fail("a MercuryDPM SuperQuadricParticle: talus-cg takes superquadric shapes from Talus restart files only "
                  "(as a sphere of its .data radius, its bounding radius, its mass and volume would be wrong)");
    file.fail("particle of an unknown kind '" + std::string(kind) + "' (BaseParticle, SphericalParticle, LiquidFilmParticle "
              "or ThermalParticle)");
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
                requireSphericalKind(file, fields);
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
    if (words.size() >= 2 && words[0] == restart::magicWords[0] && words[1] == restart::magicWords[1]) {
        // A later format may hold what this reader does not know (another kind of shape, say).
        if (words.size() != 3) file.fail("expected 'Talus restart VERSION'");
        const long version = parseCount(words[2], file, "the format version");
        if (version > restart::version)
            file.fail("format version " + std::to_string(version) + " is newer than this talus-cg reads (up to " +
                      std::to_string(restart::version) + ")");
        return readTalusRestart(file);
    }
    if (first.starts_with("MercuryDPM")) return readMercuryRestart(file);
    file.fail("not a restart file of Talus ('Talus restart ...') or MercuryDPM ('MercuryDPM ...')");
}

}  // namespace talus::cg
