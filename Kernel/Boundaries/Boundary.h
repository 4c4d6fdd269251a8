// A boundary: something that acts on the particles every step besides their contacts (the maser's
// inflow, an outlet that deletes what left, timed events). The scene owns it: a driver makes one
// with scene().addBoundary<B>(arguments), which returns a reference to keep, and it lives as long
// as the simulation. Its constructor keeps its totals in the restart file (Run::keepInRestart),
// so a restarted run goes on counting.
//
// Each step (Documentation/Architecture.md "One time step"): afterDrift between the drift and the
// force computation of velocity Verlet, the moment at which a periodic wrap acts, so that the
// step's forces already see what it moved, copied or removed; afterStep at the end of the step
// (of a wave's last step), before the driver's actionsAfterTimeStep. A scene with a boundary that
// acts after the drift steps one step at a time (Integration/Stepper.h).
#pragma once

namespace talus {

class Scene;
class Simulation;

class Boundary {
public:
    // Only the scene makes boundaries (Scene::addBoundary): one made elsewhere would never act.
    class Made {
        friend class Scene;
        Made() = default;
    };
    explicit Boundary(Made) {}
    virtual ~Boundary() = default;
    Boundary(const Boundary&) = delete;  // the restart file's kept values point into it
    Boundary& operator=(const Boundary&) = delete;

    virtual bool actsAfterDrift() const { return false; }
    virtual void afterDrift(Simulation&) {}
    virtual void afterStep(Simulation&) {}
    // Whether it works under an MPI domain split (Parallel/DomainSplit.h): it then acts on the
    // particles each rank owns (slots below owned()) and sums what it counts over the ranks.
    // A boundary that does not refuses to start on more than one rank.
    virtual bool runsOnRanks() const { return false; }
};

}  // namespace talus
