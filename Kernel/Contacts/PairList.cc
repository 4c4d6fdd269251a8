#include "Contacts/PairList.h"

#include <algorithm>
#include <sstream>

#include "Error.h"

namespace talus {

bool PairList::needsRebuild(const ParticleStore& particles, const Domain& domain, double time) const {
    bool moved = !valid || referencePosition.size() != particles.size();
    const double limit2 = 0.25 * skin * skin;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Vec3& x = particles.position[i];
        if (!isFinite(x) || !isFinite(particles.velocity[i])) {
            std::ostringstream message;
            message << "blow-up at t = " << time << ": particle id " << particles.id[i]
                    << " has a non-finite position or velocity (" << x.transpose() << "; "
                    << particles.velocity[i].transpose()
                    << "); the time step may be too large for the stiffest contact";
            throw Error(message.str());
        }
        if (!moved && domain.nearestImage(x - referencePosition[i]).squaredNorm() >= limit2) moved = true;
    }
    return moved;
}

namespace {

// History of one touching pair, keyed by the global ids (smaller first); the spring is stored
// as seen from the smaller id.
struct CarriedSpring {
    std::uint64_t a, b;
    Vec3 spring;
    std::uint8_t touching;
    bool operator<(const CarriedSpring& o) const { return a < o.a || (a == o.a && b < o.b); }
};

}  // namespace

void PairList::rebuild(const ParticleStore& particles, const Domain& domain, const std::vector<PlaneWall>& walls,
                       HGrid& grid) {
    // 1. Remember the springs of touching pairs by global ids (a wall w is id ~w, an id that no
    //    particle can have).
    std::vector<CarriedSpring> carried;
    const std::uint64_t wallKey = ~std::uint64_t{0};
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (!touching[k] && springs[k].isZero(0)) continue;
        std::uint64_t a = particles.id[pairs[k].i], b = particles.id[pairs[k].j];
        carried.push_back(a < b ? CarriedSpring{a, b, springs[k], touching[k]}
                                : CarriedSpring{b, a, Vec3(-springs[k]), touching[k]});
    }
    for (std::size_t k = 0; k < wallPairs.size(); ++k)
        if (wallTouching[k] || !wallSprings[k].isZero(0))
            carried.push_back(
                {particles.id[wallPairs[k].particle], wallKey - wallPairs[k].wall, wallSprings[k], wallTouching[k]});
    std::sort(carried.begin(), carried.end());
    auto find = [&carried](std::uint64_t a, std::uint64_t b) -> const CarriedSpring* {
        auto it = std::lower_bound(carried.begin(), carried.end(), CarriedSpring{a, b, Vec3::Zero(), 0});
        return it != carried.end() && it->a == a && it->b == b ? &*it : nullptr;
    };

    // 2. New candidates.
    pairs.clear();
    grid.findPairs(particles, domain, skin, pairs);
    springs.assign(pairs.size(), Vec3::Zero());
    touching.assign(pairs.size(), 0);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        std::uint64_t a = particles.id[pairs[k].i], b = particles.id[pairs[k].j];
        if (const CarriedSpring* c = find(std::min(a, b), std::max(a, b))) {
            springs[k] = a < b ? c->spring : Vec3(-c->spring);
            touching[k] = c->touching;
        }
    }
    wallPairs.clear();
    for (std::uint32_t w = 0; w < walls.size(); ++w)
        for (std::uint32_t i = 0; i < particles.size(); ++i) {
            if (particles.fixed[i]) continue;
            if (walls[w].motion < 0 && walls[w].signedDistance(particles.position[i]) >= particles.radius[i] + skin)
                continue;
            wallPairs.push_back({i, w});
        }
    wallSprings.assign(wallPairs.size(), Vec3::Zero());
    wallTouching.assign(wallPairs.size(), 0);
    for (std::size_t k = 0; k < wallPairs.size(); ++k)
        if (const CarriedSpring* c = find(particles.id[wallPairs[k].particle], wallKey - wallPairs[k].wall)) {
            wallSprings[k] = c->spring;
            wallTouching[k] = c->touching;
        }

    referencePosition = particles.position;
    valid = true;
    ++builds;
}

}  // namespace talus
