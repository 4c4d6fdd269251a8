// A boundary that acts on the particles every step, between the drift and the force computation
// of velocity Verlet (Simulation.h): the moment at which a periodic wrap acts, so that the forces
// of the step already see what it moved, copied or removed. Registered with
// Scene::addBoundary by the boundary's constructor; the simulation does not own it.
#pragma once

namespace talus {

class Simulation;

class Boundary {
public:
    virtual ~Boundary() = default;
    virtual void afterDrift(Simulation& simulation) = 0;
    // Whether it works under an MPI domain split (Parallel/DomainSplit.h): it then acts on the
    // particles each rank owns (slots below owned()) and sums what it counts over the ranks.
    // A boundary that does not refuses to start on more than one rank.
    virtual bool runsOnRanks() const { return false; }
};

}  // namespace talus
