// The MPI domain split (Documentation/Architecture.md "Parallel", Documentation/Parallel.md): the ranks form a
// Cartesian grid of gx x gy x gz cells (all along x unless set otherwise: a long chute splits
// along its flow); each rank owns the particles in its cell of the domain, and holds as ghosts
// copies of the particles of other ranks within the ghost width (the largest interaction
// distance plus the list's reach) of its cell. The cell boundaries along each axis are placed
// for equal counts of moving particles along that axis (fixed ones only where nothing moves).
//
// The pair list is built over owned particles and ghosts and lasts as long as in a serial run:
// between rebuilds a particle moves less than half the reach, so every pair that can touch is
// listed on the rank of each of its owned particles. At a rebuild (all ranks at once) the
// ghosts are dropped, particles that left their slab move to their new owner together with the
// contact histories that involve them, and the ghosts are made anew. Between rebuilds each
// step sends the ghosts' positions, velocities, spins, orientations and last forces from their
// owners (startGhostUpdate, finishGhostUpdate).
//
// Ghosts keep their owners' wrapped coordinates: a pair across a periodic face is found and
// computed through the nearest image exactly as in a serial run, and a pair across a rank
// boundary has the same arithmetic on both of its ranks (PairList::rebuild orients it by ids),
// so both apply exactly opposite forces. What differs from a serial run is only the order in
// which a particle's contact forces are summed (round-off; Documentation/Parallel.md).
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/ContactReport.h"
#include "Contacts/PairList.h"
#include "Parallel/Communicator.h"
#include "Particles/ParticleStore.h"

namespace talus {

class DomainSplit {
public:
    explicit DomainSplit(Communicator& communicator) : communicator_(communicator) {}

    Communicator& communicator() { return communicator_; }
    int rank() const { return communicator_.rank(); }
    int ranks() const { return communicator_.size(); }
    bool isParallel() const { return communicator_.size() > 1; }

    // The ranks per axis (their product is ranks()); rank r sits in the cell (r mod gx,
    // (r / gx) mod gy, r / (gx gy)). Before the first balance.
    void setGrid(const std::array<int, 3>& ranksPerAxis);
    const std::array<int, 3>& grid() const { return grid_; }
    // Places the cell boundaries along each split axis so that each layer of cells holds an equal
    // share of the moving particles' work (a superquadric counts as four spheres; a histogram
    // along the axis; the same result on every rank,
    // whatever the particles' order). replicated: every rank holds the whole scene (after setup
    // or a restart read), so nothing needs to be summed over ranks.
    void balance(const ParticleStore& particles, const Domain& domain, bool replicated);
    // The rank whose cell holds x: along each axis, cells are [bound(c), bound(c + 1)) with the
    // outer ends open.
    int ownerOf(const Vec3& x) const;
    // The interior cell boundaries along an axis, cell c starting at boundaries(axis)[c - 1].
    const std::vector<double>& boundaries(int axis) const { return bounds_[axis]; }

    // Every rank holds the whole scene (after setup or a restart read): keeps its own particles.
    void keepOwnShare(ParticleStore& particles) const;
    // Drops the ghosts and sends each owned particle that left this rank's slab to its owner,
    // with the carried histories that involve it; appends what arrives (in rank order). carried
    // ends sorted, without duplicates.
    void migrate(ParticleStore& particles, std::vector<CarriedHistory>& carried);
    // Appends as ghosts the particles of other ranks closer than width to this rank's slab.
    void makeGhosts(ParticleStore& particles, const Domain& domain, double width);
    // Each step: the ghosts get their owners' positions, velocities, spins, last forces and
    // orientations, in one message per partner rank, which also carries this rank's numbers for
    // the step's agreement (their maximum over the ranks decides whether the list is rebuilt).
    // start sends and returns; finish waits for the partners' messages; apply puts their states
    // into the ghosts' slots (not on a step that rebuilds: the ghosts are then made anew). When
    // every other rank is a partner both ways (two ranks; three along a periodic axis), finish
    // makes `agreement` the maximum over all ranks and no allreduce is needed
    // (agreesThroughGhosts); otherwise the caller agrees between start and finish.
    using Agreement = std::array<double, 4>;
    // lastForces: where the last forces are, of the particles sent and for the ghosts (the
    // particles' force array, or the step's previousForce where the step has started its forces
    // already: RankContext).
    void startGhostUpdate(const ParticleStore& particles, const std::vector<Vec3>& lastForces, const Agreement& mine);
    void finishGhostUpdate(Agreement& agreement);
    void applyGhostUpdate(ParticleStore& particles, std::vector<Vec3>& lastForces);
    bool agreesThroughGhosts() const { return partnersAreAll_; }
    // Whether a particle of this species at x, owned here, is one that no other rank needs as a
    // ghost by the width of the last makeGhosts (the neighbour list's relisting on ranks), and
    // whether the owned particle in a slot is sent to another rank as a ghost.
    bool nobodyElseNeeds(const Vec3& x, std::uint32_t species, const Domain& domain) const;
    bool isSentAsGhost(std::uint32_t slot) const;

    // Output: the owned particles of every rank on rank 0, in rank order (empty elsewhere).
    ParticleStore gatherParticles(const ParticleStore& particles);
    // The contact records (slots of this rank) on rank 0, with slots of the gathered store.
    ContactRecordList gatherRecords(const ParticleStore& particles, const ContactRecordList& records,
                                    const ParticleStore& gathered);
    // Histories (of the pairs listed first on this rank) on rank 0, sorted.
    std::vector<CarriedHistory> gatherHistories(const std::vector<CarriedHistory>& mine);

    std::size_t ghostsSent() const;
    // Particles this rank sent to other ranks so far; those that changed cell along each axis;
    // and those that went more than one cell away along an axis (for three or more ranks along
    // a periodic axis: across the periodic face).
    std::uint64_t migrated = 0, migratedFar = 0;
    std::array<std::uint64_t, 3> migratedAlong{0, 0, 0};

    // Wall seconds this rank spent on the split (Documentation/Parallel.md): the ghost exchange
    // each step, the allreduce of the step's agreement where it is needed (both include waiting
    // for the slowest rank: load imbalance shows here; when the agreement rides on the ghost
    // messages, all of it is in ghosts), and migration with ghost making at list builds.
    struct Timings {
        double ghosts = 0, agreement = 0, rebuild = 0;
        double total() const { return ghosts + agreement + rebuild; }
    } seconds;
    class Stopwatch {
    public:
        explicit Stopwatch(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
        ~Stopwatch() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

    private:
        double& total_;
        std::chrono::steady_clock::time_point start_;
    };

private:
    static double workOf(const ParticleStore& p, std::size_t i);
    int cellAlong(int axis, double x) const;
    std::array<int, 3> cellOf(int rank) const;
    int rankAt(int x, int y, int z) const { return x + grid_[0] * (y + grid_[1] * z); }

    Communicator& communicator_;
    std::array<int, 3> grid_{communicator_.size(), 1, 1};
    std::array<std::vector<double>, 3> bounds_;  // grid_[a] - 1 interior boundaries along a, ascending
    // Ghost exchange of the current list: slots sent to each partner, ghosts received from each.
    std::vector<int> sendTo_, receiveFrom_;
    std::vector<std::vector<std::uint32_t>> sendSlots_;
    double ghostWidth_ = 0;  // of the last makeGhosts
    bool partnersAreAll_ = false;  // on every rank: each other rank is a partner both ways
    // Calls f(r) for every rank r other than this one whose cell lies within width of x (through
    // the periodic images, and through an active maser box's image for its members): those that
    // hold a particle at x as a ghost.
    template <class F>
    void forEachOtherRankNear(const Vec3& x, std::uint32_t species, const Domain& domain, double width, F&& f) const;
    std::vector<std::size_t> receiveCount_;
    std::vector<Bytes> outgoing_, incoming_;
};

}  // namespace talus
