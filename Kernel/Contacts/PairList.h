// The candidate contacts of the current neighbour list, with their contact history.
//
// Pairs closer than ri + rj + skin are listed by the HGrid; the list stays valid until some
// particle has moved more than half the skin since it was built (DESIGN.md "Data layout").
// Each listed pair and each particle-wall candidate carries its tangential spring; a rebuild
// carries the springs of touching pairs over by the particles' global ids, so rebuilding
// (or reordering particles) never loses history.
#pragma once

#include <cstdint>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/ContactHistory.h"
#include "Contacts/HGrid.h"
#include "Particles/ParticleStore.h"
#include "Walls/PlaneWall.h"

namespace talus {

struct WallCandidate {
    std::uint32_t particle;
    std::uint32_t wall;
    bool operator==(const WallCandidate&) const = default;
};

class PairList {
public:
    std::vector<ParticlePair> pairs;
    std::vector<ContactHistory> history;  // history[k] belongs to pairs[k]
    std::vector<WallCandidate> wallPairs;
    std::vector<ContactHistory> wallHistory;
    std::vector<Vec3> referencePosition;  // positions when the list was built
    double skin = 0;
    bool valid = false;  // false forces a rebuild (particles added, removed or reordered)
    std::uint64_t builds = 0;

    // True when some particle will have moved more than skin/2 since the last build by the end of
    // the next step (nearest-image displacement, so wrapping through a periodic face is not a
    // move, plus |v| dt). Looking one step ahead keeps every pair that can touch within the next
    // step listed, which the push ahead of a touch needs (LinearSpringDashpot::approachForce).
    // Throws talus::Error naming the particle if a position is not finite.
    // Also records the largest particle speed (maxSpeed), which bounds how fast pairs close.
    bool needsRebuild(const ParticleStore& particles, const Domain& domain, double time, double dt);
    double maxSpeed = 0;

    // Lists candidate pairs and wall contacts anew and carries the springs over. Walls that
    // move (motion >= 0) list every particle, since the wall itself may sweep over them.
    void rebuild(const ParticleStore& particles, const Domain& domain, const std::vector<PlaneWall>& walls,
                 HGrid& grid);
};

}  // namespace talus
