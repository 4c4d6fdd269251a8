// A boundary that acts on the particles every step, between the drift and the force computation
// of velocity Verlet (Simulation.h): the moment at which a periodic wrap acts, so that the forces
// of the step already see what it moved, copied or removed. Registered with
// Simulation::addBoundary by the boundary's constructor; the simulation does not own it.
#pragma once

namespace talus {

class Simulation;

class Boundary {
public:
    virtual ~Boundary() = default;
    virtual void afterDrift(Simulation& simulation) = 0;
};

}  // namespace talus
