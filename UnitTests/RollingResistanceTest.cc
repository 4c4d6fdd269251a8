// Rolling resistance (Species/LinearSpringDashpotRolling.h, Theory/ContactLaws.md "Rolling
// resistance"), driven through talus::Simulation: a sphere rolling on a plane stops where the
// law predicts, rolls on without it, feels no rolling torque in a normal collision, and a
// restart continues its rolling spring exactly.
//
// The rolling sphere (radius R, mass m, I = 2/5 m R^2) on a wall z = 0 under gravity -g z, moving
// along +x and spinning about +y so that its contact point is at rest. Forces on it: the normal
// force N = m g, the friction force F along x at the contact point, at the arm b below the
// centre, and the rolling torque M along y. Its cap, reached at once (below), is mu_r Rr N with
// Rr = R against a wall (eq. (21)), opposing the spin: M = -mu_r R N. Then
//     m v' = F,   I w' = -b F + M   (the torque of F at -b z is -b F y),
// and rolling without slip, v = b w, gives v' (I/b + m b) = M, so the sphere decelerates at
//     a = mu_r R N b / (I + m b^2)   [= 5/7 mu_r g for b = R],
// needing |F| = m a <= mu N (mu = 0.5 here, 5/7 mu_r = 0.14: it rolls). The kernel's arm is
// b = R - dn/2 (the middle of the overlap dn = m g / kn), which the expected value keeps exactly
// (it moves a by 1.4e-6). It stops after v0^2 / (2 a).
// What the ideal model leaves out:
//  - the rolling spring phase: the torque grows from 0 to the cap while the spring stretches to
//    xr = mu_r N / kr at the rolling speed vr = R w0. A rolling-force impulse D short of the
//    ideal one leaves the sphere a speed a D / (mu_r N) faster for the rest of its run, v0 / a:
//    it goes v0 D / (mu_r N) further. In continuous time D = mu_r N (xr / vr) / 2, at most
//    xr / 2 further. In the steps, the spring is advanced before the first force is applied
//    (forward Euler of eq. (23)), so the rolling force of step n is Fn = min(cap, (n + 1) kr vr dt),
//    acting over dt (half of it for n = 0, the run's first half kick): D = sum of (cap - Fn) times
//    that. The expected distance adds v0 D / (mu_r N);
//  - the tangential spring: the contact point is held by a spring stretched by F / kt = m a / kt,
//    which the centre's position carries: the tolerance;
//  - the stop is taken at the first step with v <= 0: within a dt^2 = 1.4e-9 of it (a fraction of
//    the tolerance).
// The test's rolling stiffness is a hundredth of kt so that the spring phase lasts several steps
// (xr = 1.7e-4 at v0 = 0.5: 3.4 steps) and its D is much larger than the tolerance (it moves the
// stop by 4.4e-5, the tolerance is 1.2e-6): a rolling spring applied a step late or early, or
// without its cap, fails.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "ContactTestScenes.h"
#include "IO/RestartFile.h"

using namespace talus;
using namespace talus::test;

namespace {

constexpr double radius = 0.5;
constexpr double collisionTime = 0.005;
constexpr double timeStep = collisionTime / 50;
constexpr double friction = 0.5;

LinearSpringDashpotRolling rollingLaw(double rollingFriction) {
    const auto base = LinearSpringDashpot::fromCollision(collisionTime, 0.5, sphereMass(radius)).withFriction(friction);
    return LinearSpringDashpotRolling::of(base, base.tangentialStiffness / 100, 0, rollingFriction);
}

// A sphere rolling without slip along +x at speed v0 on the plane z = 0, resting at its static
// overlap (so that the normal spring does not bounce).
template <class Law>
void rollingSphere(TestScene& s, const Law& law, double v0) {
    const double overlap = sphereMass(radius) / law.normalStiffness;
    s.scene().setGravity(Vec3(0, 0, -1));
    s.scene().setDomain(Vec3(-1, -1, -1), Vec3(10, 1, 1));
    const auto species = s.scene().addSpecies("solid", unitMassDensity, law);
    s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species);
    const double arm = radius - overlap / 2;
    s.scene().addParticle(Vec3(0, 0, radius - overlap), radius, species, Vec3(v0, 0, 0), Vec3(0, v0 / arm, 0));
}

struct Stop {
    double distance = NAN;  // x at the first step with vx <= 0
    double time = NAN;
};

Stop runUntilStop(const LinearSpringDashpotRolling& law, double v0, double endTime) {
    TestScene scene;
    scene.setup = [&](TestScene& s) { rollingSphere(s, law, v0); };
    Stop stop;
    scene.afterStep = [&](TestScene& s) {
        if (std::isnan(stop.time) && s.scene().particles().velocity[0].x() <= 0)
            stop = {s.scene().particles().position[0].x(), s.time()};
    };
    scene.runFor(timeStep, endTime);
    return stop;
}

std::size_t stretchedRollingSprings(const ContactHistories& history) {
    std::size_t n = 0;
    for (std::size_t k = 0; k < history.size(); ++k) n += !history.get(k).rollingSpring.isZero(0);
    return n;
}

}  // namespace

TEST(RollingResistance, RollingSphereStopsWhereTheLawPredicts) {
    const double v0 = 0.5, rollingFriction = 0.2;
    const auto law = rollingLaw(rollingFriction);
    const double m = sphereMass(radius), g = 1, normalForce = m * g;
    const double arm = radius - 0.5 * m * g / law.normalStiffness;
    const double inertia = 0.4 * m * radius * radius;
    const double deceleration = rollingFriction * radius * normalForce * arm / (inertia + m * arm * arm);
    const double cap = rollingFriction * normalForce, rollingSpeed = radius * v0 / arm;
    double shortfall = 0;  // D
    for (int n = 0; (n + 1) * law.rollingStiffness * rollingSpeed * timeStep < cap; ++n)
        shortfall += (n == 0 ? 0.5 : 1) * timeStep * (cap - (n + 1) * law.rollingStiffness * rollingSpeed * timeStep);
    const double springPhase = v0 * shortfall / cap;
    const double expected = v0 * v0 / (2 * deceleration) + springPhase;
    const double tolerance = m * deceleration / law.tangentialStiffness + timeStep * timeStep;

    const Stop stop = runUntilStop(law, v0, 1.2 * v0 / deceleration);
    ASSERT_FALSE(std::isnan(stop.time)) << "the sphere did not stop";
    std::printf("[ measured ] stopping distance %.9f, expected %.9f (a = %.9f of 5/7 mu_r g; spring phase %.2e), "
                "error %.2e, tolerance %.2e\n",
                stop.distance, expected, deceleration / (5.0 / 7.0 * rollingFriction * g), springPhase,
                stop.distance - expected, tolerance);
    EXPECT_NEAR(stop.distance, expected, tolerance);
    EXPECT_NEAR(stop.time, v0 / deceleration + shortfall / cap, timeStep);  // (the first step past the stop)
}

// Without rolling friction the law is LinearSpringDashpot to the bit: the sphere rolls on at v0.
TEST(RollingResistance, WithoutRollingFrictionTheSphereKeepsRolling) {
    const double v0 = 0.5, duration = 1;
    TestScene rolling, plain;
    rolling.setup = [&](TestScene& s) { rollingSphere(s, rollingLaw(0), v0); };
    plain.setup = [&](TestScene& s) { rollingSphere(s, static_cast<const LinearSpringDashpot&>(rollingLaw(0)), v0); };
    rolling.runFor(timeStep, duration);
    plain.runFor(timeStep, duration);
    expectSameParticles(rolling.scene().particles(), plain.scene().particles());
    const ParticleStore& p = rolling.scene().particles();
    std::printf("[ measured ] without rolling friction: speed change %.2e after t = %g\n", p.velocity[0].x() / v0 - 1,
                duration);
    EXPECT_NEAR(p.velocity[0].x(), v0, 1e-9);
    EXPECT_NEAR(p.position[0].x(), v0 * duration, 1e-9);
}

// A head-on collision, and one of a sphere spinning about the line of centres: the rolling
// velocity Rr (wi - wj) x n is zero in both, so no rolling torque acts, to the bit.
TEST(RollingResistance, NoRollingTorqueInANormalCollision) {
    for (const double spin : {0.0, 5.0}) {
        TestScene scene;
        scene.setup = [&](TestScene& s) {
            s.scene().setGravity(Vec3::Zero());
            s.scene().setDomain(Vec3(-1, -1, -1), Vec3(3, 1, 1));
            const auto species = s.scene().addSpecies("solid", unitMassDensity, rollingLaw(0.5));
            s.scene().addParticle(Vec3(0, 0, 0), radius, species, Vec3(1, 0, 0), Vec3(spin, 0, 0));
            s.scene().addParticle(Vec3(1.01, 0, 0), radius, species, Vec3(-1, 0, 0));
        };
        double largestTorque = 0;
        bool touched = false;
        scene.afterStep = [&](TestScene& s) {
            touched = touched || s.scene().particles().force[0].norm() > 0;
            for (int i = 0; i < 2; ++i) largestTorque = std::max(largestTorque, s.scene().particles().torque[i].norm());
        };
        scene.runFor(timeStep, 0.05);
        ASSERT_TRUE(touched);
        EXPECT_EQ(largestTorque, 0) << "spin " << spin;
        EXPECT_EQ(scene.scene().particles().angularVelocity[0], Vec3(spin, 0, 0));
        EXPECT_EQ(scene.scene().particles().angularVelocity[1], Vec3::Zero());
        EXPECT_LT(scene.scene().particles().velocity[0].x(), 0);  // it did bounce
    }
}

// A run saved while the sphere rolls (its rolling spring stretched) and restarted continues as
// the uninterrupted run, to the bit; the file keeps the rolling spring.
TEST(RollingResistance, RestartContinuesTheRollingSpringExactly) {
    // The rolling sphere with a second one, spinning the other way, on top: a wall contact and a
    // pair contact with rolling springs. Each starts at its static overlap (the lower one carries
    // both weights).
    const auto setup = [](TestScene& s) {
        s.settings().timeStep = timeStep;
        const auto law = rollingLaw(0.2);
        const double weightOverlap = sphereMass(radius) / law.normalStiffness, v0 = 0.5;
        s.scene().setGravity(Vec3(0, 0, -1));
        s.scene().setDomain(Vec3(-1, -1, -1), Vec3(10, 1, 3));
        const auto species = s.scene().addSpecies("solid", unitMassDensity, law);
        s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species);
        const double lower = radius - 2 * weightOverlap;
        s.scene().addParticle(Vec3(0, 0, lower), radius, species, Vec3(v0, 0, 0), Vec3(0, v0 / lower, 0));
        s.scene().addParticle(Vec3(0, 0, lower + 2 * radius - weightOverlap), radius, species, Vec3::Zero(), Vec3(0, -3, 0));
    };
    const int saved = 300, total = 600;
    TestScene first;
    first.setup = setup;
    first.settings().name = "rollingresistance_restart";
    first.solveOrThrow({"--end-time", std::to_string(saved * timeStep), "--output-interval",
                        std::to_string(saved * timeStep)});
    ASSERT_TRUE(first.state().pairList.history.hasRollingSprings());
    ASSERT_GT(stretchedRollingSprings(first.state().pairList.wallHistory), 0u);
    ASSERT_GT(stretchedRollingSprings(first.state().pairList.history), 0u);

    SimulationState read;
    readRestartFile("rollingresistance_restart.restart", read);
    ASSERT_TRUE(read.pairList.wallHistory.hasRollingSprings());
    EXPECT_TRUE(sameBits(read.pairList.wallHistory, first.state().pairList.wallHistory));
    EXPECT_TRUE(sameBits(read.pairList.history, first.state().pairList.history));

    // A bad rolling parameter in the file is named (species line: name, density, law, its nine
    // parameters; the rolling damping is the eleventh token).
    std::string text = readWholeFile("rollingresistance_restart.restart");
    const std::size_t speciesLine = text.find('\n', text.find("\nspecies ") + 1) + 1;
    std::size_t at = speciesLine;
    for (int token = 0; token < 10; ++token) at = text.find(' ', text.find_first_not_of(' ', at));
    const std::size_t end = text.find(' ', at + 1);
    writeWholeFile("rollingresistance_bad.restart", text.replace(at + 1, end - at - 1, "x"));
    expectError([] { SimulationState state; readRestartFile("rollingresistance_bad.restart", state); },
                {"rollingresistance_bad.restart line", "bad number 'x' for rolling damping"});

    TestScene restarted;
    restarted.solveOrThrow({"--restart", "rollingresistance_restart.restart", "--end-time",
                            std::to_string(total * timeStep), "--files", "off"});
    TestScene uninterrupted;
    uninterrupted.setup = setup;
    uninterrupted.solveOrThrow(stepsWithoutFiles(timeStep, total));
    ASSERT_EQ(restarted.step(), static_cast<std::uint64_t>(total));
    expectSameContinuation(restarted, uninterrupted);
}
