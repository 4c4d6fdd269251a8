// The Hertz-Mindlin law (Species/HertzMindlin.h) in whole simulations, driven through
// talus::Simulation, against an independent integration of the same equations of motion
// (HertzImpactReference.h): the restitution of damped central impacts at several speeds, and
// the rebound of oblique impacts on a wall, sliding and sticking.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ContactTestScenes.h"
#include "HertzImpactReference.h"

using namespace talus;
using namespace talus::test;

namespace {

// The reference's local error tolerance, and ten times lower to show that it has converged
// (its error is far below the simulation's).
constexpr double referenceTolerance = 1e-11;
constexpr double entryPhases[] = {0.1, 0.64};  // where the touch falls between two steps

// --- restitution of central impacts ---------------------------------------------------------

// The Tsuji damping gn ~ sqrt(Sn m*) ~ x^(1/4) makes the restitution independent of the impact
// speed: with x = X dmax and t = T dmax/v (dmax ~ v^(4/5)), m* x'' = -K x^(3/2) - gn(x) x' turns
// into an equation for X(T) without v, since K x^(3/2) and gn x' both scale as v^(6/5). (The
// Kuwabara-Kono form, gn ~ x^(1/2), would give an e falling with speed.) Integrated, it is the e
// the law is given, to the reference's accuracy (Antypov & Elliott 2011 chose the factor
// 2 sqrt(5/6) and beta so); the simulation is compared with the integrated number.

HertzImpact centralImpact(const HeadOnCollision& collision, const HertzMindlin& law) {
    HertzImpact impact{};
    impact.effectiveYoungsModulus = law.effectiveYoungsModulus;
    impact.effectiveShearModulus = law.effectiveShearModulus;
    impact.restitution = law.restitution;
    impact.effectiveRadius = collision.withWall()
                                 ? collision.radius
                                 : collision.radius * collision.partnerRadius / (collision.radius + collision.partnerRadius);
    impact.reducedMass = collision.reducedMass();
    impact.normalSpeed = collision.approachSpeed();
    return impact;
}

// The simulation's restitution, worst over the entry phases, against the reference's, at
// dt = elastic duration / stepsPerCollision.
double restitutionError(HeadOnCollision collision, double referenceRestitution, double elasticDuration,
                        double stepsPerCollision) {
    collision.timeStep = elasticDuration / stepsPerCollision;
    collision.longestDuration = 1.5 * elasticDuration;
    double worst = 0;
    for (double phase : entryPhases) {
        collision.entryPhase = phase;
        worst = std::max(worst, std::abs(collision.run().restitution - referenceRestitution));
    }
    return worst;
}

}  // namespace

TEST(HertzMindlin, RestitutionOfCentralImpactsIsTheIntegratedLawsAtEverySpeed) {
    for (double e : {0.5, 0.9}) {
        double firstReference = NAN;
        for (double speed : {0.3, 1.0, 3.0}) {
            for (bool withWall : {false, true}) {
                if (withWall && speed != 1.0) continue;
                HeadOnCollision collision;
                if (withWall) collision.partnerRadius = 0;
                collision.speed = withWall ? speed : 0.6 * speed;
                collision.partnerSpeed = 0.4 * speed;
                HertzMindlin law = HertzMindlin::fromMaterial(2e6, 0.3, e);
                law.characteristicVelocity = collision.approachSpeed();  // the time-step check's speed
                collision.law = law;

                HertzImpactReference reference(centralImpact(collision, law));
                const HertzImpactOutcome coarse = reference.integrate(referenceTolerance);
                const HertzImpactOutcome fine = reference.integrate(referenceTolerance / 10);
                const double expected = fine.normalSpeedAfter / collision.approachSpeed();
                const double referenceError = std::abs(coarse.normalSpeedAfter / collision.approachSpeed() - expected);
                if (std::isnan(firstReference)) firstReference = expected;

                const double tc = reference.elasticDuration();
                const double error50 = restitutionError(collision, expected, tc, 50);
                const double error100 = restitutionError(collision, expected, tc, 100);
                std::printf("[ measured ] Hertz e = %.2f, %s, v = %.1f: reference e %.10f (converged to %.1e), "
                            "simulation error %.2e at tc/50, %.2e at tc/100\n",
                            e, withWall ? "sphere-wall" : "sphere-sphere", collision.approachSpeed(), expected,
                            referenceError, error50, error100);
                EXPECT_LT(referenceError, 1e-10);
                EXPECT_NEAR(expected, firstReference, 1e-10) << "the Tsuji restitution does not depend on speed";
                EXPECT_NEAR(expected, e, 1e-9);
                // Measured 2.5e-3 (e = 0.5) and 6.4e-4 (e = 0.9) at tc/50, 4.9e-4 and 6.5e-5 at
                // tc/100, at every speed: the error falls as dt^2.3 to dt^3.3, so it is the time
                // step's. (The dashpot force ~ x^(1/4) x' starts with an unbounded slope, which
                // Verlet's second order does not see, unlike the linear law's treated jump.)
                EXPECT_LT(error50, 4e-3) << "e = " << e << ", v = " << speed;
                EXPECT_LT(error100, 8e-4) << "e = " << e << ", v = " << speed;
                EXPECT_LT(error100, error50 / 4) << "e = " << e << ", v = " << speed;
            }
        }
    }
}

// --- oblique impacts on a wall ---------------------------------------------------------------

namespace {

// A sphere (radius 1/2, mass 1, I = 2/5 m r^2) without spin hits the wall z = 0 with velocity
// (vt0, 0, -vn0), elastic (e = 1, so no dashpots) with friction mu (HertzImpactReference.h).
constexpr double sphereRadius = 0.5, wallFriction = 0.3, impactSpeed = 0.5;

HertzMindlin obliqueLaw() {
    HertzMindlin law = HertzMindlin::fromMaterial(2e6, 0.3, 1.0).withFriction(wallFriction);
    law.characteristicVelocity = impactSpeed;
    return law;
}

HertzImpact obliqueImpact(double tangentialSpeed) {
    const HertzMindlin law = obliqueLaw();
    HertzImpact impact{};
    impact.effectiveYoungsModulus = law.effectiveYoungsModulus;
    impact.effectiveShearModulus = law.effectiveShearModulus;
    impact.friction = wallFriction;
    impact.effectiveRadius = sphereRadius;
    impact.reducedMass = sphereMass(sphereRadius);
    impact.radius = sphereRadius;
    impact.inertia = 0.4 * impact.reducedMass * sphereRadius * sphereRadius;
    impact.normalSpeed = impactSpeed;
    impact.tangentialSpeed = tangentialSpeed;
    return impact;
}

struct Rebound {
    double vx, wy, vz;
    double contactPointSpeed() const { return vx - sphereRadius * wy; }  // vtc = vx - r wy in free flight
};

Rebound simulatedRebound(double tangentialSpeed, double timeStep, double duration) {
    TestScene scene;
    scene.setup = [&](TestScene& s) {
        s.scene().setGravity(Vec3::Zero());
        s.scene().setDomain(Vec3(-1, -1, -1), Vec3(2, 1, 1));
        const auto species = s.scene().addSpecies("solid", unitMassDensity, obliqueLaw());
        s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species);
        // The touch falls 0.37 of a step after the fifth step.
        s.scene().addParticle(Vec3(0, 0, sphereRadius + 5.37 * impactSpeed * timeStep), sphereRadius, species,
                      Vec3(tangentialSpeed, 0, -impactSpeed));
    };
    scene.runFor(timeStep, 5.37 * timeStep + 1.5 * duration);
    const ParticleStore& p = scene.scene().particles();
    return {p.velocity[0].x(), p.angularVelocity[0].y(), p.velocity[0].z()};
}

}  // namespace

// Steep impacts slide from the touch to the separation: 6 G*/E* vtc0/vn0 > mu (the header of
// HertzImpactReference.h), and the sliding contact point does not come to rest, since Coulomb
// takes at most 7/2 mu (1 + e) vn0 = 1.05 vn0 from vtc0 (a solid sphere: 1/m + r^2/I = 7/(2m)),
// so vt0/vn0 >= 3 keeps it sliding. Every step's tangential force is then mu times its normal
// force, so the tangential impulse is mu times the normal one, m (vn0 + vn') (Coulomb), to
// round-off whatever the time step, and with e = 1 vx' = vt0 - 2 mu vn0. The spin, whose lever
// r - x/2 changes with the overlap, and the same velocities are compared with the reference.
TEST(HertzMindlin, SteepObliqueImpactSlidesWithTheCoulombImpulse) {
    for (double ratio : {3.0, 5.0, 10.0}) {
        const double vt0 = ratio * impactSpeed;
        HertzImpactReference reference(obliqueImpact(vt0));
        const HertzImpactOutcome expected = reference.integrate(referenceTolerance);
        ASSERT_TRUE(expected.slidAtTouch);
        ASSERT_EQ(expected.phaseChanges, 0) << "vt0/vn0 = " << ratio;
        EXPECT_NEAR(expected.vx, vt0 - 2 * wallFriction * impactSpeed, 1e-9 * vt0);
        const double tc = reference.elasticDuration();
        double errors[2];
        for (int k = 0; k < 2; ++k) {
            const Rebound r = simulatedRebound(vt0, tc / (50 << k), tc);
            EXPECT_NEAR(r.vx, vt0 - wallFriction * (impactSpeed + r.vz), 1e-12) << "vt0/vn0 = " << ratio;
            errors[k] = std::max({std::abs(r.vx - expected.vx) / vt0, std::abs(r.vz - expected.normalSpeedAfter) / impactSpeed,
                                  std::abs(r.wy - expected.wy) * sphereRadius / vt0});
        }
        std::printf("[ measured ] Hertz-Mindlin sliding vt0/vn0 = %.1f: largest error %.2e at tc/50, %.2e at tc/100\n",
                    ratio, errors[0], errors[1]);
        EXPECT_LT(errors[0], 1e-4) << "vt0/vn0 = " << ratio;
        EXPECT_LT(errors[1], 3e-5) << "vt0/vn0 = " << ratio;
    }
}

// Shallow impacts (6 G*/E* vtc0/vn0 < mu) stick at the touch, and Mindlin's spring stores and
// returns the contact point's tangential motion. Unlike the linear law with kt = 2/7 kn
// (ObliqueImpactTest.cc), where the tangential oscillation has the normal one's period and
// vtc reverses exactly, here the tangential stiffness is the faster: 7/2 St against Sn gives
// 7/2 8 G* / (2 E*) = 7 (1 - nu)/(2 - nu) = 2.9 for nu = 0.3, a tangential period 0.59 of the
// normal one; the contact point's velocity turns over and back within the impact, and the
// spring, softening as the contact unloads (St ~ sqrt(x)), lets the contact slide near the end.
// The reference integrates the same equations through these phases (vtc'/vtc0 = 0.95 to 0.93
// for vt0/vn0 = 0.05 to 0.2, one switch to sliding); the simulation's spring, advanced by forward
// Euler (ContactKinematics.h), converges to it at first order in dt.
TEST(HertzMindlin, ShallowObliqueImpactSticksAsTheIntegratedLaw) {
    for (double ratio : {0.05, 0.1, 0.2}) {
        const double vt0 = ratio * impactSpeed;
        HertzImpactReference reference(obliqueImpact(vt0));
        const HertzImpactOutcome expected = reference.integrate(referenceTolerance);
        const HertzImpactOutcome finer = reference.integrate(referenceTolerance / 10);
        ASSERT_FALSE(expected.slidAtTouch);
        const double expectedRestitution = (expected.vx - sphereRadius * expected.wy) / vt0;
        const double referenceError = std::abs((finer.vx - sphereRadius * finer.wy) / vt0 - expectedRestitution);
        const double tc = reference.elasticDuration();
        double errors[2];
        for (int k = 0; k < 2; ++k)
            errors[k] = std::abs(simulatedRebound(vt0, tc / (50 << k), tc).contactPointSpeed() / vt0 - expectedRestitution);
        std::printf("[ measured ] Hertz-Mindlin sticking vt0/vn0 = %.2f: vtc'/vtc0 = %.6f (reference, converged to "
                    "%.1e, %d phase changes); simulation error %.2e at tc/50, %.2e at tc/100\n",
                    ratio, expectedRestitution, referenceError, expected.phaseChanges, errors[0], errors[1]);
        EXPECT_LT(referenceError, 1e-9);
        EXPECT_EQ(expected.phaseChanges, 1) << "vt0/vn0 = " << ratio;
        // Measured 2.7e-2, 2.7e-2, 1.4e-2 at tc/50 and half that at tc/100 (first order).
        EXPECT_LT(errors[0], 4e-2) << "vt0/vn0 = " << ratio;
        EXPECT_LT(errors[1], errors[0] / 1.7) << "vt0/vn0 = " << ratio;
    }
}

// HertzMindlin::fromCollision solves the elastic duration for E*: integrated independently
// (HertzImpactReference, no damping), the collision of the given masses and radii at the given
// speed lasts the given time; at another speed tc scales as v^(-1/5).
TEST(HertzMindlin, FromCollisionLastsTheGivenTimeAtTheGivenSpeed) {
    const double tc = 4.97e-3, reducedMass = 0.5, effectiveRadius = 0.25;
    for (double speed : {0.3, 1.0, 4.0}) {
        const HertzMindlin law = HertzMindlin::fromCollision(tc, 0.88, reducedMass, effectiveRadius, speed, 0.3);
        EXPECT_EQ(law.characteristicVelocity, speed);
        EXPECT_NEAR(law.restitution, 0.88, 0);
        // Two equal materials: G* / E* = (1 - nu) / (2 (2 - nu)) (Theory/ContactLaws.md eq. (20a)).
        EXPECT_NEAR(law.effectiveShearModulus / law.effectiveYoungsModulus, (1 - 0.3) / (2 * (2 - 0.3)), 1e-14);
        for (double at : {speed, 2 * speed}) {
            HertzImpact impact{};
            impact.effectiveYoungsModulus = law.effectiveYoungsModulus;
            impact.effectiveShearModulus = law.effectiveShearModulus;
            impact.effectiveRadius = effectiveRadius;
            impact.reducedMass = reducedMass;
            impact.normalSpeed = at;
            const double duration = HertzImpactReference(impact).integrate(referenceTolerance).duration;
            EXPECT_NEAR(duration, tc * std::pow(at / speed, -0.2), 1e-8 * tc) << "law at " << speed << ", impact at " << at;
        }
    }
    EXPECT_THROW(HertzMindlin::fromCollision(tc, 0.88, reducedMass, effectiveRadius, 0, 0.3), Error);
}
