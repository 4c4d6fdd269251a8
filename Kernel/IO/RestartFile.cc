#include "IO/RestartFile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>
#include <unordered_set>

#include "Error.h"
#include "Formats/RestartFormat.h"
#include "IO/DurableFile.h"
#include "IO/InputNumbers.h"
#include "IO/RestartTokens.h"
#include "Particles/RigidBodyRotation.h"

namespace talus {

namespace {

// The keys, the version and the fields talus-cg reads by position: Formats/RestartFormat.h.
namespace key = formats::restart::key;
constexpr int formatVersion = formats::restart::version;
constexpr const char* shapeToleranceValue = "settings.shapeTolerance";
constexpr const char* item = formats::restart::itemIndent;

using restartio::Reader;
using restartio::Writer;

// A law is its name and its parameters in the order of Law::parameters (Species/ContactLaws.h);
// flags are written as 0 or 1.
void writeLaw(Writer& w, const ContactLaw& law) {
    std::visit(
        [&w]<class Law>(const Law& l) {
            w << std::string(Law::name);
            Law::parameters(l, [&w](const char*, const auto& value) {
                if constexpr (std::is_same_v<std::decay_t<decltype(value)>, bool>)
                    w << std::uint64_t(value);
                else
                    w << value;
            });
        },
        law);
}

ContactLaw readLaw(Reader& r) {
    const std::string kind = r.token("contact law");
    ContactLaw law;
    const bool known = ContactLawList::findFirst([&]<class Law>() {
        if (kind != Law::name) return false;
        Law l;
        Law::parameters(l, [&r](const char* label, auto& value) {
            if constexpr (std::is_same_v<std::decay_t<decltype(value)>, bool>)
                value = r.flag(label);
            else
                value = r.real(label);
        });
        law = l;
        return true;
    });
    if (!known) r.fail("unknown contact law '" + kind + "'");
    return law;
}

// (Scenes with shapes add the superquadric warm start to every history, scenes whose law has
// rolling resistance the rolling spring.)
struct HistoryExtras {
    bool shapes, rolling;
};

void writeHistory(Writer& w, const ContactHistory& h, HistoryExtras extras) {
    w << h.spring << h.lastNormalForce << std::uint64_t(h.state);
    if (extras.shapes) w << h.warmPoint << h.warmMultiplier;
    if (extras.rolling) w << h.rollingSpring;
    w.end();
}

ContactHistory readHistory(Reader& r, HistoryExtras extras) {
    ContactHistory h;
    h.spring = r.vec("tangential spring");
    h.lastNormalForce = r.real("last normal force");
    h.state = static_cast<ContactHistory::State>(r.count("contact state", ContactHistory::separated));
    if (extras.shapes) {
        h.warmPoint = r.vec("warm-start point");
        h.warmMultiplier = r.real("warm-start multiplier");
    }
    if (extras.rolling) h.rollingSpring = r.vec("rolling spring");
    return h;
}

// A motion's index, or -1 for none.
std::int32_t readMotionIndex(Reader& r, const char* what, std::uint64_t motionCount) {
    const auto m = r.integer(what);
    if (m < -1 || m >= static_cast<std::int64_t>(motionCount)) r.fail(std::string(what) + " out of range");
    return static_cast<std::int32_t>(m);
}

// The meshes section (version 9): each mesh rebuilt from its vertices and triangles (the
// constructor checks them as it checks an STL file's), its triangles' walls pointed to it.
void readMeshes(Reader& r, SimulationState& t, std::uint64_t speciesCount, std::uint64_t version) {
    r.expect(key::meshes);
    const auto meshCount = r.count("mesh count", 1u << 20);
    for (std::uint64_t k = 0; k < meshCount; ++k) {
        const auto species = static_cast<std::uint32_t>(r.index("mesh species", speciesCount));
        const auto firstWall = r.index("mesh first wall", t.walls.size());
        const auto vertexCount = r.count("mesh vertex count", 1u << 30);
        const auto triangleCount = r.count("mesh triangle count", t.walls.size() - firstWall);
        if (triangleCount == 0) r.fail("a mesh without triangles");
        // (Version 9's meshes rested, with the tolerance of their bounding box.)
        const std::int32_t motion = version >= 10 ? readMotionIndex(r, "mesh motion", t.motions.size()) : -1;
        const double tolerance = version >= 10 ? r.real("mesh tolerance") : 0;
        const double travelled = version >= 10 ? r.real("mesh travel since the list build") : 0;
        const double lastStep = version >= 10 ? r.real("mesh's last step") : 0;
        if (!(travelled >= 0 && lastStep >= 0 && std::isfinite(travelled + lastStep)))
            r.fail("a mesh's travel since the list build and last step must be finite and not negative");
        std::vector<Vec3> vertices(vertexCount);
        for (Vec3& v : vertices) v = r.vec("mesh vertex");
        std::vector<TriangleCorners> corners(triangleCount);
        for (TriangleCorners& c : corners)
            for (Vec3& corner : c) corner = vertices[r.index("mesh triangle vertex", vertexCount)];
        std::shared_ptr<MeshWalls> walls;
        MeshSource source;
        source.name = "mesh " + std::to_string(k);
        try {
            walls = std::make_shared<MeshWalls>(TriangleMesh(corners, source, tolerance), species,
                                                static_cast<std::uint32_t>(firstWall), motion);
        } catch (const Error& e) {
            r.fail(e.what());
        }
        for (std::uint32_t tri = 0; tri < triangleCount; ++tri) {
            Wall& w = t.walls[firstWall + tri];
            if (w.mesh != nullptr) r.fail("wall " + std::to_string(firstWall + tri) + " is in two meshes");
            if (w.motion != motion) r.fail("wall " + std::to_string(firstWall + tri) + " moves otherwise than its mesh");
            w.mesh = walls.get();
            w.triangle = tri;
        }
        walls->travelled = travelled;
        walls->lastStep = lastStep;
        t.meshes.push_back(std::move(walls));
    }
}

}  // namespace

void writeRestartFile(const std::string& path, const SimulationState& s) {
    replaceFile(path, [&s](std::ostream& out) {
        Writer w(out);
        const RunSettings& c = s.settings;
        w.key(formats::restart::magicWords[0]) << std::string(formats::restart::magicWords[1])
                                               << std::uint64_t(formatVersion); w.end();
        w.key(key::name) << c.name; w.end();
        w.key(key::run) << c.timeStep << c.endTime << c.outputInterval << c.skin << c.cellSizeRatio << c.progressInterval
                     << c.maxOverlapFraction << c.maxInitialOverlapFraction << std::uint64_t(c.reorderParticles); w.end();
        w.key(key::files) << std::uint64_t(c.writeData) << std::uint64_t(c.writeFstat) << std::uint64_t(c.writeEne)
                       << std::uint64_t(c.writeVtu) << std::uint64_t(c.writeRestart); w.end();
        w.key(key::summation) << std::uint64_t(c.idOrderedSums) << std::uint64_t(c.relist)
                           << std::uint64_t(c.stepper.waveSteps) << std::uint64_t(c.stepper.waveStripColumns); w.end();
        w.key(key::time) << s.time << s.step; w.end();
        w.key(key::gravity) << s.gravity; w.end();
        w.key(key::domain) << s.domain.lo << s.domain.hi << std::uint64_t(s.domain.periodic[0])
                        << std::uint64_t(s.domain.periodic[1]) << std::uint64_t(s.domain.periodic[2]); w.end();
        const OneWayPeriodicBox& box = s.domain.oneWay;
        w.key(key::oneWay) << std::uint64_t(box.active) << box.lo << box.hi << std::uint64_t(box.outflowSpecies.size());
        for (std::int32_t species : box.outflowSpecies) w << std::int64_t(species);
        w.end();
        w.key(key::species) << std::uint64_t(s.species.size()); w.end();
        for (std::size_t k = 0; k < s.species.size(); ++k) {
            w.key(item) << s.species[k].name << s.species[k].density;
            writeLaw(w, s.species[k].law);
            w.end();
        }
        w.key(key::pairs) << std::uint64_t(s.species.explicitPairs().size()); w.end();
        for (const auto& [key, law] : s.species.explicitPairs()) {
            w.key(item) << std::uint64_t(key.first) << std::uint64_t(key.second);
            writeLaw(w, law);
            w.end();
        }
        w.key(key::motions) << std::uint64_t(s.motions.size()); w.end();
        for (const PrescribedMotion& m : s.motions) { w.key(item) << m.velocity << m.angularVelocity << m.centre; w.end(); }
        w.key(key::walls) << std::uint64_t(s.walls.size()); w.end();
        for (const Wall& wall : s.walls) {
            w.key(item) << wall.normal << wall.point << std::uint64_t(wall.species) << std::int64_t(wall.motion)
                        << wall.radius;
            for (double v : wall.profile) w << v;
            w << wall.next[0] << wall.next[1] << std::uint64_t(wall.startJoined);
            w.end();
        }
        // The meshes whose triangles are walls: species, first wall, vertex and triangle counts,
        // motion, tolerance, distance travelled since the list's build and in the last step; then
        // the vertices and each triangle's vertex indices.
        w.key(key::meshes) << std::uint64_t(s.meshes.size()); w.end();
        for (const auto& m : s.meshes) {
            w.key(item) << std::uint64_t(m->species) << std::uint64_t(m->firstWall)
                        << std::uint64_t(m->mesh.vertexCount()) << std::uint64_t(m->mesh.triangleCount())
                        << std::int64_t(m->motion) << m->mesh.tolerance() << m->travelled << m->lastStep;
            w.end();
            for (std::size_t v = 0; v < m->mesh.vertexCount(); ++v) { w.key(item) << m->mesh.vertex(v); w.end(); }
            for (std::size_t t = 0; t < m->mesh.triangleCount(); ++t) {
                w.key(item);
                for (std::uint32_t v : m->mesh.triangle(t)) w << std::uint64_t(v);
                w.end();
            }
        }
        const ParticleStore& p = s.particles;
        const bool shapes = p.hasShapes();
        const HistoryExtras extras{shapes, s.species.keepsRollingSprings()};
        w.key(key::shapes) << std::uint64_t(shapes) << std::uint64_t(s.shapes.size()); w.end();
        for (const Superquadric& q : s.shapes) { w.key(item) << q.semiAxes() << q.e1() << q.e2(); w.end(); }
        w.key(key::particles) << std::uint64_t(p.size()) << s.nextId; w.end();
        for (std::size_t i = 0; i < p.size(); ++i) {
            w.key(item) << p.id[i] << p.position[i] << p.velocity[i] << p.angularVelocity[i] << p.force[i] << p.torque[i]
                        << p.radius[i] << p.mass[i] << p.invMass[i] << p.invInertia[i] << std::uint64_t(p.species[i])
                        << std::uint64_t(p.fixed[i]) << std::int64_t(p.motion[i]);
            if (shapes) {
                const Quat& q = p.orientation[i];
                w << q.w() << q.x() << q.y() << q.z() << p.angularMomentum[i] << p.principalInertia[i]
                  << std::int64_t(p.shape[i]);
            }
            w.end();
        }
        const PairList& l = s.pairList;
        w.key(key::pairList) << l.skin << l.reach << l.maxSpeed << std::uint64_t(l.valid) << l.builds << std::uint64_t(l.pairs.size())
                          << std::uint64_t(l.wallPairs.size()) << std::uint64_t(l.referencePosition.size())
                          << std::uint64_t(l.interiorPairs) << l.meshTravel; w.end();
        for (std::size_t k = 0; k < l.pairs.size(); ++k) {
            w.key(item) << std::uint64_t(l.pairs[k].i) << std::uint64_t(l.pairs[k].j);
            writeHistory(w, l.history.get(k), extras);
        }
        for (std::size_t k = 0; k < l.wallPairs.size(); ++k) {
            w.key(item) << std::uint64_t(l.wallPairs[k].particle) << std::uint64_t(l.wallPairs[k].wall);
            writeHistory(w, l.wallHistory.get(k), extras);
        }
        for (const Vec3& x : l.referencePosition) { w.key(item) << x; w.end(); }
        w.key(key::oneWayPairs) << std::uint64_t(l.oneWayPairs.size()); w.end();
        for (std::size_t k = 0; k < l.oneWayPairs.size(); ++k) {
            w.key(item) << std::uint64_t(l.oneWayPairs[k].i) << std::uint64_t(l.oneWayPairs[k].j);
            writeHistory(w, l.oneWayHistory.get(k), extras);
        }
        std::ostringstream random;
        random << s.random;
        w.key(key::random) << random.str(); w.end();
        w.key(key::output) << s.output.savedFrames << s.output.dataBytes << s.output.fstatBytes << s.output.eneBytes
                        << std::uint64_t(s.output.frameTimes.size()); w.end();
        for (double t : s.output.frameTimes) { w.key(item) << t; w.end(); }
        // (The Newton tolerance of superquadric contacts among the kept values, in scenes with
        // shapes: it changes their trajectories, so a restart keeps it, and the section takes a
        // new name without a new format version.)
        const bool keepsTolerance = s.particles.hasShapes();
        w.key(key::values) << std::uint64_t(s.keptValues.size() + keepsTolerance); w.end();
        if (keepsTolerance) { w.key(item) << std::string(shapeToleranceValue) << c.shapeTolerance; w.end(); }
        for (const auto& [name, value] : s.keptValues) { w.key(item) << name << value; w.end(); }
        w.key(key::end); w.end();
    });
}

void readRestartFile(const std::string& path, SimulationState& s) {
    std::ifstream in(path);
    if (!in) throw Error("cannot open restart file " + path);
    Reader r(in, path);
    for (const char* word : formats::restart::magicWords) r.expect(word);
    // (Version 7 differs only in its wall lines, which had no revolved segments; 8 has no meshes.)
    const auto version = r.count("format version");
    if (version < 7 || version > static_cast<std::uint64_t>(formatVersion))
        r.fail("format version " + std::to_string(version) + " is not supported (this build reads versions 7 to " +
               std::to_string(formatVersion) + ")");
    SimulationState t;  // filled completely before it replaces s
    RunSettings& c = t.settings;
    c = s.settings;  // (the settings a file does not hold stay as the driver made them)
    r.expect(key::name);
    c.name = r.token("name");
    r.expect(key::run);
    c.timeStep = r.real("time step");
    c.endTime = r.real("end time");
    c.outputInterval = r.real("output interval");
    c.skin = r.real("skin");
    c.cellSizeRatio = r.real("cell size ratio");
    c.progressInterval = r.real("progress interval");
    c.maxOverlapFraction = r.real("maximum overlap fraction");
    c.maxInitialOverlapFraction = r.real("maximum initial overlap fraction");
    c.reorderParticles = r.flag("reorder flag");
    r.expect(key::files);
    c.writeData = r.flag("data flag");
    c.writeFstat = r.flag("fstat flag");
    c.writeEne = r.flag("ene flag");
    c.writeVtu = r.flag("vtu flag");
    c.writeRestart = r.flag("restart flag");
    r.expect(key::summation);
    c.idOrderedSums = r.flag("id-ordered sums flag");
    c.relist = r.flag("relist flag");
    c.stepper.waveSteps = static_cast<int>(r.count("wave steps", 255));
    if (c.stepper.waveSteps < 1) r.fail("wave steps must be 1 to 255, got 0");
    c.stepper.waveStripColumns = static_cast<int>(r.count("wave strip columns", 1u << 30));
    r.expect(key::time);
    t.time = r.real("time");
    t.step = r.count("step");
    r.expect(key::gravity);
    t.gravity = r.vec("gravity");
    r.expect(key::domain);
    t.domain.lo = r.vec("domain lower corner");
    t.domain.hi = r.vec("domain upper corner");
    if (!((t.domain.hi - t.domain.lo).minCoeff() > 0))
        r.fail("domain: the upper corner must lie above the lower corner along x, y and z");
    for (int a = 0; a < 3; ++a) t.domain.periodic[a] = r.flag("periodic flag");
    r.expect(key::oneWay);
    t.domain.oneWay.active = r.flag("one-way box flag");
    t.domain.oneWay.lo = r.real("one-way box lower end");
    t.domain.oneWay.hi = r.real("one-way box upper end");
    if (t.domain.oneWay.active && !(t.domain.oneWay.hi > t.domain.oneWay.lo))
        r.fail("one-way box: the upper end must lie above the lower end");
    const auto outflowCount = r.count("one-way box species count", 1u << 16);
    for (std::uint64_t k = 0; k < outflowCount; ++k) {
        const auto species = r.integer("one-way box outflow species");
        if (species < -1 || species >= (1 << 16)) r.fail("one-way box outflow species out of range");
        t.domain.oneWay.outflowSpecies.push_back(static_cast<std::int32_t>(species));
    }
    r.expect(key::species);
    const auto speciesCount = r.count("species count", 1u << 16);
    for (std::uint64_t k = 0; k < speciesCount; ++k) {
        std::string name = r.token("species name");
        const double density = r.real("density");
        ContactLaw law = readLaw(r);
        try {
            t.species.add(name, density, law);
        } catch (const Error& e) {
            r.fail(e.what());
        }
    }
    r.expect(key::pairs);
    const auto pairCount = r.count("pair count", speciesCount * speciesCount);
    for (std::uint64_t k = 0; k < pairCount; ++k) {
        const auto a = r.index("species index", speciesCount), b = r.index("species index", speciesCount);
        ContactLaw law = readLaw(r);
        try {
            std::visit([](const auto& l) { l.validate("species pair"); }, law);
            t.species.setPair(a, b, law);
        } catch (const Error& e) {
            r.fail(e.what());
        }
    }
    r.expect(key::motions);
    const auto motionCount = r.count("motion count", 1u << 20);
    t.motions.resize(motionCount);
    for (PrescribedMotion& m : t.motions) {
        m.velocity = r.vec("motion velocity");
        m.angularVelocity = r.vec("motion angular velocity");
        m.centre = r.vec("motion centre");
    }
    auto motionIndex = [&](const char* what) { return readMotionIndex(r, what, motionCount); };
    r.expect(key::walls);
    t.walls.resize(r.count("wall count", 1u << 20));
    for (Wall& w : t.walls) {
        w.normal = r.vec("wall normal");
        w.point = r.vec("wall point");
        w.species = static_cast<std::uint32_t>(r.index("wall species", speciesCount));
        w.motion = motionIndex("wall motion");
        w.radius = r.real("wall radius");
        if (!(w.radius >= 0)) r.fail("wall radius must be 0 (a plane) or positive (a cylinder)");
        if (version < 8) continue;
        for (double& v : w.profile) v = r.real("wall profile");
        if (w.isRevolved() && (w.profile[0] < 0 || w.profile[2] < 0))
            r.fail("a revolved wall's distances from the axis must not be negative");
        for (double& v : w.next) v = r.real("wall next segment direction");
        w.startJoined = r.flag("wall start-joined flag");
    }
    if (version >= 9) readMeshes(r, t, speciesCount, version);
    r.expect(key::shapes);
    const bool shapes = r.flag("shapes flag");
    t.shapes.clear();
    const auto shapeCount = r.count("shape count", 1u << 20);
    for (std::uint64_t k = 0; k < shapeCount; ++k) {
        const Vec3 axes = r.vec("semi-axes");
        const double e1 = r.real("blockiness e1"), e2 = r.real("blockiness e2");
        try {
            t.shapes.emplace_back(axes.x(), axes.y(), axes.z(), e1, e2);
        } catch (const Error& e) {
            r.fail(e.what());
        }
    }
    r.expect(key::particles);
    const auto n = r.count("particle count", 0xffffffffu);
    t.nextId = r.count("next id");
    ParticleStore& p = t.particles;
    if (shapes) {
        p.enableShapes();
        t.pairList.enableWarmStarts();
    }
    const HistoryExtras extras{shapes, t.species.keepsRollingSprings()};
    if (extras.rolling) t.pairList.enableRollingSprings();
    // (A file of n particles has at least n lines of 23 words; a corrupt count reserves no more.)
    std::error_code noSize;
    const std::uintmax_t bytes = std::filesystem::file_size(path, noSize);
    p.reserve(noSize ? 0 : std::min<std::uint64_t>(n, bytes / 46));
    std::unordered_set<std::uint64_t> ids;
    for (std::uint64_t i = 0; i < n; ++i) {
        p.id.push_back(r.count("particle id"));
        if (!ids.insert(p.id.back()).second) r.fail("particle id " + std::to_string(p.id.back()) + " appears twice");
        p.position.push_back(r.vec("position"));
        p.velocity.push_back(r.vec("velocity"));
        p.angularVelocity.push_back(r.vec("angular velocity"));
        p.force.push_back(r.vec("force"));
        p.torque.push_back(r.vec("torque"));
        p.radius.push_back(r.real("radius"));
        if (!(p.radius.back() > 0)) r.fail("radius must be positive");
        p.mass.push_back(r.real("mass"));
        if (!(p.mass.back() > 0)) r.fail("mass must be positive");
        p.invMass.push_back(r.real("inverse mass"));
        p.invInertia.push_back(r.real("inverse inertia"));
        if (!(p.invMass.back() >= 0 && p.invInertia.back() >= 0))
            r.fail("inverse mass and inverse inertia must not be negative (0: a fixed particle)");
        p.species.push_back(static_cast<std::uint32_t>(r.index("species", speciesCount)));
        p.fixed.push_back(r.flag("fixed flag"));
        p.motion.push_back(motionIndex("particle motion"));
        if (shapes) {
            const double qw = r.real("orientation w"), qx = r.real("orientation x"), qy = r.real("orientation y"),
                         qz = r.real("orientation z");
            const Quat q(qw, qx, qy, qz);
            try {
                requireValidOrientation(q, "particle id " + std::to_string(p.id.back()));
            } catch (const Error& e) {
                r.fail(e.what());
            }
            p.orientation.push_back(q);
            p.angularMomentum.push_back(r.vec("angular momentum"));
            p.principalInertia.push_back(r.vec("principal inertia"));
            const auto shape = r.integer("particle shape");
            if (shape < -1 || shape >= static_cast<std::int64_t>(t.shapes.size())) r.fail("particle shape out of range");
            p.shape.push_back(static_cast<std::int32_t>(shape));
        }
        if (p.id.back() >= t.nextId) r.fail("particle id " + std::to_string(p.id.back()) + " is not below the next id");
    }
    r.expect(key::pairList);
    PairList& l = t.pairList;
    l.skin = r.real("skin");
    l.reach = r.real("reach");
    l.maxSpeed = r.real("largest speed");
    l.valid = r.flag("valid flag");
    l.builds = r.count("build count");
    const auto pairs = r.count("pair count", 1ull << 40), wallPairs = r.count("wall pair count", 1ull << 40);
    const auto references = r.count("reference count", n);
    l.interiorPairs = r.count("interior pair count", pairs);
    if (version >= 10) l.meshTravel = r.real("mesh travel");
    if (!(l.meshTravel >= 0 && std::isfinite(l.meshTravel))) r.fail("the mesh travel must be finite and not negative");
    for (std::uint64_t k = 0; k < pairs; ++k) {
        const auto i = r.index("pair particle", n), j = r.index("pair particle", n);
        l.pairs.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        l.history.push_back(readHistory(r, extras));
    }
    for (std::uint64_t k = 0; k < wallPairs; ++k) {
        const auto i = r.index("wall pair particle", n);
        const auto w = r.index("wall pair wall", t.walls.size());
        l.wallPairs.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(w)});
        l.wallHistory.push_back(readHistory(r, extras));
    }
    for (std::uint64_t k = 0; k < references; ++k) l.referencePosition.push_back(r.vec("reference position"));
    r.expect(key::oneWayPairs);
    const auto oneWayPairs = r.count("one-way pair count", 1ull << 40);
    for (std::uint64_t k = 0; k < oneWayPairs; ++k) {
        const auto i = r.index("one-way pair particle", n), j = r.index("one-way pair particle", n);
        l.oneWayPairs.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        l.oneWayHistory.push_back(readHistory(r, extras));
    }
    r.expect(key::random);
    {
        std::istringstream engine;
        std::string state;
        for (int k = 0; k < 313; ++k) state += r.token("random generator state") + " ";
        engine.str(state);
        engine >> t.random;
        if (!engine) r.fail("bad random generator state");
    }
    r.expect(key::output);
    t.output.savedFrames = r.count("saved frames");
    t.output.dataBytes = r.count("data bytes");
    t.output.fstatBytes = r.count("fstat bytes");
    t.output.eneBytes = r.count("ene bytes");
    const auto frames = r.count("frame count", 1ull << 32);
    for (std::uint64_t k = 0; k < frames; ++k) t.output.frameTimes.push_back(r.real("frame time"));
    r.expect(key::values);
    const auto values = r.count("value count", 1ull << 20);
    for (std::uint64_t k = 0; k < values; ++k) {
        std::string name = r.token("value name");
        const double value = r.real("kept value");
        if (name == shapeToleranceValue) c.shapeTolerance = value;
        else t.keptValues.emplace_back(std::move(name), value);
    }
    for (std::int32_t species : t.domain.oneWay.outflowSpecies)
        if (species >= static_cast<std::int32_t>(t.species.size()) || t.domain.oneWay.outflowSpecies.size() > t.species.size())
            r.fail("one-way box: outflow species " + std::to_string(species) + " does not exist");
    r.expect(key::end);
    if (!r.atEnd()) r.fail("unexpected text after 'end'");
    s = std::move(t);
}

}  // namespace talus
