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
    if (host.onRanks() || p.ghostCount > 0) return "the scene is on more than one rank";
    if (p.hasShapes()) return "non-spherical particles turn as rigid bodies";
    if (!s.motions.empty()) return "prescribed motions move particles or walls";
    if (host.hasBoundaries()) return "boundaries act between the drift and the forces";
    if (s.domain.oneWay.active) return "a one-way periodic box (a maser)";
    if (!s.pairList.noted().empty()) return "particles added or moved are to be relisted";
    return {};
}

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
    const DriftPassResult drifted =
        kickDriftAndStartForces(p, work.previousForce, s.domain, list.comparable(p) ? &list.referencePosition : nullptr,
                                s.gravity, frame, s.settings.timeStep, list.sweepPointScratch);
    work.positions.checkFound(drifted.positionsBefore, s);
    list.sweepPointsGrowth = drifted.growth;
    work.driftFrame = drifted.meanVelocity;
    work.lastDisplacement = std::sqrt(drifted.moves.displacement2);
    finishStep(host, recordContacts, &drifted);
}

}  // namespace talus
