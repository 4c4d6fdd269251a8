#include "Integration/PlainVerlet.h"

#include <algorithm>

#include "Integration/StepWorkspace.h"
#include "Particles/DriftPass.h"
#include "Particles/RotationBatch.h"
#include "Particles/VelocityVerlet.h"
#include "SimulationState.h"

namespace talus {

void moveWithPrescribedMotion(SimulationState& s) {
    const double dt = s.settings.timeStep;
    if (s.motions.empty()) return;
    std::vector<Mat3> rotation;
    for (const PrescribedMotion& m : s.motions) rotation.push_back(m.stepRotation(dt));
    ParticleStore& p = s.particles;
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (p.motion[i] < 0) continue;
        const PrescribedMotion& m = s.motions[p.motion[i]];
        p.position[i] = m.moved(p.position[i], rotation[p.motion[i]], dt);
    }
    for (Wall& w : s.walls) {
        if (w.motion < 0 || w.isTriangle()) continue;  // (a mesh's triangles move with their mesh, below)
        // A wall that slid in place was listed as resting (PairList::rebuild): no longer, a new list.
        const bool slides = w.slidesInPlaceUnder(s.motions[w.motion]);
        if (w.slidesInPlace && !slides) s.pairList.valid = false;
        w.slidesInPlace = slides;
        w.point = s.motions[w.motion].moved(w.point, rotation[w.motion], dt);
        w.normal = (rotation[w.motion] * w.normal).normalized();
    }
    if (p.hasShapes())
        for (std::size_t i = 0; i < p.owned(); ++i)
            if (p.motion[i] >= 0 && p.shape[i] >= 0)
                p.orientation[i] = Quat(rotation[p.motion[i]] * p.orientation[i].toRotationMatrix()).normalized();
    for (const auto& mesh : s.meshes) {
        if (!mesh->moves()) continue;
        mesh->move(s.motions[mesh->motion], rotation[mesh->motion], dt, s.walls);
        s.pairList.meshTravel = std::max(s.pairList.meshTravel, mesh->travelled + mesh->lastStep);
    }
    for (PrescribedMotion& m : s.motions) m.advanceCentre(dt);
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (p.motion[i] < 0) continue;
        const PrescribedMotion& m = s.motions[p.motion[i]];
        p.velocity[i] = m.pointVelocity(p.position[i]);
        p.angularVelocity[i] = m.angularVelocity;
    }
}

void PlainVerlet::advance(StepHost& host, bool recordContacts) {
    SimulationState& s = host.state();
    StepWorkspace& work = host.workspace();
    ParticleStore& p = s.particles;
    const double dt = s.settings.timeStep;
    const std::size_t owned = p.owned();  // ghosts are their owners' business
    work.positions.checkFound(positionSum(p, owned), s);
    work.driftFrame.reset();
    halfKickAndDrift(p, owned, 0.5 * dt, dt);
    if (p.hasShapes()) turnShapedParticles(p, 0.5 * dt, dt);
    moveWithPrescribedMotion(s);
    if (s.domain.anyPeriodic()) s.domain.wrap(p.position.data(), owned);
    finishStep(host, recordContacts, nullptr);
}

void finishStep(StepHost& host, bool recordContacts, const DriftPassResult* drifted) {
    SimulationState& s = host.state();
    ParticleStore& p = s.particles;
    const double half = 0.5 * s.settings.timeStep;
    s.time += s.settings.timeStep;
    ++s.step;
    host.afterDrift();
    host.computeForces(recordContacts, recordContacts ? OverlapCheck::now : OverlapCheck::withNextStep, drifted);
    halfKick(p, p.owned(), half);
    if (p.hasShapes()) turnShapedParticles(p, half, 0);
    host.workspace().positions.noteLeft(drifted ? drifted->positionsAfter : positionSum(p, p.owned()), p.owned());
}

void PositionWatch::checkFound(std::uint64_t found, SimulationState& state) {
    if (left_ && *left_ == found) return;
    PairList& list = state.pairList;
    // (Counted where the near list would have been swept: particles added, removed or moved by
    // moveParticleBy change the list, which makes it anew anyway.)
    if (state.particles.owned() == particlesLeft_ && list.noted().empty() &&
        nearPairsAreCurrent(list, list.nearSkinFraction * list.skin))
        ++changedBetweenSteps;
    list.near.made = false;
    changedThisStep = true;  // (on ranks, the ghosts of the moved particles moved too)
}

}  // namespace talus
