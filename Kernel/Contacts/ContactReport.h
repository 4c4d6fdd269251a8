// What the force loop reports of a step (Contacts/ContactForces.h): each contact on output
// steps, and a summary every step.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>

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

// The records of a step, in a deque: it grows block by block, never holding the old and the new
// copy of the whole as a vector does when it reallocates (up to 3x its size at the last doubling).
using ContactRecordList = std::deque<ContactRecord>;

// The contacts of an output step: each one's record where the .fstat file wants them, else only
// what the .ene file and Simulation::energies() take from them, their number and elastic energy.
// (A record is 120 bytes: at the output steps of a large scene without .fstat the records were
// the largest array, more than the particles; Documentation/Performance.md, "Scaling and memory".)
// On ranks a pair across two ranks is computed on both and counts where its first particle is
// owned (PairList::rebuild puts the smaller id first): pairs whose first particle is a ghost are
// left out.
class ContactRecords {
public:
    // Empties the records for a new step; keepEach: keep every record, not only the sums.
    void start(bool keepEach, std::size_t ownedParticles) {
        keepEach_ = keepEach || keepEachForSampler_;
        owned_ = ownedParticles;
        each_.clear();
        count_ = 0;
        elasticEnergy_ = 0;
    }
    void add(const ContactRecord& r) {
        if (r.i >= owned_) return;
        ++count_;
        elasticEnergy_ += r.elasticEnergy;  // (in the order of the records, as a sum over them)
        if (keepEach_) each_.push_back(r);
    }
    // Gives the memory of the records back (between output steps).
    void release() { ContactRecordList().swap(each_); }
    // Whether the next recording keeps every record whatever start() is told: a step sampler
    // (Sampling/StepSampler.h) needs each contact of its steps, with or without .fstat.
    void keepEachForSampler(bool keep) { keepEachForSampler_ = keep; }

    const ContactRecordList& each() const { return each_; }  // empty unless kept
    std::size_t count() const { return count_; }
    double elasticEnergy() const { return elasticEnergy_; }

private:
    bool keepEach_ = true;
    bool keepEachForSampler_ = false;
    std::size_t owned_ = std::numeric_limits<std::size_t>::max();
    ContactRecordList each_;
    std::size_t count_ = 0;
    double elasticEnergy_ = 0;
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
