#include "Contacts/PairList.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

#include "Contacts/CarriedHistories.h"
#include "Error.h"

namespace talus {

using namespace pairListing;

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
        throw Error("blow-up at t = " + str(time) + ": a position or velocity is not finite");
    }
    maxSpeed = std::sqrt(moves.speed2);
    // (With --relist off a moving mesh's travel calls for a whole build, not relistWalls.)
    return !compare || std::sqrt(moves.displacement2) + maxSpeed * dt >= 0.5 * reach ||
           (maxRelisted == 0 && meshTravel >= 0.5 * reach);
}

std::vector<CarriedHistory> PairList::carriedHistories(const ParticleStore& particles, bool firstOwned) const {
    std::vector<CarriedHistory> carried;
    carriedHistoriesInto(carried, particles, firstOwned);
    return carried;
}

void PairList::carriedHistoriesInto(std::vector<CarriedHistory>& carried, const ParticleStore& particles,
                                    bool firstOwned, bool sorted) const {
    carried.clear();
    const std::size_t firstGhost = firstOwned ? particles.owned() : particles.size();
    auto owned = [firstGhost](const ParticlePair& pair) { return pair.i < firstGhost; };
    carryPairs(pairs, history, particles, owned, carried);
    carryPairs(oneWayPairs, oneWayHistory, particles, owned, carried);
    carryWallPairs(wallPairs, wallHistory, particles, [](const WallCandidate&) { return true; }, carried);
    if (sorted) std::sort(carried.begin(), carried.end());
}

void PairList::rebuild(const ParticleStore& particles, const Domain& domain, const std::vector<Wall>& walls,
                       HGrid& grid, double dt) {
    // (Unsorted: the build looks them up in a hash table, CarriedLookup, and sorting them was 3% of
    // a drum's step.)
    carriedHistoriesInto(carried_, particles, /*firstOwned*/ false, /*sorted*/ false);
    rebuild(particles, domain, walls, grid, dt, carried_);
}

void PairList::rebuild(const ParticleStore& particles, const Domain& domain, const std::vector<Wall>& walls,
                       HGrid& grid, double dt, const std::vector<CarriedHistory>& carried) {
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
    listWallPairs(particles, particles.position, walls);
    wallHistory.assign(wallPairs.size());
    restoreWallPairs(wallPairs, 0, wallHistory, particles, lookup);
    noted_.clear();

    referencePosition = particles.position;
    meshTravel = 0;
    valid = true;
    ++builds;
}

void PairList::listWallPairs(const ParticleStore& particles, const std::vector<Vec3>& at,
                             const std::vector<Wall>& walls) {
    const auto owned = static_cast<std::uint32_t>(particles.owned());
    wallPairs.clear();
    forEachWallOrMesh(
        walls,
        [&](std::uint32_t w) {
            for (std::uint32_t i = 0; i < owned; ++i)
                if (isWallCandidate(particles, walls[w], i, at[i], reach)) wallPairs.push_back({i, w});
        },
        [&](const MeshWalls& mesh) {
            for (std::uint32_t i = 0; i < owned; ++i) addMeshWallCandidates(wallPairs, particles, mesh, i, at[i], reach);
        });
}

void PairList::relistWalls(const ParticleStore& particles, const std::vector<Wall>& walls) {
    require(comparable(particles), "PairList::relistWalls: the list has no reference positions to list from");
    std::vector<CarriedHistory>& carried = carried_;
    carried.clear();
    carryWallPairs(wallPairs, wallHistory, particles, [](const WallCandidate&) { return true; }, carried);
    listWallPairs(particles, referencePosition, walls);
    wallHistory.assign(wallPairs.size());
    restoreWallPairs(wallPairs, 0, wallHistory, particles, CarriedLookup(carried));
    meshTravel = 0;
    ++wallRelistings;  // (not an edit: the pairs, and a near list made of them, stay)
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

}  // namespace talus
