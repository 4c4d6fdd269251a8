// What the force loop reports of a step (Contacts/ContactForces.h): each contact on output
// steps, and a summary every step.
#pragma once

#include <cstddef>
#include <cstdint>

#include "Math/Vector.h"

namespace talus {

// One contact as written to .fstat (Documentation/FileFormats/fstat.md); recorded only on
// output steps.
struct ContactRecord {
    std::uint32_t i;
    std::int64_t j;          // partner slot, or -(wall + 1)
    Vec3 contactPoint;       // middle of the overlap, next to particle i
    double overlap;
    double springLength;     // |xi|
    double normalForce;      // signed, along normal
    Vec3 normal;             // from j (or the wall) to i
    Vec3 tangentialForce;    // on i
    double elasticEnergy;
};

// What the force loop learned about the contacts of this step.
struct ContactSummary {
    std::size_t contacts = 0;
    std::size_t contactsInLanes = 0;  // of them, ellipsoid pairs wholly in EllipsoidContactBatch's lanes
    double maxOverlapFraction = 0;  // largest dn / min(ri, rj) (walls: dn / ri)
    std::uint64_t worstA = 0, worstB = 0;  // global ids (worstB = -1 for a wall)
    bool worstIsWall = false;
    std::size_t oneWayReactions = 0;  // one-way pairs past OneWayPeriodicBox::reactionOverlap
};

}  // namespace talus
