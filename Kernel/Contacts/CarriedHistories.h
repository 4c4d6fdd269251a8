// Contact histories carried across a change of the pair list (Contacts/PairList.h), by the ids
// of their pairs: what a build keeps of the list before it (PairList.cc) and what relisting a few
// particles keeps (PairListEdits.cc); and the listing rules both apply to walls and to the pairs
// across the one-way box's face. For the pair list's own source files only.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "Contacts/PairList.h"
#include "Walls/MeshWalls.h"

namespace talus::pairListing {

// The same history seen from the other particle: the spring turns round, an approach does not,
// nor does a rolling spring (its rolling velocity, Theory/ContactLaws.md eq. (22), is the same
// from either side).
// A superquadric warm start is kept relative to particle i and does not turn round: the pair
// starts its next solve cold (from the bounding spheres), which costs iterations, not accuracy.
inline ContactHistory reversed(ContactHistory h) {
    if (h.isTouching()) h.spring = -h.spring;
    h.warmPoint.setZero();
    h.warmMultiplier = 0;
    return h;
}

inline bool worthCarrying(const ContactHistory& h) {
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

    // Asks the memory for the slot where find(a, b) starts, ahead of the call.
    void prefetch(std::uint64_t a, std::uint64_t b) const { __builtin_prefetch(slots_.data() + (hash(a, b) & mask_)); }

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
// (Each find reads a slot of a table of megabytes, at random: the slot of the pair 16 places on
// is asked for ahead, so that its miss overlaps the work between.)
inline void restorePairs(const std::vector<ParticlePair>& list, std::size_t from, ContactHistories& histories,
                  const ParticleStore& particles, const CarriedLookup& carried) {
    constexpr std::size_t ahead = 16;
    for (std::size_t k = from; k < list.size(); ++k) {
        if (k + ahead < list.size()) {
            const std::uint64_t a = particles.id[list[k + ahead].i], b = particles.id[list[k + ahead].j];
            carried.prefetch(std::min(a, b), std::max(a, b));
        }
        const std::uint64_t a = particles.id[list[k].i], b = particles.id[list[k].j];
        if (const ContactHistory* h = carried.find(std::min(a, b), std::max(a, b)))
            histories.set(k, a < b ? *h : reversed(*h));
    }
}

inline void restoreWallPairs(const std::vector<WallCandidate>& list, std::size_t from, ContactHistories& histories,
                      const ParticleStore& particles, const CarriedLookup& carried) {
    for (std::size_t k = from; k < list.size(); ++k)
        if (const ContactHistory* h = carried.find(particles.id[list[k].particle], CarriedHistory::wallKey(list[k].wall)))
            histories.set(k, *h);
}

// The build's rule for wall candidates: mobile particles within the reach of a resting wall or one
// that slides in place (Wall::slidesInPlace), and every mobile particle for another moving wall
// (which may sweep over them).
inline bool isWallCandidate(const ParticleStore& particles, const Wall& wall, std::uint32_t i, const Vec3& x, double reach) {
    if (particles.fixed[i]) return false;
    return (wall.motion >= 0 && !wall.slidesInPlace) || wall.signedDistance(x) < particles.radius[i] + reach;
}

// The same rule for the triangles of a mesh (Walls/MeshWalls.h): those within the reach of particle i
// at x, appended as wall candidates.
inline void addMeshWallCandidates(std::vector<WallCandidate>& candidates, const ParticleStore& particles,
                                  const MeshWalls& mesh, std::uint32_t i, const Vec3& x, double reach) {
    if (particles.fixed[i]) return;
    mesh.forTrianglesWithin(x, particles.radius[i] + reach,
                            [&](std::uint32_t t) { candidates.push_back({i, mesh.firstWall + t}); });
}

// The wall candidates of particle i at x by the build's rules (isWallCandidate,
// addMeshWallCandidates), appended in the build's order: by wall, a mesh's triangles in theirs.
inline void addWallCandidates(std::vector<WallCandidate>& candidates, const ParticleStore& particles,
                              const std::vector<Wall>& walls, std::uint32_t i, const Vec3& x, double reach) {
    forEachWallOrMesh(
        walls, [&](std::uint32_t w) { if (isWallCandidate(particles, walls[w], i, x, reach)) candidates.push_back({i, w}); },
        [&](const MeshWalls& mesh) { addMeshWallCandidates(candidates, particles, mesh, i, x, reach); });
}

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

}  // namespace talus::pairListing
