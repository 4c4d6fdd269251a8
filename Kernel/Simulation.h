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
#include "Particles/Energies.h"
#include "Run/Run.h"
#include "Scene/Scene.h"
#include "SimulationState.h"

namespace talus {

class DomainSplit;
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

    // The ranks of the run (1 without mpirun) and this one; rank 0 writes the files.
    int rank() const;
    int ranks() const;
    // Sums of numbers over the ranks (every rank calls it, with its own values, at the same point).
    double sumOverRanks(double x) const;
    void sumOverRanks(std::vector<double>& values) const;
    // The domain split of the run (after solve has set it up; one rank without mpirun).
    const DomainSplit* domainSplit() const { return split_.get(); }
    // Drivers run on ranks by default: their measurements go through Kernel/Sampling (whole-scene
    // sums, files and messages written once). A driver whose hooks read particles() directly for
    // whole-scene numbers says setRunsOnRanks(false) and then refuses to start on more ranks.
    void setRunsOnRanks(bool on) { runsOnRanks_ = on; }
    // Place the rank boundaries by particle count at the next list build (Documentation/Parallel.md);
    // done at the start and after every save anyway.
    void requestRebalance();
    double maxOverRanks(double x) const;
    // Whether the scene is split over more than one rank (false during setupInitialConditions,
    // which every rank runs on the whole scene).
    bool onRanks() const;
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

protected:
    // --- hooks ---
    virtual void setupInitialConditions() {}
    virtual void actionsBeforeTimeStep() {}
    virtual void actionsAfterTimeStep() {}
    // Called at every save; the default writes .data, .fstat, .ene, .vtu and .restart.
    virtual void writeOutput();
    virtual void actionsAfterSolve() {}

private:
    class Host;  // the StepHost the steppers advance and the SceneRanks the scene asks (SimulationHost.h)
    friend struct SimulationInternals;  // (SimulationInternals.h: the state, mutable, for tests)
    void initialise(bool restarted);
    void refuseContradictions(const RunSettings& saved, const std::string& restartFile) const;
    // The forces at the positions now, the neighbour list updated first (StepHost::computeForces).
    void computeForces(bool recordContacts, OverlapCheck check, const DriftPassResult* drifted = nullptr);
    void checkOverlaps(double limit, bool initial, bool agreeNow = true);
    std::size_t mobileParticleCount() const;  // mobile (not fixed) particles in the whole scene
    void reorderParticles(bool withPreviousForces);
    std::uint64_t saveEvery() const;

    // On more than one rank (Parallel/SimulationOnRanks.cc).
    void releaseGhosts();
    void rebalance();
    void renumberNewParticles();
    void splitScene();
    bool updateNeighbourhoodOnRanks(std::vector<CarriedHistory>& carried);
    void agreeOnOverlaps(const std::string& diagnosis);
    std::string overlapsToAgree_;  // this rank's overlap blow-up, for the next step's agreement
    void writeGatheredOutput();

    SimulationState state_;
    // Outside the saved state: the force loop's scratch and what the steppers keep between steps
    // (Integration/StepWorkspace.h), the steppers, and the host they advance.
    std::unique_ptr<StepWorkspace> work_;
    std::unique_ptr<Integrator> integrator_;
    std::unique_ptr<Host> host_;
    std::unique_ptr<Run> run_;
    std::unique_ptr<Scene> scene_;
    std::unique_ptr<OutputFiles> files_;
    std::unique_ptr<DomainSplit> split_;
    std::vector<CarriedHistory> pendingHistories_;  // of a scene just split, until its first list build
    double largestRadius_ = 0;                      // over all ranks, for the ghost width
    bool rebalancePending_ = false;
    // Rank boundaries by particle count (Documentation/Parallel.md), at the start, at saves, on
    // request, and every rebalanceInterval_ of simulated time.
    double rebalanceInterval_ = 0, lastBalanceTime_ = 0;
    std::array<int, 3> rankGrid_{0, 0, 0};  // --rank-grid; zeros: all ranks along x
    bool runsOnRanks_ = true;
    std::uint64_t provisionalIds_ = 0;  // particles this rank added since the last renumbering
    static constexpr std::uint64_t provisionalIdBase = std::uint64_t{1} << 62;
    RunStatistics lastRun_;
};

}  // namespace talus
