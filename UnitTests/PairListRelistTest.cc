// Relisting the pairs of particles that boundaries add or move (PairList::relist), instead of
// building the whole list anew: the list it gives is the list a build gives, histories included,
// and a run with it follows the run that rebuilds to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "Boundaries/InsertionBoundary.h"
#include "Boundaries/MaserBoundary.h"
#include "TestHelpers.h"

using namespace talus;

namespace {

// A maser box [-10, 0] x [0, 4] (periodic in y), active from the start, feeding a flat chute
// to x = 20: 100 spheres of two sizes dropped into the box slide and roll down a frictional
// base wall under gravity tilted by 24 degrees, through the box's faces and into the chute.
struct FedChute : test::SceneSimulation {
    MaserBoundary& maser = scene().addBoundary<MaserBoundary>(*this, -10, 0, 1);
    std::size_t grain = 0;
    FedChute() {
        setup = [this](SceneSimulation&) {
            scene().setGravity(Vec3(std::sin(24 * pi / 180), 0, -std::cos(24 * pi / 180)));
            scene().setDomain(Vec3(-10, 0, 0), Vec3(0, 4, 10));
            scene().setPeriodic(true, true, false);
            grain = scene().addSpecies("grain", 1, LinearSpringDashpot::fromCollision(0.05, 0.5, 0.5).withFriction(0.5));
            const std::size_t boxGrain = maser.maserSpecies(*this, grain);
            scene().addWall(Vec3::UnitZ(), Vec3::Zero(), grain);
            scene().random().seed(3);
            InsertionBoundary box(Vec3(-10, 0, 0.5), Vec3(0, 4, 6),
                                  SizeDistribution::byNumber().add(boxGrain, 0.5).add(boxGrain, 0.4));
            ASSERT_TRUE(box.insertCount(*this, 100).complete);
            maser.activate(*this, 20, /*seedChute*/ false);
        };
    }
};

// The entries of a list by the ids of their particles (walls by ~wall), each with its history as
// seen from the smaller id for the direct pairs, which either orientation may list.
using Key = std::tuple<int, std::uint64_t, std::uint64_t>;  // list (0 direct, 1 one-way, 2 walls), ids
std::map<Key, ContactHistory> entriesByIds(const PairList& l, const ParticleStore& p) {
    std::map<Key, ContactHistory> entries;
    for (std::size_t k = 0; k < l.pairs.size(); ++k) {
        const std::uint64_t a = p.id[l.pairs[k].i], b = p.id[l.pairs[k].j];
        ContactHistory h = l.history.get(k);
        if (a > b && h.isTouching()) h.spring = -h.spring;
        EXPECT_TRUE(entries.emplace(Key{0, std::min(a, b), std::max(a, b)}, h).second) << "pair listed twice";
    }
    for (std::size_t k = 0; k < l.oneWayPairs.size(); ++k)
        entries.emplace(Key{1, p.id[l.oneWayPairs[k].i], p.id[l.oneWayPairs[k].j]}, l.oneWayHistory.get(k));
    for (std::size_t k = 0; k < l.wallPairs.size(); ++k)
        entries.emplace(Key{2, p.id[l.wallPairs[k].particle], l.wallPairs[k].wall}, l.wallHistory.get(k));
    return entries;
}

}  // namespace

// At the first step after 1500 with spheres of the box touching others within a diameter of its
// downstream face, the list is built at the positions of that moment; then the maser's work is
// done by hand on (up to three of) those spheres:
// each is copied into the chute where it is and moved back by the box length. The list relisted
// for them must hold exactly the entries that a build at the same positions lists, with the same
// histories: the springs of the moved spheres' contacts at the downstream face carried into the
// one-way list (they now feel those partners through the face), the copies' new pairs apart, and
// a sphere added to the box at its downstream face felt one way by a sphere at the upstream face.
TEST(PairListRelist, ListsWhatABuildListsWithTheSameHistories) {
    FedChute s;
    std::size_t moved = 0, carriedSprings = 0, copyPairs = 0, insertedFelt = 0;
    s.afterStep = [&](test::SceneSimulation&) {
        if (s.step() < 1500 || moved > 0) return;
        ParticleStore& p = s.scene().particles();
        PairList& list = SimulationInternals::state(s).pairList;
        // Spheres of the box within a diameter of its downstream face touching another such
        // sphere: moved back, they will feel it through the face.
        auto nearFace = [&](std::size_t i) { return s.scene().domain().oneWay.isMember(p.species[i]) && p.position[i].x() > -1; };
        std::vector<std::uint32_t> touching(p.size(), 0);
        for (std::size_t k = 0; k < list.pairs.size(); ++k) {
            const auto [i, j] = list.pairs[k];
            if (list.history.get(k).isTouching() && nearFace(i) && nearFace(j)) ++touching[i], ++touching[j];
        }
        auto candidate = [&](std::size_t i) { return nearFace(i) && touching[i] > 0; };
        bool any = false;
        for (std::size_t i = 0; i < p.size(); ++i) any |= candidate(i);
        if (!any) return;  // none at the face at this step: the next one
        HGrid grid;
        list.rebuild(p, s.scene().domain(), s.scene().walls(), grid, s.settings().timeStep);  // reference positions = positions now
        const std::uint64_t relistedBefore = list.relistedParticles;
        std::vector<std::uint64_t> movedIds, copyIds;
        const std::size_t n = p.size();
        for (std::size_t i = 0; i < n && moved < 3; ++i) {
            if (!candidate(i)) continue;
            const std::size_t copy = s.scene().addParticle(p.position[i], p.radius[i], s.grain, p.velocity[i], p.angularVelocity[i]);
            copyIds.push_back(p.id[copy]);
            s.scene().moveParticleBy(i, Vec3(-10, 0, 0));
            movedIds.push_back(p.id[i]);
            ++moved;
            for (const ParticlePair& pair : list.pairs)  // its partners stay, to be felt through the face
                if (pair.i == i || pair.j == i) touching[pair.i == i ? pair.j : pair.i] = 0;
        }
        // And a new sphere of the box at its downstream face, 0.8 from an upstream one through
        // the face (as an insertion into the box would add it): felt by that one, one way.
        std::uint64_t insertedId = ~std::uint64_t{0};
        for (std::size_t u = 0; u < n; ++u) {
            if (!s.scene().domain().oneWay.isMember(p.species[u]) || p.fixed[u] || p.position[u].x() > -9.5) continue;
            const std::size_t slot = s.scene().addParticle(p.position[u] + Vec3(10 - 0.8, 0, 0), 0.4, p.species[u]);
            insertedId = p.id[slot];
            break;
        }
        auto among = [](const std::vector<std::uint64_t>& ids, std::uint64_t id) {
            return std::find(ids.begin(), ids.end(), id) != ids.end();
        };
        PairList relisted = list, rebuilt = list;
        relisted.relist(p, s.scene().domain(), s.scene().walls());
        rebuilt.rebuild(p, s.scene().domain(), s.scene().walls(), grid, s.settings().timeStep);
        ASSERT_TRUE(relisted.valid);
        EXPECT_EQ(relisted.relistedParticles - relistedBefore, 2 * moved + 1);
        EXPECT_EQ(relisted.reach, rebuilt.reach);
        EXPECT_EQ(relisted.referencePosition.size(), p.size());
        const auto expected = entriesByIds(rebuilt, p), got = entriesByIds(relisted, p);
        EXPECT_EQ(got.size(), expected.size());
        for (const auto& [key, h] : expected) {
            const auto [listed, a, b] = key;
            const auto it = got.find(key);
            ASSERT_NE(it, got.end()) << "list " << listed << ": " << a << "-" << b;
            EXPECT_TRUE(test::sameBits(it->second, h)) << "list " << listed << ": " << a << "-" << b;
            carriedSprings += listed == 1 && among(movedIds, a) && !among(movedIds, b) && h.isTouching();
            copyPairs += listed == 0 && (among(copyIds, a) || among(copyIds, b));
            insertedFelt += listed == 1 && b == insertedId;
        }
        s.scene().removeParticle(s.scene().slotOf(insertedId));  // it may overlap others: not part of the flow
    };
    s.runFor(1e-3, 3000 * 1e-3);
    EXPECT_GT(moved, 0u);
    EXPECT_GT(carriedSprings, 0u);  // not vacuous: contacts went through the face with their springs
    EXPECT_GT(copyPairs, 0u);
    EXPECT_GT(insertedFelt, 0u);
}

// The same flow run 4000 steps (spheres crossing the downstream face every few steps, each
// copied into the chute and moved back) with the pairs of the copies and the moved spheres
// relisted, and with the list built anew at every crossing: the same crossings, the same
// trajectories to round-off (only the order in which forces are summed differs).
TEST(PairListRelist, ChangesNoPhysics) {
    FedChute relisting, rebuilding;
    rebuilding.settings().relist = false;
    relisting.runFor(1e-3, 4000 * 1e-3);
    rebuilding.runFor(1e-3, 4000 * 1e-3);
    const PairList &a = relisting.state().pairList, &b = rebuilding.state().pairList;
    std::printf("[ measured ] 4000 steps: %.0f crossings; builds %lu relisting (%lu particles relisted), %lu rebuilding\n",
                relisting.maser.crossings(), static_cast<unsigned long>(a.builds),
                static_cast<unsigned long>(a.relistedParticles), static_cast<unsigned long>(b.builds));
    EXPECT_GT(relisting.maser.crossings(), 20);
    EXPECT_EQ(relisting.maser.crossings(), rebuilding.maser.crossings());
    EXPECT_EQ(b.relistedParticles, 0u);
    EXPECT_GE(a.relistedParticles, static_cast<std::uint64_t>(2 * relisting.maser.crossings()));
    EXPECT_LT(a.builds, b.builds);
    const ParticleStore &p = relisting.scene().particles(), &q = rebuilding.scene().particles();
    ASSERT_EQ(p.size(), q.size());
    double position = 0, velocity = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {  // the slots differ (particles reordered at builds)
        const std::size_t j = rebuilding.scene().slotOf(p.id[i]);
        position = std::max(position, (p.position[i] - q.position[j]).norm());
        velocity = std::max(velocity, (p.velocity[i] - q.velocity[j]).norm());
    }
    std::printf("[ measured ] relisting against rebuilding: position %.2e, velocity %.2e\n", position, velocity);
    EXPECT_LT(position, 1e-9);
    EXPECT_LT(velocity, 1e-7);
}

