// The parts of talus::Simulation that run only on more than one rank (Parallel/DomainSplit.h,
// Documentation/Parallel.md): splitting the scene, the neighbourhood update of each step, the
// agreement of all ranks on errors, and output gathered on rank 0.
#include <algorithm>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "IO/OutputFiles.h"
#include "Integration/StepWorkspace.h"
#include "Parallel/DomainSplit.h"
#include "Simulation.h"

namespace talus {

// Every rank set up (or read) the whole scene; each keeps the particles of its slab and the
// contact histories that involve them. The first step builds the list (and rebalances).
void Simulation::splitScene() {
    require(runsOnRanks_, "driver '" + name() + "' has not been made rank-aware (setRunsOnRanks): its analysis "
                          "would see the particles of one rank only; run it without mpirun (Documentation/Parallel.md)");
    for (const Boundary* b : boundaries_)
        require(b->runsOnRanks(), "this driver has a boundary that does not run on more than one rank yet; run it "
                                  "without mpirun (Documentation/Parallel.md lists what runs on ranks)");
    ParticleStore& p = state_.particles;
    PairList& list = state_.pairList;
    pendingHistories_ = list.carriedHistories(p);
    for (Vec3& x : p.position) state_.domain.wrap(x);
    split_->balance(p, state_.domain, /*replicated*/ true);
    split_->keepOwnShare(p);
    const std::unordered_set<std::uint64_t> mine(p.id.begin(), p.id.end());
    std::erase_if(pendingHistories_, [&mine](const CarriedHistory& c) { return !mine.count(c.a) && !mine.count(c.b); });
    list.clear();
    rebalancePending_ = true;
}

void Simulation::requestRebalance() { rebalancePending_ = true; }

// All ranks agree whether to rebuild (any rank's particle moved too far), on the largest speed,
// and on stopping if a rank found a non-finite position now or overlaps beyond the limit at the
// end of the last step (Simulation::OverlapCheck): the one collective of a step that writes no
// output. A rebuild drops the ghosts, rebalances
// if asked, migrates particles with their histories, reorders, and makes the ghosts anew;
// otherwise the ghosts are brought up to date.
bool Simulation::updateNeighbourhoodOnRanks(std::vector<CarriedHistory>& carried) {
    ParticleStore& p = state_.particles;
    PairList& list = state_.pairList;
    const double dt = state_.settings.timeStep;
    std::string failure = std::move(overlapsToAgree_);  // the earlier of two diagnoses
    overlapsToAgree_.clear();
    bool rebuild = false;
    try {
        // Particles that boundaries added or moved have their pairs relisted if no other rank
        // needs them as ghosts (PairList::relist); else the list is built anew, on every rank.
        for (std::uint32_t slot : list.noted())
            if (slot < list.referencePosition.size() &&
                !split_->nobodyElseNeeds(list.referencePosition[slot], p.species[slot], state_.domain))
                list.valid = false;
        list.relist(p, state_.domain, state_.walls);
        rebuild = list.needsRebuild(p, state_.domain, state_.time, dt);
    } catch (const Error& e) {
        if (failure.empty()) failure = e.what();
    }
    // A rebalance that is due (the same step on every rank) needs a list build to act.
    const bool due = rebalanceInterval_ > 0 && state_.time >= lastBalanceTime_ + rebalanceInterval_ - 0.5 * dt;
    // (And whether a rank found its particles moved by hand since the last step: their ghosts
    // on other ranks moved too, and every rank's near list is made anew: PositionWatch::checkFound.)
    bool& positionsChanged = work_->positions.changedThisStep;
    double agreed[4] = {rebuild || due ? 1.0 : 0.0, list.maxSpeed, failure.empty() ? 0.0 : rank() + 1.0,
                        positionsChanged ? 1.0 : 0.0};
    positionsChanged = false;
    {
        const DomainSplit::Stopwatch watch(split_->seconds.agreement);
        split_->communicator().allReduce(agreed, 4, Communicator::Reduction::max);
    }
    if (agreed[3] > 0) list.near.made = false;
    if (agreed[2] > 0)
        throw CollectiveError(failure.empty() ? "stopped: rank " + std::to_string(int(agreed[2]) - 1) + " found a blow-up"
                                              : failure,
                              failure.empty());
    list.maxSpeed = agreed[1];
    if (agreed[0] == 0) {
        split_->updateGhosts(p);
        return false;
    }
    renumberNewParticles();
    carried = list.carriedHistories(p);
    carried.insert(carried.end(), pendingHistories_.begin(), pendingHistories_.end());
    pendingHistories_.clear();
    list.clear();
    if (rebalancePending_ || due) rebalance();
    split_->migrate(p, carried);
    reorderParticles(/*withPreviousForces*/ false);
    split_->makeGhosts(p, state_.domain, 2 * largestRadius_ + list.skin + 2 * list.maxSpeed * dt);
    return true;
}

// Equal particle counts (a function of the positions only, so runs stay repeatable).
void Simulation::rebalance() {
    split_->balance(state_.particles, state_.domain, /*replicated*/ false);
    lastBalanceTime_ = state_.time;
    rebalancePending_ = false;
}

// A boundary adds or removes a particle while ghosts sit behind the owned particles: the list's
// histories are kept by ids until the rebuild that the change forces, and the ghosts go (the
// rebuild makes them anew).
void Simulation::releaseGhosts() {
    std::vector<CarriedHistory> carried = state_.pairList.carriedHistories(state_.particles);
    pendingHistories_.insert(pendingHistories_.end(), carried.begin(), carried.end());
    state_.pairList.clear();
    state_.particles.dropGhosts();
}

// The particles added on any rank since the last call get their ids: every rank learns the new
// particles of all (their provisional ids and positions), orders them by position, and numbers
// them from nextId on, so that the ids do not depend on which rank made which particle.
void Simulation::renumberNewParticles() {
    ParticleStore& p = state_.particles;
    struct Added {
        double x, y, z;
        std::uint64_t provisional;
        bool operator<(const Added& o) const {
            return std::tie(x, y, z, provisional) < std::tie(o.x, o.y, o.z, o.provisional);
        }
    };
    Bytes mine;
    Packer out(mine);
    if (provisionalIds_ > 0)
        for (std::size_t i = 0; i < p.owned(); ++i)
            if (p.id[i] >= provisionalIdBase) out.put(Added{p.position[i].x(), p.position[i].y(), p.position[i].z(), p.id[i]});
    std::vector<Added> all;
    for (const Bytes& bytes : split_->communicator().allGather(mine)) {
        Unpacker in(bytes);
        while (!in.atEnd()) all.push_back(in.get<Added>());
    }
    if (all.empty()) return;
    std::sort(all.begin(), all.end());
    std::unordered_map<std::uint64_t, std::uint64_t> finalId;
    for (std::size_t k = 0; k < all.size(); ++k) finalId.emplace(all[k].provisional, state_.nextId + k);
    for (std::size_t i = 0; i < p.owned(); ++i)
        if (p.id[i] >= provisionalIdBase) p.id[i] = finalId.at(p.id[i]);
    state_.nextId += all.size();
    provisionalIds_ = 0;
}

void Simulation::agreeOnOverlaps(const std::string& diagnosis) {
    double failed = diagnosis.empty() ? 0.0 : rank() + 1.0;
    {
        const DomainSplit::Stopwatch watch(split_->seconds.agreement);
        split_->communicator().allReduce(&failed, 1, Communicator::Reduction::max);
    }
    if (failed > 0)
        throw CollectiveError(diagnosis.empty() ? "stopped: rank " + std::to_string(int(failed) - 1) +
                                                      " found overlaps beyond the limit"
                                                : diagnosis,
                              diagnosis.empty());
}

namespace {

// The gathered histories as the pair list of the gathered particles, marked invalid: a run
// restarted from it (on any number of ranks) builds its list at the first step and finds the
// histories by ids, as the running one does after every save.
PairList listOfGathered(const std::vector<CarriedHistory>& histories, const ParticleStore& gathered,
                        const PairList& running, std::size_t walls) {
    PairList saved;
    if (running.history.hasWarmStarts()) saved.enableWarmStarts();
    saved.skin = running.skin;
    saved.reach = running.reach;
    saved.maxSpeed = running.maxSpeed;
    saved.builds = running.builds;
    std::unordered_map<std::uint64_t, std::uint32_t> slotOf;
    for (std::uint32_t i = 0; i < gathered.size(); ++i) slotOf.emplace(gathered.id[i], i);
    for (const CarriedHistory& c : histories) {
        const std::uint32_t a = slotOf.at(c.a);
        if (c.b > CarriedHistory::wallKey(static_cast<std::uint32_t>(walls))) {
            saved.wallPairs.push_back({a, static_cast<std::uint32_t>(~std::uint64_t{0} - c.b)});
            saved.wallHistory.push_back(c.history);
        } else {
            saved.pairs.push_back({a, slotOf.at(c.b)});
            saved.history.push_back(c.history);
        }
    }
    return saved;
}

}  // namespace

// Rank 0 writes the frame and the restart file of the particles, contacts and histories of all
// ranks, with the same writers as a serial run; then every rank marks its list for a rebuild at
// the next step, which is what a run restarted from these files does first (exact restarts).
void Simulation::writeGatheredOutput() {
    saveKeptValues();
    const RunSettings& c = state_.settings;
    if (!(c.writeData || c.writeFstat || c.writeEne || c.writeVtu || c.writeRestart)) return;  // nothing to gather
    renumberNewParticles();
    ParticleStore& p = state_.particles;
    ParticleStore gathered = split_->gatherParticles(p);
    const ContactRecordList records = split_->gatherRecords(p, work_->records.each(), gathered);
    const std::vector<CarriedHistory> histories =
        split_->gatherHistories(state_.pairList.carriedHistories(p, /*firstOwned*/ true));
    if (rank() == 0 && files_) {
        PairList saved = listOfGathered(histories, gathered, state_.pairList, state_.walls.size());
        std::swap(state_.particles, gathered);
        std::swap(state_.pairList, saved);
        auto swapBack = [&] {
            std::swap(state_.particles, gathered);
            std::swap(state_.pairList, saved);
        };
        try {
            files_->writeFrame(state_, records, work_->recordedContacts, work_->elasticEnergy);
            files_->writeRestart(state_);
        } catch (...) {
            swapBack();
            throw;
        }
        swapBack();
    }
    if (!c.writeRestart) return;
    state_.pairList.valid = false;
    rebalancePending_ = true;
}

}  // namespace talus
