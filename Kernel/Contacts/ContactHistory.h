// Per-contact memory, stored with the pair list (Contacts/PairList.h).
#pragma once

#include "Math/Vector.h"

namespace talus {

// What a contact remembers from step to step (SPEC.md 1): the tangential spring, whether the
// pair touched at the last force evaluation, and the force it had then (for the
// separation impulse of LinearSpringDashpot).
struct ContactHistory {
    Vec3 spring = Vec3::Zero();
    double normalForce = 0;          // at the last force evaluation
    Vec3 tangentialForce = Vec3::Zero();
    bool touching = false;
    bool operator==(const ContactHistory&) const = default;
};

}  // namespace talus
