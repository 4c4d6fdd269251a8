// Checks of the rotating-drum driver (Theory/RotatingDrum.md eq. (3)-(4)) on small drums: the wall
// turns as a rigid body at w, the bed is at rest when it starts, no particle is lost, a single
// sphere is carried as the mechanics of rolling predicts, and bad flags are named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "DrumAnalysis.h"
#include "RotatingDrum.h"

using namespace talus;

namespace {

// The drum with a check after every step of the driver's own actions.
class CheckedDrum : public RotatingDrum {
public:
    std::function<void(CheckedDrum&)> check;
    std::function<void(CheckedDrum&)> afterSetup;

    void runWith(std::vector<std::string> flags) {
        flags.insert(flags.end(), {"--files", "off", "--progress-interval", "1e9"});
        settings().name = "RotatingDrumTest";
        settings().timeStep = collisionTime / 50;
        solveOrThrow(flags);
    }

protected:
    void setupInitialConditions() override {
        RotatingDrum::setupInitialConditions();
        if (afterSetup) afterSetup(*this);
    }
    void actionsAfterTimeStep() override {
        RotatingDrum::actionsAfterTimeStep();
        if (check) check(*this);
    }
};

std::string errorOf(const std::vector<std::string>& flags) {
    CheckedDrum drum;
    try {
        drum.runWith(flags);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// The wall's particles turn by x <- R x each step (PrescribedMotion::moved, centre 0), with R the
// rotation by theta = |w| dt about y computed once per step from the library's cos and sin
// (c, s, each within one ulp: relative error 2u, u = 2^-53), and get the velocity w x x. Round-off
// per step, for a particle at distance rho from the axis (y is untouched: R's middle row is exact):
//  - R in the xz-plane is rho-preserving up to its scale sqrt(c^2 + s^2) = 1 +- 2u, and the
//    product's two roundings per component err by at most 2u (|c x| + |s z|) <= 2u rho each, so
//    |R x| stays within (2 + 2 sqrt 2) u rho < 5u rho of rho;
//  - the angle: the product's error turns x by at most 2 sqrt 2 u; R's angle atan2(s, c) is theta
//    to 4u theta, theta is w dt to 2.5u theta and the reference w dt n to 2u of itself: under
//    3u a step for theta = 5e-5 here.
// After n turning steps, and with the one-off roundings of the measurement (hypot within an ulp
// at the start and now; atan2 twice and the sums of angles of a turn or less, under 40u): the
// radius within (5n + 4) u rho, the angle within (3n + 40) u. A worst-case bound: the rounding
// errors of the steps mostly cancel (measured below), but nothing guarantees that they do. The
// speed is made anew each step from the position, |w x x| = w rho to a few roundings: within 6u w
// rho. (The reference angle counts steps, w dt n, instead of w (t - t0): the time is a sum of steps
// whose rounding would exceed these bounds; with it the angle erred by 8e-13, now by 1.6e-14.)
// Measured over the 21000 turning steps: the radius within 7.0e-13 (0.22 of its bound at worst,
// early in the turn; the bound is 5.2e-11 at the end), the speed within 6e-17 (0.46 of its bound),
// the angle within 1.6e-14 (0.08).
TEST(RotatingDrum, WallTurnsRigidlyAtOmegaAndTheBedIsConserved) {
    constexpr double u = 0x1p-53;  // unit round-off
    CheckedDrum drum;
    struct Start { double radius, angle, y; };
    std::map<std::uint64_t, Start> wall;  // by particle id, at t = 0
    double worstRadius = 0, worstSpeed = 0, worstAngle = 0, restSpeed = -1;
    double worstRadiusOfBound = 0, worstSpeedOfBound = 0, worstAngleOfBound = 0;  // each error / its bound
    std::uint64_t startStep = 0, turningSteps = 0;
    drum.check = [&](CheckedDrum& d) {
        const ParticleStore& p = d.scene().particles();
        const double w = d.rotating() ? d.angularSpeed() : 0;
        if (d.rotating() && startStep == 0) startStep = d.step();
        const std::uint64_t n = d.rotating() ? d.step() - startStep : 0;
        const double turned = w * d.settings().timeStep * static_cast<double>(n);
        turningSteps = n;
        double fastest = 0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            const Vec3& x = p.position[i];
            if (!p.fixed[i]) {
                fastest = std::max(fastest, p.velocity[i].norm());
                continue;
            }
            const double rho = std::hypot(x.x(), x.z()), angle = std::atan2(x.z(), x.x());
            if (d.step() == 1) wall[p.id[i]] = {rho, angle, x.y()};
            const Start& s = wall.at(p.id[i]);
            ASSERT_EQ(x.y(), s.y);
            // Theory/RotatingDrum.md eq. (3)-(4): speed w rho along the circle, the angle advanced
            // by w dt a step.
            const double radiusError = std::abs(rho - s.radius), speedError = std::abs(p.velocity[i].norm() - w * rho),
                         angleError = std::abs(std::remainder(angle - s.angle - turned, 2 * pi));
            worstRadius = std::max(worstRadius, radiusError);
            worstSpeed = std::max(worstSpeed, speedError);
            worstAngle = std::max(worstAngle, angleError);
            worstRadiusOfBound = std::max(worstRadiusOfBound, radiusError / ((5.0 * double(n) + 4) * u * s.radius));
            worstSpeedOfBound = std::max(worstSpeedOfBound, speedError / std::max(6 * u * w * rho, 1e-300));
            worstAngleOfBound = std::max(worstAngleOfBound, angleError / ((3.0 * double(n) + 40) * u));
        }
        if (d.rotating() && restSpeed < 0) restSpeed = fastest;  // the first step of the turning drum
    };
    drum.runWith({"--radius", "4", "--length", "4", "--particles", "30", "--end-time", "40"});
    ASSERT_TRUE(drum.rotating());
    EXPECT_GT(drum.rotations(), 0.1);
    std::printf("[ measured ] wall after %.3f turns (%llu steps): radius drift %.2e, |speed - w r| %.2e, angle error "
                "%.2e, at most %.3f, %.3f and %.3f of their bounds; fastest particle when the drum starts %.2e\n",
                drum.rotations(), static_cast<unsigned long long>(turningSteps), worstRadius, worstSpeed, worstAngle,
                worstRadiusOfBound, worstSpeedOfBound, worstAngleOfBound, restSpeed);
    EXPECT_GT(wall.size(), 200u);
    EXPECT_LE(worstRadiusOfBound, 1);
    EXPECT_LE(worstSpeedOfBound, 1);
    EXPECT_LE(worstAngleOfBound, 1);
    // At rest when it starts: kinetic energy per particle below 1e-4 means speeds below
    // sqrt(2e-4) = 0.014 for mass 1; a moving bed falls at about sqrt(g d) = 1.
    EXPECT_GE(restSpeed, 0);
    EXPECT_LT(restSpeed, std::sqrt(2e-4));
    // Mass conservation: all 30 in the drum, 15 of each kind, each of mass 1 (equal volumes pi/6,
    // density 6/pi: the ellipsoid's 4/3 pi a b^2 = pi/6 R^(2/3) R^(-2/3)).
    const ParticleStore& p = drum.scene().particles();
    int spheres = 0, ellipsoids = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.fixed[i]) continue;
        (p.species[i] == 0 ? spheres : ellipsoids) += 1;
        EXPECT_NEAR(p.mass[i], 1, 1e-12);
        EXPECT_LT(std::hypot(p.position[i].x(), p.position[i].z()), drum.innerRadius());
        EXPECT_GE(p.position[i].y(), 0);
        EXPECT_LT(p.position[i].y(), 4);
    }
    EXPECT_EQ(spheres, 15);
    EXPECT_EQ(ellipsoids, 15);
}

TEST(RotatingDrum, SmoothDrumRollsASphereUpToThePendulumAmplitude) {
    // One sphere (d = 1, s = 1/2) at rest at the bottom of a smooth drum of radius r that starts to
    // turn with surface speed V = w r. While its contact slips, friction's impulse J gives the
    // centre v = J/m and the spin w_s s = J s^2/I = 5J/(2m): the contact point moves at 7J/(2m),
    // and slipping ends when that reaches V, with v = 2V/7 whatever the force's history. Then it
    // rolls: with the contact point moving at V, (r - s) phi' + w_s s = V, so w_s' = -(r - s)
    // phi''/s, friction F = I w_s'/s and m (r - s) phi'' = -m g sin(phi) + F give
    // (7/5)(r - s) phi'' = -g sin(phi): a pendulum, not a climb (no rolling resistance, so friction
    // never has to hold the sphere up). Energy: (7/10) m v^2 = m g (r - s)(1 - cos phi_max), so
    // 1 - cos phi_max = 2 V^2 / (35 g (r - s)) = 2 F r / (35 (r - s)) with V^2 = w^2 r^2 = F g r.
    // (Rolling needs |F| = (2/7) m g sin(phi) <= mu m g cos(phi), tan(phi) <= 3.5 mu: far away.)
    // What the formula leaves out, each a few 1e-4 of the amplitude: the sphere sinks into the
    // wall by m g / kn = 6.6e-4 s, which shortens its lever arm (v = V / (1 + (5/2)(1 - dn/(2s))^2)
    // is (5/7) dn/s = 4.7e-4 faster), and gravity acts during the slip (it ends near
    // t_s = 2V / (7 mu g) = 0.11, after the sphere has climbed 1e-3 rad). Measured: 2.7e-4, so
    // the amplitude is checked to 1e-3. The pendulum starts when the slip ends, about t_s / 2
    // late, so half a period after the drum starts the sphere is still about
    // sin(2 pi (t_s / 2) / T) = 2.6% of the amplitude from the bottom (measured 3.1%): checked to
    // 10%.
    CheckedDrum drum;
    const double r = 4, s = 0.5, froude = 0.01;
    drum.afterSetup = [&](CheckedDrum& d) {
        ParticleStore& p = d.scene().particles();
        for (std::size_t i = 0; i < p.size(); ++i)
            if (!p.fixed[i]) {
                // At the bottom, sunk into the wall by its weight m g / kn (no bounce).
                const double kn = LinearSpringDashpot::fromCollision(RotatingDrum::collisionTime, 0.1, 0.5).normalStiffness;
                p.position[i] = Vec3(0, 1, -(r - s) - 1 / kn);
                p.velocity[i] = Vec3::Zero();
            }
    };
    double phiMax = 0, lastPhi = 0;
    const double period = 2 * pi * std::sqrt(7 * (r - s) / 5);
    drum.check = [&](CheckedDrum& d) {
        if (!d.rotating() || d.time() - d.rotationStartTime() > period / 2) return;
        for (std::size_t i = 0; i < d.scene().particles().size(); ++i)
            if (!d.scene().particles().fixed[i]) {
                const Vec3& x = d.scene().particles().position[i];
                lastPhi = std::atan2(x.x(), -x.z());
                phiMax = std::max(phiMax, lastPhi);
            }
    };
    drum.runWith({"--radius", "4", "--length", "4", "--particles", "1", "--wall", "smooth", "--froude", "0.01",
              "--end-time", "30"});
    ASSERT_TRUE(drum.rotating());
    ASSERT_LT(drum.rotationStartTime(), 30 - period / 2);
    const double expected = std::acos(1 - 2 * froude * r / (35 * (r - s)));
    std::printf("[ measured ] sphere carried to %.7f rad (pendulum amplitude %.7f, relative error %.2e), %.5f half a "
                "period later\n",
                phiMax, expected, phiMax / expected - 1, lastPhi);
    EXPECT_NEAR(phiMax, expected, 1e-3 * expected);
    EXPECT_LT(std::abs(lastPhi), 0.1 * expected);  // back at the bottom after half a period
}

TEST(RotatingDrum, BadFlagsAreNamed) {
    EXPECT_NE(errorOf({"--radius", "2"}).find("--radius 2 is too small"), std::string::npos);
    EXPECT_NE(errorOf({"--fill", "1.5"}).find("--fill must lie in (0, 1)"), std::string::npos);
    EXPECT_NE(errorOf({"--fill", "0"}).find("--fill must lie in (0, 1)"), std::string::npos);
    EXPECT_NE(errorOf({"--aspect", "0.5"}).find("--aspect must be at least 1"), std::string::npos);
    EXPECT_NE(errorOf({"--wall", "bumpy"}).find("--wall must be particles or smooth"), std::string::npos);
    EXPECT_NE(errorOf({"--particles", "5000"}).find("do not fit into the drum"), std::string::npos);
    EXPECT_NE(errorOf({"--froude", "1"}).find("--froude must lie in (0, 1) (F >= 1 centrifuges the bed)"), std::string::npos);
    EXPECT_NE(errorOf({"--rotations", "-1"}).find("--rotations must not be negative"), std::string::npos);
    EXPECT_NE(errorOf({"--sphere-fraction", "1.5"}).find("--sphere-fraction must lie in [0, 1]"), std::string::npos);
}

namespace {

// A bare particle store for the measurements (they read position, mass, species and fixed).
void addPoint(ParticleStore& p, const Vec3& x, std::uint32_t species, bool fixed = false) {
    p.position.push_back(x);
    p.velocity.push_back(Vec3::Zero());
    p.radius.push_back(0.5);
    p.mass.push_back(1);
    p.species.push_back(species);
    p.fixed.push_back(fixed ? 1 : 0);
}

}  // namespace

TEST(DrumAnalysis, SurfaceAngleOfABedUnderAPlane) {
    // Columns of particles every 0.5 in x, the top one on the line z = x tan(30 deg), three more
    // below it: every column's surface particle lies on the line, so the fit is exact. Fixed
    // particles far above (a wall) must not count.
    ParticleStore p;
    const double slope = std::tan(30 * pi / 180);
    for (int k = -10; k <= 10; ++k)
        for (int j = 0; j < 4; ++j) addPoint(p, Vec3(0.5 * k, 0, 0.5 * k * slope - j), k % 2 == 0 ? 0 : 1);
    for (int k = -5; k <= 5; ++k) addPoint(p, Vec3(k, 0, 100 - k), 2, true);
    EXPECT_NEAR(drum::surfaceAngle(p), 30, 1e-9);
    // A flat bed: 0.
    ParticleStore flat;
    for (int k = -10; k <= 10; ++k) addPoint(flat, Vec3(0.5 * k, 0, -2), 0);
    EXPECT_NEAR(drum::surfaceAngle(flat), 0, 1e-12);
}

TEST(DrumAnalysis, MixingIndexOfTwinsAndOfASeparatedCore) {
    // Twins (a sphere and an ellipsoid at every place): phi = 1/2 wherever there is mass,
    // m = -ln 2, M = 1.
    ParticleStore twins;
    for (int k = 0; k < 20; ++k) {
        const Vec3 x(std::cos(k) * 0.2 * k, 0, std::sin(k) * 0.2 * k - 1);
        addPoint(twins, x, 0);
        addPoint(twins, x, 1);
    }
    const drum::MixingIndices mixed = drum::mixingIndices(twins, 0, 6, 48, 1);
    EXPECT_NEAR(mixed.mixing, 1, 1e-12);
    EXPECT_NEAR(std::abs(mixed.segregation), 0, 1e-12);
    // Spheres within 0.5 of the centre, ellipsoids on a ring of radius 4: the kernels (width 1) of
    // the two kinds never meet, phi is 0 or 1 everywhere, M = 0; the spheres are at the core,
    // S = M - 1 = -1.
    ParticleStore core;
    for (int k = 0; k < 8; ++k) addPoint(core, Vec3(0.5 * std::cos(k * pi / 4), 0, 0.5 * std::sin(k * pi / 4)), 0);
    for (int k = 0; k < 40; ++k) addPoint(core, Vec3(4 * std::cos(k * pi / 20), 0, 4 * std::sin(k * pi / 20)), 1);
    const drum::MixingIndices separated = drum::mixingIndices(core, 0, 6, 48, 1);
    EXPECT_NEAR(separated.mixing, 0, 1e-12);
    EXPECT_TRUE(separated.speciesAtCore);
    EXPECT_NEAR(separated.segregation, -1, 1e-12);
    // The same with the kinds swapped: the spheres at the periphery, S = 1 - M = 1.
    const drum::MixingIndices swapped = drum::mixingIndices(core, 1, 6, 48, 1);
    EXPECT_FALSE(swapped.speciesAtCore);
    EXPECT_NEAR(swapped.segregation, 1, 1e-12);
}
