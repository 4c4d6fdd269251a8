// Superquadric particles driven through talus::Simulation: sphere-shaped superquadrics made
// spheres, the sphere path reproduced by nearly spherical superquadrics, energy conservation of an elastic ellipsoid bouncing on a
// plane, the restitution of a central ellipsoid collision, exact restart, bad restart input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "IO/RestartFile.h"
#include "TestHelpers.h"

using namespace talus;
using namespace talus::test;

namespace {

// Two particles touching obliquely, spinning, with friction: the state after a few steps.
struct PairState {
    Vec3 x[2], v[2], w[2];
    bool shaped;
};
// The pair as spheres (aspect 0), as superquadrics of axes 0.5, 0.5, 0.5 x aspect.
PairState obliqueContact(double aspect, int steps) {
    SceneSimulation s;
    s.setup = [&](SceneSimulation& sim) {
        sim.scene().setGravity(Vec3::Zero());
        sim.scene().setDomain(Vec3(-5, -5, -5), Vec3(5, 5, 5));
        LinearSpringDashpot law = LinearSpringDashpot::fromCollision(0.005, 0.7, 0.25).withFriction(0.4);
        law.treatContactEnds = false;  // the superquadric path steps contacts plainly (ContactForces.h)
        const auto species = sim.scene().addSpecies("grains", 6 / pi, law);
        const Vec3 x0(0, 0, 0), x1(0.98, 0.1, -0.05), v0(0.3, 0.05, 0), v1(-0.2, 0, 0.1);
        const Vec3 w0(1, -2, 0.5), w1(-0.3, 0.4, 2);
        if (aspect > 0) {
            const std::size_t shape = sim.scene().addShape(Superquadric(0.5, 0.5, 0.5 * aspect, 1, 1));
            sim.scene().addSuperquadric(x0, shape, species, Quat::Identity(), v0, w0);
            sim.scene().addSuperquadric(x1, shape, species, Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())), v1, w1);
        } else {
            sim.scene().addParticle(x0, 0.5, species, v0, w0);
            sim.scene().addParticle(x1, 0.5, species, v1, w1);
        }
    };
    s.settings().reorderParticles = false;
    s.runFor(1e-4, steps * 1e-4);
    PairState out;
    out.shaped = s.scene().particles().hasShapes();
    for (int k = 0; k < 2; ++k) {
        const std::size_t i = s.scene().slotOf(static_cast<std::uint64_t>(k));
        out.x[k] = s.scene().particles().position[i], out.v[k] = s.scene().particles().velocity[i], out.w[k] = s.scene().particles().angularVelocity[i];
    }
    return out;
}

}  // namespace

TEST(SuperquadricSimulation, SphereShapedSuperquadricsAreSpheres) {
    const PairState spheres = obliqueContact(0, 5), sphereShaped = obliqueContact(1, 5);
    EXPECT_FALSE(sphereShaped.shaped) << "a sphere-shaped superquadric is added as a sphere";
    for (int k = 0; k < 2; ++k) {
        EXPECT_EQ(spheres.x[k], sphereShaped.x[k]);
        EXPECT_EQ(spheres.v[k], sphereShaped.v[k]);
        EXPECT_EQ(spheres.w[k], sphereShaped.w[k]);
    }
}

TEST(SuperquadricSimulation, NearlySphericalSuperquadricsFollowTheSpherePath) {
    // Over the first steps of a contact (spring still small, so that rotating it, as spheres do,
    // and projecting it with its length kept, as superquadrics do, agree to O(dt^2) of it); the
    // third axis 1e-12 longer, so that the superquadric path's contact solve runs.
    for (int steps : {1, 5}) {
        const PairState spheres = obliqueContact(0, steps), shaped = obliqueContact(1 + 1e-12, steps);
        EXPECT_TRUE(shaped.shaped);
        for (int k = 0; k < 2; ++k) {
            EXPECT_LT((spheres.x[k] - shaped.x[k]).norm(), 1e-12) << steps;
            EXPECT_LT((spheres.v[k] - shaped.v[k]).norm(), 1e-9 * spheres.v[k].norm()) << steps;
            EXPECT_LT((spheres.w[k] - shaped.w[k]).norm(), 1e-9 * spheres.w[k].norm()) << steps;
        }
    }
}

TEST(SuperquadricSimulation, ElasticEllipsoidBouncingOnAPlaneConservesEnergy) {
    // Frictionless and undamped (e = 1): gravity, the normal spring and the rigid-body rotation
    // exchange energy and nothing dissipates it; the tilted ellipsoid starts spinning at each
    // impact. Kinetic, rotational and gravitational energy in flight (no contact) against the start
    // value, over several bounces.
    SceneSimulation s;
    double startEnergy = NAN, worst = 0;
    int contactSteps = 0;
    double largestSpin = 0;
    s.setup = [&](SceneSimulation& sim) {
        sim.scene().setGravity(Vec3(0, 0, -1));
        sim.scene().setDomain(Vec3(-5, -5, 0), Vec3(5, 5, 10));
        const Superquadric shape = Superquadric::ellipsoid(0.5, 0.25, 0.25);
        const double mass = 6 / pi * shape.volume();
        const auto species = sim.scene().addSpecies("grains", 6 / pi, LinearSpringDashpot::fromCollision(0.005, 1, mass));
        sim.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species);
        sim.scene().addSuperquadric(Vec3(0, 0, 1.5), sim.scene().addShape(shape), species,
                            Quat(Eigen::AngleAxisd(0.6, Vec3(0.3, 1, 0.2).normalized())));
    };
    s.afterStep = [&](SceneSimulation& sim) {
        const Energies e = sim.energies();
        const double total = e.kinetic + e.rotational + e.gravitational;
        if (std::isnan(startEnergy)) startEnergy = total;
        if (sim.contactSummary().contacts == 0) worst = std::max(worst, std::abs(total - startEnergy));
        contactSteps += sim.contactSummary().contacts > 0;
        largestSpin = std::max(largestSpin, sim.scene().particles().angularVelocity[0].norm());
    };
    s.runFor(2.5e-5, 6);  // tc/200: the error is second order in dt (4.8e-4 at tc/50, 1.9e-4 at tc/100)
    std::printf("[ measured ] elastic ellipsoid on a plane: largest energy error %.2e of %.4f (%d contact steps, "
                "spin up to %.3f)\n", worst / std::abs(startEnergy), startEnergy, contactSteps, largestSpin);
    EXPECT_GT(contactSteps, 100);
    EXPECT_GT(largestSpin, 0.1);
    EXPECT_LT(worst, 1e-4 * std::abs(startEnergy));
}

TEST(SuperquadricSimulation, CentralEllipsoidCollisionAlongAPrincipalAxisHasTheLawsRestitution) {
    // Along the long axis, the normal stays on the line of centres and nothing turns: the linear
    // law's restitution of Theory/ContactLaws.md eq. (10)-(11), here stepped plainly (O(dt) error,
    // so dt = tc/1000).
    for (double e : {0.5, 0.88}) {
        SceneSimulation s;
        const Superquadric shape = Superquadric::ellipsoid(0.5, 0.25, 0.2);
        const double mass = 6 / pi * shape.volume();
        s.setup = [&](SceneSimulation& sim) {
            sim.scene().setGravity(Vec3::Zero());
            sim.scene().setDomain(Vec3(-5, -5, -5), Vec3(5, 5, 5));
            const auto species = sim.scene().addSpecies("grains", 6 / pi, LinearSpringDashpot::fromCollision(0.005, e, mass / 2));
            const std::size_t sq = sim.scene().addShape(shape);
            sim.scene().addSuperquadric(Vec3(-0.52, 0, 0), sq, species, Quat::Identity(), Vec3(1, 0, 0));
            sim.scene().addSuperquadric(Vec3(0.52, 0, 0), sq, species, Quat::Identity(), Vec3(-1, 0, 0));
        };
        s.settings().reorderParticles = false;
        s.runFor(5e-6, 0.05);
        const double vAfter = s.scene().particles().velocity[s.scene().slotOf(1)].x() - s.scene().particles().velocity[s.scene().slotOf(0)].x();
        std::printf("[ measured ] central ellipsoid collision e = %.2f: restitution %.6f\n", e, vAfter / 2);
        EXPECT_NEAR(vAfter / 2, e, 1e-3 * e);
        EXPECT_LT(s.scene().particles().angularVelocity[0].norm(), 1e-12);
    }
}

TEST(SuperquadricSimulation, UnnormalisedOrientationInARestartIsRefused) {
    SceneSimulation s;
    s.setup = [](SceneSimulation& sim) {
        sim.scene().setDomain(Vec3(-5, -5, -5), Vec3(5, 5, 5));
        const auto species = sim.scene().addSpecies("grains", 6 / pi, LinearSpringDashpot::fromCollision(0.005, 0.5, 0.1));
        sim.scene().addSuperquadric(Vec3::Zero(), sim.scene().addShape(Superquadric::ellipsoid(0.5, 0.25, 0.25)), species,
                            Quat(Eigen::AngleAxisd(0.4, Vec3::UnitY())));
    };
    s.runFor(1e-4, 1e-3);
    writeRestartFile("unnormalised.restart", s.state());
    std::string text = readWholeFile("unnormalised.restart");
    // The orientation's w is the first number after the motion index of the particle line.
    SimulationState read;
    readRestartFile("unnormalised.restart", read);
    ASSERT_TRUE(read.particles.hasShapes());
    EXPECT_TRUE(sameBits(read.particles.orientation, s.scene().particles().orientation));
    const Quat q = s.scene().particles().orientation[0];
    std::ostringstream w;
    w.precision(17);
    w << q.w();
    const std::size_t at = text.find(w.str());
    ASSERT_NE(at, std::string::npos);
    text.replace(at, w.str().size(), "1.5");
    writeWholeFile("unnormalised.restart", text);
    expectError([&] { readRestartFile("unnormalised.restart", read); },
                {"unnormalised.restart line", "particle id 0", "not normalised"});
}

TEST(SuperquadricSimulation, HertzianTipToTipCollisionUsesTheTipsCurvature) {
    // Two prolate spheroids (a = 0.5, b = c = 0.25) meet tip to tip along their long axes. Both
    // principal curvatures at a tip are a/b^2, so each tip is a sphere of radius b^2/a = 0.125
    // there and R* = 0.0625: the elastic Hertz duration tc = 2 (2/5) B(2/5, 1/2) dmax / v with
    // dmax = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5) (Hertz theory, as HeadOnCollision checks for
    // spheres). Slow enough that dmax is 1.6% of the tip radius, where the tip is still the
    // paraboloid Hertz assumes.
    const Superquadric shape = Superquadric::ellipsoid(0.5, 0.25, 0.25);
    const double mass = 6 / pi * shape.volume(), reducedMass = mass / 2, speed = 0.2;  // approach speed
    HertzMindlin law;
    law.effectiveYoungsModulus = 1e5;
    law.restitution = 1;
    law.characteristicVelocity = speed;
    const double effectiveRadius = 0.125 / 2;
    const double maxOverlap = std::pow(15 * reducedMass * speed * speed / (16 * law.effectiveYoungsModulus * std::sqrt(effectiveRadius)), 0.4);
    const double expected = 2 * 0.4 * std::beta(0.4, 0.5) * maxOverlap / speed;
    SceneSimulation s;
    int contactSteps = 0;
    const double dt = expected / 2000;
    s.setup = [&](SceneSimulation& sim) {
        sim.scene().setGravity(Vec3::Zero());
        sim.scene().setDomain(Vec3(-5, -5, -5), Vec3(5, 5, 5));
        const auto species = sim.scene().addSpecies("grains", 6 / pi, law);
        const std::size_t sq = sim.scene().addShape(shape);
        sim.scene().addSuperquadric(Vec3(-0.501, 0, 0), sq, species, Quat::Identity(), Vec3(speed / 2, 0, 0));
        sim.scene().addSuperquadric(Vec3(0.501, 0, 0), sq, species, Quat::Identity(), Vec3(-speed / 2, 0, 0));
    };
    s.afterStep = [&](SceneSimulation& sim) { contactSteps += sim.contactSummary().contacts > 0; };
    s.settings().reorderParticles = false;
    s.runFor(dt, 0.002 / speed + 2 * expected);
    const double duration = contactSteps * dt;
    const double rebound = (s.scene().particles().velocity[s.scene().slotOf(1)].x() - s.scene().particles().velocity[s.scene().slotOf(0)].x()) / speed;
    std::printf("[ measured ] Hertz tip to tip: duration %.6e against %.6e, rebound speed ratio %.8f\n", duration,
                expected, rebound);
    EXPECT_NEAR(duration / expected, 1, 2e-3);
    EXPECT_NEAR(rebound, 1, 1e-6);
}

TEST(SuperquadricSimulation, SphereComesToRestOnAFixedEllipsoid) {
    // A sphere (r = 0.3, m = 6/pi 4/3 pi r^3) dropped onto the top of a fixed ellipsoid lying
    // along x (semi-axes 1, 0.6, 0.4, centre at the origin) settles where the linear spring
    // carries its weight: z = c + r - m g / kn (the top of the ellipsoid is at z = c, the overlap
    // m g / kn), with no sideways drift (the top is a point of symmetry).
    // The equilibrium is exact and the damping (e = 0.3) has taken the bounce down to round-off
    // by t = 3 (measured: z off by 4e-16 r, speed 1e-13). The bounds allow for the contact
    // solver, which may stop anywhere within its tolerance, 1e-10 of the ellipsoid's bounding
    // radius 1 (another compiler's rounding could make it): z to 1e-9 r (3 times that), and the
    // speed to 1e-7 (an overlap off by 1e-10 changes the speed by kn 1e-10 dt / m = 5e-9 a step).
    SceneSimulation s;
    const double r = 0.3, mass = 6 / pi * 4.0 / 3.0 * pi * r * r * r;
    const LinearSpringDashpot law = LinearSpringDashpot::fromCollision(0.005, 0.3, mass).withFriction(0.5);
    s.setup = [&](SceneSimulation& sim) {
        sim.scene().setGravity(Vec3(0, 0, -1));
        sim.scene().setDomain(Vec3(-3, -3, -3), Vec3(3, 3, 3));
        const auto species = sim.scene().addSpecies("grains", 6 / pi, law);
        sim.scene().addFixedSuperquadric(Vec3::Zero(), sim.scene().addShape(Superquadric::ellipsoid(1, 0.6, 0.4)), species);
        sim.scene().addParticle(Vec3(0, 0, 0.4 + r + 0.05), r, species);
    };
    s.runFor(1e-4, 3);
    const std::size_t sphere = s.scene().slotOf(1), ellipsoid = s.scene().slotOf(0);
    const double expected = 0.4 + r - mass / law.normalStiffness;
    std::printf("[ measured ] sphere on a fixed ellipsoid: z = %.10f against %.10f, error %.2e of r, sideways %.1e, "
                "speed %.1e\n",
                s.scene().particles().position[sphere].z(), expected, (s.scene().particles().position[sphere].z() - expected) / r,
                s.scene().particles().position[sphere].head<2>().norm(), s.scene().particles().velocity[sphere].norm());
    EXPECT_NEAR(s.scene().particles().position[sphere].z(), expected, 1e-9 * r);
    EXPECT_LT(s.scene().particles().position[sphere].head<2>().norm(), 1e-9);
    EXPECT_EQ(s.scene().particles().position[ellipsoid], Vec3::Zero());
    EXPECT_LT(s.scene().particles().velocity[sphere].norm(), 1e-7);
}

// Ellipsoids settling in a box, continued from a restart file two ways: their lasting contacts
// stepped in EllipsoidContactBatch's lanes (forceLanes, on the steps that record no contacts),
// and on the scalar path (every step an output step: each contact is recorded, so the lanes
// hand every contact to the scalar path). The same motion to rounding, with most ellipsoid
// contacts in the lanes. (Restarts continue exactly, so both start from the same state.) Then
// the same with every other particle a plain sphere of the same volume: the lanes take its
// contacts with ellipsoids too (a sphere is the ellipsoid I / r^2 there): about half of all its
// contacts, walls and sphere pairs included.
TEST(SuperquadricSimulation, BatchedEllipsoidContactStepFollowsTheScalarStep) {
    for (const bool mixture : {false, true}) {
        const std::string name = mixture ? "mixture_lanes" : "ellipsoid_lanes";
        SceneSimulation settling;
        settling.setup = [mixture](SceneSimulation& sim) {
            sim.scene().setGravity(Vec3(0, 0, -1));
            const double width = 2.2;
            sim.scene().setDomain(Vec3(0, 0, 0), Vec3(width, width, 6));
            const Superquadric shape = Superquadric::ellipsoid(0.5, 0.25, 0.25);
            const double mass = 6 / pi * shape.volume();
            const auto species =
                sim.scene().addSpecies("grains", 6 / pi, LinearSpringDashpot::fromCollision(0.005, 0.5, mass).withFriction(0.5));
            sim.scene().addOpenBox(Vec3::Zero(), Vec3(width, width, 0), species);  // floor and four sides
            const std::size_t sq = sim.scene().addShape(shape);
            for (int n = 0; n < 20; ++n) {  // five layers of 2 x 2, tilted each its own way
                const int layer = n / 4;
                const Vec3 x(0.55 + 1.1 * (n % 2) + 0.03 * (layer % 2), 0.55 + 1.1 * ((n / 2) % 2), 0.6 + 1.05 * layer);
                if (mixture && (n + layer) % 2 == 1)
                    sim.scene().addParticle(x, std::cbrt(0.5 * 0.25 * 0.25), species);
                else
                    sim.scene().addSuperquadric(x, sq, species, Quat(Eigen::AngleAxisd(0.3 + 0.7 * n, Vec3(1, 2, 3 + n).normalized())));
            }
        };
        settling.settings().name = name;
        settling.settings().timeStep = 1e-4;
        settling.solveOrThrow({"--end-time", "12", "--output-interval", "12"});

        auto continued = [&name](const char* outputInterval, std::size_t& inLanes, std::size_t& contacts) {
            SceneSimulation s;
            s.afterStep = [&](SceneSimulation& sim) {
                inLanes += sim.contactSummary().contactsInLanes;
                contacts += sim.contactSummary().contacts;
            };
            s.solveOrThrow({"--restart", name + ".restart", "--end-time", "12.5", "--output-interval", outputInterval,
                            "--files", "off"});
            std::vector<std::array<Vec3, 3>> motion;  // by id: position, velocity, spin
            for (std::uint64_t id = 0; id < 20; ++id) {
                const std::size_t i = s.scene().slotOf(id);
                motion.push_back({s.scene().particles().position[i], s.scene().particles().velocity[i], s.scene().particles().angularVelocity[i]});
            }
            return motion;
        };
        std::size_t inLanes = 0, contacts = 0, inLanesScalar = 0, contactsScalar = 0;
        const auto lanes = continued("1", inLanes, contacts), scalar = continued("1e-4", inLanesScalar, contactsScalar);
        double worst[3] = {0, 0, 0};
        for (std::size_t n = 0; n < lanes.size(); ++n)
            for (int q = 0; q < 3; ++q) worst[q] = std::max(worst[q], (lanes[n][q] - scalar[n][q]).norm());
        std::printf("[ measured ] settling %s, t in (12, 12.5]: %zu of %zu contacts in the lanes; lanes - scalar: "
                    "position %.1e, velocity %.1e, spin %.1e\n",
                    mixture ? "ellipsoids and spheres" : "ellipsoids", inLanes, contacts, worst[0], worst[1], worst[2]);
        EXPECT_EQ(inLanesScalar, 0u) << name;
        // (The mixture with its ellipsoid pairs alone in the lanes had 12% of its contacts there.)
        EXPECT_GT(inLanes, mixture ? contacts / 3 : contacts / 2) << name;
        EXPECT_LT(worst[0], 1e-9) << name;
        EXPECT_LT(worst[1], 1e-7) << name;
        EXPECT_LT(worst[2], 1e-7) << name;
    }
}
