// Per-contact memory, stored with the pair list (Contacts/PairList.h): 33 bytes a listed pair.
#pragma once

#include <cstdint>
#include <vector>

#include "Math/Vector.h"

namespace talus {

// What a pair remembers from step to step: whether it touches, the tangential spring of
// SPEC.md 1, and the normal force it applied at the last step (to tell its own part of the
// particles' last forces from the rest, ContactKinematics::otherAcceleration). A pair that is apart but will touch within the next step is "approaching"
// (LinearSpringDashpot::approachForce); it has no spring then, and the same three numbers hold
// the push applied ahead of the touch, the approach speed and the overlap (minus the gap) then.
struct ContactHistory {
    enum State : std::uint8_t { apart = 0, approaching = 1, touching = 2 };

    Vec3 spring = Vec3::Zero();
    double lastNormalForce = 0;  // the normal force the pair applied at the last step
    State state = apart;

    bool isTouching() const { return state == touching; }
    bool isApproaching() const { return state == approaching; }
    double& pushAhead() { return spring.x(); }
    double& approachSpeed() { return spring.y(); }
    double& overlapBefore() { return spring.z(); }
    bool operator==(const ContactHistory&) const = default;
};

// The histories of a list of pairs, stored field by field: the force loop reads the state of
// every listed pair each step but the spring only of the few that touch or are about to, so the
// states are kept apart, one byte each.
class ContactHistories {
public:
    std::size_t size() const { return states_.size(); }
    ContactHistory::State state(std::size_t k) const { return states_[k]; }
    ContactHistory get(std::size_t k) const { return {springs_[k], lastNormalForces_[k], states_[k]}; }
    void set(std::size_t k, const ContactHistory& h) {
        springs_[k] = h.spring;
        lastNormalForces_[k] = h.lastNormalForce;
        states_[k] = h.state;
    }
    void clearLastNormalForce(std::size_t k) { lastNormalForces_[k] = 0; }
    double lastNormalForceOf(std::size_t k) const { return lastNormalForces_[k]; }
    const Vec3& springOf(std::size_t k) const { return springs_[k]; }
    void assign(std::size_t n) {
        springs_.assign(n, Vec3::Zero());
        lastNormalForces_.assign(n, 0);
        states_.assign(n, ContactHistory::apart);
    }
    void push_back(const ContactHistory& h) {
        springs_.push_back(h.spring);
        lastNormalForces_.push_back(h.lastNormalForce);
        states_.push_back(h.state);
    }

private:
    std::vector<Vec3> springs_;
    std::vector<double> lastNormalForces_;
    std::vector<ContactHistory::State> states_;
};

}  // namespace talus
