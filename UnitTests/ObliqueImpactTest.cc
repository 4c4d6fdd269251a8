// Oblique impact of a sphere on a flat wall, in the spirit of Chung & Ooi (2011) tests 4 and 6:
// elastic normal contact (e = 1), no tangential damping, kt = 2/7 kn, Coulomb friction mu,
// no gravity. Driven through talus::Simulation (Theory/ContactLaws.md eq. (7)-(8) contact law).
//
// The wall is z = 0 with normal +z; the sphere (radius r, mass m, inertia I = 2/5 m r^2) comes
// in with velocity (vt0, 0, -vn0) and no spin. The contact point sits at b = -r z from the
// centre, so its tangential velocity is vtc = vx - r wy. A tangential force -F x on the sphere
// (F > 0) gives torque b x (-F x) = +r F y: friction spins the sphere up positively about y.
//
// Impulses: the normal one is Jn = m (1 + e) vn0. A tangential impulse Jt changes
// vx by -Jt/m and r wy by +r^2 Jt/I = +5/2 Jt/m, hence vtc by -7/2 Jt/m.
//  - Gross sliding (|ft| = mu fn throughout): Jt = mu Jn, so vx' = vt0 - mu (1+e) vn0 and
//    wy' = 5 mu (1+e) vn0 / (2 r). The contact point keeps sliding forward while
//    vtc0 - 7/2 mu (1+e) vn0 >= 0, i.e. vt0/vn0 >= 7/2 mu (1+e) = 7 mu for e = 1.
//  - Sticking: the spring xi obeys xi' = vtc and vtc' = 7/2 ft/m = -7/2 kt xi/m = -kn xi/m when
//    kt = 2/7 kn: the same angular frequency w = sqrt(kn/m) as the normal overlap
//    dn = vn0/w sin(w t). Then xi = vtc0/w sin(w t), and at separation (t = pi/w) vtc' = -vtc0.
//    The ratio |ft|/fn = kt vtc0/(kn vn0) = 2/7 vtc0/vn0 is constant, so the contact sticks the
//    whole time iff vt0/vn0 <= 7/2 mu. Then Jt = 2/7 m vtc0, vx' = 3/7 vt0, wy' = 10/7 vt0/r.
//  - With kt = 2/7 kn there is no partial slip: while sliding, xi = mu fn/kt, and the contact
//    sticks again only when the spring would grow slower than the limit, kt vtc < mu kn dn'.
//    Sliding gives vtc = vtc0 - 7/2 mu vn0 (1 - cos wt) and dn' = vn0 cos wt, so the condition
//    reads 2/7 vtc0 < mu vn0 at every t: a contact that slides at first touch
//    (vt0/vn0 > 7/2 mu) slides to the end, and the gross-sliding result above holds for every
//    vt0/vn0 > 7/2 mu, even where the rigid-body argument (7 mu) would have it stick.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ContactTestScenes.h"

using namespace talus;
using namespace talus::test;

namespace {

constexpr double radius = 0.5;
constexpr double friction = 0.1;
constexpr double collisionTime = 0.005;
constexpr double timeStep = collisionTime / 50;
// A slow normal speed keeps the largest overlap dmax = vn0 tc/pi at 3e-4 r: the kernel's lever
// arm r - dn/2 (the branch vector ends at the middle of the overlap) then changes the spin by
// O(dmax/r), 1e-4 to 2e-4, which the checks below either predict or allow for.
constexpr double normalSpeed = 0.1;
constexpr double largestOverlap = normalSpeed * collisionTime / pi;

struct ObliqueResult {
    double vx, wy;              // after the impact
    int stuckSteps = 0;         // steps in contact with |ft| < mu fn (not at the Coulomb limit)
    int slidingSteps = 0;
};

ObliqueResult impact(double tangentialToNormalRatio) {
    const double mass = sphereMass(radius);
    LinearSpringDashpot law = LinearSpringDashpot::fromCollision(collisionTime, 1.0, mass).withFriction(friction);
    law.tangentialDamping = 0;  // fromCollision with e = 1 gives gt = gn = 0 already; stated for clarity
    const double gap = 5.37 * normalSpeed * timeStep;

    Scene scene;
    scene.setup = [&](Scene& s) {
        s.setGravity(Vec3::Zero());
        s.setDomain(Vec3(-1, -1, -1), Vec3(2, 1, 1));
        const auto species = s.addSpecies("solid", unitMassDensity, law);
        s.addWall(Vec3::UnitZ(), Vec3::Zero(), species);
        s.addParticle(Vec3(0, 0, radius + gap), radius, species,
                      Vec3(tangentialToNormalRatio * normalSpeed, 0, -normalSpeed));
    };
    ObliqueResult result{};
    // With gt = 0 the tangential force is -kt xi; it sits at the Coulomb limit when
    // kt |xi| = mu kn dn (up to round-off), and below it while the contact sticks.
    scene.afterStep = [&](Scene& s) {
        const PairList& list = s.pairList();
        for (std::size_t k = 0; k < list.wallPairs.size(); ++k) {
            const double overlap = radius - s.walls()[list.wallPairs[k].wall].signedDistance(
                                                s.particles().position[list.wallPairs[k].particle]);
            if (overlap <= 0) continue;
            const double tangential = law.tangentialStiffness * list.wallHistory.get(k).spring.norm();
            const double limit = friction * law.normalStiffness * overlap;
            if (tangential < limit * (1 - 1e-9)) ++result.stuckSteps;
            else ++result.slidingSteps;
        }
    };
    scene.run(timeStep, 2 * collisionTime);
    result.vx = scene.particles().velocity[0].x();
    result.wy = scene.particles().angularVelocity[0].y();
    return result;
}

}  // namespace

// Chung & Ooi test 6, gross sliding: vt0/vn0 = 10 mu and 20 mu (>= 7 mu), and 4 mu, 6 mu
// (between 7/2 mu and 7 mu, where kt = 2/7 kn still slides throughout: see the header).
// The spin with the kernel's lever arm r - dn/2: the friction mu kn dn (e = 1, no damping) with
// dn = dmax sin(w t) over 0 < t < pi/w gives the torque impulse
//     int (r - dn/2) mu kn dn dt = r Jt - mu kn dmax^2 pi / (4 w),   Jt = mu kn 2 dmax / w,
// so wy' is the rigid-sphere value times 1 - (pi/8) dmax/r (1.25e-4 here).
// Tolerances: vx is off only by the error of the normal impulse (the restitution of the treated
// contact ends, ~1e-6 at dt = tc/50; measured at most 5.6e-8 here, 3.5e-9 at tc/100), and the
// spin by that and the lever arm's O(dmax^2) remainder; neither is round-off.
TEST(ObliqueImpact, GrossSlidingFollowsCoulombImpulse) {
    const double e = 1;
    for (double ratio : {4 * friction, 6 * friction, 10 * friction, 20 * friction}) {
        const ObliqueResult r = impact(ratio);
        const double vt0 = ratio * normalSpeed;
        const double expectedVx = vt0 - friction * (1 + e) * normalSpeed;
        const double rigidWy = 5 * friction * (1 + e) * normalSpeed / (2 * radius);
        const double expectedWy = rigidWy * (1 - pi / 8 * largestOverlap / radius);
        std::printf("[ measured ] sliding vt0/vn0 = %.2f: vx error %.2e, wy error %.2e (%.2e against the rigid-sphere "
                    "value), stuck steps %d\n",
                    ratio, std::abs(r.vx / expectedVx - 1), std::abs(r.wy / expectedWy - 1), std::abs(r.wy / rigidWy - 1),
                    r.stuckSteps);
        EXPECT_NEAR(r.vx / expectedVx, 1, 1e-6) << "vt0/vn0 = " << ratio;
        EXPECT_NEAR(r.wy / expectedWy, 1, 1e-6) << "vt0/vn0 = " << ratio;
        EXPECT_EQ(r.stuckSteps, 0) << "vt0/vn0 = " << ratio;
    }
}

// Chung & Ooi test 4 regime, sticking: vt0/vn0 = mu and 3 mu (<= 7/2 mu): the contact point's
// tangential velocity reverses, vtc' = -vtc0. What is left is the lever arm r - dn/2 again: it
// shortens the arm by up to dmax/2 and so detunes the tangential oscillation from the normal
// one, by O(dmax/r): measured 1.7e-4 (vtc'), 2.3e-4 (vx') and 5e-5 (wy'), the same at dt = tc/100
// (not the time step's error). The tolerance 1e-3 is four times the largest.
TEST(ObliqueImpact, StickingReversesContactPointVelocity) {
    for (double ratio : {1 * friction, 3 * friction}) {
        const ObliqueResult r = impact(ratio);
        const double vt0 = ratio * normalSpeed;
        const double contactPointVelocity = r.vx - radius * r.wy;
        std::printf("[ measured ] sticking vt0/vn0 = %.2f: vtc'/vtc0 = %.6f, vx'/(3/7 vt0) = %.6f, "
                    "wy'/(10/7 vt0/r) = %.6f, sliding steps %d\n",
                    ratio, contactPointVelocity / vt0, r.vx / (3.0 / 7.0 * vt0), r.wy / (10.0 / 7.0 * vt0 / radius),
                    r.slidingSteps);
        EXPECT_NEAR(contactPointVelocity / vt0, -1, 1e-3) << "vt0/vn0 = " << ratio;
        EXPECT_NEAR(r.vx / (3.0 / 7.0 * vt0), 1, 1e-3) << "vt0/vn0 = " << ratio;
        EXPECT_NEAR(r.wy / (10.0 / 7.0 * vt0 / radius), 1, 1e-3) << "vt0/vn0 = " << ratio;
        // Below 7/2 mu the gross-sliding impulse mu (1 + e) m vn0 is not reached.
        EXPECT_LT(r.vx, ratio * normalSpeed) << "vt0/vn0 = " << ratio;
        EXPECT_LT(ratio * normalSpeed - r.vx, friction * 2 * normalSpeed) << "vt0/vn0 = " << ratio;
        // Stuck in (nearly) every step: only the last steps, where fn and ft both vanish, may
        // touch the limit through discretisation.
        EXPECT_GT(r.stuckSteps, 0.9 * (r.stuckSteps + r.slidingSteps)) << "vt0/vn0 = " << ratio;
    }
}
