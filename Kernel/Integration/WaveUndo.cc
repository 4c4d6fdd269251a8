#include "Integration/WaveUndo.h"

#include <utility>

#include "SimulationState.h"

namespace talus {

void WaveUndo::keep(const SimulationState& s, const StepWorkspace& work) {
    const ParticleStore& p = s.particles;
    position_ = p.position, velocity_ = p.velocity, angularVelocity_ = p.angularVelocity;
    force_ = p.force, torque_ = p.torque;
    history_ = s.pairList.history, wallHistory_ = s.pairList.wallHistory;
    time_ = s.time, step_ = s.step, maxSpeed_ = s.pairList.maxSpeed;
    lastDisplacement_ = work.lastDisplacement, driftFrame_ = work.driftFrame, positions_ = work.positions;
}

void WaveUndo::restore(SimulationState& s, StepWorkspace& work) {
    ParticleStore& p = s.particles;
    PairList& list = s.pairList;
    p.position.swap(position_), p.velocity.swap(velocity_), p.angularVelocity.swap(angularVelocity_);
    p.force.swap(force_), p.torque.swap(torque_);
    std::swap(list.history, history_), std::swap(list.wallHistory, wallHistory_);
    s.time = time_, s.step = step_, list.maxSpeed = maxSpeed_;
    list.near.made = false;
    list.sweepPointsByDrift.reset();
    work.lastDisplacement = lastDisplacement_, work.driftFrame = driftFrame_, work.positions = positions_;
}

}  // namespace talus
