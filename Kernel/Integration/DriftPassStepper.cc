#include "Integration/DriftPassStepper.h"

#include <cmath>

#include "Contacts/PairSweep.h"
#include "Integration/PlainVerlet.h"
#include "Integration/StepWorkspace.h"
#include "Particles/DriftPass.h"
#include "SimulationState.h"

namespace talus {

std::string_view DriftPassStepper::whyNot(const StepHost& host) const {
    const SimulationState& s = host.state();
    const ParticleStore& p = s.particles;
    if (!s.settings.stepper.driftPass) return "turned off (--drift-pass off)";
    if (p.hasShapes()) return "non-spherical particles turn as rigid bodies";
    if (host.onRanks() && s.settings.stepper.overlapGhosts)
        return "the interior pairs are computed while the ghosts travel (--overlap-ghosts on)";
    // (Walls and meshes on prescribed motions move after the pass, as in the plain step; particles
    // on them would be drifted by the pass along their velocity, not turned exactly.)
    if (!s.motions.empty())
        for (std::size_t i = 0; i < p.owned(); ++i)
            if (p.motion[i] >= 0) return "prescribed motions move particles";
    if (host.boundariesActAfterDrift()) return "boundaries act between the drift and the forces";
    if (s.domain.oneWay.active) return "a one-way periodic box (a maser)";
    if (!s.pairList.noted().empty()) return "particles added or moved are to be relisted";
    return {};
}

namespace {

// The ghosts' forces as startForcesWithGravity starts them in the pass-by-pass step (no force of
// a ghost is used: each rank sums its own particles'; started alike, the ghost slots hold the same
// numbers with and without the pass).
void startGhostForces(ParticleStore& p, const Vec3& gravity) {
    for (std::size_t i = p.owned(); i < p.size(); ++i) {
        p.force[i] = p.fixed[i] ? Vec3::Zero() : Vec3(p.mass[i] * gravity);
        p.torque[i] = Vec3::Zero();
    }
}

}  // namespace

Vec3 sweepFrame(const SimulationState& state, const StepWorkspace& work) {
    if (!state.pairList.sweepInFlowFrame) return Vec3::Zero();
    return work.driftFrame ? *work.driftFrame : sweepFrameVelocity(state.particles);
}

void DriftPassStepper::advance(StepHost& host, bool recordContacts) {
    SimulationState& s = host.state();
    StepWorkspace& work = host.workspace();
    ParticleStore& p = s.particles;
    PairList& list = s.pairList;
    const Vec3 frame = sweepFrame(s, work);
    // On ranks the pass covers the owned particles; the ghosts' states arrive with the
    // neighbourhood update (Parallel/RankContext.h), their last forces into previousForce, and
    // the force loop makes their sweep points with the same frame.
    const std::size_t owned = p.owned();
    startFirstHalf(p, work.previousForce, list.sweepPointScratch);
    const DriftPassResult drifted =
        kickDriftAndStartForces(p, work.previousForce, s.domain, list.comparable(p) ? &list.referencePosition : nullptr,
                                s.gravity, frame, s.settings.timeStep, list.sweepPointScratch, 0, owned);
    startGhostForces(p, s.gravity);
    moveWithPrescribedMotion(s);  // (the walls and meshes that follow one)
    work.positions.checkFound(drifted.positionsBefore, s);
    list.sweepPointsByDrift = PairList::PointsByDrift{drifted.growth, owned, frame};
    work.driftFrame = drifted.meanVelocity;
    work.lastDisplacement = std::sqrt(drifted.moves.displacement2);
    finishStep(host, recordContacts, &drifted);
}

}  // namespace talus
