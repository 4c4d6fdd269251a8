// Per-contact memory, stored with the pair list (Contacts/PairList.h).
#pragma once

#include "Math/Vector.h"

namespace talus {

// What a pair remembers from step to step. The tangential spring of SPEC.md 1, and what the
// linear law needs at the ends of a contact (LinearSpringDashpot.h): the normal overlap, speed
// and force at the last step, and the tangential force then. The pair is in one of three
// states: apart, approaching (it closes its gap within the next step, and an impulse was applied
// ahead of the touch: normalForce is the force of that impulse, overlap the negative gap, speed
// the approach speed), or touching (the values at the last contact step).
struct ContactHistory {
    Vec3 spring = Vec3::Zero();
    Vec3 tangentialForce = Vec3::Zero();
    double normalForce = 0;
    double normalSpeed = 0;
    double overlap = 0;
    bool touching = false;
    bool approaching = false;
    bool operator==(const ContactHistory&) const = default;
};

}  // namespace talus
