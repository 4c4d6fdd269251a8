// The force loop's entry point: contact forces and torques of every listed pair and wall
// candidate for one contact law, in the lanes of the form in use (Math/LaneForm.h). The loop
// itself is Contacts/ContactForceLoop.h, compiled once per form; this header is all a caller
// needs (no intrinsics, no force loop in its compile).
#pragma once

#include <memory>
#include <tuple>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/ContactReport.h"
#include "Contacts/IdOrderedForceSums.h"
#include "Contacts/PairList.h"
#include "Contacts/PairSweep.h"
#include "Contacts/SuperquadricContact.h"
#include "Contacts/WaveSchedule.h"
#include "Particles/ParticleStore.h"
#include "Shapes/Superquadric.h"
#include "Species/SpeciesTable.h"
#include "Walls/PrescribedMotion.h"
#include "Walls/Wall.h"

namespace talus {

// What a force loop works on: the particles, the law of each species pair, the time step, the
// largest speed (for the skipping of far walls), the forces of the last step, where the summary
// and the records go, the shapes (null: spheres only) and the per-pair forces of the sums in id
// order (IdOrderedForceSums.h; null: summed as they come).
template <class Law>
struct ContactForceLoopArguments {
    ParticleStore& p;
    const PairTable<Law>& laws;
    double dt, maxSpeed;
    const std::vector<Vec3>& previousForce;
    ContactSummary& summary;
    ContactRecords* records;
    const std::vector<Superquadric>* shapes;
    PairContribution* perPair;
    SuperquadricContactSettings shapeSettings;  // the Newton solve of superquadric pairs
};

// The force loop of one lane form (Contacts/ContactForceLoop.h ContactForceLoopInLanes), of any
// contact law. particlePairs is interiorPairs then restPairs (ContactForceLoop.h): a rank whose
// ghosts are on their way computes the first part meanwhile (Parallel/RankContext.h).
class AnyContactForceLoop {
public:
    virtual ~AnyContactForceLoop() = default;
    virtual void particlePairs(PairList& list, const Domain& domain, bool nearPairs) = 0;
    virtual void interiorPairs(PairList& list, const Domain& domain, bool nearPairs, ContactHistoryLog& changed) = 0;
    virtual void restPairs(PairList& list, const Domain& domain, bool nearPairs) = 0;
    virtual void oneWayPairs(PairList& list, const Domain& domain) = 0;
    virtual void wallPairs(PairList& list, const std::vector<Wall>& walls,
                           const std::vector<PrescribedMotion>& motions) = 0;
    virtual void regionPairs(PairList& list, const Domain& domain, const WaveSchedule& schedule,
                             const WaveRegion& region, const std::vector<Wall>& walls, const PlaceRun* nearRuns) = 0;
    virtual void allowSpeed(double maxSpeed) = 0;
};
template <class Law>
class ContactForceLoopOfForm : public AnyContactForceLoop {};

// The force loop of one contact law in one form: its entries (Contacts/ContactForceLoop.h), and
// the table of them of every law of Species/ContactLaws.h.
template <class Law>
struct ForceLoopKernels {
    std::unique_ptr<ContactForceLoopOfForm<Law>> (*make)(const ContactForceLoopArguments<Law>& arguments);
    void (*addContactForces)(const ContactForceLoopArguments<Law>& arguments, PairList& list,
                             const std::vector<Wall>& walls, const std::vector<PrescribedMotion>& motions,
                             const Domain& domain);
};
using ForceLoopKernelTable = ContactLawList::TupleOf<ForceLoopKernels>;
// The table of the form in use (Math/LaneForm.cc).
const ForceLoopKernelTable& forceLoopKernelsInUse();

// The loop of the form in use.
template <class Law>
std::unique_ptr<ContactForceLoopOfForm<Law>> makeContactForceLoop(const ContactForceLoopArguments<Law>& arguments) {
    return std::get<ForceLoopKernels<Law>>(forceLoopKernelsInUse()).make(arguments);
}
template <class Law>
void addContactForcesInLanes(const ContactForceLoopArguments<Law>& arguments, PairList& list,
                             const std::vector<Wall>& walls, const std::vector<PrescribedMotion>& motions,
                             const Domain& domain) {
    std::get<ForceLoopKernels<Law>>(forceLoopKernelsInUse()).addContactForces(arguments, list, walls, motions, domain);
}

// The force loop over the listed pairs and wall candidates of one step, for one contact law.
template <class Law>
class ContactForceLoop {
public:
    ContactForceLoop(ParticleStore& p, const PairTable<Law>& laws, double dt, double maxSpeed,
                     const std::vector<Vec3>& previousForce, ContactSummary& summary, ContactRecords* records,
                     const std::vector<Superquadric>* shapes = nullptr, PairContribution* perPair = nullptr,
                     const SuperquadricContactSettings& shapeSettings = {})
        : loop_(makeContactForceLoop<Law>(
              {p, laws, dt, maxSpeed, previousForce, summary, records, shapes, perPair, shapeSettings})) {}

    // nearPairs: the near list may be swept (not with particles on prescribed motions, whose
    // positions the step sets apart from their velocities).
    void particlePairs(PairList& list, const Domain& domain, bool nearPairs) {
        loop_->particlePairs(list, domain, nearPairs);
    }
    // The pairs across the downstream face of the one-way periodic box (Domain::oneWay): the
    // force on i alone.
    void oneWayPairs(PairList& list, const Domain& domain) { loop_->oneWayPairs(list, domain); }
    void wallPairs(PairList& list, const std::vector<Wall>& walls, const std::vector<PrescribedMotion>& motions) {
        loop_->wallPairs(list, walls, motions);
    }
    // The pairs and wall candidates one region of a wave computes (Contacts/WaveSchedule.h).
    // nearRuns: if given, the places in the near list (list.near) of each run's near pairs.
    void regionPairs(PairList& list, const Domain& domain, const WaveSchedule& schedule, const WaveRegion& region,
                     const std::vector<Wall>& walls, const PlaceRun* nearRuns = nullptr) {
        loop_->regionPairs(list, domain, schedule, region, walls, nearRuns);
    }
    // Raises the largest speed the skipping of far walls assumes (to one measured since).
    void allowSpeed(double maxSpeed) { loop_->allowSpeed(maxSpeed); }

private:
    std::unique_ptr<ContactForceLoopOfForm<Law>> loop_;
};

// The force loop of one step for the law of a pair table, without records or pair forces kept,
// for spheres, and with the largest speed given later (allowSpeed): the loop a rank starts while
// its ghosts travel (Parallel/RankContext.h).
template <class Law>
std::unique_ptr<AnyContactForceLoop> sphereContactForceLoop(ParticleStore& p, const PairTable<Law>& laws, double dt,
                                                            const std::vector<Vec3>& previousForce,
                                                            ContactSummary& summary) {
    return makeContactForceLoop<Law>({p, laws, dt, 0, previousForce, summary, nullptr, nullptr, nullptr, {}});
}

// The forces of one step: the listed pairs, the one-way pairs, the wall candidates.
template <class Law>
void addContactForces(ParticleStore& p, PairList& list, const std::vector<Wall>& walls,
                      const std::vector<PrescribedMotion>& motions, const PairTable<Law>& laws, const Domain& domain,
                      double dt, double maxSpeed, const std::vector<Vec3>& previousForce, ContactSummary& summary,
                      ContactRecords* records, const std::vector<Superquadric>* shapes = nullptr,
                      PairContribution* perPair = nullptr, const SuperquadricContactSettings& shapeSettings = {}) {
    addContactForcesInLanes<Law>({p, laws, dt, maxSpeed, previousForce, summary, records, shapes, perPair, shapeSettings},
                                 list, walls, motions, domain);
}

}  // namespace talus
