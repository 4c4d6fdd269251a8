// The passes over the particles' coordinates (Particles/VelocityVerlet.h, Domain::wrap) in each
// lane form (LaneFormTest.h): with AVX-512 they take eight particles at a time in lanes, with
// AVX2 four (the same loop over Math/Lanes.h for both widths), and the last few one by one. Both must give the same results to the bit, whichever path a particle takes: here each
// pass over all particles is compared with the same pass called for one particle at a time
// (which is always the loop), on particles with fixed ones among them, negative zeros and
// coordinates outside the periodic box. (The scalar form has only the loop: not compared.)
#include <cstring>

#include "Boundaries/Domain.h"
#include "LaneFormTest.h"
#include "Particles/VelocityVerlet.h"
#include "Particles/VelocityVerletLanes.h"
#include "TestHelpers.h"

using namespace talus;
namespace form = talus::TALUS_LANES;

namespace {

constexpr std::size_t count = 45;  // five blocks of eight and a tail of five

ParticleStore someParticles() {
    ParticleStore p = test::someParticles(count, 11);
    p.velocity[9] = Vec3(-0.0, 0.0, -0.0);  // x + 0 must keep the sign of zero where fixed
    p.position[2] = Vec3(-0.0, 1, -0.0);
    return p;
}

[[maybe_unused]] bool sameBits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

}  // namespace

#ifdef TALUS_LANE_FORM_HAS_LANES
TALUS_LANE_TEST(VelocityVerlet, KickAndDriftInLanesEqualTheLoopToTheBit) {
    ParticleStore all = someParticles(), oneByOne = someParticles();
    halfKickAndDrift(all, count, 0.37, 0.61);
    for (std::size_t i = 0; i < count; ++i) {
        form::detail::kickAndDriftMobile(oneByOne.position[i].data(), oneByOne.velocity[i].data(), oneByOne.force[i].data(),
                                   &oneByOne.invMass[i], &oneByOne.fixed[i], 1, 0.37, 0.61);
        form::detail::advanceMobile(oneByOne.angularVelocity[i].data(), oneByOne.torque[i].data(), &oneByOne.invInertia[i],
                              &oneByOne.fixed[i], 1, 0.37);
    }
    EXPECT_TRUE(sameBits(all.position, oneByOne.position));
    EXPECT_TRUE(sameBits(all.velocity, oneByOne.velocity));
    EXPECT_TRUE(sameBits(all.angularVelocity, oneByOne.angularVelocity));
    // And the fixed particles did not move.
    const ParticleStore before = someParticles();
    for (std::size_t i = 0; i < count; ++i)
        if (before.fixed[i]) {
            EXPECT_TRUE(std::memcmp(all.position[i].data(), before.position[i].data(), sizeof(Vec3)) == 0) << i;
            EXPECT_TRUE(std::memcmp(all.velocity[i].data(), before.velocity[i].data(), sizeof(Vec3)) == 0) << i;
        }

    halfKick(all, count, 0.29);
    for (std::size_t i = 0; i < count; ++i) {
        form::detail::advanceMobile(oneByOne.velocity[i].data(), oneByOne.force[i].data(), &oneByOne.invMass[i],
                              &oneByOne.fixed[i], 1, 0.29);
        form::detail::advanceMobile(oneByOne.angularVelocity[i].data(), oneByOne.torque[i].data(), &oneByOne.invInertia[i],
                              &oneByOne.fixed[i], 1, 0.29);
    }
    EXPECT_TRUE(sameBits(all.velocity, oneByOne.velocity));
    EXPECT_TRUE(sameBits(all.angularVelocity, oneByOne.angularVelocity));
}

#endif

// Gravity m g on the mobile particles, +0 on the fixed ones, no torque: written out directly.
TALUS_LANE_TEST(VelocityVerlet, ForcesStartFromGravityOnTheMobileParticles) {
    ParticleStore p = someParticles();
    const Vec3 gravity(0.4067366430758002, -0.0, -0.9135454576426009);
    startForcesWithGravity(p, gravity);
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 expected = p.fixed[i] ? Vec3(0.0, 0.0, 0.0) : Vec3(p.mass[i] * gravity.x(), p.mass[i] * gravity.y(),
                                                                      p.mass[i] * gravity.z());
        EXPECT_TRUE(std::memcmp(p.force[i].data(), expected.data(), sizeof(Vec3)) == 0) << i;
        EXPECT_TRUE(p.torque[i] == Vec3::Zero()) << i;
    }
}

#ifdef TALUS_LANE_FORM_HAS_LANES
TALUS_LANE_TEST(VelocityVerlet, WrapInLanesEqualsTheParticleByParticleWrap) {
    Domain domain;
    domain.lo = Vec3(-1, -0.5, -3);
    domain.hi = Vec3(1, 0.5, 3);
    domain.periodic = {true, true, false};
    ParticleStore p = someParticles();  // coordinates in (-2, 2): about half outside along x and y
    p.position[17] = Vec3(1, -0.5, 9);   // on the upper face (wrapped), on the lower (kept), z open
    p.position[30] = Vec3(7.5, -1e-300, 0);  // more than a box length out
    std::vector<Vec3> oneByOne = p.position;
    domain.wrap(p.position.data(), count);
    for (Vec3& x : oneByOne) domain.wrap(x);
    EXPECT_TRUE(sameBits(p.position, oneByOne));
    for (const Vec3& x : p.position) {
        EXPECT_GE(x.x(), -1);
        EXPECT_LT(x.x(), 1);
        EXPECT_GE(x.y(), -0.5);
        EXPECT_LT(x.y(), 0.5);
    }
    EXPECT_EQ(p.position[17].x(), -1);
    EXPECT_EQ(p.position[17].z(), 9);
}
#endif
