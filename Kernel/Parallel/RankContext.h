// The ranks of a run, as the simulation and its helpers see them (Documentation/Architecture.md
// "Parallel", Documentation/Parallel.md): who this rank is, sums and maxima over the ranks, and
// everything a split scene needs between the steps: the domain split (Parallel/DomainSplit.h),
// the neighbourhood update of each step (the one synchronisation of a step), the numbering of
// particles added on ranks, the agreement of all ranks on errors, and output gathered on rank 0.
//
// A simulation owns one; drivers never see it: their measurements go through Kernel/Sampling,
// which asks it (Simulation::ranks()). Without mpirun it is a single rank and every sum is the
// number itself. Collective calls (said so below) are made by every rank at the same point.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace talus {

class AnyContactForceLoop;
class Boundary;
class Communicator;
class ContactHistoryLog;
class DomainSplit;
class OutputFiles;
struct CarriedHistory;
struct DriftPassResult;
struct SimulationState;
struct StepWorkspace;

class RankContext {
public:
    explicit RankContext(Communicator& world);
    ~RankContext();
    RankContext(const RankContext&) = delete;
    RankContext& operator=(const RankContext&) = delete;

    // --- asked by the helpers of drivers (Kernel/Sampling), boundaries and tests ---
    // This rank (0 without mpirun; rank 0 writes the files) and the ranks of the run.
    int rank() const;
    int count() const;
    // Whether the scene is split over more than one rank (false during setupInitialConditions,
    // which every rank runs on the whole scene).
    bool isSplit() const;
    // Sums and maxima over the ranks (collective when split; the number itself otherwise).
    double sum(double x) const;
    void sum(std::vector<double>& values) const;
    double max(double x) const;
    // The domain split of the run (after the run has started; one rank without mpirun).
    const DomainSplit* split() const { return split_.get(); }

    // --- settings ---
    // Drivers run on ranks by default: their measurements go through Kernel/Sampling (whole-scene
    // sums, files and messages written once). A driver whose hooks read particles() directly for
    // whole-scene numbers says setRunsOnRanks(false) and then refuses to start on more ranks.
    void setRunsOnRanks(bool on) { runsOnRanks_ = on; }
    // Place the rank boundaries by particle count at the next list build (Documentation/Parallel.md);
    // done at the start and after every save anyway, and every interval of simulated time if set.
    void requestRebalance() { rebalancePending_ = true; }
    void setRebalanceInterval(double interval);
    // The ranks along x, y and z (--rank-grid); zeros: all along x.
    void setGrid(const std::array<int, 3>& ranksPerAxis) { grid_ = ranksPerAxis; }

    // --- the simulation's side (Simulation*.cc) ---
    // A run starts: a new split of the world; the largest radius over the scene (for the ghost
    // width). Every rank holds the whole scene here.
    void start(const SimulationState& s);
    // Every rank set up (or read) the whole scene; each keeps the particles of its cell and the
    // contact histories that involve them. boundariesRunOnRanks: all of the scene's do.
    void splitScene(SimulationState& s, bool boundariesRunOnRanks, const std::string& name);
    // The id of a particle added now: the next id, or on a split scene a provisional one unique
    // to this rank until all ranks number their new particles together (at the next list build
    // or save).
    std::uint64_t idOfNewParticle(SimulationState& s);
    // Whether the owned particle in a slot is another rank's ghost (a jump there needs a build).
    bool isSentAsGhost(std::size_t slot) const;
    // A particle is added or removed while ghosts sit behind the owned ones: the list's histories
    // are kept by ids until the build that the change forces, and the ghosts go.
    void releaseGhosts(SimulationState& s);
    // Before each step's forces on a split scene (collective): relists, agrees with all ranks on
    // a rebuild, the largest speed, errors and moved positions; then either updates the ghosts
    // (returns false) or migrates, rebalances if due, calls reorder and makes the ghosts anew,
    // filling carried with the histories for the build (returns true).
    // begun (given by a step that may: no contacts recorded, no drift pass): while the ghosts'
    // states travel, a rank that keeps its list starts the step's forces (the last ones become
    // work.previousForce, the new ones start from gravity) and computes its interior pairs,
    // which read no ghost (AnyContactForceLoop::interiorPairs), in the loop it leaves in begun
    // for the rest of the step; if another rank rebuilds the list after all, all of that is
    // undone (begun empty), and the step computes its forces after the build as without begun.
    // Spheres only, in a periodic domain, without sums in id order, and with --overlap-ghosts on.
    // drifted (a step whose drift pass, Particles/DriftPass.h, measured the owned particles' moves
    // and started their forces, the last ones in work.previousForce): the moves are taken from it,
    // the ghosts' last forces go into work.previousForce, and a rebuild first puts the last forces
    // back into the particles (they travel with migrating particles; the step starts its forces
    // after the build).
    bool updateNeighbourhood(SimulationState& s, bool& positionsChanged, const DriftPassResult* drifted,
                             std::vector<CarriedHistory>& carried,
                             const std::function<void()>& reorder, StepWorkspace* work = nullptr,
                             std::unique_ptr<AnyContactForceLoop>* begun = nullptr);
    // Steps that computed interior pairs while their ghosts travelled, and those of them undone
    // (another rank rebuilt the list), on this rank.
    std::uint64_t overlappedSteps() const { return overlappedSteps_; }
    std::uint64_t undoneOverlaps() const { return undoneOverlaps_; }
    // A blow-up diagnosis (empty: none): agreed now by all ranks (collective), or with the next
    // step's neighbourhood update.
    void agreeOnOverlaps(const std::string& diagnosis);
    void agreeOnOverlapsWithNextStep(const std::string& diagnosis) { overlapsToAgree_ = diagnosis; }
    // Rank 0 writes the frame and the restart file of the particles, contacts and histories of
    // all ranks with files (null elsewhere; collective); every rank then builds its list anew.
    void writeGatheredOutput(SimulationState& s, OutputFiles* files, const StepWorkspace& work);

private:
    void renumberNewParticles(SimulationState& s);
    void rebalance(SimulationState& s);
    void beginInteriorPairs(SimulationState& s, StepWorkspace& work, std::unique_ptr<AnyContactForceLoop>& begun);
    void undoInteriorPairs(SimulationState& s, StepWorkspace& work, std::unique_ptr<AnyContactForceLoop>& begun);

    Communicator& world_;
    std::unique_ptr<DomainSplit> split_;
    std::vector<CarriedHistory> pendingHistories_;  // of a scene just split, until its first list build
    double largestRadius_ = 0;                      // over all ranks, for the ghost width
    bool rebalancePending_ = false;
    // Rank boundaries by particle count (Documentation/Parallel.md), at the start, at saves, on
    // request, and every rebalanceInterval_ of simulated time.
    double rebalanceInterval_ = 0, lastBalanceTime_ = 0;
    std::array<int, 3> grid_{0, 0, 0};
    bool runsOnRanks_ = true;
    std::uint64_t provisionalIds_ = 0;  // particles this rank added since the last renumbering
    static constexpr std::uint64_t provisionalIdBase = std::uint64_t{1} << 62;
    std::string overlapsToAgree_;  // this rank's overlap blow-up, for the next step's agreement
    std::unique_ptr<ContactHistoryLog> interiorChanges_;  // the histories the interior pairs changed this step
    std::uint64_t overlappedSteps_ = 0, undoneOverlaps_ = 0;
};

}  // namespace talus
