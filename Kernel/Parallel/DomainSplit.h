// The MPI domain split (DESIGN.md "Parallel", Documentation/Parallel.md): each rank owns the
// particles in its slab of the domain along x, and holds as ghosts copies of the particles of
// other ranks within the ghost width (the largest interaction distance plus the list's reach)
// of its slab.
//
// The pair list is built over owned particles and ghosts and lasts as long as in a serial run:
// between rebuilds a particle moves less than half the reach, so every pair that can touch is
// listed on the rank of each of its owned particles. At a rebuild (all ranks at once) the
// ghosts are dropped, particles that left their slab move to their new owner together with the
// contact histories that involve them, and the ghosts are made anew. Between rebuilds each
// step sends the ghosts' positions, velocities, spins, orientations and last forces from their
// owners (updateGhosts).
//
// Ghosts keep their owners' wrapped coordinates: a pair across a periodic face is found and
// computed through the nearest image exactly as in a serial run, and a pair across a rank
// boundary has the same arithmetic on both of its ranks (PairList::rebuild orients it by ids),
// so both apply exactly opposite forces. What differs from a serial run is only the order in
// which a particle's contact forces are summed (round-off; Documentation/Parallel.md).
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/PairList.h"
#include "Parallel/Communicator.h"
#include "Particles/ParticleStore.h"

namespace talus {

struct ContactRecord;

class DomainSplit {
public:
    explicit DomainSplit(Communicator& communicator) : communicator_(communicator) {}

    Communicator& communicator() { return communicator_; }
    int rank() const { return communicator_.rank(); }
    int ranks() const { return communicator_.size(); }
    bool isParallel() const { return communicator_.size() > 1; }

    // Places the slab boundaries so that each rank owns an equal share of the particles (a
    // histogram of x; the same result on every rank, whatever the particles' order).
    // replicated: every rank holds the whole scene (after setup or a restart read), so nothing
    // needs to be summed over ranks.
    void balance(const ParticleStore& particles, const Domain& domain, bool replicated);
    // The rank whose slab holds x: slabs are [bound(r), bound(r + 1)) with the outer ends open.
    int ownerOf(double x) const;
    // The interior slab boundaries, rank r's slab starting at boundaries()[r - 1].
    const std::vector<double>& boundaries() const { return bounds_; }

    // Every rank holds the whole scene (after setup or a restart read): keeps its own particles.
    void keepOwnShare(ParticleStore& particles) const;
    // Drops the ghosts and sends each owned particle that left this rank's slab to its owner,
    // with the carried histories that involve it; appends what arrives (in rank order). carried
    // ends sorted, without duplicates.
    void migrate(ParticleStore& particles, std::vector<CarriedHistory>& carried);
    // Appends as ghosts the particles of other ranks closer than width to this rank's slab.
    void makeGhosts(ParticleStore& particles, const Domain& domain, double width);
    // Each step: the ghosts get their owners' positions, velocities, spins, last forces and
    // orientations.
    void updateGhosts(ParticleStore& particles);

    // Output: the owned particles of every rank on rank 0, in rank order (empty elsewhere).
    ParticleStore gatherParticles(const ParticleStore& particles);
    // The contact records (slots of this rank) on rank 0, with slots of the gathered store.
    std::vector<ContactRecord> gatherRecords(const ParticleStore& particles, const std::vector<ContactRecord>& records,
                                             const ParticleStore& gathered);
    // Histories (of the pairs listed first on this rank) on rank 0, sorted.
    std::vector<CarriedHistory> gatherHistories(const std::vector<CarriedHistory>& mine);

    std::size_t ghostsSent() const;
    // Particles this rank sent to other ranks so far, and those of them that went to a rank more
    // than one slab away (for three or more ranks along a periodic x: across the periodic face).
    std::uint64_t migrated = 0, migratedFar = 0;

    // Wall seconds this rank spent on the split (Documentation/Parallel.md): sending ghosts each
    // step, agreeing with the other ranks each step (which includes waiting for the slowest:
    // load imbalance shows here), and migration with ghost making at list builds.
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
    Communicator& communicator_;
    std::vector<double> bounds_;  // ranks() - 1 interior boundaries, ascending
    // Ghost exchange of the current list: slots sent to each partner, ghosts received from each.
    std::vector<int> sendTo_, receiveFrom_;
    std::vector<std::vector<std::uint32_t>> sendSlots_;
    std::vector<std::size_t> receiveCount_;
    std::vector<Bytes> outgoing_, incoming_;
};

}  // namespace talus
