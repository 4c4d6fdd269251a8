// The candidate contacts of the current neighbour list, with their contact history.
//
// Pairs closer than ri + rj + reach are listed by the HGrid, where reach = skin + 2 vmax dt
// looks one step ahead (vmax the largest particle speed); the list stays valid while no particle
// can have moved reach/2 by the end of the next step (Documentation/Architecture.md "Data layout").
// So every pair that can touch within the next step is listed, even with skin 0. Each listed pair
// and each particle-wall candidate carries its tangential spring; a rebuild carries the springs of
// touching pairs over by the particles' global ids, so rebuilding (or reordering particles) never
// loses history.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/ContactHistory.h"
#include "Contacts/HGrid.h"
#include "Contacts/SuperquadricContact.h"
#include "Particles/ParticleStore.h"
#include "Walls/Wall.h"

namespace talus {

struct WallCandidate {
    std::uint32_t particle;
    std::uint32_t wall;
    bool operator==(const WallCandidate&) const = default;
};

// A particle as the force loop's sweep reads it (Contacts/PairSweep.h): its position and its
// radius as the sweep tests it (grown by the step's reach), in one 32-byte record: one memory
// stream and half a cache line per particle, where two arrays would be two streams and up to
// three lines (a pass that reads many arrays side by side can get a fraction of the bandwidth
// of one reading records: Documentation/CacheCliff.md).
struct SweepPoint {
    double x, y, z, radius;
};
static_assert(sizeof(SweepPoint) == 32);

// What the list's check measures over the particles each step (PairList::needsRebuild): the
// largest squared displacement since the build (nearest image), the largest squared speed, and
// whether the motion is sane (saneMotion).
struct LargestMoves {
    double displacement2, speed2;
    bool finite;
};

// Not a blow-up: every squared speed finite (so every velocity too), and every position
// coordinate finite and below 1e150 in magnitude (the arithmetic of distances squares them);
// given the largest squared speed and the largest magnitude of a coordinate (NaN if any is).
constexpr double largestSaneCoordinate = 1e150;
inline bool saneMotion(double largestSpeed2, double largestCoordinate) {
    return largestSpeed2 < std::numeric_limits<double>::infinity() && largestCoordinate < largestSaneCoordinate;
}

// The force loop's near list (Contacts/PairSweep.h, makeNearPairs): the listed pairs closer
// than ri + rj + skin, or with a contact pending, when it was made; the force loop sweeps these
// instead of the whole list until some particle may have moved far enough to bring another
// listed pair within its pick (moved, a bound on every particle's displacement since).
struct NearPairs {
    // A near pair: its place in PairList::pairs (ascending along the near list) and its particles,
    // in one record (one memory stream for the sweep, Documentation/Performance.md).
    struct Pair {
        ParticlePair particles;
        std::uint32_t index;
    };
    std::vector<Pair> pairs;
    std::size_t interior = 0;  // pairs[0, interior) are interior pairs (PairList::interiorPairs)
    double skin = 0;
    double moved = 0;
    bool made = false;
    // The list it was made from: a build or an edit (PairList::edits) changes the pairs and unmakes it.
    std::uint64_t builds = 0, edits = 0;
    std::size_t listed = 0;
    std::uint64_t makes = 0;  // times made (for the run's report)
};

// The history of one pair, keyed by the global ids (smaller first; a wall w is b = ~w, an id no
// particle has); the spring is stored as seen from the smaller id. What a rebuild carries over,
// and what an MPI split sends along with a particle that changes rank.
struct CarriedHistory {
    std::uint64_t a, b;
    ContactHistory history;
    bool operator<(const CarriedHistory& o) const { return a < o.a || (a == o.a && b < o.b); }
    static std::uint64_t wallKey(std::uint32_t wall) { return ~std::uint64_t{0} - wall; }
};

class PairList {
public:
    std::vector<ParticlePair> pairs;
    ContactHistories history;  // history.get(k) belongs to pairs[k]
    // pairs[0, interiorPairs) are the direct difference xi - xj apart (its nearest periodic image)
    // until the next build: both particles owned and too far from every periodic face to cross
    // one before then, and not paired through an image. They come first, so that the force loop
    // sweeps them without the image's compare-and-shift (Contacts/PairSweep.h). 0 after any
    // change to the pairs but a build. In a domain without periodic faces: all pairs, ghosts' too
    // (there is no image to avoid).
    std::size_t interiorPairs = 0;
    std::vector<WallCandidate> wallPairs;
    ContactHistories wallHistory;
    // Pairs across the downstream face of an active one-way periodic box (Domain::oneWay): i, a
    // mobile particle near the upstream face, feels j's image at xj - length along x; j feels
    // nothing. Carried across rebuilds by ids like the other pairs, so a contact keeps its spring
    // when j passes the face and the pair becomes an ordinary one.
    std::vector<ParticlePair> oneWayPairs;
    ContactHistories oneWayHistory;
    std::vector<Vec3> referencePosition;  // positions when the list was built
    double skin = 0;
    double reach = 0;  // skin + 2 vmax dt at the last build
    double reachOfNextBuild(double dt) const { return skin + 2 * maxSpeed * dt; }
    bool valid = false;  // false forces a rebuild (particles removed or reordered; added ones are relisted)
    // The farthest a point of a moving mesh may be from where it was when the wall candidates were
    // listed, by the end of the next step (set as the meshes move, Walls/MeshWalls.h; 0 at a build
    // and at relistWalls): the candidates hold while it is below reach/2, the bound the particles
    // keep too, so a particle and a triangle listed farther apart than the reach cannot touch
    // before they are listed anew.
    double meshTravel = 0;
    bool wallsNeedRelisting() const { return valid && maxRelisted > 0 && meshTravel >= 0.5 * reach; }
    // Lists the wall candidates anew by the rule and in the order of a build, at the reference
    // positions, carrying their histories by ids; the particles' pairs stay. For a moving mesh that
    // has travelled reach/2 (its grid made anew first, MeshWalls::regrid): a particle has moved
    // less than reach/2 from its reference position, the mesh less than reach/2 from where it is
    // now, so a triangle farther than the reach from the reference position cannot touch it
    // before the next build or relisting (from the particle's present position it could: it may
    // have moved up to reach/2 and come back).
    void relistWalls(const ParticleStore& particles, const std::vector<Wall>& walls);
    std::uint64_t wallRelistings = 0;
    bool orientById = false;  // every pair with the smaller id first (Contacts/IdOrderedForceSums.h)
    std::uint64_t builds = 0;
    std::vector<PlacedSuperquadric> shapedFrameScratch;  // the force loop's lab frames of shaped particles
    std::vector<double> spinScratch;  // |w_i| of every particle, for the gap bounds of shaped pairs apart
    std::vector<SweepPoint> sweepPointScratch;  // the force loop's positions and radii grown by the step's reach (PairSweep.h)
    // The sweep grows the radii by the speeds relative to the mobile particles' mean velocity
    // (sweepFrameVelocity), not by the speeds themselves: the same pairs get their forces, fewer
    // are picked that then turn out apart (false: the speeds; for tests and measurements). Set
    // from the run's StepperTuning::sweepInFlowFrame (--sweep-frame).
    bool sweepInFlowFrame = true;
    // The near list of the force loop, made with nearSkinFraction x skin (0: the whole list is
    // swept every step), and its scratch points (positions, radii grown by half that skin). 0.15
    // was the fastest of 0.06-0.4 on the benchmark chute (Documentation/Performance.md). Set
    // from the run's StepperTuning::nearSkinFraction (--near-skin-fraction).
    NearPairs near;
    double nearSkinFraction = 0.15;
    std::vector<SweepPoint> nearPointScratch;

    // True when some particle will have moved more than skin/2 since the last build by the end of
    // the next step (nearest-image displacement, so wrapping through a periodic face is not a
    // move, plus |v| dt). Looking one step ahead keeps every pair that can touch within the next
    // step listed, which the push ahead of a touch needs (LinearSpringDashpot::approachForce).
    // Throws talus::Error naming the particle if a position is not finite.
    // Also records the largest particle speed (maxSpeed), which bounds how fast pairs close. (A
    // moving mesh's travel calls for relistWalls, not a build: wallsNeedRelisting.)
    bool needsRebuild(const ParticleStore& particles, const Domain& domain, double time, double dt);
    // The same on moves measured by the caller (Particles/DriftPass.h, which measures them while
    // it drifts the particles), from referencePosition if comparable(particles), else none.
    bool needsRebuild(const LargestMoves& moves, const ParticleStore& particles, double time, double dt);
    bool comparable(const ParticleStore& particles) const {
        return valid && referencePosition.size() == particles.size();
    }
    double maxSpeed = 0;
    // Set when the drift (Particles/DriftPass.h) made this step's sweepPointScratch for the slots
    // [0, slots) (on ranks the owned ones: the ghosts' states arrive later) with the frame
    // velocity u and this largest growth: the force loop takes those points as they are, makes the
    // rest with the same u (PairSweep.h: one u for all points keeps the sweep's bound), and clears
    // it. Cleared when the particles change slots.
    struct PointsByDrift {
        double growth = 0;
        std::size_t slots = 0;
        Vec3 frame = Vec3::Zero();
    };
    std::optional<PointsByDrift> sweepPointsByDrift;

    // Lists candidate pairs and wall contacts anew and carries the springs over. Walls that
    // move (motion >= 0) list every particle, since the wall itself may sweep over them, unless
    // they slide in place (Wall::slidesInPlace: a drum's mantle); a moving mesh's triangles are
    // listed by distance, the mesh's travel calling for their relisting (meshTravel).
    // With ghosts (ParticleStore::ghostCount) only pairs with an owned particle are listed, and a
    // pair with a ghost has the smaller id first, so that the two ranks that list it compute
    // its force with the same arithmetic; ghosts have no wall contacts.
    void rebuild(const ParticleStore& particles, const Domain& domain, const std::vector<Wall>& walls,
                 HGrid& grid, double dt);
    // The same with the histories given (carriedHistories before the particles changed slots, as
    // an MPI split hands them over; in any order).
    void rebuild(const ParticleStore& particles, const Domain& domain, const std::vector<Wall>& walls,
                 HGrid& grid, double dt, const std::vector<CarriedHistory>& carried);

    // Particles added (in the slot after the owned particles, at the given position, which
    // becomes their reference) or moved by a jump (a maser's wrap, which moves their reference
    // position along) since the last build: relist() lists their pairs, and the rest of the list
    // stays, instead of a whole rebuild. Without a valid list there is nothing to note (the
    // rebuild will list them). An insertion before ghosts moves their slots up by one in the list.
    void noteInserted(std::uint32_t slot, const Vec3& position);
    void noteJumped(std::uint32_t slot, const Vec3& jump);
    const std::vector<std::uint32_t>& noted() const { return noted_; }
    // Lists the pairs, one-way pairs and wall candidates of the noted particles by the rule of a
    // build, applied to the reference positions (a new particle's is where it was added), and
    // carries their histories over by ids. The list then holds every pair that can touch before the
    // next build, as a build would. It searches all particles for each noted one, so beyond
    // maxRelisted noted particles, for a noted particle within reach of a ghost (on ranks, the
    // caller also checks that no other rank needs it as a ghost), or with pairs oriented by ids it
    // forces a rebuild instead.
    void relist(const ParticleStore& particles, const Domain& domain, const std::vector<Wall>& walls);
    static constexpr std::size_t defaultMaxRelisted = 64;
    std::size_t maxRelisted = defaultMaxRelisted;  // 0: every change to the particles forces a rebuild (--relist off)
    std::uint64_t relistedParticles = 0;
    std::uint64_t removedParticles = 0;  // removals followed without a rebuild (followRemoval)
    // Changes to the listed pairs between builds (relistings, removals): what was made of the
    // pairs before one (a near list, a wave schedule) is stale.
    std::uint64_t edits = 0;

    // The histories worth keeping (touching, approaching, or with a spring or warm start), by ids,
    // sorted. firstOwned: only of the pairs whose first particle is owned (not a ghost), so that
    // ranks together give each pair once.
    std::vector<CarriedHistory> carriedHistories(const ParticleStore& particles, bool firstOwned = false) const;
    // The same into `carried` (cleared first; sorted unless asked not to be): a buffer kept from
    // build to build keeps its memory, where a new one takes fresh pages from the system, each a
    // page fault, at every build (Documentation/Performance.md, "Memory kept between list builds").
    void carriedHistoriesInto(std::vector<CarriedHistory>& carried, const ParticleStore& particles,
                              bool firstOwned = false, bool sorted = true) const;
    // Forgets every listed pair and history (the particles are about to change slots).
    void clear();

    // The particles were permuted (new slot k holds old slot order[k], ParticleStore::permute):
    // the listed pairs and wall candidates follow their particles, so that a rebuild still finds
    // their histories. The reference positions are dropped, which forces that rebuild.
    void followPermutation(const std::vector<std::size_t>& order);

    // The pairs take the order `order` (new place k holds the pair and history at place
    // order[k]; the first interiorPairs places keep interior pairs: WaveSchedule::make's order).
    // Unmakes the near list.
    void reorderPairs(const std::vector<std::uint32_t>& order);

    // The particle in slot `removed` is gone and the last one, `last`, took its slot
    // (ParticleStore::removeBySwap): the removed particle's pairs are dropped and the moved
    // one's follow it, with its reference position. The list stays valid: a removal takes no
    // pair a build would list (with maxRelisted 0, --relist off, or pairs ordered by ids it forces
    // a rebuild instead).
    void followRemoval(std::uint32_t removed, std::uint32_t last);

    // Wall `removed` is gone and the walls after it moved down one index (Scene::removeWall): its
    // candidates are dropped and the others follow their walls. Forces a rebuild.
    void followWallRemoval(std::uint32_t removed);

    // Scenes with superquadrics: every history keeps its contact's warm start.
    void enableWarmStarts() {
        history.enableWarmStarts();
        wallHistory.enableWarmStarts();
        oneWayHistory.enableWarmStarts();
    }
    // Scenes whose contact law has rolling resistance: every history keeps its rolling spring.
    void enableRollingSprings() {
        history.enableRollingSprings();
        wallHistory.enableRollingSprings();
        oneWayHistory.enableRollingSprings();
    }

private:
    std::vector<std::uint32_t> noted_;  // slots for relist()
    std::vector<CarriedHistory> carried_;  // the histories a build carries over (scratch, kept for its memory)

    void listOneWayPairs(const ParticleStore& particles, const Domain& domain);
    // The wall candidates of the owned particles at the positions `at` (wallPairs, cleared first).
    void listWallPairs(const ParticleStore& particles, const std::vector<Vec3>& at, const std::vector<Wall>& walls);
    std::size_t putInteriorPairsFirst(const ParticleStore& particles, const Domain& domain);
};

}  // namespace talus
