// What stops a run before it goes wrong (Documentation/Reliability.md): overlaps beyond a sane
// fraction of the radius, at the start (bad input) and during the run (a blow-up); the time step
// against the stiffest contact is the scene's check (Scene::validate). Part of talus::Simulation.
#include <sstream>

#include "Integration/StepWorkspace.h"

#include "Simulation.h"

namespace talus {

// Overlaps beyond the limit stop the run with the worst pair named: at the start (initial) they
// are bad input, during the run a blow-up.
void Simulation::checkOverlaps(double limit, bool initial, bool agreeNow) {
    std::string diagnosis;
    if (work_->summary.maxOverlapFraction > limit) {
        std::ostringstream m;
        auto at = [this](std::uint64_t id) {
            std::ostringstream where;
            where << " at (" << state_.particles.position[scene_->slotOf(id, /*ghosts*/ true)].transpose() << ")";
            return where.str();
        };
        if (initial)
            m << "initial conditions: particle id " << work_->summary.worstA;
        else
            m << "blow-up at t = " << state_.time << ": particle id " << work_->summary.worstA << at(work_->summary.worstA);
        m << " and " << (work_->summary.worstIsWall ? "wall " : "particle id ") << work_->summary.worstB
          << (work_->summary.worstIsWall || initial ? std::string() : at(work_->summary.worstB)) << " overlap by "
          << 100 * work_->summary.maxOverlapFraction << "% of the smaller radius (limit " << 100 * limit;
        if (initial)
            m << "%, settings().maxInitialOverlapFraction); place them further apart or make them smaller";
        else
            m << "%); the contact is too soft for the impact speed, or the time step too large";
        diagnosis = m.str();
    }
    if (ranks_->isSplit() && agreeNow)
        ranks_->agreeOnOverlaps(diagnosis);
    else if (ranks_->isSplit())
        ranks_->agreeOnOverlapsWithNextStep(diagnosis);
    else if (!diagnosis.empty())
        throw Error(diagnosis);
}

}  // namespace talus
