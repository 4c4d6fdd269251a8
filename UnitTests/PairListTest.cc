// The pair list with a skin (Contacts/PairList.h) changes no physics: a trajectory with the
// list rebuilt only when needed equals the one with the list rebuilt every step (skin 0, a fresh
// HGrid search each step), to round-off: only the order in which contact forces are summed differs.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <random>

#include "Contacts/ContactForces.h"
#include "ContactTestScenes.h"
#include "Integration/Integrator.h"

using namespace talus;
using namespace talus::test;

namespace {

// A small periodic chute (Theory/Chutes.md "The rough base"): a jittered base of fixed spheres and
// 150 flowing spheres of two sizes dropped on it with random velocities, inclined at 24 degrees.
LinearSpringDashpot chuteLaw() { return LinearSpringDashpot::fromCollision(0.005, 0.88, 0.25).withFriction(0.5); }

void chuteScene(TestScene& s) {
    s.scene().setDomain(Vec3::Zero(), Vec3(6, 6, 12));
    s.scene().setPeriodic(true, true, false);
    s.scene().setGravity(Vec3(std::sin(degrees(24)), 0, -std::cos(degrees(24))));
    const auto grain = s.scene().addSpecies("grain", unitMassDensity, chuteLaw());
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1), speed(-0.5, 0.5);
    for (int ix = 0; ix < 6; ++ix)
        for (int iy = 0; iy < 6; ++iy) s.scene().addFixedParticle(Vec3(ix + 0.5 + jitter(random), iy + 0.5 + jitter(random), 0.5), 0.5, grain);
    for (int k = 0; k < 150; ++k) {
        const Vec3 x(k % 6 + 0.5, (k / 6) % 6 + 0.5, 1.6 + 1.05 * (k / 36));
        s.scene().addParticle(x, k % 2 ? 0.5 : 0.4, grain, Vec3(speed(random), speed(random), speed(random)));
    }
}

// The chute scene with a setting of its pair list, skin 0.2, run for 3 time units: the bed flows
// down the slope and through the periodic faces.
void runChuteWith(TestScene& s, const std::function<void(StepperTuning&)>& set) {
    s.setup = [set](TestScene& scene) {
        chuteScene(scene);
        set(scene.settings().stepper);
    };
    s.settings().skin = 0.2;
    s.runFor(1e-4, 3);
}

// The particles whose position, velocity or angular velocity differ in any bit.
std::size_t particlesThatDiffer(const ParticleStore& a, const ParticleStore& b) {
    EXPECT_EQ(a.size(), b.size());
    std::size_t different = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        different += !(a.position[i] == b.position[i] && a.velocity[i] == b.velocity[i] &&
                       a.angularVelocity[i] == b.angularVelocity[i]);
    return different;
}

}  // namespace

TEST(PairList, SkinChangesNoPhysics) {
    const double dt = 1e-4;
    TestScene withSkin, everyStep;
    withSkin.setup = everyStep.setup = chuteScene;
    std::size_t contactSteps = 0;
    withSkin.afterStep = [&contactSteps](TestScene& s) { contactSteps += s.contactSummary().contacts; };
    withSkin.settings().skin = 0.2;
    everyStep.settings().skin = 0;
    withSkin.runFor(dt, 1000 * dt);
    everyStep.runFor(dt, 1000 * dt);
    EXPECT_LT(withSkin.state().pairList.builds, 100u);      // the skin saves rebuilds...
    EXPECT_GE(everyStep.state().pairList.builds, 1000u);    // ...which skin 0 does every step
    EXPECT_GT(contactSteps, 20000u);  // and the particles did collide, for many steps
    double position = 0, velocity = 0;
    const auto &a = withSkin.scene().particles(), &b = everyStep.scene().particles();
    for (std::size_t i = 0; i < a.size(); ++i) {
        position = std::max(position, (a.position[i] - b.position[i]).norm());
        velocity = std::max(velocity, (a.velocity[i] - b.velocity[i]).norm());
    }
    std::printf("[ measured ] skin 0.2 vs 0 after 1000 steps: position %.2e, velocity %.2e\n", position, velocity);
    EXPECT_LT(position, 1e-10);
    EXPECT_LT(velocity, 1e-8);
}

// Removing a particle (ParticleStore::removeBySwap moves the last one into its slot) keeps every
// other pair's history under the same two ids and drops the removed particle's pairs; the list
// follows the removal without a build, or (--relist off) the next build carries the springs over:
// without following the removal, a rebuild read the ids of stale slots and gave springs to the
// wrong pairs (or read past the end). Both ways.
TEST(PairList, RemovalKeepsTheOtherPairsHistories) {
    for (const bool relist : {true, false}) {
        SCOPED_TRACE(relist ? "list kept" : "list rebuilt");
        using Key = std::pair<std::uint64_t, std::uint64_t>;
        auto histories = [](const TestScene& s) {
            std::map<Key, ContactHistory> byIds;
            const PairList& l = s.state().pairList;
            const ParticleStore& p = s.scene().particles();
            for (std::size_t k = 0; k < l.pairs.size(); ++k) {
                const std::uint64_t a = p.id[l.pairs[k].i], b = p.id[l.pairs[k].j];
                ContactHistory h = l.history.get(k);
                if (a > b && h.isTouching()) h.spring = -h.spring;  // as seen from the smaller id
                byIds[{std::min(a, b), std::max(a, b)}] = h;
            }
            return byIds;
        };
        std::map<Key, ContactHistory> before;
        std::size_t kept = 0, touching = 0, carried = 0, sticking = 0, springsBeyondTheirBound = 0;
        const double dt = 1e-4;
        TestScene s;
        s.setup = chuteScene;
        s.settings().relist = relist;
        std::uint64_t buildsAtRemoval = 0;
        s.afterStep = [&](TestScene& s) {
            if (s.step() == 300) {
                buildsAtRemoval = s.state().pairList.builds;
                before = histories(s);
                // A mobile particle in a middle slot.
                std::size_t slot = s.scene().particles().size() / 2;
                while (s.scene().particles().fixed[slot]) ++slot;
                const std::uint64_t removedId = s.scene().particles().id[slot];
                s.scene().removeParticle(slot);
                const auto after = histories(s);
                for (const auto& [key, h] : before) {
                    if (key.first == removedId || key.second == removedId) {
                        EXPECT_EQ(after.count(key), 0u);
                        continue;
                    }
                    ASSERT_EQ(after.count(key), 1u);
                    EXPECT_EQ(after.at(key), h);
                    ++kept;
                    touching += h.isTouching() && !h.spring.isZero(0);
                }
                EXPECT_EQ(after.size(), kept);
            }
            // Step 301: the list followed the removal, or (relist off) this step built it anew from
            // the ids, and every pair that touched at step 300 and still touches must have its own
            // spring s0, advanced by one step of the law. That step is forward Euler,
            // s* = s0 + dt (vt - n (s0 . v) / r) (Species/ContactKinematics.h), with the relative
            // velocity v of the centres and the tangential velocity vt at the half step (recomputed
            // below from the end-of-step velocities and forces), so |s* - s0| <= g, where
            // g = dt (|vt| + |v| |s0| / r). A sliding pair's spring is then moved onto the Coulomb
            // limit, s = s* + (1 - mu fn / |f*|) f* / kt for the trial force f* = -(kt s* + gt vt): a
            // move of (|f*| - mu fn) / kt, at most (|kt s0 + gt vt| + kt g - mu fn) / kt. So
            // |s - s0| <= g + max(0, that), times 1 + 1e-9 for round-off. A spring given to the wrong
            // pair, turned the wrong way or lost differs by about its own length, many times the
            // bound for most pairs (measured: 34 of the 40 springs are longer than twice their bound;
            // 39 pairs stick, their |s - s0| is 0.988 to 1.000 of g. The springs are 1.5e-5 to 1.1e-3
            // long: a check of |s - s0| < 1e-3 let them all be halved at the rebuild).
            if (s.step() == 301) {
                EXPECT_EQ(s.state().pairList.builds - buildsAtRemoval, relist ? 0u : 1u);
                const ParticleStore& p = s.scene().particles();
                const PeriodicImage image(s.scene().domain());
                const LinearSpringDashpot law = chuteLaw();
                const double kt = law.tangentialStiffness;
                // The half-step velocities the force loop saw: v(n+1) - (dt/2) F(n+1)/m, w likewise.
                const auto halfStepVelocity = [&](std::size_t i) {
                    return std::pair<Vec3, Vec3>{p.velocity[i] - 0.5 * dt * p.invMass[i] * p.force[i],
                                                 p.angularVelocity[i] - 0.5 * dt * p.invInertia[i] * p.torque[i]};
                };
                for (const auto& [key, h] : histories(s)) {
                    if (!h.isTouching() || !before.count(key) || !before.at(key).isTouching()) continue;
                    const std::size_t i = s.scene().slotOf(key.first), j = s.scene().slotOf(key.second);
                    const auto [vi, wi] = halfStepVelocity(i);
                    const auto [vj, wj] = halfStepVelocity(j);
                    const Vec3 d = image.nearest(p.position[i] - p.position[j]);
                    const double r = d.norm();
                    // The contact point's tangential velocity (Theory/ContactLaws.md eq. (4)): arms
                    // ri - dn/2 and rj - dn/2 along n, vt = v - (v.n) n - (ai wi + aj wj) x n.
                    const Vec3 n = d / r, v = vi - vj;
                    const double halfOverlap = 0.5 * (p.radius[i] + p.radius[j] - r);
                    const Vec3 vt =
                        v - v.dot(n) * n - ((p.radius[i] - halfOverlap) * wi + (p.radius[j] - halfOverlap) * wj).cross(n);
                    const Vec3& carriedSpring = before.at(key).spring;
                    const double growth = dt * (vt.norm() + v.norm() * carriedSpring.norm() / r);
                    const double trialForce = (kt * carriedSpring + law.tangentialDamping * vt).norm() + kt * growth;
                    const double slip = std::max(0.0, trialForce - law.friction * h.lastNormalForce) / kt;
                    const double bound = (growth + slip) * (1 + 1e-9);
                    EXPECT_LE((h.spring - carriedSpring).norm(), bound)
                        << key.first << "-" << key.second << ": spring " << carriedSpring.norm() << " carried";
                    ++carried;
                    sticking += slip == 0;
                    springsBeyondTheirBound += carriedSpring.norm() > 2 * bound;
                }
            }
        };
        s.runFor(dt, 302 * dt);
        std::printf("[ measured ] %s: %zu springs carried over the removal, %zu of them sticking, %zu longer than twice "
                    "their bound\n", relist ? "list kept" : "list rebuilt", carried, sticking, springsBeyondTheirBound);
        EXPECT_GT(touching, 20u);
        EXPECT_GT(carried, 20u);
        EXPECT_GT(springsBeyondTheirBound, 20u) << "the bounds should tell a carried spring from a lost one";
    }
}

// The pairs a build puts first (PairList::interiorPairs) are swept without the nearest periodic
// image (Contacts/PairSweep.h), so their direct difference xi - xj must stay their nearest image
// for every step until the next build, while particles cross the periodic faces and wrap.
TEST(PairList, InteriorPairsNeedNoPeriodicImageUntilTheNextBuild) {
    TestScene s;
    s.setup = chuteScene;
    s.settings().skin = 0.2;
    std::size_t checked = 0, interiorSteps = 0, imageSteps = 0, wraps = 0, violations = 0;
    std::vector<Vec3> before;
    s.afterStep = [&](TestScene& scene) {
        const PairList& list = scene.state().pairList;
        const PeriodicImage image(scene.scene().domain());
        const auto& x = scene.scene().particles().position;
        ASSERT_LE(list.interiorPairs, list.pairs.size());
        for (std::size_t k = 0; k < list.interiorPairs; ++k) {
            const Vec3 d = x[list.pairs[k].i] - x[list.pairs[k].j];
            violations += !(d == image.nearest(d));
            ++checked;
        }
        interiorSteps += list.interiorPairs > 0;
        imageSteps += list.interiorPairs < list.pairs.size();
        for (std::size_t i = 0; i < std::min(before.size(), x.size()); ++i)
            wraps += (x[i] - before[i]).norm() > 3;  // a jump across the 6 x 6 box
        before = x;
    };
    s.runFor(1e-4, 3);  // the bed flows down the slope and through the downstream face
    std::printf("[ measured ] %zu interior pair-steps checked, %zu wraps through a face, %llu builds\n", checked,
                wraps, static_cast<unsigned long long>(s.state().pairList.builds));
    EXPECT_EQ(violations, 0u) << "an interior pair's direct difference was not its nearest image";
    EXPECT_GT(wraps, 20u) << "the test needs particles crossing the periodic faces";
    EXPECT_EQ(interiorSteps, 30000u) << "every step has interior pairs";
    EXPECT_EQ(imageSteps, 30000u) << "and pairs that need the image";
}

// The force loop sweeps the near list (PairList::near: the pairs within a fraction of the skin,
// remade when a particle may have moved far enough) instead of every listed pair. It must pick
// exactly the pairs the whole list's sweep picks, in the same order: the trajectory is the
// same to the bit, through a flow that remakes the near list many times between builds.
TEST(PairList, NearListChangesNothing) {
    TestScene nearList, wholeList;
    runChuteWith(nearList, [](StepperTuning& tuning) { tuning.nearSkinFraction = 0.15; });
    runChuteWith(wholeList, [](StepperTuning& tuning) { tuning.nearSkinFraction = 0; });
    const std::uint64_t makes = nearList.state().pairList.near.makes, builds = nearList.state().pairList.builds;
    std::printf("[ measured ] near list made %llu times in 30000 steps, the list built %llu times\n",
                static_cast<unsigned long long>(makes), static_cast<unsigned long long>(builds));
    EXPECT_EQ(wholeList.state().pairList.near.makes, 0u);
    EXPECT_GT(makes, 2 * builds) << "the near list should be remade between builds";
    EXPECT_LT(makes, 30000u / 4) << "and used for several steps each time";
    EXPECT_EQ(particlesThatDiffer(nearList.scene().particles(), wholeList.scene().particles()), 0u)
        << "particles whose state differs from the whole list's sweep";
}

// A driver's hook that moves a particle by hand between steps (here 0.045 towards a sphere 0.05
// away: outside the near list, within the neighbour list, which it keeps) and sends it on towards
// that sphere: the next step finds the positions changed and makes the near list anew
// (Simulation::checkPositionsFound), so the spheres collide as with the whole list, to the bit.
// (Without that check the near list missed the pair: the spheres overlapped by 0.025 before it
// was remade, against 0.002 with the whole list.)
TEST(PairList, NearListFollowsParticlesMovedByHand) {
    const auto run = [](TestScene& s, double nearSkinFraction) {
        s.setup = [nearSkinFraction](TestScene& scene) {
            scene.scene().setDomain(Vec3(-3, -3, -3), Vec3(3, 3, 3));
            const auto grain =
                scene.scene().addSpecies("grain", unitMassDensity, LinearSpringDashpot::fromCollision(0.005, 0.88, 0.25));
            scene.scene().addParticle(Vec3(0, 0, 0), 0.5, grain);
            scene.scene().addParticle(Vec3(1.05, 0, 0), 0.5, grain);
            scene.settings().stepper.nearSkinFraction = nearSkinFraction;
        };
        s.settings().skin = 0.2;
        int step = 0;
        double closest = INFINITY;
        s.afterStep = [&](TestScene& scene) {
            ParticleStore& p = scene.scene().particles();
            const std::size_t a = scene.scene().slotOf(0), b = scene.scene().slotOf(1);
            if (++step == 10) {
                p.position[b].x() -= 0.045;
                p.velocity[b].x() = -1;
            }
            closest = std::min(closest, (p.position[b] - p.position[a]).norm() - 1);
        };
        s.runFor(1e-4, 400e-4);
        return closest;
    };
    TestScene nearList, wholeList;
    const double nearClosest = run(nearList, 0.15), wholeClosest = run(wholeList, 0);
    EXPECT_GT(nearList.state().pairList.near.makes, 1u);
    EXPECT_EQ(wholeList.state().pairList.near.makes, 0u);
    EXPECT_LT(wholeClosest, -1e-3) << "the spheres should collide";
    EXPECT_GT(wholeClosest, -5e-3);
    EXPECT_EQ(nearClosest, wholeClosest);
    EXPECT_EQ(particlesThatDiffer(nearList.scene().particles(), wholeList.scene().particles()), 0u)
        << "particles whose state differs from the whole list's sweep";
}

// The sweep grows the radii by the speeds relative to the mean velocity of the mobile particles
// (Contacts/PairSweep.h, sweepFrameVelocity), not by the speeds themselves. Any common velocity
// bounds how fast pairs close, so the force loop gives every pair that needs it its force either
// way: the trajectory is the same to the bit. In the flowing chute the frame's smaller growths
// also let the near list last longer, which shows that the frame was used.
TEST(PairList, SweepFrameChangesNothing) {
    TestScene inFlowFrame, withSpeeds;
    runChuteWith(inFlowFrame, [](StepperTuning& tuning) { tuning.sweepInFlowFrame = true; });
    runChuteWith(withSpeeds, [](StepperTuning& tuning) { tuning.sweepInFlowFrame = false; });
    const std::uint64_t makesInFrame = inFlowFrame.state().pairList.near.makes, makes = withSpeeds.state().pairList.near.makes;
    std::printf("[ measured ] near list made %llu times in the flow's frame, %llu times with the speeds\n",
                static_cast<unsigned long long>(makesInFrame), static_cast<unsigned long long>(makes));
    EXPECT_LT(makesInFrame, makes) << "the frame's growths should be smaller in the flow";
    EXPECT_EQ(particlesThatDiffer(inFlowFrame.scene().particles(), withSpeeds.scene().particles()), 0u)
        << "particles whose state differs from the sweep with the speeds";
}

// The first half of the step in one pass (Particles/DriftPass.h: kick, drift, wrap, the list's
// check, the sweep's points and the forces started with gravity) against the same done pass by
// pass: the same trajectory to the bit, through builds that reorder the particles and wraps
// through the periodic faces. (186 particles: blocks of eight in lanes and a tail of two.)
TEST(PairList, DriftInOnePassChangesNothing) {
    TestScene onePass, passByPass;
    passByPass.settings().stepper.driftPass = false;
    runChuteWith(onePass, [](StepperTuning&) {});
    runChuteWith(passByPass, [](StepperTuning&) {});
    const Integrator::Statistics one = onePass.integrator().statistics(), byPass = passByPass.integrator().statistics();
    EXPECT_EQ(one.driftPassSteps, 30000u) << "the chute should drift in one pass at every step";
    EXPECT_EQ(byPass.driftPassSteps, 0u);
    EXPECT_EQ(byPass.plainSteps, 30000u);
    EXPECT_GT(onePass.state().pairList.builds, 5u) << "the test needs builds (and reorders) during the run";
    EXPECT_EQ(onePass.state().pairList.builds, passByPass.state().pairList.builds);
    EXPECT_EQ(particlesThatDiffer(onePass.scene().particles(), passByPass.scene().particles()), 0u)
        << "particles whose state differs from the step done pass by pass";
}

// Pairs put in another order (the wave schedule's: PairList::reorderPairs) keep their histories;
// an order that is not a permutation, or that moves a face pair among the interior ones, is
// refused.
TEST(PairList, ReorderedPairsKeepTheirHistories) {
    PairList list;
    const std::uint32_t n = 7;
    const auto historyOf = [](std::uint32_t k) {  // (pair 5 has a new pair's history)
        ContactHistory h;
        if (k == 5) return h;
        h.spring = Vec3(k, 2.0 * k, -1.0 * k);
        h.lastNormalForce = 0.5 * k;
        h.state = k % 2 ? ContactHistory::touching : ContactHistory::approaching;
        return h;
    };
    for (std::uint32_t k = 0; k < n; ++k) {
        list.pairs.push_back({k, k + 10});
        list.history.push_back(historyOf(k));
    }
    list.interiorPairs = 4;
    const std::vector<std::uint32_t> order = {2, 0, 3, 1, 6, 4, 5};
    list.reorderPairs(order);
    for (std::uint32_t k = 0; k < n; ++k) {
        const std::uint32_t from = order[k];
        EXPECT_EQ(list.pairs[k].i, from);
        EXPECT_EQ(list.pairs[k].j, from + 10);
        const ContactHistory h = list.history.get(k), expected = historyOf(from);
        EXPECT_EQ(h.spring, expected.spring);
        EXPECT_EQ(h.lastNormalForce, expected.lastNormalForce);
        EXPECT_EQ(h.state, expected.state);
    }
    EXPECT_THROW(list.reorderPairs({0, 1, 2, 3, 4, 5, 5}), Error);     // not a permutation
    EXPECT_THROW(list.reorderPairs({0, 1, 2, 4, 3, 5, 6}), Error);     // a face pair among the interior ones
    EXPECT_THROW(list.reorderPairs({0, 1, 2}), Error);                 // too short
}
