// talus::Simulation, the base class of every driver (Documentation/Architecture.md "The driver contract").
//
// A driver builds its scene (scene(): species, particles, walls, boundaries; Scene/Scene.h) in
// setupInitialConditions() and may override the hooks; main() writes the settings (settings():
// name, time step, end time, ...; Run/RunSettings.h) and calls solve(argc, argv). The driver's
// own flags and the values a restart keeps go through run() (Run/Run.h).
// The time loop is velocity Verlet (Theory/Integration.md eq. (3)-(6)): half kick, drift, prescribed motions, periodic
// wrap, boundaries (addBoundary), neighbour-list update when needed, forces, half kick.
#pragma once

#include <array>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "Contacts/ContactReport.h"
#include "Error.h"
#include "Integration/StepHost.h"
#include "Parallel/RankContext.h"
#include "Particles/Energies.h"
#include "Run/Run.h"
#include "Sampling/StepSampler.h"
#include "Scene/Scene.h"
#include "SimulationState.h"

namespace talus {

class Integrator;
class OutputFiles;
struct StepWorkspace;

class Simulation {
public:
    Simulation();
    virtual ~Simulation();

    // Parses the flags (--help lists them), sets up or restarts, runs to the end time.
    // Returns 0 on success; on any talus::Error prints it and returns 1.
    int solve(int argc, char** argv);
    // The same, with the flags as strings, throwing talus::Error instead of returning 1.
    void solveOrThrow(const std::vector<std::string>& flags = {});

    // The run settings (Run/RunSettings.h), which command-line flags override; validated at solve().
    RunSettings& settings() { return state_.settings; }
    const RunSettings& settings() const { return state_.settings; }
    // The driver's own flags and the values a restart file keeps (Run/Run.h).
    Run& run() { return *run_; }
    // The scene: gravity, box, species, particles, walls, motions, boundaries (Scene/Scene.h).
    Scene& scene() { return *scene_; }
    const Scene& scene() const { return *scene_; }

    // The ranks of the run (Parallel/RankContext.h): this one, sums over them, the domain split.
    // For Kernel/Sampling and boundaries; drivers measure through Kernel/Sampling instead.
    const RankContext& ranks() const { return *ranks_; }
    RankContext& ranks() { return *ranks_; }

    double time() const { return state_.time; }
    std::uint64_t step() const { return state_.step; }

    // What the last solve's time loop did: steps, mobile particles, wall seconds (the loop only).
    struct RunStatistics {
        std::uint64_t steps = 0;
        std::size_t mobileParticles = 0;
        double wallSeconds = 0;
        double particleStepsPerSecond() const { return wallSeconds > 0 ? steps * double(mobileParticles) / wallSeconds : 0; }
    };
    const RunStatistics& lastRun() const { return lastRun_; }

    // Energies of the mobile particles; elastic energy of the last force evaluation.
    Energies energies() const;
    const ContactSummary& contactSummary() const;

    // Everything the run is (SimulationState.h), to read; a driver changes it through settings()
    // and scene() only.
    const SimulationState& state() const { return state_; }
    // The steppers (Integration/Integrator.h): which took the steps of the last solve, and their
    // statistics (integrator().statistics()).
    const Integrator& integrator() const { return *integrator_; }

    // Attaches a sampler that samples the run at its steps with each contact of them
    // (Sampling/StepSampler.h; in-run coarse graining: Tools/CG/InRun). It must live as long as
    // the simulation runs (a member of the driver, say); the samplers are called in the order added.
    void addSampler(StepSampler& sampler) { samplers_.attached.push_back(&sampler); }

protected:
    // --- hooks ---
    virtual void setupInitialConditions() {}
    virtual void actionsBeforeTimeStep() {}
    virtual void actionsAfterTimeStep() {}
    // Called at every save; the default writes .data, .fstat, .ene, .vtu and .restart.
    virtual void writeOutput();
    virtual void actionsAfterSolve() {}

private:
    class Host;  // the StepHost the steppers advance (SimulationHost.h)
    friend struct SimulationInternals;  // (SimulationInternals.h: the state, mutable, for tests)
    void initialise(bool restarted);
    void refuseContradictions(const RunSettings& saved, const std::string& restartFile) const;
    void chooseTimeStep();
    // The forces at the positions now, the neighbour list updated first (StepHost::computeForces).
    void computeForces(bool recordContacts, OverlapCheck check, const DriftPassResult* drifted = nullptr);
    void checkOverlaps(double limit, bool initial, bool agreeNow = true);
    std::size_t mobileParticleCount() const;  // mobile (not fixed) particles in the whole scene
    void reorderParticles(bool withPreviousForces);
    std::uint64_t saveEvery() const;
    // Whether a sampler wants a step of first..last; the samplers that want the current one sampled.
    bool samplersWant(std::uint64_t first, std::uint64_t last);
    void sampleStep();

    SimulationState state_;
    // Outside the saved state: the force loop's scratch and what the steppers keep between steps
    // (Integration/StepWorkspace.h), the steppers, and the host they advance.
    std::unique_ptr<StepWorkspace> work_;
    std::unique_ptr<Integrator> integrator_;
    std::unique_ptr<Host> host_;
    std::unique_ptr<RankContext> ranks_;
    std::unique_ptr<Run> run_;
    std::unique_ptr<Scene> scene_;
    std::unique_ptr<OutputFiles> files_;
    RunStatistics lastRun_;
    StepSamplers samplers_;
};

}  // namespace talus
