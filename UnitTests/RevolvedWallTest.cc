// Surfaces of revolution as walls (Walls/Wall.h, Scene::addRevolvedWall; Theory/ContactLaws.md
// "Surfaces of revolution"): a profile of segments turned about an axis, each segment a wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "TestHelpers.h"

using namespace talus;
using namespace talus::test;

namespace {

// The walls of `profile` turned about the z axis through the origin, as Scene::addRevolvedWall
// makes them, in a scene of their own.
std::vector<Wall> revolvedWalls(const std::vector<std::array<double, 2>>& profile) {
    SceneSimulation s;
    s.scene().addSpecies("steel", 1, LinearSpringDashpot::fromCollision(0.01, 0.5, 1));
    s.scene().addRevolvedWall(Vec3::Zero(), Vec3::UnitZ(), profile, 0);
    return s.scene().walls();
}

}  // namespace

TEST(RevolvedWall, AnUprightSegmentIsTheCylinderBetweenItsEnds) {
    Wall drum;
    drum.normal = Vec3::UnitZ();
    drum.radius = 2;
    const Wall segment = revolvedWalls({{2, -1}, {2, 5}})[0];
    for (const Vec3& x : {Vec3(0.6, -0.8, 3), Vec3(-1.2, 0.3, 0), Vec3(0.1, 1.7, 4.9)}) {
        const Wall::Gap a = drum.gapTo(x), b = segment.gapTo(x);
        EXPECT_NEAR(a.distance, b.distance, 1e-15);
        EXPECT_LT((a.normal - b.normal).norm(), 1e-14);
        EXPECT_NEAR(a.curvature, b.curvature, 1e-15);
        EXPECT_TRUE(b.counts);
    }
}

// The cone through (rho, z) = (1, 0) and (2, 1), 45 degrees, about z. From (rho, z) = (1, 1) its
// generator rho - z = 1 is 1/sqrt(2) away, at (1.5, 0.5), the normal (-1, 1)/sqrt(2) in (rho, z);
// there the circle of radius 1.5 curves it by cos(45 deg) / 1.5 towards the axis (Meusnier),
// concave from that side. From (3, 0.5), outside, the same generator is 1.5/sqrt(2) away at
// (2.25, ...) beyond the end (2, 1): the open rim is nearest, at distance |(1, -0.5)|.
TEST(RevolvedWall, DistanceNormalAndCurvatureOfAConeAreThoseOfItsGenerator) {
    const Wall cone = revolvedWalls({{1, 0}, {2, 1}})[0];
    const double phi = 0.7;  // any azimuth
    const Vec3 outward(std::cos(phi), std::sin(phi), 0);
    const Wall::Gap inside = cone.gapTo(1 * outward + Vec3(0, 0, 1));
    EXPECT_NEAR(inside.distance, 1 / std::sqrt(2), 1e-15);
    EXPECT_LT((inside.normal - (-outward + Vec3::UnitZ()) / std::sqrt(2)).norm(), 1e-15);
    EXPECT_NEAR(inside.curvature, 1 / std::sqrt(2) / 1.5, 1e-15);
    EXPECT_TRUE(inside.counts);
    const Wall::Gap rim = cone.gapTo(3 * outward + Vec3(0, 0, 0.5));
    EXPECT_NEAR(rim.distance, std::hypot(1, 0.5), 1e-15);
    EXPECT_LT((rim.normal - (outward - 0.5 * Vec3::UnitZ()) / std::hypot(1, 0.5)).norm(), 1e-15);
    EXPECT_EQ(rim.curvature, 0);  // a rim is met as a corner
    EXPECT_TRUE(rim.counts);
}

// The contacts of a sphere with a profile are the local minima of the distance from its centre
// along the profile that are nearer than its radius, each counted once: at a concave joint the
// segments' own nearest points, at a convex one the joint once, at an open rim the rim. Checked
// against those minima found by sampling the profile (2e5 points) for random centres around a
// profile with concave and convex joints, open rims and a straight joint.
TEST(RevolvedWall, CountsEachLocalMinimumOfTheDistanceOnce) {
    const std::vector<std::array<double, 2>> profile = {{0.5, 0}, {2, 1.5}, {2, 2.5}, {2, 3}, {3, 3}, {3.5, 2}, {2.8, 1.2}};
    const std::vector<Wall> walls = revolvedWalls(profile);
    std::vector<std::array<double, 2>> samples;
    const int perSegment = 40000;
    for (std::size_t s = 0; s + 1 < profile.size(); ++s)
        for (int k = s == 0 ? 0 : 1; k <= perSegment; ++k) {
            const double t = double(k) / perSegment;
            samples.push_back({profile[s][0] + t * (profile[s + 1][0] - profile[s][0]),
                               profile[s][1] + t * (profile[s + 1][1] - profile[s][1])});
        }
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> rhoOf(0.3, 4.2), zOf(-0.5, 3.8), azimuth(0, 2 * pi);
    const double radius = 0.45;
    int tried = 0, withContacts = 0, withTwo = 0;
    for (int n = 0; n < 400; ++n) {
        const double rho = rhoOf(random), z = zOf(random), phi = azimuth(random);
        std::vector<double> minima;
        std::vector<double> d(samples.size());
        for (std::size_t k = 0; k < samples.size(); ++k) d[k] = std::hypot(rho - samples[k][0], z - samples[k][1]);
        for (std::size_t k = 0; k < d.size(); ++k) {
            const bool belowBefore = k == 0 || d[k] < d[k - 1];
            const bool notAboveAfter = k + 1 == d.size() || d[k] <= d[k + 1];
            if (belowBefore && notAboveAfter) minima.push_back(d[k]);
        }
        // (Centres whose nearest distance is within sampling error of the radius are ambiguous.)
        if (std::any_of(minima.begin(), minima.end(), [&](double m) { return std::abs(m - radius) < 1e-3; })) continue;
        std::erase_if(minima, [&](double m) { return m >= radius; });
        std::vector<double> counted;
        const Vec3 x(rho * std::cos(phi), rho * std::sin(phi), z);
        for (const Wall& w : walls) {
            const Wall::Gap g = w.gapTo(x);
            if (g.counts && g.distance < radius) counted.push_back(g.distance);
        }
        std::sort(minima.begin(), minima.end());
        std::sort(counted.begin(), counted.end());
        ++tried;
        withContacts += !counted.empty();
        withTwo += counted.size() >= 2;
        ASSERT_EQ(counted.size(), minima.size()) << "centre (rho, z) = (" << rho << ", " << z << ")";
        for (std::size_t k = 0; k < counted.size(); ++k)
            EXPECT_NEAR(counted[k], minima[k], 1e-4) << "centre (rho, z) = (" << rho << ", " << z << ")";
    }
    std::printf("[ measured ] %d centres: %d touch the profile, %d of them twice\n", tried, withContacts, withTwo);
    EXPECT_GT(withContacts, 40);
    EXPECT_GT(withTwo, 3);
}

namespace {

// A sphere (radius 0.1, mass 1) in a funnel about z: a cone of 45 degrees from (rho, z) = (0.5, 0)
// up to (2, 1.5), then an upright wall to z = 3. Linear springs, tc = 0.01.
struct Funnel {
    double radius = 0.1, mass = 1, g = 1;
    LinearSpringDashpot law;
    explicit Funnel(double restitution, double friction)
        : law(LinearSpringDashpot::fromCollision(0.01, restitution, 1).withFriction(friction)) {}
    void build(SceneSimulation& s, const Vec3& position, const Vec3& velocity) const {
        s.scene().setGravity(Vec3(0, 0, -g));
        s.scene().setDomain(Vec3(-3, -3, -2), Vec3(3, 3, 4));
        const auto species = s.scene().addSpecies("grains", mass / (4.0 / 3.0 * pi * std::pow(radius, 3)), law);
        s.scene().addRevolvedWall(Vec3::Zero(), Vec3::UnitZ(), {{0.5, 0}, {2, 1.5}, {2, 3}}, species);
        s.scene().addParticle(position, radius, species, velocity);
    }
};

}  // namespace

// A sphere in an annular groove: two cones meeting at (rho, z) = (1.5, 0), their faces rising
// 2 in z per 1 in rho on either side. At rest in the valley it touches both faces, whose normals
// (+-2, 1)/sqrt(5) (in rho, z) carry its weight: each pushes N = m g sqrt(5) / 2, the overlap is
// N / kn, and its centre stands sqrt(5) (r - N / kn) above the valley, on the circle rho = 1.5.
// Frictionless: with friction the steep faces could wedge it, holding larger forces in their springs.
TEST(RevolvedWall, ASphereRestsInAGrooveOfTwoConesUnderItsWeight) {
    const Funnel funnel(0.3, 0);
    SceneSimulation s;
    s.setup = [&](SceneSimulation& sim) {
        sim.scene().setGravity(Vec3(0, 0, -funnel.g));
        sim.scene().setDomain(Vec3(-3, -3, -2), Vec3(3, 3, 3));
        const auto species = sim.scene().addSpecies(
            "grains", funnel.mass / (4.0 / 3.0 * pi * std::pow(funnel.radius, 3)), funnel.law);
        sim.scene().addRevolvedWall(Vec3::Zero(), Vec3::UnitZ(), {{1, 1}, {1.5, 0}, {2, 1}}, species);
        // Dropped from a little above its rest, off the valley's circle by 0.01.
        sim.scene().addParticle(Vec3(1.51, 0, std::sqrt(5) * funnel.radius + 0.02), funnel.radius, species);
    };
    s.runFor(2e-4, 4);
    const ParticleStore& p = s.scene().particles();
    const double normalForce = funnel.mass * funnel.g * std::sqrt(5) / 2;
    const double expected = std::sqrt(5) * (funnel.radius - normalForce / funnel.law.normalStiffness);
    std::printf("[ measured ] sphere in a groove of two cones: z = %.12f against %.12f, rho = %.12f, speed %.1e\n",
                p.position[0].z(), expected, std::hypot(p.position[0].x(), p.position[0].y()), p.velocity[0].norm());
    EXPECT_NEAR(p.position[0].z(), expected, 1e-10);
    EXPECT_NEAR(std::hypot(p.position[0].x(), p.position[0].y()), 1.5, 1e-10);
    EXPECT_LT(p.velocity[0].norm(), 1e-8);
}

// Frictionless and elastic (e = 1), a sphere slides up the cone, across the concave joint up the
// upright wall and back: kinetic, potential and spring energy, summed over the counted contacts
// (overlap^2 kn / 2), stay what they were: velocity Verlet keeps a spring's energy to about
// (omega dt)^2 / 8 of it, 1.2e-4 at dt = tc/100, so to 5e-4 of the kinetic energy at the start.
// Another slides down the cone to the orifice and round its open rim (a convex corner) through
// it, its energy kept too.
TEST(RevolvedWall, AFrictionlessSphereKeepsItsEnergyAcrossJointsAndRims) {
    const Funnel funnel(1, 0);
    struct Case {
        const char* what;
        Vec3 position, velocity;
        int mostContacts;  // at once: 2 at the concave joint, 1 round the rim
    };
    for (const Case& c : {Case{"inside, across the joint", Vec3(1.6, 0, 1.6 - 0.5 + 0.1 * std::sqrt(2)), Vec3(1, 0, 1), 2},
                          Case{"down the cone, over the rim", Vec3(0.8, 0, 0.8 - 0.5 + 0.1 * std::sqrt(2)),
                               Vec3(-0.3, 0, -0.3), 1}}) {
        SceneSimulation s;
        s.setup = [&](SceneSimulation& sim) { funnel.build(sim, c.position, c.velocity); };
        const double kinetic = 0.5 * funnel.mass * c.velocity.squaredNorm();
        double first = NAN, worst = 0, lowest = 10;
        int mostContacts = 0;
        s.afterStep = [&](SceneSimulation& sim) {
            const ParticleStore& p = sim.scene().particles();
            double energy = 0.5 * funnel.mass * p.velocity[0].squaredNorm() + funnel.mass * funnel.g * p.position[0].z() +
                            0.5 * p.angularVelocity[0].squaredNorm() / p.invInertia[0];
            int contacts = 0;
            for (const Wall& w : sim.scene().walls()) {
                const Wall::Gap g = w.gapTo(p.position[0]);
                if (g.counts && g.distance < funnel.radius) {
                    energy += 0.5 * funnel.law.normalStiffness * std::pow(funnel.radius - g.distance, 2);
                    ++contacts;
                }
            }
            mostContacts = std::max(mostContacts, contacts);
            lowest = std::min(lowest, p.position[0].z());
            if (std::isnan(first)) first = energy;
            worst = std::max(worst, std::abs(energy - first));
        };
        s.runFor(1e-4, 1.5);
        std::printf("[ measured ] %s: energy kept to %.2e of the kinetic energy, lowest z %.3f, up to %d contacts at once\n",
                    c.what, worst / kinetic, lowest, mostContacts);
        EXPECT_LT(worst, 5e-4 * kinetic);
        EXPECT_EQ(mostContacts, c.mostContacts);
    }
}

// A sphere resting on a floor of collinear segments (an annulus cut in rings) feels its weight
// once, above a joint as on a segment: its overlap is m g / kn.
TEST(RevolvedWall, ASphereOnAFloorOfManyRingsFeelsItsWeightOnce) {
    const Funnel funnel(0.3, 0.5);
    for (const double rho : {1.5, 2.0, 2.5, 2.0 + 1e-12}) {
        SceneSimulation s;
        s.setup = [&](SceneSimulation& sim) {
            sim.scene().setGravity(Vec3(0, 0, -funnel.g));
            sim.scene().setDomain(Vec3(-4, -4, -2), Vec3(4, 4, 4));
            const auto species = sim.scene().addSpecies(
                "grains", funnel.mass / (4.0 / 3.0 * pi * std::pow(funnel.radius, 3)), funnel.law);
            sim.scene().addRevolvedWall(Vec3::Zero(), Vec3::UnitZ(), {{1, 0}, {1.5, 0}, {2, 0}, {2.5, 0}, {3, 0}}, species);
            sim.scene().addParticle(Vec3(rho, 0, funnel.radius), funnel.radius, species);
        };
        s.runFor(2e-4, 2);
        const double overlap = funnel.radius - s.scene().particles().position[0].z();
        EXPECT_NEAR(overlap, funnel.mass * funnel.g / funnel.law.normalStiffness, 1e-12) << "at rho = " << rho;
    }
}

// An ellipsoid lying on a floor of revolution (an annulus) meets the tangent plane at the point
// nearest its centre, as on a plane wall (Theory/Superquadrics.md "Walls"): its lowest point sinks
// m g / kn below the floor, as a sphere's does.
TEST(RevolvedWall, AnEllipsoidRestsOnAnAnnulusAsOnAPlane) {
    const Superquadric shape = Superquadric::ellipsoid(0.6, 0.5, 0.3);  // lying along x, 0.3 high
    const double mass = 6 / pi * shape.volume();
    const LinearSpringDashpot law = LinearSpringDashpot::fromCollision(0.005, 0.3, mass).withFriction(0.5);
    SceneSimulation s;
    s.setup = [&](SceneSimulation& sim) {
        sim.scene().setGravity(Vec3(0, 0, -1));
        sim.scene().setDomain(Vec3(-4, -4, -1), Vec3(4, 4, 3));
        const auto species = sim.scene().addSpecies("grains", 6 / pi, law);
        sim.scene().addRevolvedWall(Vec3::Zero(), Vec3::UnitZ(), {{0.5, 0}, {3, 0}}, species);
        sim.scene().addSuperquadric(Vec3(0, 1.5, 0.3), sim.scene().addShape(shape), species);
    };
    s.runFor(1e-4, 4);
    const double expected = 0.3 - mass / law.normalStiffness;
    std::printf("[ measured ] ellipsoid on an annulus: z = %.10f against %.10f\n", s.scene().particles().position[0].z(),
                expected);
    EXPECT_NEAR(s.scene().particles().position[0].z(), expected, 1e-8);
    EXPECT_LT(s.scene().particles().velocity[0].norm(), 1e-6);
}

// Opening a lid (Scene::removeWall): the sphere it held falls free from that step, and a second
// sphere sliding on the floor, whose wall moves down one index then, keeps its tangential spring:
// it goes on exactly as in a run that never had the lid.
TEST(RevolvedWall, RemovingAWallEndsItsContactsAndKeepsTheOthers) {
    const LinearSpringDashpot law = LinearSpringDashpot::fromCollision(0.01, 0.5, 1).withFriction(0.5);
    auto run = [&](bool withLid) {
        SceneSimulation s;
        s.setup = [&](SceneSimulation& sim) {
            sim.scene().setGravity(Vec3(0, 0, -1));
            sim.scene().setDomain(Vec3(-3, -3, -3), Vec3(3, 3, 3));
            const auto species = sim.scene().addSpecies("grains", 6 / pi, law);
            // The lid: a disc at z = 0 under the first sphere, then the floor at z = -1.
            if (withLid) sim.scene().addRevolvedWall(Vec3(-1.2, 0, 0), Vec3::UnitZ(), {{0, 0}, {0.6, 0}}, species);
            sim.scene().addWall(Vec3::UnitZ(), Vec3(0, 0, -1), species);
            sim.scene().addParticle(Vec3(-1, 0, 0.5), 0.5, species);
            // Spun backwards: it slides until t = 0.74 (slip 1.3 lost at (1 + 5/2) mu g).
            sim.scene().addParticle(Vec3(1, 0, -0.5), 0.5, species, Vec3(0.3, 0, 0), Vec3(0, -2, 0));
        };
        bool opened = !withLid;
        s.afterStep = [&](SceneSimulation& sim) {
            if (!opened && sim.time() >= 0.5) {
                sim.scene().removeWall(0);
                opened = true;
            }
        };
        s.runFor(1e-4, 1.2);
        return std::pair{s.scene().particles().position, s.scene().particles().velocity};
    };
    const auto [withLid, withLidVelocity] = run(true);
    const auto [without, withoutVelocity] = run(false);
    EXPECT_TRUE(sameBits(withLid[1], without[1]));  // the slider, its spring kept across the removal
    EXPECT_TRUE(sameBits(withLidVelocity[1], withoutVelocity[1]));
    // The held sphere (mass 1) rested on the lid until t = 0.5 (overlap m g / kn) and fell free for 0.7.
    const double rest = 0.5 - 1 / law.normalStiffness;
    EXPECT_NEAR(withLid[0].z(), rest - 0.5 * 0.7 * 0.7, 2e-3);
    EXPECT_NEAR(withLidVelocity[0].z(), -0.7, 2e-3);
}

// A profile that is no surface is refused with the point it names: too few points, a point not
// finite, one on the wrong side of the axis, one repeated; and removing a wall that does not exist.
TEST(RevolvedWall, BadProfilesAreNamed) {
    using Profile = std::vector<std::array<double, 2>>;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Case {
        Profile profile;
        std::vector<std::string> parts;
    };
    for (const Case& c : {Case{{{1, 0}}, {"revolved wall", "at least two points, got 1"}},
                          Case{{{1, 0}, {nan, 1}}, {"profile point 1", "not finite"}},
                          Case{{{1, 0}, {-0.5, 1}}, {"profile point 1 (-0.5, 1)", "must not be negative"}},
                          Case{{{1, 0}, {2, 1}, {2, 1}}, {"profile point 2 (2, 1)", "repeats the point before it"}}}) {
        SceneSimulation s;
        s.setup = [&](SceneSimulation& sim) {
            const auto species = sim.scene().addSpecies("grains", 1, LinearSpringDashpot::fromCollision(0.005, 0.5, 1));
            sim.scene().addRevolvedWall(Vec3::Zero(), Vec3::UnitZ(), c.profile, species);
        };
        expectError([&] { s.runFor(1e-4, 1e-3); }, c.parts);
    }
    SceneSimulation s;
    s.setup = [](SceneSimulation& sim) {
        const auto species = sim.scene().addSpecies("grains", 1, LinearSpringDashpot::fromCollision(0.005, 0.5, 1));
        sim.scene().addRevolvedWall(Vec3::Zero(), Vec3::UnitZ(), {{1, 0}, {2, 1}}, species);
        sim.scene().removeWall(1);
    };
    expectError([&] { s.runFor(1e-4, 1e-3); }, {"removeWall", "wall 1 does not exist"});
}
