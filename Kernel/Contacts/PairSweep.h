// The first pass of the force loop (Contacts/ContactForces.h): of the listed pairs, pick those
// that need work this step: closer than the sum of their radii as given (the force loop passes
// each radius grown by how far the particle can move within the step, so this takes the pairs
// that touch or may touch within it), or with a contact still pending (state not apart). The picked
// pairs go into a SweptPairs chunk in order, each with its separation: the second pass then
// reads it in sequence instead of gathering the two positions and finding the periodic image
// again.
//
// Every step visits every listed pair here (4-5 per particle against 0.5-3 contacts), so this
// pass is a fifth of the step of a sphere flow (Documentation/Performance.md). With AVX-512 it
// takes eight pairs at a time: gathers of the two positions and radii, the nearest periodic
// image by the same compare-and-shift as PeriodicImage::nearest, and compress-stores of the
// picked indices and separations. Both versions make the same decisions and give the same
// separations, bit for bit (the same operations in the same order).
//
// With AVX2 (and so with AVX-512 too) lanes take four pairs at a time without gathers
// (sweepInFourPairLanes): faster than the scalar loop on AVX2 processors, and than the
// gathers where those are slow (Documentation/Performance/History.md has the measurements).
//
// Which runs is decided per process by timing (chooseSweepForm): the gathers are fast on some
// processors and slow on others (on some the scalar loop made the whole step
// 6-7% faster; on an Intel processor the gathers made the sweep 1.5x faster).
#pragma once

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/ContactHistory.h"
#include "Contacts/PairList.h"
#include "Contacts/SweepForm.h"

namespace talus {

// The picked pairs of one chunk of the list: small enough to stay in the first-level cache
// between the two passes (and on the stack: no allocation). Each with its two particles, so
// that the second pass does not read the list's pairs again (one memory stream less).
struct SweptPairs {
    static constexpr std::size_t capacity = 512;
    std::size_t count = 0;
    std::uint32_t pair[capacity];
    ParticlePair particles[capacity];
    double dx[capacity], dy[capacity], dz[capacity];  // xi - xj, nearest image

    Vec3 separation(std::size_t a) const { return {dx[a], dy[a], dz[a]}; }
};

// A velocity common to all particles for the sweep's growths (sweepPointsForStep): the mean
// velocity of the mobile particles, from every 16th slot (any common velocity keeps the sweep's
// bound; the mean of a sample makes the growths small in a flow at a sixteenth of a pass). Zero
// without mobile particles in the sample or if the sample's mean is not finite (a blow-up is
// reported by the list's check, PairList::needsRebuild). Of the owned particles: on ranks the
// ghosts' velocities may still be on their way when the sweep starts (Parallel/RankContext.h).
inline Vec3 sweepFrameVelocity(const ParticleStore& p) {
    constexpr std::size_t stride = 16;
    Vec3 sum = Vec3::Zero();
    std::size_t mobile = 0;
    for (std::size_t i = 0; i < p.owned(); i += stride)
        if (!p.fixed[i]) sum += p.velocity[i], ++mobile;
    const Vec3 mean = mobile > 0 ? Vec3(sum / static_cast<double>(mobile)) : Vec3::Zero();
    return mean.allFinite() ? mean : Vec3::Zero();
}

// The particles as the sweep reads them: each position, and each radius grown by how far the
// particle can move within the step relative to the frame that moves with the velocity u
// (sweepFrameVelocity), ri (1 + 1e-12) + 1.000001 |vi - u| dt, for every particle, ghosts
// included. A pair closes its gap within the step by at most |vi - vj| dt, and
// vi - vj = (vi - u) - (vj - u) for any u common to both: so the sum of two growths bounds it
// whatever u is, and the force loop's picks of the pairs that need work do not depend on u
// (the force loop explains the margins). With u = 0 the growths are the particles' own speeds:
// in a chute flow, where all particles move downslope at about the mean velocity, those are
// many times the relative speeds, and the sweep picks many pairs that then turn out apart and
// not closing (Documentation/Performance.md). Returns the largest growth,
// 1.000001 |vi - u| dt + 1e-12 ri.
constexpr double sweepRadiusMargin = 1 + 1e-12, sweepReachMargin = 1.000001;  // (the margins above)

// Whether this step may sweep the near list (made now if it is not). The separation of every
// pair changed by at most the sum of its two growths in the drift before this step (the drift
// used the velocities the growths are made of, and the frame's velocity is common to both), so
// `moved` adds the largest growth each step. A pair left out of the near list was
// at least ri + rj + skin apart when the list was made and is now at least that less 2 moved;
// the sweep picks it only within the sum of the two grown radii, at most ri + rj + 2 growth.
// So the near list holds every pair the sweep would pick while moved + growth < skin / 2 (a
// billionth less, for the rounding of the tests). A change of the list unmakes it; a near list
// made now is usable if a step's growth is below skin / 2 (else the whole list is swept).
// The sum of growths a near list of this skin holds for (a billionth under half the skin).
inline double nearAllowance(double skin) { return 0.5 * skin * (1 - 1e-9); }

// The near list is made, of the list as it is now (a build or an edit changes its pairs),
// with this skin.
inline bool nearPairsAreCurrent(const PairList& list, double skin) {
    const NearPairs& near = list.near;
    return near.made && near.builds == list.builds && near.edits == list.edits &&
           near.listed == list.pairs.size() && near.skin == skin;
}

// Whether the near list, as it is, holds every pair among its interior ones (NearPairs::interior)
// that this step's sweep picks, given the largest growth of the owned particles alone: the test
// of useNearPairs, for the interior pairs a rank computes before its ghosts' growths are known
// (Parallel/RankContext.h); it changes nothing (useNearPairs counts the step once all are known).
inline bool nearPairsHoldInterior(const PairList& list, double ownedGrowth) {
    const double skin = list.nearSkinFraction * list.skin;
    return skin > 0 && ownedGrowth < nearAllowance(skin) && nearPairsAreCurrent(list, skin) &&
           list.near.moved + ownedGrowth + ownedGrowth < nearAllowance(skin);
}

inline bool useNearPairs(PairList& list, double growth) {
    NearPairs& near = list.near;
    const double skin = list.nearSkinFraction * list.skin;
    if (!(skin > 0) || !(growth < nearAllowance(skin))) {
        near.made = false;
        return false;
    }
    if (!nearPairsAreCurrent(list, skin)) near.made = false;
    if (near.made) {
        near.moved += growth;
        if (!(near.moved + growth < nearAllowance(skin))) near.made = false;
    }
    return true;
}

// The near list (NearPairs): the pairs of `list` that the sweep's rule picks with every radius
// grown by skin / 2 (closer than ri + rj + skin, or pending), in list order. Until a particle
// may have moved so far that a pair left out could come within the pick of a step, sweeping it
// picks exactly the pairs the whole list's sweep picks, in the same order (ContactForces.h).
// (In the lanes of the form in use: Contacts/PairSweepLanes.h.)
void makeNearPairs(PairList& list, const Vec3* position, std::size_t particleCount, const double* radius, double skin,
                   const PeriodicImage& image, std::vector<SweepPoint>& grownScratch, SweptPairs& scratch);

// The sweep form the force loop of the lane form in use runs (Math/LaneForm.h; undecided until
// its first long list).
SweepForm sweepForm();

}  // namespace talus
