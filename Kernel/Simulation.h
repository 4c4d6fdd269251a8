// talus::Simulation, the base class of every driver (Documentation/Architecture.md "The driver contract").
//
// A driver sets species, particles, walls and boundaries in setupInitialConditions() and may
// override the hooks; main() sets the name, time step and end time and calls solve(argc, argv).
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

#include "Boundaries/Boundary.h"
#include "Contacts/ContactReport.h"
#include "Error.h"
#include "Integration/StepHost.h"
#include "Parallel/RankContext.h"
#include "Particles/Energies.h"
#include "SimulationState.h"

namespace talus {

class CommandLine;
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

    // --- run settings (command-line flags override them) ---
    void setName(const std::string& name);
    void setTimeStep(double dt);
    void setEndTime(double endTime);
    void setOutputInterval(double interval);
    void setSkin(double skin);
    void setCellSizeRatio(double ratio);  // of successive HGrid levels (Contacts/HGrid.h)
    // Renew the particle order along a space-filling curve at neighbour-list rebuilds (default on;
    // Particles/SpaceFillingCurve.h). Slots then change during a run: find a particle by its id.
    void setParticleReordering(bool on) { state_.settings.reorderParticles = on; }
    void setVtuOutput(bool on) { state_.settings.writeVtu = on; }
    void setFileOutput(bool on);  // all of .data, .fstat, .ene, .vtu and .restart
    // The run settings, with settings().stepper the steppers' tuning (Integration/StepperTuning.h:
    // waves of several steps per pass, Documentation/TimeSkewing.md; the drift pass). With waves,
    // actionsBeforeTimeStep and actionsAfterTimeStep run once per wave.
    RunSettings& settings() { return state_.settings; }

    // A driver's own flag --name VALUE, listed by --help, parsed before setupInitialConditions.
    void addFlag(const std::string& name, const std::string& help, double& value);
    void addFlag(const std::string& name, const std::string& help, int& value);
    void addTextFlag(const std::string& name, const std::string& help, std::string& value);
    // A number of the driver's (or of a boundary it owns) that the restart file keeps: saved with
    // every restart file and put back when the run restarts, before the command line is read
    // again. Number flags (addFlag) are kept this way too, as "flag.NAME". Names are one word
    // and unique.
    void keepInRestart(const std::string& name, double& value);
    void keepInRestart(const std::string& name, int& value);
    // A list of numbers kept the same way (a detector's recent samples, running sums): `save`
    // gives it at every save (on every rank at once, so it may sum over ranks), `restore` takes
    // it back when the run restarts (on every rank: what is summed over ranks must be put back
    // on one of them only). Saved as NAME.size and NAME.0, NAME.1, ...
    void keepInRestart(const std::string& name, std::function<std::vector<double>()> save,
                       std::function<void(const std::vector<double>&)> restore);

    // --- the scene ---
    void setGravity(const Vec3& g) { state_.gravity = g; }
    const Vec3& gravity() const { return state_.gravity; }
    void setDomain(const Vec3& lo, const Vec3& hi);
    void setPeriodic(bool x, bool y, bool z);
    const Domain& domain() const { return state_.domain; }

    std::size_t addSpecies(const std::string& name, double density, const ContactLaw& law);
    SpeciesTable& species() { return state_.species; }

    // Adds a sphere; returns its slot. Radius must be positive and the species must exist.
    std::size_t addParticle(const Vec3& position, double radius, std::size_t species,
                            const Vec3& velocity = Vec3::Zero(), const Vec3& angularVelocity = Vec3::Zero());
    // A fixed particle: never integrated, still collides; follows motion if motion >= 0.
    std::size_t addFixedParticle(const Vec3& position, double radius, std::size_t species, int motion = -1);
    // Superquadric particles (Theory/Superquadrics.md): a shape added once, then particles of it. The particle's
    // radius is the shape's bounding radius, its mass density x volume; it turns as a rigid body
    // (Particles/RigidBodyRotation.h). Returns the shape's index / the particle's slot.
    std::size_t addShape(const Superquadric& shape);
    std::size_t addSuperquadric(const Vec3& position, std::size_t shape, std::size_t species,
                                const Quat& orientation = Quat::Identity(), const Vec3& velocity = Vec3::Zero(),
                                const Vec3& angularVelocity = Vec3::Zero());
    // A fixed superquadric: never integrated, still collides; follows motion if motion >= 0 (its
    // orientation turns with the motion).
    std::size_t addFixedSuperquadric(const Vec3& position, std::size_t shape, std::size_t species,
                                     const Quat& orientation = Quat::Identity(), int motion = -1);
    const std::vector<Superquadric>& shapes() const { return state_.shapes; }
    void removeParticle(std::size_t slot);
    // Moves a particle by a jump (a boundary's wrap, like the maser's): the neighbour list then
    // relists its pairs rather than being built anew.
    void moveParticleBy(std::size_t slot, const Vec3& jump);

    // A boundary that acts every step after the drift, before the forces (Boundaries/Boundary.h);
    // boundaries register themselves, in their constructors. Not owned: it must outlive the run.
    void addBoundary(Boundary& boundary) { boundaries_.push_back(&boundary); }

    std::size_t addWall(const Vec3& normal, const Vec3& point, std::size_t species, int motion = -1);
    // The inside of a cylinder (a drum's mantle, Walls/Wall.h) of the given radius about the axis
    // through axisPoint along axisDirection; a drum turns with a motion whose centre is on the
    // axis and whose angular velocity is along it (addMotion).
    std::size_t addCylinderWall(const Vec3& axisPoint, const Vec3& axisDirection, double radius, std::size_t species,
                                int motion = -1);
    std::size_t addMotion(const PrescribedMotion& motion);

    // Under MPI (Parallel/DomainSplit.h, Documentation/Parallel.md) the store holds this rank's
    // particles (slots below particles().owned()) and then ghosts: loop to owned() and sum over
    // ranks (ranks().sum) for anything about the whole scene. Without MPI owned() == size().
    ParticleStore& particles() { return state_.particles; }
    const ParticleStore& particles() const { return state_.particles; }
    // The ranks of the run (Parallel/RankContext.h): this one, sums over them, the domain split.
    // For Kernel/Sampling and boundaries; drivers measure through Kernel/Sampling instead.
    const RankContext& ranks() const { return *ranks_; }
    RankContext& ranks() { return *ranks_; }
    // Mobile (not fixed) particles in the whole scene.
    std::size_t mobileParticleCount() const;
    // The current slot of the particle with global id `id` (ids count from 0 in the order of
    // addParticle/addFixedParticle). A linear search: for drivers and tests, not inner loops.
    std::size_t slotOf(std::uint64_t id) const;  // of an owned particle
    std::vector<Wall>& walls() { return state_.walls; }
    std::vector<PrescribedMotion>& motions() { return state_.motions; }
    std::mt19937_64& random() { return state_.random; }

    double time() const { return state_.time; }
    std::uint64_t step() const { return state_.step; }
    double timeStep() const { return state_.settings.timeStep; }
    double endTime() const { return state_.settings.endTime; }
    const std::string& name() const { return state_.settings.name; }

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
    // The shortest collision time over the species pairs present (Theory/ContactLaws.md eq. (9)-(10)), and what it is.
    double shortestCollisionTime(std::string* which = nullptr) const;

    SimulationState& state() { return state_; }
    const SimulationState& state() const { return state_; }
    const PairList& pairList() const { return state_.pairList; }
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
    class Host;  // the StepHost the steppers advance (Simulation.cc)
    void initialise(bool restarted);
    void refuseContradictions(const RunSettings& saved, const std::string& restartFile) const;
    void checkTimeStep() const;
    // The forces at the positions now, the neighbour list updated first (StepHost::computeForces).
    void computeForces(bool recordContacts, OverlapCheck check, const DriftPassResult* drifted = nullptr);
    void checkOverlaps(double limit, bool initial, bool agreeNow = true);
    std::size_t slotOf(std::uint64_t id, bool ghosts) const;
    void requireMotion(int motion, const std::string& what) const;
    std::size_t fixParticle(std::size_t slot, int motion);
    void reorderParticles(bool withPreviousForces);
    std::uint64_t saveEvery() const;

    SimulationState state_;
    // Outside the saved state: the force loop's scratch and what the steppers keep between steps
    // (Integration/StepWorkspace.h), the steppers, and the host they advance.
    std::unique_ptr<StepWorkspace> work_;
    std::unique_ptr<Integrator> integrator_;
    std::unique_ptr<Host> host_;
    std::unique_ptr<CommandLine> commandLine_;
    struct KeptValue {
        std::string name;
        double* real = nullptr;
        int* integer = nullptr;
        std::function<std::vector<double>()> saveList;  // a list, when set
        std::function<void(const std::vector<double>&)> restoreList;
    };
    std::vector<KeptValue> kept_;
    void addKept(KeptValue value);
    void saveKeptValues();
    void restoreKeptValues(const std::string& restartFile);
    std::vector<Boundary*> boundaries_;
    std::unique_ptr<OutputFiles> files_;
    std::unique_ptr<RankContext> ranks_;
    RunStatistics lastRun_;
    std::string restartFile_;
};

}  // namespace talus
