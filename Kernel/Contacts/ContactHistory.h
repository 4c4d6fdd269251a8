// Per-contact memory, stored with the pair list (Contacts/PairList.h): 33 bytes a listed pair
// (and 24 more with a law of rolling resistance).
#pragma once

#include <cstdint>
#include <vector>

#include "Math/Vector.h"

namespace talus {

// What a pair remembers from step to step: whether it touches, the tangential spring of
// Theory/ContactLaws.md eq. (13), and the normal force it applied at the last step (to tell its own
// part of the particles' last forces from the rest, ContactKinematics::otherAcceleration). A pair
// that is apart but will touch within the next step is "approaching"
// (LinearSpringDashpot::approachForce); it has no spring then, and the same three numbers hold the
// push applied ahead of the touch, the approach speed and the overlap (minus the gap) then. A pair
// that stopped touching at this step and applied its separation impulse is "separated" for one
// step. So a pair that applied a force at the last step is never "apart", and the force loop's
// sweep, which skips pairs apart and out of reach, always visits it: its lastNormalForce is then
// either used or cleared, never left stale (ContactForces.h).
struct ContactHistory {
    enum State : std::uint8_t { apart = 0, approaching = 1, touching = 2, separated = 3 };

    Vec3 spring = Vec3::Zero();
    double lastNormalForce = 0;  // the normal force the pair applied at the last step
    State state = apart;
    // Pairs with a superquadric (Contacts/SuperquadricContact.h): the contact point relative to
    // particle i (or the particle of a wall pair) and the multiplier of the last solve, where the
    // next solve starts; multiplier 0: no solve yet. Stored only in scenes with shapes.
    Vec3 warmPoint = Vec3::Zero();
    double warmMultiplier = 0;
    // Laws with rolling resistance (Species/LinearSpringDashpotRolling.h): the rolling spring of
    // Theory/ContactLaws.md "Rolling resistance", zero unless touching. Stored only in scenes
    // with such a law.
    Vec3 rollingSpring = Vec3::Zero();

    bool isTouching() const { return state == touching; }
    bool isApproaching() const { return state == approaching; }
    double& pushAhead() { return spring.x(); }
    double& approachSpeed() { return spring.y(); }
    double& overlapBefore() { return spring.z(); }
    // A pair with a superquadric that is apart: a lower bound of its gap (ContactForces.h).
    double& gapBound() { return spring.x(); }
    bool operator==(const ContactHistory&) const = default;
};

// The histories of a list of pairs: the force loop reads the state of every listed pair each
// step but the spring only of the few that touch or are about to, so the states are kept apart,
// one byte each; the spring and the last normal force, read and written together, share one
// 32-byte record (one memory stream instead of two: a pass that reads 16 or more arrays at once
// can get under half the bandwidth of one that reads a single array of records;
// Documentation/CacheCliff.md).
class ContactHistories {
public:
    std::size_t size() const { return states_.size(); }
    ContactHistory::State state(std::size_t k) const { return states_[k]; }
    const ContactHistory::State* states() const { return states_.data(); }
    // (Inlined always: the shaped pairs' path calls get and set per pair and step, and out of
    // line the two took 5.5% of a settled ellipsoid packing's cycles; Performance/History.md.)
    [[gnu::always_inline]] ContactHistory get(std::size_t k) const {
        ContactHistory h{forces_[k].spring, forces_[k].lastNormalForce, states_[k]};
        if (withWarmStarts_) [[unlikely]]
            h.warmPoint = warmStarts_[k].point, h.warmMultiplier = warmStarts_[k].multiplier;
        if (withRollingSprings_) [[unlikely]]
            h.rollingSpring = rollingSprings_[k];
        return h;
    }
    [[gnu::always_inline]] void set(std::size_t k, const ContactHistory& h) {
        forces_[k] = {h.spring, h.lastNormalForce};
        states_[k] = h.state;
        if (withWarmStarts_) [[unlikely]]
            warmStarts_[k] = {h.warmPoint, h.warmMultiplier};
        if (withRollingSprings_) [[unlikely]]
            rollingSprings_[k] = h.rollingSpring;
    }
    // A contact that touches, written in place (its rolling spring, if kept, left as it is): the
    // batched ellipsoid contacts (Contacts/ShapedContactForces.h) come with these numbers in
    // lanes, and a whole ContactHistory put together on the stack and copied stalled each contact
    // on its own stores (a third of the time of applying them).
    [[gnu::always_inline]] void setTouching(std::size_t k, const Vec3& spring, double lastNormalForce,
                                            const Vec3& warmPoint, double warmMultiplier) {
        forces_[k] = {spring, lastNormalForce};
        states_[k] = ContactHistory::touching;
        if (withWarmStarts_) [[likely]]
            warmStarts_[k] = {warmPoint, warmMultiplier};
    }
    // Keep the superquadric warm starts too (scenes with shapes; ParticleStore::enableShapes).
    void enableWarmStarts() {
        withWarmStarts_ = true;
        warmStarts_.resize(size());
    }
    bool hasWarmStarts() const { return withWarmStarts_; }
    // Keep the rolling springs too (scenes whose law has rolling resistance; SpeciesTable::
    // keepsRollingSprings).
    void enableRollingSprings() {
        withRollingSprings_ = true;
        rollingSprings_.resize(size(), Vec3::Zero());
    }
    bool hasRollingSprings() const { return withRollingSprings_; }
    void clearLastNormalForce(std::size_t k) { forces_[k].lastNormalForce = 0; }
    double& gapBoundOf(std::size_t k) { return forces_[k].spring.x(); }  // (ContactHistory::gapBound)
    double lastNormalForceOf(std::size_t k) const { return forces_[k].lastNormalForce; }
    void prefetch(std::size_t k) const { __builtin_prefetch(forces_.data() + k); }  // (its spring and last force)
    void prefetchWarmStart(std::size_t k) const {
        if (withWarmStarts_) __builtin_prefetch(warmStarts_.data() + k);
    }
    const Vec3& springOf(std::size_t k) const { return forces_[k].spring; }
    // The springs and last normal forces as plain numbers, four a pair (x, y, z, last force),
    // and the states: for the force loop's batches (ContactForces.h), which read them when they
    // gather and write them when they apply their contacts (in scenes without warm starts, which
    // set() keeps in step with them).
    double* lastingRecords() {
        static_assert(sizeof(Forces) == 4 * sizeof(double));
        return reinterpret_cast<double*>(forces_.data());
    }
    const double* lastingRecords() const { return reinterpret_cast<const double*>(forces_.data()); }
    ContactHistory::State* mutableStates() { return states_.data(); }
    // n apart histories. A list that has grown since the last build gets room for more: vector::assign
    // allocates exactly n, so a list growing by a few pairs a build got fresh memory every build,
    // and the first touch of its pages was 5-6% of a settling drum's step (Performance/History.md).
    void assign(std::size_t n) {
        assignWithRoom(forces_, n, Forces{});
        assignWithRoom(states_, n, ContactHistory::apart);
        if (withWarmStarts_) assignWithRoom(warmStarts_, n, WarmStart{});
        if (withRollingSprings_) assignWithRoom(rollingSprings_, n, Vec3(Vec3::Zero()));
    }
    // Keeps the first n histories, or adds apart ones up to n.
    void resize(std::size_t n) {
        forces_.resize(n, {});
        states_.resize(n, ContactHistory::apart);
        if (withWarmStarts_) warmStarts_.resize(n);
        if (withRollingSprings_) rollingSprings_.resize(n, Vec3::Zero());
    }
    void push_back(const ContactHistory& h) {
        forces_.push_back({h.spring, h.lastNormalForce});
        states_.push_back(h.state);
        if (withWarmStarts_) warmStarts_.push_back({h.warmPoint, h.warmMultiplier});
        if (withRollingSprings_) rollingSprings_.push_back(h.rollingSpring);
    }
    // An empty list of the same kind (with warm starts and rolling springs if this one has them).
    ContactHistories emptyLike() const {
        ContactHistories h;
        if (withWarmStarts_) h.enableWarmStarts();
        if (withRollingSprings_) h.enableRollingSprings();
        return h;
    }

private:
    template <class T>
    static void assignWithRoom(std::vector<T>& v, std::size_t n, const T& value) {
        if (n > v.capacity()) {
            v.clear();
            v.reserve(n + n / 4);
        }
        v.assign(n, value);
    }
    bool withWarmStarts_ = false;
    // A pair's warm start, its point and multiplier side by side: the force loop reads both for
    // every superquadric pair it solves, and from two arrays that was two cache misses a pair.
    struct alignas(32) WarmStart {  // (on a line of its own)
        Vec3 point = Vec3::Zero();
        double multiplier = 0;
    };
    std::vector<WarmStart> warmStarts_;
    bool withRollingSprings_ = false;
    std::vector<Vec3> rollingSprings_;
    struct Forces {
        Vec3 spring = Vec3::Zero();
        double lastNormalForce = 0;
    };
    std::vector<Forces> forces_;
    std::vector<ContactHistory::State> states_;
};

// Histories as they were before a pass changed them, to be put back: the interior pairs that a
// rank computes while its ghosts travel, on a step that turns out to rebuild the list
// (Parallel/RankContext.h). Each pair is saved before its first change of the pass.
class ContactHistoryLog {
public:
    void save(const ContactHistories& histories, std::size_t k) { entries_.push_back({k, histories.get(k)}); }
    // Puts the saved histories back (in reverse, so that a pair saved twice gets its first) and
    // forgets them.
    void restore(ContactHistories& histories) {
        for (auto e = entries_.rbegin(); e != entries_.rend(); ++e) histories.set(e->pair, e->history);
        entries_.clear();
    }
    void clear() { entries_.clear(); }
    std::size_t size() const { return entries_.size(); }

private:
    struct Entry {
        std::size_t pair;
        ContactHistory history;
    };
    std::vector<Entry> entries_;
};

}  // namespace talus
