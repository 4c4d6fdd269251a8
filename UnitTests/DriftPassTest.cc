// The first half of a step in one pass (Particles/DriftPass.h) against the passes it stands in for
// (Particles/VelocityVerlet.h, Domain::wrap, Contacts/PairSweep.h) and against the definitions of
// what it measures, on particles with fixed ones among them, coordinates outside the periodic box
// and a reference to measure displacements from: five blocks of eight in lanes (with AVX-512) and
// a tail of five. (That the trajectories equal those of the pass-by-pass step to the bit:
// PairListTest.cc, DriftInOnePassChangesNothing.)
#include <algorithm>
#include <cmath>
#include <cstring>

#include "LaneFormTest.h"
#include "Contacts/PairSweepLanes.h"
#include "Particles/DriftPass.h"
#include "Particles/VelocityVerlet.h"
#include "TestHelpers.h"

using namespace talus;
using namespace talus::TALUS_LANES;

namespace {

constexpr std::size_t count = 45;
constexpr double dt = 0.05;

ParticleStore someParticles() { return test::someParticles(count, 7); }

Domain someDomain() {
    Domain domain;
    domain.lo = Vec3(-1, -0.5, -3);
    domain.hi = Vec3(1, 0.5, 3);
    domain.periodic = {true, true, false};
    return domain;
}

bool sameBits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

const Vec3 gravity(0.4067366430758002, -0.0, -0.9135454576426009), frame(0.3, -0.1, 0.05);

// The reference of the list's displacements: the wrapped positions a little while ago.
std::vector<Vec3> wrappedReference(const Domain& domain) {
    std::vector<Vec3> reference = someParticles().position;
    for (Vec3& x : reference) domain.wrap(x);
    return reference;
}

void expectSameParticles(const ParticleStore& a, const ParticleStore& b) {
    EXPECT_TRUE(sameBits(a.position, b.position));
    EXPECT_TRUE(sameBits(a.velocity, b.velocity));
    EXPECT_TRUE(sameBits(a.angularVelocity, b.angularVelocity));
    EXPECT_TRUE(sameBits(a.force, b.force));
    EXPECT_TRUE(sameBits(a.torque, b.torque));
}

}  // namespace

TALUS_LANE_TEST(DriftPass, EqualsThePassesItStandsIn) {
    const Domain domain = someDomain();
    ParticleStore onePass = someParticles(), byPasses = someParticles();
    std::vector<Vec3> reference = wrappedReference(domain);  // (some of them across a face:)
    for (std::size_t i = 0; i < count; i += 4) reference[i].x() += reference[i].x() > 0 ? -1.9 : 1.9;
    std::vector<Vec3> previousForce, points3;
    std::vector<SweepPoint> points;
    const DriftPassResult result =
        kickDriftAndStartForces(onePass, previousForce, domain, &reference, gravity, frame, dt, points);

    halfKickAndDrift(byPasses, count, 0.5 * dt, dt);
    domain.wrap(byPasses.position.data(), count);
    const std::vector<Vec3> lastForces = byPasses.force;
    startForcesWithGravity(byPasses, gravity);
    std::vector<SweepPoint> expectedPoints;
    const double expectedGrowth = sweepPointsForStep(byPasses, dt, frame, expectedPoints);

    expectSameParticles(onePass, byPasses);
    EXPECT_TRUE(sameBits(previousForce, lastForces)) << "the last step's forces";
    ASSERT_EQ(points.size(), count);
    const PeriodicImage image(domain);
    double displacement2 = 0, speed2 = 0, direct2 = 0;
    Vec3 velocitySum = Vec3::Zero();
    std::size_t mobile = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3& x = byPasses.position[i];
        EXPECT_TRUE(points[i].x == x.x() && points[i].y == x.y() && points[i].z == x.z()) << i;
        // (The grown radius's sum of squares may round differently from sweepPointsForStep's.)
        EXPECT_NEAR(points[i].radius, expectedPoints[i].radius, 1e-15) << i;
        displacement2 = std::max(displacement2, image.nearest(x - reference[i]).squaredNorm());
        direct2 = std::max(direct2, (x - reference[i]).squaredNorm());
        speed2 = std::max(speed2, byPasses.velocity[i].squaredNorm());
        if (!byPasses.fixed[i]) velocitySum += byPasses.velocity[i], ++mobile;
    }
    EXPECT_NEAR(result.growth, expectedGrowth, 1e-15);
    EXPECT_GT(direct2, 1) << "the test should measure displacements across a face";
    EXPECT_LT(displacement2, 0.25);
    EXPECT_NEAR(result.moves.displacement2, displacement2, 1e-15);
    EXPECT_NEAR(result.moves.speed2, speed2, 1e-14);
    EXPECT_TRUE(result.moves.finite);
    EXPECT_LT((result.meanVelocity - velocitySum / static_cast<double>(mobile)).norm(), 1e-14)
        << "the mean velocity of the mobile particles after the kick";
    EXPECT_EQ(result.positionsBefore, positionSum(someParticles(), count)) << "the checksum of the positions found";
    EXPECT_EQ(result.positionsAfter, positionSum(byPasses, count)) << "and of those left (drifted and wrapped)";
    EXPECT_NE(result.positionsBefore, result.positionsAfter);
}

// A wave's advance of a region (Integration/WaveStepper.cc): the end of one step and the start of
// the next in one pass over some of the slots (from an odd slot, so that lanes and the tail both
// run), against halfKick, the copy of the forces and the pass that kicks with them.
TALUS_LANE_TEST(DriftPass, ClosingAStepInThePassEqualsTheThreePasses) {
    const Domain domain = someDomain();
    ParticleStore onePass = someParticles(), byPasses = someParticles();
    const std::vector<Vec3> reference = wrappedReference(domain);
    const std::size_t first = 3, last = onePass.size() - 1;  // (lanes from an odd slot, and a tail of one)
    std::vector<Vec3> keptOne(count, Vec3(7, 7, 7)), keptByPasses = keptOne;
    std::vector<SweepPoint> pointsOne(count), pointsByPasses(count);
    const DriftPassResult one = closeKickDriftAndStartForces(onePass, keptOne, domain, &reference, gravity, frame, dt,
                                                             pointsOne, first, last);

    halfKick(byPasses, first, last, 0.5 * dt);
    std::copy(byPasses.force.begin() + first, byPasses.force.begin() + last, keptByPasses.begin() + first);
    const DriftPassResult three = kickDriftAndStartForces(byPasses, keptByPasses, domain, &reference, gravity, frame,
                                                          dt, pointsByPasses, first, last);

    expectSameParticles(onePass, byPasses);
    EXPECT_TRUE(sameBits(keptOne, keptByPasses)) << "the forces kicked with, kept (the slots outside untouched)";
    EXPECT_EQ(std::memcmp(pointsOne.data(), pointsByPasses.data(), count * sizeof(SweepPoint)), 0);
    EXPECT_EQ(one.moves.displacement2, three.moves.displacement2);
    EXPECT_EQ(one.moves.speed2, three.moves.speed2);
    EXPECT_EQ(one.growth, three.growth);
    EXPECT_EQ(one.mobile, three.mobile);
    // (And that the kicks happened at all: the velocities moved from the start's.)
    EXPECT_FALSE(sameBits(onePass.velocity, someParticles().velocity));
}

TALUS_LANE_TEST(DriftPass, WithoutAReferenceMeasuresNoDisplacement) {
    ParticleStore p = someParticles();
    std::vector<Vec3> previousForce;
    std::vector<SweepPoint> points;
    const DriftPassResult result =
        kickDriftAndStartForces(p, previousForce, someDomain(), nullptr, Vec3(0, 0, -1), Vec3::Zero(), dt, points);
    EXPECT_EQ(result.moves.displacement2, 0);
    EXPECT_GT(result.moves.speed2, 1);
}

// A NaN or a position or velocity too large to square, in a block of lanes or in the tail, is
// reported as not finite (the list's check then names the particle: PairList::needsRebuild).
TALUS_LANE_TEST(DriftPass, FindsWhatIsNotFinite) {
    for (std::size_t bad : {3u, 21u, 42u}) {
        for (int kind = 0; kind < 3; ++kind) {
            ParticleStore p = someParticles();
            p.fixed[bad] = 0;
            p.invMass[bad] = p.invInertia[bad] = 1;
            if (kind == 0) p.velocity[bad].y() = std::nan("");
            if (kind == 1) p.position[bad].z() = 1e200;  // (z is not periodic: not wrapped)
            if (kind == 2) p.force[bad].x() = INFINITY;
            std::vector<Vec3> previousForce;
            std::vector<SweepPoint> points;
            const DriftPassResult result = kickDriftAndStartForces(p, previousForce, someDomain(), nullptr,
                                                                   Vec3(0, 0, -1), Vec3::Zero(), dt, points);
            EXPECT_FALSE(result.moves.finite) << "particle " << bad << ", kind " << kind;
        }
    }
}

// A NaN of either sign is larger than every number in the running maxima (they compare bit
// patterns as unsigned integers; x86 makes its NaNs with the sign bit set): a fixed particle's
// NaN velocity, which moves no coordinate, still makes the speed and the growth NaN.
TALUS_LANE_TEST(DriftPass, ANegativeNaNWinsTheMaxima) {
    for (std::size_t bad : {3u, 21u, 42u})
        for (double sign : {1.0, -1.0}) {
            ParticleStore p = someParticles();
            p.fixed[bad] = 1;
            p.velocity[bad].x() = std::copysign(std::nan(""), sign);
            std::vector<Vec3> previousForce;
            std::vector<SweepPoint> points;
            const DriftPassResult result = kickDriftAndStartForces(p, previousForce, someDomain(), nullptr,
                                                                   Vec3(0, 0, -1), Vec3::Zero(), dt, points);
            EXPECT_TRUE(std::isnan(result.moves.speed2)) << "particle " << bad << ", sign " << sign;
            EXPECT_TRUE(std::isnan(result.growth)) << "particle " << bad << ", sign " << sign;
            EXPECT_FALSE(result.moves.finite);
        }
}
