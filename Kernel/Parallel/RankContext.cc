// The ranks of a run (Parallel/RankContext.h, Documentation/Parallel.md): splitting the scene,
// the neighbourhood update of each step, the agreement of all ranks on errors, and output
// gathered on rank 0.
#include "Parallel/RankContext.h"

#include <algorithm>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "Contacts/PairList.h"
#include "IO/OutputFiles.h"
#include "Integration/StepWorkspace.h"
#include "Parallel/DomainSplit.h"
#include "Particles/DriftPass.h"
#include "Particles/VelocityVerlet.h"
#include "SimulationState.h"

namespace talus {

RankContext::RankContext(Communicator& world) : world_(world) {}
RankContext::~RankContext() = default;

int RankContext::rank() const { return world_.rank(); }
int RankContext::count() const { return world_.size(); }
bool RankContext::isSplit() const { return split_ && split_->isParallel(); }

double RankContext::sum(double x) const { return isSplit() ? world_.sum(x) : x; }
double RankContext::max(double x) const { return isSplit() ? world_.max(x) : x; }
void RankContext::sum(std::vector<double>& values) const {
    if (isSplit()) world_.allReduce(values.data(), static_cast<int>(values.size()), Communicator::Reduction::sum);
}

void RankContext::setRebalanceInterval(double interval) {
    require(interval >= 0, "flag --rebalance-interval must not be negative");
    rebalanceInterval_ = interval;
}

void RankContext::start(const SimulationState& s) {
    split_ = std::make_unique<DomainSplit>(world_);
    if (grid_[0] > 0) split_->setGrid(grid_);
    largestRadius_ = 0;
    for (double r : s.particles.radius) largestRadius_ = std::max(largestRadius_, r);
}

std::uint64_t RankContext::idOfNewParticle(SimulationState& s) {
    if (!isSplit()) return s.nextId++;
    return provisionalIdBase + (std::uint64_t(rank()) << 40) + provisionalIds_++;
}

bool RankContext::isSentAsGhost(std::size_t slot) const {
    return isSplit() && split_->isSentAsGhost(static_cast<std::uint32_t>(slot));
}

// The first step builds the list (and rebalances).
void RankContext::splitScene(SimulationState& s, bool boundariesRunOnRanks, const std::string& name) {
    require(runsOnRanks_, "driver '" + name + "' has not been made rank-aware (setRunsOnRanks): its analysis "
                          "would see the particles of one rank only; run it without mpirun (Documentation/Parallel.md)");
    require(boundariesRunOnRanks, "this driver has a boundary that does not run on more than one rank yet; run it "
                                  "without mpirun (Documentation/Parallel.md lists what runs on ranks)");
    ParticleStore& p = s.particles;
    PairList& list = s.pairList;
    pendingHistories_ = list.carriedHistories(p);
    for (Vec3& x : p.position) s.domain.wrap(x);
    split_->balance(p, s.domain, /*replicated*/ true);
    split_->keepOwnShare(p);
    const std::unordered_set<std::uint64_t> mine(p.id.begin(), p.id.end());
    std::erase_if(pendingHistories_, [&mine](const CarriedHistory& c) { return !mine.count(c.a) && !mine.count(c.b); });
    list.clear();
    rebalancePending_ = true;
}

// All ranks agree whether to rebuild (any rank's particle moved too far), on the largest speed,
// and on stopping if a rank found a non-finite position now or overlaps beyond the limit at the
// end of the last step (OverlapCheck, Integration/StepHost.h): the one collective of a step that
// writes no output. A rebuild drops the ghosts, rebalances if asked, migrates particles with
// their histories, reorders, and makes the ghosts anew; otherwise the ghosts are brought up to
// date.
bool RankContext::updateNeighbourhood(SimulationState& s, bool& positionsChanged, const DriftPassResult* drifted,
                                      std::vector<CarriedHistory>& carried,
                                      const std::function<void()>& reorder, StepWorkspace* work,
                                      std::unique_ptr<AnyContactForceLoop>* begun) {
    ParticleStore& p = s.particles;
    PairList& list = s.pairList;
    const double dt = s.settings.timeStep;
    std::string failure = std::move(overlapsToAgree_);  // the earlier of two diagnoses
    overlapsToAgree_.clear();
    require(!drifted || work, "updateNeighbourhood: a drift pass without its workspace");
    bool rebuild = false;
    try {
        // Particles that boundaries added or moved have their pairs relisted if no other rank
        // needs them as ghosts (PairList::relist); else the list is built anew, on every rank.
        for (std::uint32_t slot : list.noted())
            if (slot < list.referencePosition.size() &&
                !split_->nobodyElseNeeds(list.referencePosition[slot], p.species[slot], s.domain))
                list.valid = false;
        list.relist(p, s.domain, s.walls);
        rebuild = drifted ? list.needsRebuild(drifted->moves, p, s.time, dt) : list.needsRebuild(p, s.domain, s.time, dt);
    } catch (const Error& e) {
        if (failure.empty()) failure = e.what();
    }
    // A rebalance that is due (the same step on every rank) needs a list build to act.
    const bool due = rebalanceInterval_ > 0 && s.time >= lastBalanceTime_ + rebalanceInterval_ - 0.5 * dt;
    // (And whether a rank found its particles moved by hand since the last step: their ghosts
    // on other ranks moved too, and every rank's near list is made anew: PositionWatch::checkFound.)
    DomainSplit::Agreement agreed = {rebuild || due ? 1.0 : 0.0, list.maxSpeed, failure.empty() ? 0.0 : rank() + 1.0,
                                     positionsChanged ? 1.0 : 0.0};
    positionsChanged = false;
    // The ghosts' states travel while the ranks agree, with this rank's numbers: when every
    // other rank is a partner they are the agreement (no allreduce); else an allreduce runs while
    // the messages travel. One wait for both; the states are applied unless the step rebuilds.
    split_->startGhostUpdate(p, drifted ? work->previousForce : p.force, agreed);
    // The interior pairs meanwhile, unless this rank already knows that the list goes (or that
    // the run stops, or that its near list was unmade: moved particles). Only in periodic
    // domains: without periodic faces the list has no interior pairs apart (PairList::interiorPairs).
    const bool overlap = begun && work && s.settings.stepper.overlapGhosts && !s.settings.idOrderedSums &&
                         !p.hasShapes() && s.domain.anyPeriodic() && agreed[0] == 0 && agreed[2] == 0 &&
                         agreed[3] == 0;
    if (overlap) beginInteriorPairs(s, *work, *begun);
    if (!split_->agreesThroughGhosts()) {
        const DomainSplit::Stopwatch watch(split_->seconds.agreement);
        world_.allReduce(agreed.data(), static_cast<int>(agreed.size()), Communicator::Reduction::max);
    }
    split_->finishGhostUpdate(agreed);
    const bool keep = agreed[0] == 0 && agreed[2] == 0;
    if (overlap && !keep) undoInteriorPairs(s, *work, *begun);
    if (keep) split_->applyGhostUpdate(p, overlap || drifted ? work->previousForce : p.force);
    if (drifted && !keep) p.force.swap(work->previousForce);
    if (agreed[3] > 0) list.near.made = false;
    if (agreed[2] > 0)
        throw CollectiveError(failure.empty() ? "stopped: rank " + std::to_string(int(agreed[2]) - 1) + " found a blow-up"
                                              : failure,
                              failure.empty());
    list.maxSpeed = agreed[1];
    if (agreed[0] == 0) return false;
    renumberNewParticles(s);
    list.carriedHistoriesInto(carried, p);
    carried.insert(carried.end(), pendingHistories_.begin(), pendingHistories_.end());
    pendingHistories_.clear();
    list.clear();
    if (rebalancePending_ || due) rebalance(s);
    split_->migrate(p, carried);
    reorder();
    split_->makeGhosts(p, s.domain, 2 * largestRadius_ + list.skin + 2 * list.maxSpeed * dt);
    return true;
}

// As the step would start its forces after the ghost update (Simulation::computeForces), but
// with the contact histories that the interior pairs change saved, to be put back by
// undoInteriorPairs. The largest speed is that of the last agreement until the caller gives the
// new one (allowSpeed: only the wall candidates read it).
void RankContext::beginInteriorPairs(SimulationState& s, StepWorkspace& work,
                                     std::unique_ptr<AnyContactForceLoop>& begun) {
    ParticleStore& p = s.particles;
    work.previousForce.swap(p.force);
    startForcesWithGravity(p, s.gravity);
    work.summary = ContactSummary{};
    if (!interiorChanges_) interiorChanges_ = std::make_unique<ContactHistoryLog>();
    interiorChanges_->clear();
    begun = std::visit(
        [&](const auto& laws) {
            return sphereContactForceLoop(p, laws, s.settings.timeStep, work.previousForce, work.summary);
        },
        work.laws);
    begun->interiorPairs(s.pairList, s.domain, s.motions.empty(), *interiorChanges_);
    ++overlappedSteps_;
}

// The histories as they were, and the last forces back in the particles' array, where the
// step takes them from after the build (the forces begun are dropped: the build starts anew).
void RankContext::undoInteriorPairs(SimulationState& s, StepWorkspace& work,
                                    std::unique_ptr<AnyContactForceLoop>& begun) {
    begun.reset();
    interiorChanges_->restore(s.pairList.history);
    s.particles.force.swap(work.previousForce);
    ++undoneOverlaps_;
}

// Equal work per rank (particles counted by their work, a function of the positions and shapes
// only, so runs stay repeatable: DomainSplit::balance).
void RankContext::rebalance(SimulationState& s) {
    split_->balance(s.particles, s.domain, /*replicated*/ false);
    lastBalanceTime_ = s.time;
    rebalancePending_ = false;
}

// (The rebuild makes the ghosts anew.)
void RankContext::releaseGhosts(SimulationState& s) {
    std::vector<CarriedHistory> carried = s.pairList.carriedHistories(s.particles);
    pendingHistories_.insert(pendingHistories_.end(), carried.begin(), carried.end());
    s.pairList.clear();
    s.particles.dropGhosts();
}

// The particles added on any rank since the last call get their ids: every rank learns the new
// particles of all (their provisional ids and positions), orders them by position, and numbers
// them from nextId on, so that the ids do not depend on which rank made which particle.
void RankContext::renumberNewParticles(SimulationState& s) {
    ParticleStore& p = s.particles;
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
    for (const Bytes& bytes : world_.allGather(mine)) {
        Unpacker in(bytes);
        while (!in.atEnd()) all.push_back(in.get<Added>());
    }
    if (all.empty()) return;
    std::sort(all.begin(), all.end());
    std::unordered_map<std::uint64_t, std::uint64_t> finalId;
    for (std::size_t k = 0; k < all.size(); ++k) finalId.emplace(all[k].provisional, s.nextId + k);
    for (std::size_t i = 0; i < p.owned(); ++i)
        if (p.id[i] >= provisionalIdBase) p.id[i] = finalId.at(p.id[i]);
    s.nextId += all.size();
    provisionalIds_ = 0;
}

void RankContext::agreeOnOverlaps(const std::string& diagnosis) {
    double failed = diagnosis.empty() ? 0.0 : rank() + 1.0;
    {
        const DomainSplit::Stopwatch watch(split_->seconds.agreement);
        world_.allReduce(&failed, 1, Communicator::Reduction::max);
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
    if (running.history.hasRollingSprings()) saved.enableRollingSprings();
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

// With the same writers as a serial run; then every rank marks its list for a rebuild at the next
// step, which is what a run restarted from these files does first (exact restarts).
void RankContext::writeGatheredOutput(SimulationState& s, OutputFiles* files, const StepWorkspace& work) {
    const RunSettings& c = s.settings;
    if (!(c.writeData || c.writeFstat || c.writeEne || c.writeVtu || c.writeRestart)) return;  // nothing to gather
    renumberNewParticles(s);
    ParticleStore& p = s.particles;
    ParticleStore gathered = split_->gatherParticles(p);
    const ContactRecordList records = split_->gatherRecords(p, work.records.each(), gathered);
    const std::vector<CarriedHistory> histories =
        split_->gatherHistories(s.pairList.carriedHistories(p, /*firstOwned*/ true));
    if (rank() == 0 && files) {
        PairList saved = listOfGathered(histories, gathered, s.pairList, s.walls.size());
        std::swap(s.particles, gathered);
        std::swap(s.pairList, saved);
        auto swapBack = [&] {
            std::swap(s.particles, gathered);
            std::swap(s.pairList, saved);
        };
        try {
            files->writeFrame(s, records, work.recordedContacts, work.elasticEnergy);
            files->writeRestart(s);
        } catch (...) {
            swapBack();
            throw;
        }
        swapBack();
    }
    if (!c.writeRestart) return;
    s.pairList.valid = false;
    rebalancePending_ = true;
}

}  // namespace talus
