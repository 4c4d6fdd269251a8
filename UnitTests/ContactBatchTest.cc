// The batched lasting sphere contacts (Contacts/ContactBatch.h): a batch filled by add, gather
// and compute must give, lane by lane, what the scalar path gives for the same pair (the
// kinematics of contactKinematics and the law's force of a touching pair, as
// ContactForceLoop::pairContact takes them when the batch is not used), for the linear law and
// for Hertz-Mindlin (whose stiffness depends on the pair's effective radius): the force, both
// torques, the advanced spring, the normal force and the overlap. The lanes name particles
// that recur in other lanes, in either role, and alternate between two laws, so a lane that
// gathered another particle's or pair's numbers, or another lane's law, would differ.
// Each lane is also computed as the last of a partial batch, to the same bits.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "LaneFormTest.h"
#include "Contacts/ContactForceLoop.h"

using namespace talus;
using namespace talus::TALUS_LANES;

namespace {

// `count` particles with random velocities, spins, radii and last forces (some fixed partners).
ParticleStore randomParticles(std::mt19937_64& random, std::size_t count, std::vector<Vec3>& previousForce) {
    std::uniform_real_distribution<double> unit(-1, 1), radiusOf(0.4, 0.6);
    ParticleStore p;
    previousForce.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        p.position.push_back(Vec3(unit(random), unit(random), unit(random)) * 10);
        p.velocity.push_back(Vec3(unit(random), unit(random), unit(random)));
        p.angularVelocity.push_back(Vec3(unit(random), unit(random), unit(random)) * 3);
        p.force.push_back(Vec3::Zero());
        p.torque.push_back(Vec3::Zero());
        p.radius.push_back(radiusOf(random));
        p.invMass.push_back(i % 7 == 3 ? 0 : 1 / (1 + unit(random) * 0.5));  // some fixed partners
        previousForce[i] = Vec3(unit(random), unit(random), unit(random)) * 5;
    }
    return p;
}

template <class Law>
void expectLanesEqualTheScalarPath(const Law (&laws)[2]) {
    std::mt19937_64 random(20261204);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0.001, 0.05);
    const std::size_t particles = 20;
    std::vector<Vec3> previousForce;
    const ParticleStore p = randomParticles(random, particles, previousForce);
    const double dt = 1e-4;
    ContactHistories histories;
    histories.assign(ContactBatch::size + 5);
    ContactBatch batch;
    struct Lane {
        std::size_t k;
        std::uint32_t i, j;
        Vec3 d;
    };
    std::vector<Lane> lanes;
    while (!batch.full()) {
        const auto i = static_cast<std::uint32_t>(random() % particles), j = static_cast<std::uint32_t>(random() % particles);
        if (i == j) continue;
        // Touching: the separation xi - xj shorter than ri + rj by a few percent.
        const Vec3 direction = Vec3(unit(random), unit(random), unit(random)).normalized();
        const Vec3 d = direction * (p.radius[i] + p.radius[j]) * (1 - fraction(random));
        const std::size_t k = lanes.size() + 3;  // (places in the list that are not the lane numbers)
        histories.set(k, {Vec3(unit(random), unit(random), unit(random)) * 1e-3, 10 * fraction(random) + 0.01,
                          ContactHistory::touching});
        batch.add(k, i, j, d, p.radius[i], p.radius[j], laws[lanes.size() % 2].lane());
        lanes.push_back({k, i, j, d});
    }
    const ContactBatch given = batch;
    batch.gather(p, previousForce, histories);
    batch.compute<Law>(dt);
    // Every lane also as the last of a partial batch: the same bits (a pair's answer may not
    // depend on its companions; Documentation/Architecture.md, "Determinism").
    for (int last = 0; last + 1 < ContactBatch::size; ++last) {
        ContactBatch partial = given;
        partial.count = last + 1;
        partial.gather(p, previousForce, histories);
        partial.compute<Law>(dt);
        for (double(ContactBatch::*out)[ContactBatch::size] :
             {&ContactBatch::fx, &ContactBatch::fy, &ContactBatch::fz, &ContactBatch::tix, &ContactBatch::tiy,
              &ContactBatch::tiz, &ContactBatch::tjx, &ContactBatch::tjy, &ContactBatch::tjz, &ContactBatch::sx,
              &ContactBatch::sy, &ContactBatch::sz, &ContactBatch::fn, &ContactBatch::overlap})
            ASSERT_EQ((batch.*out)[last], (partial.*out)[last]) << "lane " << last << " of " << last + 1;
    }
    double worst = 0;
    for (std::size_t l = 0; l < lanes.size(); ++l) {
        const auto [k, i, j, d] = lanes[l];
        const Law& law = laws[l % 2];
        const double distance = d.norm(), sumR = p.radius[i] + p.radius[j];
        const Vec3 n = d / distance;
        ContactHistory history = histories.get(k);
        Arms arms;
        ContactKinematics c = contactKinematics(n, sumR - distance, p.radius[i], p.radius[j], p.velocity[i] - p.velocity[j],
                                                p.angularVelocity[i], p.angularVelocity[j], arms);
        c.inverseDistance = 1 / distance;
        c.inverseReducedMass = p.invMass[i] + p.invMass[j];
        c.otherAcceleration = previousForce[i].dot(n) * p.invMass[i] - previousForce[j].dot(n) * p.invMass[j] -
                              history.lastNormalForce * c.inverseReducedMass;
        if constexpr (Law::usesEffectiveRadius) c.effectiveRadius = p.radius[i] * p.radius[j] / sumR;
        const ContactForce f = law.force(c, history, dt);
        const Vec3 force = f.normalForce * n + f.tangentialForce;
        const Vec3 turn = n.cross(f.tangentialForce);
        const int b = static_cast<int>(l);
        const auto near = [&](const Vec3& lane, const Vec3& expected, const char* what) {
            const double error = (lane - expected).norm() / std::max(1.0, expected.norm());
            worst = std::max(worst, error);
            EXPECT_LT(error, 1e-11) << what << " of lane " << l << " (particles " << i << ", " << j << "): " << lane.transpose()
                                    << " against " << expected.transpose();
        };
        near(Vec3(batch.fx[b], batch.fy[b], batch.fz[b]), force, "force on i");
        near(Vec3(batch.tix[b], batch.tiy[b], batch.tiz[b]), -arms.i * turn, "torque on i");
        near(Vec3(batch.tjx[b], batch.tjy[b], batch.tjz[b]), -arms.j * turn, "torque on j");
        near(Vec3(batch.sx[b], batch.sy[b], batch.sz[b]), history.spring, "spring");
        near(Vec3(batch.fn[b], batch.overlap[b], 0), Vec3(f.normalForce, c.overlap, 0), "normal force and overlap");
        EXPECT_GT(f.tangentialForce.norm(), 0) << "a lane without friction would not test the spring";
    }
    std::printf("[ measured ] %s: largest relative difference of %zu lanes from the scalar path: %.3g\n", Law::name,
                lanes.size(), worst);
}

// A batch of frictionless lanes (two laws of friction 0) through the path without friction
// (ContactBatch::frictionless) against the full path: the same force, normal force, overlap and
// (zero) spring to the bit, and the full path's torques exactly zero, so that leaving them out
// adds nothing that was not zero.
template <class Law>
void expectFrictionlessPathEqualsTheFullPath(const Law (&laws)[2]) {
    std::mt19937_64 random(20261207);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0.001, 0.05);
    const std::size_t particles = 20;
    std::vector<Vec3> previousForce;
    const ParticleStore p = randomParticles(random, particles, previousForce);
    ContactHistories histories;
    histories.assign(ContactBatch::size);
    ContactBatch full;
    while (!full.full()) {
        const auto i = static_cast<std::uint32_t>(random() % particles), j = static_cast<std::uint32_t>(random() % particles);
        if (i == j || (p.invMass[i] == 0 && p.invMass[j] == 0)) continue;  // (no pair of two fixed is listed)
        const Vec3 d = Vec3(unit(random), unit(random), unit(random)).normalized() * (p.radius[i] + p.radius[j]) *
                       (1 - fraction(random));
        const auto k = static_cast<std::size_t>(full.count);
        histories.set(k, {Vec3::Zero(), 10 * fraction(random) + 0.01, ContactHistory::touching});
        full.add(k, i, j, d, p.radius[i], p.radius[j], laws[k % 2].lane());
    }
    ASSERT_TRUE(full.template frictionless<Law>());
    ContactBatch cheap = full;
    full.gather(p, previousForce, histories);
    full.compute<Law>(1e-4);
    cheap.gather<true>(p, previousForce, histories);
    cheap.compute<Law, true>(1e-4);
    const auto same = [](const double(&a)[ContactBatch::size], const double(&b)[ContactBatch::size]) {
        return std::memcmp(a, b, sizeof a) == 0;
    };
    EXPECT_TRUE(same(full.fx, cheap.fx) && same(full.fy, cheap.fy) && same(full.fz, cheap.fz)) << "force";
    EXPECT_TRUE(same(full.fn, cheap.fn) && same(full.overlap, cheap.overlap)) << "normal force, overlap";
    for (int l = 0; l < full.count; ++l) {
        EXPECT_EQ(full.sx[l], 0.0) << "lane " << l;
        EXPECT_EQ(cheap.sx[l], 0.0) << "lane " << l;
        for (const double t : {full.tix[l], full.tiy[l], full.tiz[l], full.tjx[l], full.tjy[l], full.tjz[l]})
            EXPECT_EQ(t, 0.0) << "torque of lane " << l;
        EXPECT_GT(std::abs(full.fn[l]), 0) << "lane " << l;
    }
    // A batch with one lane of friction is not frictionless.
    full.law[Law::laneFriction][7] = 0.1;
    EXPECT_FALSE(full.template frictionless<Law>());
}

}  // namespace

TALUS_LANE_TEST(ContactBatch, FrictionlessLanesLeaveOutTheTangentialPartToTheSameBits) {
    const LinearSpringDashpot linear[2] = {LinearSpringDashpot::fromCollision(0.005, 0.88, 0.5).withFriction(0),
                                           LinearSpringDashpot::fromCollision(0.004, 0.6, 0.3).withFriction(0)};
    expectFrictionlessPathEqualsTheFullPath(linear);
    const HertzMindlin hertz[2] = {HertzMindlin::fromCollision(0.005, 0.88, 0.5, 0.25, 1, 0.3).withFriction(0),
                                   HertzMindlin::fromCollision(0.004, 0.6, 0.3, 0.25, 2, 0.2).withFriction(0)};
    expectFrictionlessPathEqualsTheFullPath(hertz);
}

TALUS_LANE_TEST(ContactBatch, LanesEqualTheScalarPathOfEachPair) {
    const LinearSpringDashpot laws[2] = {LinearSpringDashpot::fromCollision(0.005, 0.88, 0.5).withFriction(0.5),
                                         LinearSpringDashpot::fromCollision(0.004, 0.6, 0.3).withFriction(0.2)};
    expectLanesEqualTheScalarPath(laws);
}

TALUS_LANE_TEST(ContactBatch, HertzMindlinLanesEqualTheScalarPathOfEachPair) {
    const HertzMindlin laws[2] = {HertzMindlin::fromCollision(0.005, 0.88, 0.5, 0.25, 1, 0.3).withFriction(0.5),
                                  HertzMindlin::fromCollision(0.004, 0.6, 0.3, 0.25, 2, 0.2).withFriction(0.2)};
    expectLanesEqualTheScalarPath(laws);
}
