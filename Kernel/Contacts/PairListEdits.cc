// The pair list (Contacts/PairList.h) between builds: the pairs of particles added, moved by a
// jump or removed, relisted without a build, and the list following a reordering or a removal of
// particles.
#include "Contacts/PairList.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "Contacts/CarriedHistories.h"
#include "Error.h"

namespace talus {

using namespace pairListing;

void PairList::noteInserted(std::uint32_t slot, const Vec3& position) {
    if (!valid) return;
    if (slot > referencePosition.size()) {  // not the slot after the owned particles
        valid = false;
        return;
    }
    if (slot < referencePosition.size()) {  // before the ghosts: they move up a slot
        auto follow = [slot](std::uint32_t& s) { s += s >= slot; };
        for (ParticlePair& pair : pairs) follow(pair.i), follow(pair.j);
        for (ParticlePair& pair : oneWayPairs) follow(pair.i), follow(pair.j);
        for (WallCandidate& candidate : wallPairs) follow(candidate.particle);
        for (std::uint32_t& noted : noted_) follow(noted);
    }
    referencePosition.insert(referencePosition.begin() + slot, position);
    noted_.push_back(slot);
}

void PairList::noteJumped(std::uint32_t slot, const Vec3& jump) {
    if (!valid) return;
    if (slot < referencePosition.size()) referencePosition[slot] += jump;  // its displacement since the build stays
    noted_.push_back(slot);
}

namespace {

// Drops the entries for which `drop` holds, keeping the order of the rest; returns how many of
// the first `prefix` entries were dropped.
template <class Entry, class Drop>
std::size_t dropEntries(std::vector<Entry>& list, ContactHistories& histories, Drop drop, std::size_t prefix = 0) {
    std::size_t kept = 0, droppedInPrefix = 0;
    for (std::size_t k = 0; k < list.size(); ++k) {
        if (drop(list[k])) {
            droppedInPrefix += k < prefix;
            continue;
        }
        if (kept != k) {
            list[kept] = list[k];
            histories.set(kept, histories.get(k));
        }
        ++kept;
    }
    list.resize(kept);
    histories.resize(kept);
    return droppedInPrefix;
}

}  // namespace

// A build costs a grid search over all particles (and a sort for the reordering); a few particles
// added or moved need only their own pairs. Those are found by a pass over all particles for
// each: O(N) where the build is O(N log N) with a larger constant, and no particle changes slot.
void PairList::relist(const ParticleStore& particles, const Domain& domain, const std::vector<Wall>& walls) {
    if (noted_.empty()) return;
    std::vector<std::uint32_t> noted;
    noted.swap(noted_);
    if (!valid) return;
    std::sort(noted.begin(), noted.end());
    noted.erase(std::unique(noted.begin(), noted.end()), noted.end());
    const std::size_t n = particles.size(), owned = particles.owned();
    // A store changed behind the list's back, or a noted particle that is another rank's
    // partner (a ghost within its reach: that rank does not know it), cannot be relisted.
    const std::vector<Vec3>& x = referencePosition;
    const PeriodicImage image(domain);
    const bool oneWay = domain.oneWay.active;
    const OneWayRule rule(particles, domain, reach);
    auto pairsWithAGhost = [&](std::uint32_t a) {
        for (std::size_t k = owned; k < n; ++k) {
            const auto g = static_cast<std::uint32_t>(k);
            if (withinListReach(image.nearest(x[a] - x[g]), particles.radius[a], particles.radius[g], reach)) return true;
            if (oneWay && ((rule.upstream(a, x[a]) && rule.downstream(g, x[g]) && rule.withinReach(a, g, x[a], x[g])) ||
                           (rule.upstream(g, x[g]) && rule.downstream(a, x[a]) && rule.withinReach(g, a, x[g], x[a]))))
                return true;
        }
        return false;
    };
    bool relistable = !orientById && noted.size() <= maxRelisted && x.size() == n && noted.back() < owned &&
                      (!oneWay || domain.oneWay.length() >= 2 * rule.cut);  // (else the build names the error)
    for (std::size_t k = 0; k < noted.size() && relistable && owned < n; ++k) relistable = !pairsWithAGhost(noted[k]);
    if (!relistable) {
        valid = false;
        return;
    }
    std::vector<unsigned char> isNoted(n, 0);
    for (std::uint32_t slot : noted) isNoted[slot] = 1;
    auto involves = [&isNoted](const ParticlePair& pair) { return isNoted[pair.i] || isNoted[pair.j]; };

    // 1. The noted particles' entries go, their histories kept by ids.
    std::vector<CarriedHistory> carried;
    carryPairs(pairs, history, particles, involves, carried);
    carryPairs(oneWayPairs, oneWayHistory, particles, involves, carried);
    auto wallInvolves = [&isNoted](const WallCandidate& c) { return bool(isNoted[c.particle]); };
    carryWallPairs(wallPairs, wallHistory, particles, wallInvolves, carried);
    std::sort(carried.begin(), carried.end());
    interiorPairs -= dropEntries(pairs, history, involves, interiorPairs);
    dropEntries(oneWayPairs, oneWayHistory, involves);
    dropEntries(wallPairs, wallHistory, wallInvolves);

    // 2. Their entries by the build's rules at the reference positions, appended (pairs after
    // the interior ones: they are swept with the periodic image). A pair of two noted particles
    // is looked at once, from the smaller slot.
    const std::size_t firstPair = pairs.size(), firstOneWay = oneWayPairs.size(), firstWall = wallPairs.size();
    for (std::uint32_t a : noted) {
        const Vec3 xa = x[a];
        const double ra = particles.radius[a];
        const bool fixedA = particles.fixed[a];
        for (std::uint32_t k = 0; k < owned; ++k) {  // (no ghost within reach: checked above)
            if (k == a || (isNoted[k] && k < a)) continue;
            if (!(fixedA && particles.fixed[k]) && withinListReach(image.nearest(xa - x[k]), ra, particles.radius[k], reach))
                pairs.push_back({a, k});
            if (!oneWay) continue;
            if (rule.upstream(a, xa) && rule.downstream(k, x[k]) && rule.withinReach(a, k, xa, x[k]))
                oneWayPairs.push_back({a, k});
            if (rule.upstream(k, x[k]) && rule.downstream(a, xa) && rule.withinReach(k, a, x[k], xa))
                oneWayPairs.push_back({k, a});
        }
        addWallCandidates(wallPairs, particles, walls, a, xa, reach);
    }
    history.resize(pairs.size());
    oneWayHistory.resize(oneWayPairs.size());
    wallHistory.resize(wallPairs.size());
    const CarriedLookup lookup(carried);
    restorePairs(pairs, firstPair, history, particles, lookup);
    restorePairs(oneWayPairs, firstOneWay, oneWayHistory, particles, lookup);
    restoreWallPairs(wallPairs, firstWall, wallHistory, particles, lookup);
    relistedParticles += noted.size();
    ++edits;
}

void PairList::clear() {
    noted_.clear();
    pairs.clear();
    interiorPairs = 0;
    history.assign(0);
    wallPairs.clear();
    wallHistory.assign(0);
    oneWayPairs.clear();
    oneWayHistory.assign(0);
    referencePosition.clear();
    sweepPointsByDrift.reset();
    valid = false;
}

void PairList::followPermutation(const std::vector<std::size_t>& order) {
    std::vector<std::uint32_t> newSlot(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) newSlot[order[k]] = static_cast<std::uint32_t>(k);
    for (ParticlePair& pair : pairs) pair = {newSlot[pair.i], newSlot[pair.j]};
    interiorPairs = 0;  // the slots have no owned/ghost order any more
    for (ParticlePair& pair : oneWayPairs) pair = {newSlot[pair.i], newSlot[pair.j]};
    for (WallCandidate& candidate : wallPairs) candidate.particle = newSlot[candidate.particle];
    referencePosition.clear();
    sweepPointsByDrift.reset();
    valid = false;
}

void PairList::followRemoval(std::uint32_t removed, std::uint32_t last) {
    auto follow = [&](std::uint32_t& slot) {
        if (slot == last) slot = removed;
    };
    auto involves = [&](const ParticlePair& pair) { return pair.i == removed || pair.j == removed; };
    interiorPairs -= dropEntries(pairs, history, involves, interiorPairs);
    dropEntries(oneWayPairs, oneWayHistory, involves);
    dropEntries(wallPairs, wallHistory, [&](const WallCandidate& c) { return c.particle == removed; });
    for (ParticlePair& pair : pairs) follow(pair.i), follow(pair.j);
    for (ParticlePair& pair : oneWayPairs) follow(pair.i), follow(pair.j);
    for (WallCandidate& candidate : wallPairs) follow(candidate.particle);
    std::erase(noted_, removed);
    for (std::uint32_t& noted : noted_) follow(noted);
    sweepPointsByDrift.reset();
    ++edits;
    // (The reference positions end with the last particle's, when the store holds no ghosts. Sums
    // by ids keep each particle's pairs by place, IdOrderedForceSums: they need a build.)
    if (valid && maxRelisted > 0 && !orientById && referencePosition.size() == std::size_t{last} + 1) {
        referencePosition[removed] = referencePosition[last];
        referencePosition.pop_back();
        ++removedParticles;
    } else {
        referencePosition.clear();
        valid = false;
    }
}

void PairList::followWallRemoval(std::uint32_t removed) {
    dropEntries(wallPairs, wallHistory, [&](const WallCandidate& c) { return c.wall == removed; });
    for (WallCandidate& candidate : wallPairs) candidate.wall -= candidate.wall > removed;
    ++edits;
    referencePosition.clear();
    sweepPointsByDrift.reset();
    valid = false;
}

}  // namespace talus
