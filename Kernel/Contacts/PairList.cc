#include "Contacts/PairList.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

#include "Error.h"

namespace talus {

namespace {

// The largest squared displacement from the reference positions (nearest image), the largest
// squared speed, and whether the motion is sane (saneMotion) of the particles [0, n), over plain
// arrays. Squares and magnitudes are never negative, and for such doubles the order of the bit
// patterns is the order of the values, NaN (all exponent bits set) above everything: so the
// maxima are taken as unsigned integers, which GCC vectorises where it leaves a floating-point
// maximum scalar (NaN semantics), and a NaN wins them. This pass runs every step over every
// particle (6% of a dilute flow's step when it was scalar) unless the drift pass does its work
// (Particles/DriftPass.h).
LargestMoves largestMoves(const double* __restrict x, const double* __restrict reference, const double* __restrict v,
                          std::size_t n, const PeriodicImage& image) {
    const double length[3] = {image.length(0), image.length(1), image.length(2)};
    const double half[3] = {image.halfLength(0), image.halfLength(1), image.halfLength(2)};
    std::uint64_t displacement2 = 0, speed2 = 0, coordinate = 0;
    for (std::size_t i = 0; i < n; ++i) {
        double d[3];
        for (int a = 0; a < 3; ++a) {  // PeriodicImage::nearest
            const double raw = x[3 * i + a] - reference[3 * i + a];
            d[a] = raw > half[a] ? raw - length[a] : raw < -half[a] ? raw + length[a] : raw;
        }
        const double* vi = v + 3 * i;
        const double s2 = vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2];
        displacement2 = std::max(displacement2, std::bit_cast<std::uint64_t>(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
        speed2 = std::max(speed2, std::bit_cast<std::uint64_t>(s2));
        for (int a = 0; a < 3; ++a) coordinate = std::max(coordinate, std::bit_cast<std::uint64_t>(std::abs(x[3 * i + a])));
    }
    const double largestSpeed2 = std::bit_cast<double>(speed2);
    return {std::bit_cast<double>(displacement2), largestSpeed2,
            saneMotion(largestSpeed2, std::bit_cast<double>(coordinate))};
}

}  // namespace

bool PairList::needsRebuild(const ParticleStore& particles, const Domain& domain, double time, double dt) {
    const bool compare = comparable(particles);
    const std::size_t owned = particles.owned();  // ghosts are their owners' business (Parallel/DomainSplit.h)
    // Without a reference (a first build), the positions against themselves: no displacement.
    const double* x = owned ? particles.position[0].data() : nullptr;
    const LargestMoves moves =
        owned == 0 ? LargestMoves{0, 0, true}
                   : largestMoves(x, compare ? referencePosition[0].data() : x, particles.velocity[0].data(), owned,
                                  PeriodicImage(domain));
    return needsRebuild(moves, particles, time, dt);
}

bool PairList::needsRebuild(const LargestMoves& moves, const ParticleStore& particles, double time, double dt) {
    const bool compare = comparable(particles);
    const std::size_t owned = particles.owned();
    if (!moves.finite) [[unlikely]] {
        for (std::size_t i = 0; i < owned; ++i) {
            const Vec3& xi = particles.position[i];
            if (saneMotion(particles.velocity[i].squaredNorm(),
                           std::max({std::abs(xi.x()), std::abs(xi.y()), std::abs(xi.z())})) &&
                !std::isnan(xi.x() + xi.y() + xi.z()))
                continue;
            std::ostringstream message;
            message << "blow-up at t = " << time << ": particle id " << particles.id[i]
                    << " has a non-finite position or velocity (" << xi.transpose() << "; "
                    << particles.velocity[i].transpose()
                    << "); the time step may be too large for the stiffest contact";
            throw Error(message.str());
        }
        throw Error("blow-up at t = " + std::to_string(time) + ": a position or velocity is not finite");
    }
    maxSpeed = std::sqrt(moves.speed2);
    return !compare || std::sqrt(moves.displacement2) + maxSpeed * dt >= 0.5 * reach;
}

namespace {

// The same history seen from the other particle: the spring turns round, an approach does not,
// nor does a rolling spring (its rolling velocity, Theory/ContactLaws.md eq. (22), is the same
// from either side).
// A superquadric warm start is kept relative to particle i and does not turn round: the pair
// starts its next solve cold (from the bounding spheres), which costs iterations, not accuracy.
ContactHistory reversed(ContactHistory h) {
    if (h.isTouching()) h.spring = -h.spring;
    h.warmPoint.setZero();
    h.warmMultiplier = 0;
    return h;
}

bool worthCarrying(const ContactHistory& h) {
    return h.state != ContactHistory::apart || !h.spring.isZero(0) || h.warmMultiplier != 0;
}

// The histories worth carrying of the entries of `list` for which keep(entry) holds, by ids.
// Direct and one-way pairs share the keys: a pair keeps its spring when one of its particles
// passes the one-way box's face and the pair changes list.
template <class Keep>
void carryPairs(const std::vector<ParticlePair>& list, const ContactHistories& histories, const ParticleStore& particles,
                Keep keep, std::vector<CarriedHistory>& carried) {
    for (std::size_t k = 0; k < list.size(); ++k) {
        const ContactHistory h = histories.get(k);
        if (!worthCarrying(h) || !keep(list[k])) continue;
        std::uint64_t a = particles.id[list[k].i], b = particles.id[list[k].j];
        carried.push_back(a < b ? CarriedHistory{a, b, h} : CarriedHistory{b, a, reversed(h)});
    }
}

template <class Keep>
void carryWallPairs(const std::vector<WallCandidate>& list, const ContactHistories& histories,
                    const ParticleStore& particles, Keep keep, std::vector<CarriedHistory>& carried) {
    for (std::size_t k = 0; k < list.size(); ++k)
        if (worthCarrying(histories.get(k)) && keep(list[k]))
            carried.push_back({particles.id[list[k].particle], CarriedHistory::wallKey(list[k].wall), histories.get(k)});
}

// The carried histories by their pair of ids, in a hash table: a build looks up every listed
// pair, most of which carry nothing (a binary search over the sorted histories was 2% of a
// dilute flow's step). Open addressing over a table of at least twice the histories; each slot
// holds an index into `carried` and 32 bits of the key's hash, so that a probe reads the
// history itself only when the hashes agree.
class CarriedLookup {
public:
    explicit CarriedLookup(const std::vector<CarriedHistory>& carried) : carried_(carried) {
        std::size_t size = 16;
        while (size < 2 * carried.size()) size <<= 1;
        mask_ = size - 1;
        slots_.assign(size, 0);
        for (std::size_t k = 0; k < carried.size(); ++k) {
            const std::uint64_t h = hash(carried[k].a, carried[k].b);
            std::size_t s = h & mask_;
            while (slots_[s] != 0) s = (s + 1) & mask_;
            slots_[s] = (h & 0xffffffff00000000ull) | (k + 1);
        }
    }
    // The history carried for the ids (a, b) (a < b, or b a wall key), if any.
    const ContactHistory* find(std::uint64_t a, std::uint64_t b) const {
        const std::uint64_t h = hash(a, b);
        for (std::size_t s = h & mask_; slots_[s] != 0; s = (s + 1) & mask_) {
            if ((slots_[s] ^ h) >> 32) continue;
            const CarriedHistory& c = carried_[(slots_[s] & 0xffffffffull) - 1];
            if (c.a == a && c.b == b) return &c.history;
        }
        return nullptr;
    }

private:
    static std::uint64_t hash(std::uint64_t a, std::uint64_t b) {
        std::uint64_t h = a * 0x9e3779b97f4a7c15ull ^ (b + 0x632be59bd9b4e019ull) * 0xc2b2ae3d27d4eb4full;
        h ^= h >> 31;
        h *= 0xbf58476d1ce4e5b9ull;
        return h ^ (h >> 29);
    }
    const std::vector<CarriedHistory>& carried_;
    std::vector<std::uint64_t> slots_;
    std::size_t mask_ = 0;
};

// Gives each pair of `list` from `from` on the history carried for it, if any, turned round
// when the pair's first particle has the larger id.
void restorePairs(const std::vector<ParticlePair>& list, std::size_t from, ContactHistories& histories,
                  const ParticleStore& particles, const CarriedLookup& carried) {
    for (std::size_t k = from; k < list.size(); ++k) {
        const std::uint64_t a = particles.id[list[k].i], b = particles.id[list[k].j];
        if (const ContactHistory* h = carried.find(std::min(a, b), std::max(a, b)))
            histories.set(k, a < b ? *h : reversed(*h));
    }
}

void restoreWallPairs(const std::vector<WallCandidate>& list, std::size_t from, ContactHistories& histories,
                      const ParticleStore& particles, const CarriedLookup& carried) {
    for (std::size_t k = from; k < list.size(); ++k)
        if (const ContactHistory* h = carried.find(particles.id[list[k].particle], CarriedHistory::wallKey(list[k].wall)))
            histories.set(k, *h);
}

// The build's rule for wall candidates: mobile particles within the reach of a resting wall, and
// every mobile particle for a moving wall (which may sweep over them).
bool isWallCandidate(const ParticleStore& particles, const Wall& wall, std::uint32_t i, const Vec3& x, double reach) {
    if (particles.fixed[i]) return false;
    return wall.motion >= 0 || wall.signedDistance(x) < particles.radius[i] + reach;
}

}  // namespace

std::vector<CarriedHistory> PairList::carriedHistories(const ParticleStore& particles, bool firstOwned) const {
    std::vector<CarriedHistory> carried;
    const std::size_t firstGhost = firstOwned ? particles.owned() : particles.size();
    auto owned = [firstGhost](const ParticlePair& pair) { return pair.i < firstGhost; };
    carryPairs(pairs, history, particles, owned, carried);
    carryPairs(oneWayPairs, oneWayHistory, particles, owned, carried);
    carryWallPairs(wallPairs, wallHistory, particles, [](const WallCandidate&) { return true; }, carried);
    std::sort(carried.begin(), carried.end());
    return carried;
}

void PairList::rebuild(const ParticleStore& particles, const Domain& domain, const std::vector<Wall>& walls,
                       HGrid& grid, double dt) {
    rebuild(particles, domain, walls, grid, dt, carriedHistories(particles));
}

void PairList::rebuild(const ParticleStore& particles, const Domain& domain, const std::vector<Wall>& walls,
                       HGrid& grid, double dt, std::vector<CarriedHistory> carried) {
    // New candidates, with the history they had (`carried`: by global ids, sorted).
    pairs.clear();
    reach = reachOfNextBuild(dt);
    grid.findPairs(particles, domain, reach, pairs);
    const std::size_t owned = particles.owned();
    if (particles.ghostCount > 0)
        std::erase_if(pairs, [owned](const ParticlePair& pair) { return pair.i >= owned && pair.j >= owned; });
    if (particles.ghostCount > 0 || orientById)
        for (ParticlePair& pair : pairs)
            if ((orientById || pair.i >= owned || pair.j >= owned) && particles.id[pair.i] > particles.id[pair.j])
                std::swap(pair.i, pair.j);
    interiorPairs = putInteriorPairsFirst(particles, domain);
    history.assign(pairs.size());
    const CarriedLookup lookup(carried);
    restorePairs(pairs, 0, history, particles, lookup);
    listOneWayPairs(particles, domain);
    oneWayHistory.assign(oneWayPairs.size());
    restorePairs(oneWayPairs, 0, oneWayHistory, particles, lookup);
    wallPairs.clear();
    for (std::uint32_t w = 0; w < walls.size(); ++w)
        for (std::uint32_t i = 0; i < owned; ++i)
            if (isWallCandidate(particles, walls[w], i, particles.position[i], reach)) wallPairs.push_back({i, w});
    wallHistory.assign(wallPairs.size());
    restoreWallPairs(wallPairs, 0, wallHistory, particles, lookup);
    noted_.clear();

    referencePosition = particles.position;
    valid = true;
    ++builds;
}

void PairList::reorderPairs(const std::vector<std::uint32_t>& order) {
    if (order.size() != pairs.size()) throw Error("PairList::reorderPairs: an order of " + std::to_string(order.size()) +
                                                  " places for " + std::to_string(pairs.size()) + " pairs");
    for (std::size_t k = 0; k < interiorPairs; ++k)
        if (order[k] >= interiorPairs) throw Error("PairList::reorderPairs: the order moves a face pair among the interior ones");
    constexpr std::uint32_t unplaced = 0xffffffffu;
    std::vector<std::uint32_t> placeOf(order.size(), unplaced);
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (order[k] >= order.size() || placeOf[order[k]] != unplaced)
            throw Error("PairList::reorderPairs: the order is not a permutation (place " + std::to_string(k) + ")");
        placeOf[order[k]] = static_cast<std::uint32_t>(k);
    }
    // The histories other than a new pair's (the few that touch or are about to: a copy of them,
    // not of the whole array) go to their new places; the rest start anew, as they were.
    const ContactHistory fresh;
    std::vector<std::pair<std::uint32_t, ContactHistory>> kept;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const ContactHistory h = history.get(k);
        if (h.state != fresh.state || h.spring != fresh.spring || h.lastNormalForce != fresh.lastNormalForce ||
            h.warmPoint != fresh.warmPoint || h.warmMultiplier != fresh.warmMultiplier)
            kept.emplace_back(placeOf[k], h);
    }
    std::vector<std::uint32_t>().swap(placeOf);
    std::vector<ParticlePair> placed(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) placed[k] = pairs[order[k]];
    pairs.swap(placed);
    history.assign(pairs.size());
    for (const auto& [place, h] : kept) history.set(place, h);
    near.made = false;
}

// A particle farther than the reach from every periodic face cannot cross one before the next
// build: it would have moved reach/2 first (needsRebuild). So a pair of two such particles whose
// direct difference is its nearest image now (within half the box along every periodic axis)
// keeps it until then: it moves by less than the reach, far less than half a box (the box is at
// least two reaches long, or the HGrid would list pairs twice). Ghosts are moved by their
// owners' ranks and always take the image. The order within each part is the build's.
std::size_t PairList::putInteriorPairsFirst(const ParticleStore& particles, const Domain& domain) {
    if (!domain.periodic[0] && !domain.periodic[1] && !domain.periodic[2]) return pairs.size();
    const std::size_t owned = particles.owned();
    std::vector<unsigned char> farFromFaces(owned, 1);
    for (int a = 0; a < 3; ++a) {
        if (!domain.periodic[a]) continue;
        const double lo = domain.lo[a] + reach, hi = domain.hi[a] - reach;
        for (std::size_t i = 0; i < owned; ++i) {
            const double x = particles.position[i][a];
            farFromFaces[i] &= x > lo && x < hi;
        }
    }
    const PeriodicImage image(domain);
    auto interior = [&](const ParticlePair& pair) {
        if (pair.i >= owned || pair.j >= owned || !farFromFaces[pair.i] || !farFromFaces[pair.j]) return false;
        const Vec3 d = particles.position[pair.i] - particles.position[pair.j];
        for (int a = 0; a < 3; ++a)
            if (std::abs(d[a]) >= image.halfLength(a)) return false;
        return true;
    };
    // A stable partition that sets aside only the pairs near the faces (a tenth or so; the
    // library's one would copy the whole list).
    std::vector<ParticlePair> nearFaces;
    std::size_t kept = 0;
    for (const ParticlePair& pair : pairs)
        if (interior(pair)) pairs[kept++] = pair;
        else nearFaces.push_back(pair);
    std::copy(nearFaces.begin(), nearFaces.end(), pairs.begin() + static_cast<std::ptrdiff_t>(kept));
    return kept;
}

namespace {

// The listing rule of the one-way pairs (PairList::oneWayPairs) at positions x: i, a mobile
// member of the box within `cut` of its upstream face, and j, a member within `cut` of its
// downstream face, whose distance through the image (xj - length along x) is within the reach.
struct OneWayRule {
    const ParticleStore& particles;
    const OneWayPeriodicBox& box;
    PeriodicImage image;
    double reach, largest = 0, cut = 0;

    OneWayRule(const ParticleStore& p, const Domain& domain, double listReach)
        : particles(p), box(domain.oneWay), image(domain), reach(listReach) {
        for (std::size_t i = 0; i < p.size(); ++i)
            if (box.isMember(p.species[i])) largest = std::max(largest, p.radius[i]);
        cut = 2 * largest + reach;
    }
    bool upstream(std::uint32_t i, const Vec3& x) const {
        return box.isMember(particles.species[i]) && !particles.fixed[i] && x.x() - box.lo < cut;
    }
    bool downstream(std::uint32_t i, const Vec3& x) const {
        return box.isMember(particles.species[i]) && box.hi - x.x() < cut;
    }
    bool withinReach(std::uint32_t i, std::uint32_t j, const Vec3& xi, const Vec3& xj) const {
        Vec3 d = xi - xj;
        d.x() += box.length();
        return withinListReach(image.nearest(d), particles.radius[i], particles.radius[j], reach);
    }
};

}  // namespace

// The box's particles within reach of each face, then every upstream-downstream pair whose image
// distance is within reach: the strips hold a few hundred particles, so pairing them directly
// costs less than a grid.
void PairList::listOneWayPairs(const ParticleStore& particles, const Domain& domain) {
    oneWayPairs.clear();
    const OneWayPeriodicBox& box = domain.oneWay;
    if (!box.active) return;
    const OneWayRule rule(particles, domain, reach);
    // Two listings of one pair (directly and through the image) would count its force twice.
    if (box.length() < 2 * rule.cut) {
        std::ostringstream m;
        m << "maser box of length " << box.length() << " is too short for particles of diameter " << 2 * rule.largest
          << " and list reach " << reach << ": it must be at least " << 2 * rule.cut
          << " long (twice the largest diameter plus the reach)";
        throw Error(m.str());
    }
    // With ghosts (an MPI split) a pair is listed where either particle is owned: i's rank
    // applies the force on i, j's rank the reaction on j past the reaction overlap.
    const std::size_t owned = particles.owned();
    const std::vector<Vec3>& x = particles.position;
    std::vector<std::uint32_t> upstream, downstream;
    for (std::uint32_t i = 0; i < particles.size(); ++i) {
        if (rule.upstream(i, x[i])) upstream.push_back(i);
        if (rule.downstream(i, x[i])) downstream.push_back(i);
    }
    for (std::uint32_t i : upstream)
        for (std::uint32_t j : downstream)
            if ((i < owned || j < owned) && rule.withinReach(i, j, x[i], x[j])) oneWayPairs.push_back({i, j});
}

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
        for (std::uint32_t w = 0; w < walls.size(); ++w)
            if (isWallCandidate(particles, walls[w], a, xa, reach)) wallPairs.push_back({a, w});
    }
    history.resize(pairs.size());
    oneWayHistory.resize(oneWayPairs.size());
    wallHistory.resize(wallPairs.size());
    const CarriedLookup lookup(carried);
    restorePairs(pairs, firstPair, history, particles, lookup);
    restorePairs(oneWayPairs, firstOneWay, oneWayHistory, particles, lookup);
    restoreWallPairs(wallPairs, firstWall, wallHistory, particles, lookup);
    relistedParticles += noted.size();
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
    sweepPointsGrowth.reset();
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
    sweepPointsGrowth.reset();
    valid = false;
}

namespace {

// Keeps the entries (and their histories) for which `keep` returns true; `keep` may change them.
template <class Entry, class Keep>
void keepIf(std::vector<Entry>& list, ContactHistories& histories, Keep keep) {
    std::vector<Entry> kept;
    ContactHistories keptHistories = histories.emptyLike();
    kept.reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) {
        Entry entry = list[k];
        if (!keep(entry)) continue;
        kept.push_back(entry);
        keptHistories.push_back(histories.get(k));
    }
    list.swap(kept);
    histories = std::move(keptHistories);
}

}  // namespace

void PairList::followRemoval(std::uint32_t removed, std::uint32_t last) {
    auto follow = [&](std::uint32_t& slot) {
        if (slot == last) slot = removed;
    };
    auto keepPair = [&](ParticlePair& pair) {
        if (pair.i == removed || pair.j == removed) return false;
        follow(pair.i);
        follow(pair.j);
        return true;
    };
    keepIf(pairs, history, keepPair);
    interiorPairs = 0;
    keepIf(oneWayPairs, oneWayHistory, keepPair);
    keepIf(wallPairs, wallHistory, [&](WallCandidate& candidate) {
        if (candidate.particle == removed) return false;
        follow(candidate.particle);
        return true;
    });
    referencePosition.clear();
    sweepPointsGrowth.reset();
    valid = false;
}

}  // namespace talus

