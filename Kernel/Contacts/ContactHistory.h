// Per-contact memory, stored with the pair list (Contacts/PairList.h): 32 bytes a listed pair.
#pragma once

#include <cstdint>

#include "Math/Vector.h"

namespace talus {

// What a pair remembers from step to step: whether it touches, and the tangential spring of
// SPEC.md 1. A pair that is apart but will touch within the next step is "approaching"
// (LinearSpringDashpot::approachForce); it has no spring then, and the same three numbers hold
// the push applied ahead of the touch, the approach speed and the overlap (minus the gap) then.
struct ContactHistory {
    enum State : std::uint8_t { apart = 0, approaching = 1, touching = 2 };

    Vec3 spring = Vec3::Zero();
    State state = apart;

    bool isTouching() const { return state == touching; }
    bool isApproaching() const { return state == approaching; }
    double& pushAhead() { return spring.x(); }
    double& approachSpeed() { return spring.y(); }
    double& overlapBefore() { return spring.z(); }
    bool operator==(const ContactHistory&) const = default;
};

}  // namespace talus
