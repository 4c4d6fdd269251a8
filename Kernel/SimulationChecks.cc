// What stops a run before it goes wrong (Documentation/Reliability.md): a time step too
// large for the stiffest contact present, and overlaps beyond a sane fraction of the radius, at
// the start (bad input) and during the run (a blow-up). Part of talus::Simulation.
#include <sstream>

#include "Integration/StepWorkspace.h"

#include "Simulation.h"

namespace talus {

double Simulation::shortestCollisionTime(std::string* which) const {
    // Per species: how many mobile particles, the lightest and the smallest of them, and whether
    // fixed particles or walls of that species can be hit.
    struct Present {
        std::size_t mobile = 0;
        double lightest = INFINITY, smallest = INFINITY;
        bool immobile = false;  // fixed particles or walls
    };
    const std::size_t n = state_.species.size();
    std::vector<Present> present(n);
    const ParticleStore& p = state_.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
        Present& s = present[p.species[i]];
        if (p.fixed[i]) {
            s.immobile = true;
            continue;
        }
        ++s.mobile;
        s.lightest = std::min(s.lightest, p.mass[i]);
        s.smallest = std::min(s.smallest, p.radius[i]);
    }
    for (const Wall& w : state_.walls) present[w.species].immobile = true;

    double shortest = INFINITY;
    auto consider = [&](std::size_t a, std::size_t b, double reducedMass, double effectiveRadius) {
        const ContactLaw law = state_.species.pairLaw(a, b);
        const double tc =
            std::visit([&](const auto& l) { return l.collisionTimeOfPair(reducedMass, effectiveRadius); }, law);
        if (tc >= shortest) return;
        shortest = tc;
        if (which)
            *which = "species '" + state_.species[a].name + "' with '" + state_.species[b].name + "', reduced mass " +
                     str(reducedMass);
    };
    for (std::size_t a = 0; a < n; ++a) {
        const Present& pa = present[a];
        if (pa.mobile == 0) continue;
        for (std::size_t b = 0; b < n; ++b) {
            const Present& pb = present[b];
            // Two mobile particles (two of them if the species is the same), the lightest ones.
            if (pb.mobile > (a == b ? 1u : 0u) && b >= a)
                consider(a, b, pa.lightest * pb.lightest / (pa.lightest + pb.lightest),
                         pa.smallest * pb.smallest / (pa.smallest + pb.smallest));
            // A mobile particle against a fixed particle or a wall: the reduced mass is its own.
            if (pb.immobile) consider(a, b, pa.lightest, pa.smallest);
        }
    }
    return shortest;
}

void Simulation::checkTimeStep() const {
    std::string which;
    const double tc = shortestCollisionTime(&which);
    const double dt = state_.settings.timeStep;
    if (dt > tc / 10)
        throw Error("time step " + str(dt) + " is larger than a tenth of the shortest collision time " + str(tc) + " (" +
                    which + "); use --dt " + str(tc / 50) + " (tc/50) or smaller");
}

// Overlaps beyond the limit stop the run with the worst pair named: at the start (initial) they
// are bad input, during the run a blow-up.
void Simulation::checkOverlaps(double limit, bool initial, bool agreeNow) {
    std::string diagnosis;
    if (work_->summary.maxOverlapFraction > limit) {
        std::ostringstream m;
        auto at = [this](std::uint64_t id) {
            std::ostringstream where;
            where << " at (" << state_.particles.position[slotOf(id, /*ghosts*/ true)].transpose() << ")";
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
