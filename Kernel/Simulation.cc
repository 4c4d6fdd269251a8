#include "Simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "IO/CommandLine.h"
#include "IO/OutputFiles.h"
#include "IO/Progress.h"
#include "IO/RestartFile.h"
#include "Parallel/DomainSplit.h"
#include "Particles/RotationBatch.h"
#include "Particles/SpaceFillingCurve.h"
#include "Particles/VelocityVerlet.h"

namespace talus {

namespace {

// Whether the step numbered `step` writes output (and records its contacts): every `every`
// steps and the run's last; k: that step's count in the run, steps: the run's length.
bool isOutputStep(std::uint64_t step, std::uint64_t k, std::uint64_t steps, std::uint64_t every) {
    return step % every == 0 || k == steps;
}

}  // namespace

Simulation::~Simulation() = default;

// --- settings ---

void Simulation::setName(const std::string& name) {
    requireWord(name, "name");
    state_.settings.name = name;
}
void Simulation::setTimeStep(double dt) {
    require(std::isfinite(dt) && dt > 0, "time step (--dt) must be positive, got " + str(dt));
    state_.settings.timeStep = dt;
}
void Simulation::setEndTime(double endTime) {
    require(std::isfinite(endTime) && endTime >= 0, "end time (--end-time) must not be negative, got " + str(endTime));
    state_.settings.endTime = endTime;
}
void Simulation::setOutputInterval(double interval) {
    require(std::isfinite(interval) && interval >= 0,
            "output interval (--output-interval) must not be negative, got " + str(interval));
    state_.settings.outputInterval = interval;
}
void Simulation::setSkin(double skin) {
    require(std::isfinite(skin) && skin >= 0, "skin (--skin) must not be negative, got " + str(skin));
    state_.settings.skin = skin;
}
void Simulation::setCellSizeRatio(double ratio) {
    require(std::isfinite(ratio) && ratio > 1, "HGrid cell size ratio must be greater than 1, got " + str(ratio));
    state_.settings.cellSizeRatio = ratio;
}
void Simulation::setFileOutput(bool on) {
    RunSettings& c = state_.settings;
    c.writeData = c.writeFstat = c.writeEne = c.writeVtu = c.writeRestart = on;
}

void Simulation::addFlag(const std::string& name, const std::string& help, double& value) {
    commandLine_->add(name, "X", help + " (default " + str(value) + ")",
                      [&value, name](const std::string& v) { value = CommandLine::toDouble(name, v); });
    keepInRestart("flag." + name, value);
}
void Simulation::addFlag(const std::string& name, const std::string& help, int& value) {
    commandLine_->add(name, "N", help + " (default " + std::to_string(value) + ")",
                      [&value, name](const std::string& v) { value = CommandLine::toInt(name, v); });
    keepInRestart("flag." + name, value);
}

void Simulation::keepInRestart(const std::string& name, double& value) { addKept({name, &value, nullptr, {}, {}}); }
void Simulation::keepInRestart(const std::string& name, int& value) { addKept({name, nullptr, &value, {}, {}}); }
void Simulation::keepInRestart(const std::string& name, std::function<std::vector<double>()> save,
                               std::function<void(const std::vector<double>&)> restore) {
    require(save && restore, "keepInRestart: '" + name + "' needs both a save and a restore function");
    addKept({name, nullptr, nullptr, std::move(save), std::move(restore)});
}

void Simulation::addKept(KeptValue value) {
    require(!value.name.empty() && value.name.find_first_of(" \t\n") == std::string::npos,
            "keepInRestart: the name must be one word, got '" + value.name + "'");
    for (const KeptValue& k : kept_)
        require(k.name != value.name, "keepInRestart: the name '" + value.name + "' is taken");
    kept_.push_back(std::move(value));
}

void Simulation::saveKeptValues() {
    state_.keptValues.clear();
    for (const KeptValue& k : kept_) {
        if (!k.saveList) {
            state_.keptValues.emplace_back(k.name, k.real ? *k.real : *k.integer);
            continue;
        }
        const std::vector<double> values = k.saveList();
        state_.keptValues.emplace_back(k.name + ".size", static_cast<double>(values.size()));
        for (std::size_t i = 0; i < values.size(); ++i) state_.keptValues.emplace_back(k.name + "." + std::to_string(i), values[i]);
    }
}

// Every kept value must be in the file: a restart file of another driver (or of an older build
// of this one) would otherwise continue with values that were never saved.
void Simulation::restoreKeptValues(const std::string& restartFile) {
    const std::unordered_map<std::string, double> values(state_.keptValues.begin(), state_.keptValues.end());
    auto saved = [&](const std::string& name) {
        const auto it = values.find(name);
        require(it != values.end(), restartFile + ": no value '" + name + "' (a restart file of another driver?)");
        return it->second;
    };
    for (const KeptValue& k : kept_) {
        if (k.real)
            *k.real = saved(k.name);
        else if (k.integer)
            *k.integer = static_cast<int>(saved(k.name));
        else {
            const double size = saved(k.name + ".size");
            require(size >= 0 && size == std::floor(size) && size <= static_cast<double>(state_.keptValues.size()),
                    restartFile + ": '" + k.name + ".size' is not a list length");
            std::vector<double> list(static_cast<std::size_t>(size));
            for (std::size_t i = 0; i < list.size(); ++i) list[i] = saved(k.name + "." + std::to_string(i));
            k.restoreList(list);
        }
    }
}

void Simulation::addTextFlag(const std::string& name, const std::string& help, std::string& value) {
    commandLine_->add(name, "TEXT", help + " (default " + value + ")", [&value](const std::string& v) { value = v; });
}

Energies Simulation::energies() const {
    Energies e = particleEnergies(state_.particles, state_.gravity);
    e.elastic = elasticEnergy_;
    if (!onRanks()) return e;
    const Vec3 moment = e.mass > 0 ? Vec3(e.mass * e.centreOfMass) : Vec3::Zero();
    std::vector<double> sums = {e.gravitational, e.kinetic, e.rotational, e.mass, moment.x(), moment.y(), moment.z()};
    sumOverRanks(sums);
    e.gravitational = sums[0], e.kinetic = sums[1], e.rotational = sums[2], e.mass = sums[3];
    e.centreOfMass = e.mass > 0 ? Vec3(Vec3(sums[4], sums[5], sums[6]) / e.mass) : Vec3::Constant(NAN);
    return e;  // elastic: summed over ranks when the contacts were recorded
}

int Simulation::rank() const { return split_ ? split_->rank() : worldCommunicator().rank(); }
int Simulation::ranks() const { return split_ ? split_->ranks() : worldCommunicator().size(); }
bool Simulation::onRanks() const { return split_ && split_->isParallel(); }

double Simulation::sumOverRanks(double x) const { return onRanks() ? split_->communicator().sum(x) : x; }
double Simulation::maxOverRanks(double x) const { return onRanks() ? split_->communicator().max(x) : x; }
void Simulation::sumOverRanks(std::vector<double>& values) const {
    if (onRanks())
        split_->communicator().allReduce(values.data(), static_cast<int>(values.size()), Communicator::Reduction::sum);
}

std::size_t Simulation::mobileParticleCount() const {
    const ParticleStore& p = state_.particles;
    double mobile = 0;
    for (std::size_t i = 0; i < p.owned(); ++i) mobile += !p.fixed[i];
    return static_cast<std::size_t>(sumOverRanks(mobile));
}

// --- the run ---

int Simulation::solve(int argc, char** argv) {
    std::vector<std::string> flags(argv + (argc > 0 ? 1 : 0), argv + argc);
    try {
        solveOrThrow(flags);
        return 0;
    } catch (const Error& e) {
        // Before the scene is split every rank does the same (and fails alike): rank 0 speaks.
        const auto* collective = dynamic_cast<const CollectiveError*>(&e);
        const bool replicated = !onRanks() && rank() != 0;
        if ((!collective || !collective->silent()) && !replicated)
            std::cerr << (argc > 0 ? argv[0] : "talus") << ": error: " << e.what() << std::endl;
        // An error that only this rank saw would leave the others waiting for it: end them all.
        if (!collective && ranks() > 1) worldCommunicator().abort(1);
        return 1;
    }
}

void Simulation::solveOrThrow(const std::vector<std::string>& flags) {
    restartFile_.clear();
    if (!commandLine_->parse(flags)) {
        std::cout << commandLine_->help(name());
        return;
    }
    const std::string restartFile = restartFile_;
    if (!restartFile.empty()) {
        readRestartFile(restartFile, state_);
        restoreKeptValues(restartFile);
    } else
        setupInitialConditions();
    // The command line has the last word: over the settings of the restart file, and over run
    // settings that setupInitialConditions may have made; a restarted run's time step and
    // summation mode excepted.
    const RunSettings saved = state_.settings;
    commandLine_->parse(flags);
    if (!restartFile.empty()) refuseContradictions(saved, restartFile);
    initialise(!restartFile.empty());

    const double dt = state_.settings.timeStep;
    const double remaining = state_.settings.endTime - state_.time;
    const auto steps = remaining > 0 ? static_cast<std::uint64_t>(std::llround(remaining / dt)) : 0;
    std::size_t mobile = mobileParticleCount();
    std::ostringstream quiet;  // ranks other than 0 print nothing
    std::ostream& out = rank() == 0 ? std::cout : quiet;
    Progress progress(out, state_.settings.progressInterval);
    progress.start(name(), state_.time, state_.settings.endTime, steps, mobile);
    const std::uint64_t every = saveEvery();
    std::size_t counted = state_.particles.size();
    const std::uint64_t buildsAtStart = state_.pairList.builds;
    const std::uint64_t relistedAtStart = state_.pairList.relistedParticles;
    const std::uint64_t nearMakesAtStart = state_.pairList.near.makes;
    stepsInWaves_ = waveNearRunsFound_ = waveNearGivenUp_ = 0;
    for (std::uint64_t k = 1; k <= steps; ++k) {
        if (waveAllowed(steps - k + 1, every) && !waveHasRoom(lastDisplacement_, state_.pairList.reach))
            buildListForWave();  // (instead of single steps until the list needs a build)
        if (waveFits(steps - k + 1, every)) {  // several steps in one pass (SimulationWaves.cc)
            const auto waveSteps = static_cast<std::uint64_t>(state_.settings.waveSteps);
            const std::uint64_t last = k + waveSteps - 1;
            const bool savingLast = isOutputStep(state_.step + waveSteps, last, steps, every);
            actionsBeforeTimeStep();
            const std::uint64_t done = integrateWave(savingLast);
            k += done - 1;
            actionsAfterTimeStep();
            if (k == last && savingLast) {
                writeOutput();
                records_.release();
            }
            progress.update(state_.time, k, mobile);
            continue;
        }
        const bool saving = isOutputStep(state_.step + 1, k, steps, every);
        actionsBeforeTimeStep();
        integrate(saving);
        actionsAfterTimeStep();
        if (saving) {
            writeOutput();
            records_.release();  // (the next output step records anew)
        }
        // Boundaries may add and delete particles: count again when the number changed (on
        // ranks, where that takes all ranks, every 256 steps).
        if (onRanks() ? (k & 255) == 0 : state_.particles.size() != counted) {
            counted = state_.particles.size();
            mobile = mobileParticleCount();
        }
        progress.update(state_.time, k, mobile);
    }
    progress.finish(state_.time, steps);
    if (steps > 0) {
        if (onRanks()) positionsChangedBetweenSteps_ = static_cast<std::uint64_t>(sumOverRanks(
                           static_cast<double>(positionsChangedBetweenSteps_)));
        // Rebuilds cost a full neighbour search; boundaries that delete particles force one,
        // those that add or move a few have their pairs relisted.
        const std::uint64_t builds = state_.pairList.builds - buildsAtStart;
        out << name() << ": neighbour list built " << builds << " times, every "
                  << (builds ? static_cast<double>(steps) / static_cast<double>(builds) : 0.0) << " steps on average";
        if (const std::uint64_t near = state_.pairList.near.makes - nearMakesAtStart; near > 0)
            out << "; its near list (the pairs within " << state_.pairList.nearSkinFraction << " x the skin) made "
                << near << " times, every " << static_cast<double>(steps) / static_cast<double>(near) << " steps";
        const double relisted = static_cast<double>(state_.pairList.relistedParticles - relistedAtStart);
        if (const double all = onRanks() ? sumOverRanks(relisted) : relisted; all > 0)
            out << "; the pairs of " << all << " added or moved particles relisted";
        if (positionsChangedBetweenSteps_ > 0 && state_.pairList.nearSkinFraction > 0)
            out << "; particles moved between steps (by hand) found at " << positionsChangedBetweenSteps_
                << (positionsChangedBetweenSteps_ == 1 ? " step" : " steps") << ": the near list made anew";
        out << std::endl;
        reportWaves(out, steps);
    }
    lastRun_ = {steps, mobile, progress.wallSeconds()};
    actionsAfterSolve();
}

// A restarted run continues the saved one: the flags that would make it another run are refused
// when they contradict the restart file (Documentation/FileFormats/restart.md, "What a restart
// keeps"). The time step changes the discretisation; --id-ordered-sums promises results that
// are the same to the bit on any number of ranks, which a run that changes it halfway keeps on
// neither side. The other settings that change the sums' order (skin, HGrid, reorder, relist,
// waves) change only round-off and may be changed, as the number of ranks may.
void Simulation::refuseContradictions(const RunSettings& saved, const std::string& restartFile) const {
    const RunSettings& now = state_.settings;
    auto refuse = [&](const std::string& flag, const std::string& given, const std::string& kept) {
        throw Error("--" + flag + " " + given + " contradicts the restart file " + restartFile + ", whose run has --" +
                    flag + " " + kept + ": a restarted run keeps it (leave the flag out or give " + kept + ")");
    };
    auto text = [](double x) {  // (the shortest %g that reads back as x)
        char b[32];
        for (int digits = 1; digits <= 17; ++digits)
            if (std::snprintf(b, sizeof b, "%.*g", digits, x); std::strtod(b, nullptr) == x) break;
        return std::string(b);
    };
    if (now.timeStep != saved.timeStep) refuse("dt", text(now.timeStep), text(saved.timeStep));
    if (now.idOrderedSums != saved.idOrderedSums)
        refuse("id-ordered-sums", now.idOrderedSums ? "on" : "off", saved.idOrderedSums ? "on" : "off");
}

std::uint64_t Simulation::saveEvery() const {
    const RunSettings& c = state_.settings;
    if (c.outputInterval <= 0) return ~std::uint64_t{0};
    return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(c.outputInterval / c.timeStep)));
}

void Simulation::initialise(bool restarted) {
    RunSettings& c = state_.settings;
    require(c.timeStep > 0, "no time step: call setTimeStep or pass --dt");
    // Half a step of slack: the time is a sum of steps, so a run that reached its end time may sit
    // a few ulps past it.
    require(c.endTime >= state_.time - 0.5 * c.timeStep,
            "end time " + str(c.endTime) + " lies before the current time " + str(state_.time));
    state_.species.validate();
    if (std::holds_alternative<LinearSpringDashpot>(state_.species[0].law))
        laws_ = state_.species.table<LinearSpringDashpot>();
    else
        laws_ = state_.species.table<HertzMindlin>();
    for (const Wall& w : state_.walls)
        require(w.species < state_.species.size(), "wall species " + std::to_string(w.species) + " does not exist");
    checkTimeStep();
    split_ = std::make_unique<DomainSplit>(worldCommunicator());
    if (rankGrid_[0] > 0) split_->setGrid(rankGrid_);
    grid_ = HGrid(c.cellSizeRatio);
    if (c.skin < 0) {
        double rmin = INFINITY;
        for (double r : state_.particles.radius) rmin = std::min(rmin, r);
        c.skin = std::isfinite(rmin) ? 0.2 * rmin : 0;
    }
    state_.pairList.skin = c.skin;
    if (state_.settings.idOrderedSums) {
        require(state_.domain.oneWay.outflowSpecies.empty(), "--id-ordered-sums is for scenes without a maser");
        state_.pairList.valid = false;  // the list is built anew with every pair oriented by ids
    }
    state_.pairList.orientById = c.idOrderedSums;
    state_.pairList.maxRelisted = c.relist ? PairList::defaultMaxRelisted : 0;
    largestRadius_ = 0;
    for (double r : state_.particles.radius) largestRadius_ = std::max(largestRadius_, r);
    files_.reset();
    const bool anyFile = c.writeData || c.writeFstat || c.writeEne || c.writeVtu || c.writeRestart;
    if (anyFile && rank() == 0) files_ = std::make_unique<OutputFiles>(state_, restarted);
    if (onRanks()) splitScene();
    positionsChangedBetweenSteps_ = 0;
    if (restarted) {
        continueWavesAfterRestart();
        notePositionsLeft(positionSum(state_.particles, state_.particles.owned()));
        return;
    }

    // Initial forces, and overlaps checked against the stricter initial limit.
    for (Vec3& x : state_.particles.position) state_.domain.wrap(x);
    computeForces(&records_, OverlapCheck::none);
    checkOverlaps(c.maxInitialOverlapFraction, /*initial*/ true);
    notePositionsLeft(positionSum(state_.particles, state_.particles.owned()));
    writeOutput();
    records_.release();
}

// The near list (NearPairs) holds while the particles move by the steps' drifts alone: a step
// that finds the positions other than the last step left them (a driver's hook moved particles
// by hand) unmakes it, to be made anew at the positions as they are. (The neighbour list
// itself measures the particles' real displacements: PairList::needsRebuild.)
void Simulation::notePositionsLeft(std::uint64_t sum) {
    positionsLeft_ = sum;
    particlesLeft_ = state_.particles.owned();
}

void Simulation::checkPositionsFound(std::uint64_t found) {
    if (positionsLeft_ && *positionsLeft_ == found) return;
    PairList& list = state_.pairList;
    // (Counted where the near list would have been swept: particles added, removed or moved by
    // moveParticleBy change the list, which makes it anew anyway.)
    if (state_.particles.owned() == particlesLeft_ && list.noted().empty() &&
        nearPairsAreCurrent(list, list.nearSkinFraction * list.skin))
        ++positionsChangedBetweenSteps_;
    list.near.made = false;
    positionsChangedThisStep_ = true;  // (on ranks, the ghosts of the moved particles moved too)
}

void Simulation::computeForces(ContactRecords* records, OverlapCheck check, const DriftPassResult* drifted) {
    ParticleStore& p = state_.particles;
    PairList& list = state_.pairList;
    std::vector<CarriedHistory> carried;
    bool rebuild;
    if (onRanks()) {
        rebuild = updateNeighbourhoodOnRanks(carried);
    } else {
        list.relist(p, state_.domain, state_.walls);  // particles added or moved by boundaries
        rebuild = drifted ? list.needsRebuild(drifted->moves, p, state_.time, state_.settings.timeStep)
                          : list.needsRebuild(p, state_.domain, state_.time, state_.settings.timeStep);
        if (rebuild && state_.settings.reorderParticles) reorderParticles(/*withPreviousForces*/ drifted != nullptr);
    }
    // The forces of the last step become previousForce_ by a swap (no copy: at 10^6 particles a
    // step is bound by memory bandwidth), and the old array is overwritten with gravity (done by
    // the drift pass if there was one).
    if (!drifted) {
        previousForce_.swap(p.force);
        startForcesWithGravity(p, state_.gravity);
    }
    if (rebuild && onRanks())
        list.rebuild(p, state_.domain, state_.walls, grid_, state_.settings.timeStep, std::move(carried));
    else if (rebuild)
        list.rebuild(p, state_.domain, state_.walls, grid_, state_.settings.timeStep);
    const bool idOrdered = state_.settings.idOrderedSums;
    if (rebuild && idOrdered) idOrderedForceSums_.rebuild(list, p);
    if (rebuild) lastDisplacement_ = 0;  // (the positions are the new reference)
    if (rebuild && state_.settings.waveSteps > 1) makeWaveSchedule();
    PairContribution* perPair = idOrdered ? idOrderedForceSums_.contributions(list.pairs.size()).data() : nullptr;
    summary_ = ContactSummary{};
    if (records) records->start(/*keepEach*/ state_.settings.writeFstat, p.owned());
    std::visit(
        [&](const auto& laws) {
            addContactForces(p, state_.pairList, state_.walls, state_.motions, laws, state_.domain,
                             state_.settings.timeStep, state_.pairList.maxSpeed, previousForce_, summary_, records,
                             &state_.shapes, perPair);
        },
        laws_);
    if (idOrdered) idOrderedForceSums_.addTo(p);
    if (records) {
        elasticEnergy_ = records->elasticEnergy();
        recordedContacts_ = records->count();
        if (onRanks()) {  // (one reduction for both)
            std::vector<double> totals{elasticEnergy_, static_cast<double>(recordedContacts_)};
            sumOverRanks(totals);
            elasticEnergy_ = totals[0];
            recordedContacts_ = static_cast<std::size_t>(totals[1]);
        }
    }
    if (check != OverlapCheck::none)
        checkOverlaps(state_.settings.maxOverlapFraction, /*initial*/ false, check == OverlapCheck::now);
}

std::size_t Simulation::slotOf(std::uint64_t id) const { return slotOf(id, false); }

std::size_t Simulation::slotOf(std::uint64_t id, bool ghosts) const {
    const std::vector<std::uint64_t>& ids = state_.particles.id;
    const auto end = ids.begin() + static_cast<std::ptrdiff_t>(ghosts ? ids.size() : state_.particles.owned());
    const auto it = std::find(ids.begin(), end, id);
    require(it != end, "no particle has id " + std::to_string(id) + (onRanks() ? " on rank " + std::to_string(rank()) : ""));
    return static_cast<std::size_t>(it - ids.begin());
}

// Cells of the largest diameter: the particles of one cell and its neighbours, which make up most
// listed pairs, end up close in memory.
void Simulation::reorderParticles(bool withPreviousForces) {
    ParticleStore& p = state_.particles;
    double largest = 0;
    for (double r : p.radius) largest = std::max(largest, r);
    if (p.size() < 2 || largest <= 0) return;
    // On ranks the order must not depend on the order particles arrived in (exact restarts).
    // With waves, the order of their cells (Contacts/WaveSchedule.h), where the box has them.
    // (the reach the coming build takes: PairList::rebuild)
    const std::optional<WaveCells> cells =
        waveCellsForBuild(state_.pairList.reachOfNextBuild(state_.settings.timeStep), nullptr);
    const std::vector<std::size_t> order =
        cells ? cells->order(p.position)
              : spaceFillingCurveOrder(p.position, state_.domain.lo, 2 * largest, onRanks() ? &p.id : nullptr);
    bool unchanged = true;
    for (std::size_t k = 0; k < order.size() && unchanged; ++k) unchanged = order[k] == k;
    if (unchanged) return;
    p.permute(order);
    if (withPreviousForces) {  // (the drift pass has made them the last step's already)
        std::vector<Vec3> sorted;
        sorted.reserve(order.size());
        for (std::size_t k : order) sorted.push_back(previousForce_[k]);
        previousForce_.swap(sorted);
    }
    state_.pairList.followPermutation(order);
}

void Simulation::moveWithPrescribedMotion() {
    const double dt = state_.settings.timeStep;
    if (state_.motions.empty()) return;
    std::vector<Mat3> rotation;
    for (const PrescribedMotion& m : state_.motions) rotation.push_back(m.stepRotation(dt));
    ParticleStore& p = state_.particles;
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (p.motion[i] < 0) continue;
        const PrescribedMotion& m = state_.motions[p.motion[i]];
        p.position[i] = m.moved(p.position[i], rotation[p.motion[i]], dt);
    }
    for (Wall& w : state_.walls) {
        if (w.motion < 0) continue;
        w.point = state_.motions[w.motion].moved(w.point, rotation[w.motion], dt);
        w.normal = (rotation[w.motion] * w.normal).normalized();
    }
    if (p.hasShapes())
        for (std::size_t i = 0; i < p.owned(); ++i)
            if (p.motion[i] >= 0 && p.shape[i] >= 0)
                p.orientation[i] = Quat(rotation[p.motion[i]] * p.orientation[i].toRotationMatrix()).normalized();
    for (PrescribedMotion& m : state_.motions) m.advanceCentre(dt);
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (p.motion[i] < 0) continue;
        const PrescribedMotion& m = state_.motions[p.motion[i]];
        p.velocity[i] = m.pointVelocity(p.position[i]);
        p.angularVelocity[i] = m.angularVelocity;
    }
}

Vec3 Simulation::sweepFrame() const {
    if (!state_.pairList.sweepInFlowFrame) return Vec3::Zero();
    return driftFrame_ ? *driftFrame_ : sweepFrameVelocity(state_.particles);
}

// Velocity Verlet (Theory/Integration.md eq. (3)-(6)): half kick, drift, forces at the new positions, half kick.
void Simulation::integrate(bool recordContacts) {
    ParticleStore& p = state_.particles;
    const double dt = state_.settings.timeStep;
    const double half = 0.5 * dt;
    const std::size_t owned = p.owned();  // ghosts are their owners' business
    std::optional<DriftPassResult> drifted;
    if (driftsInOnePass()) {
        PairList& list = state_.pairList;
        const Vec3 frame = sweepFrame();
        drifted = kickDriftAndStartForces(p, previousForce_, state_.domain,
                                          list.comparable(p) ? &list.referencePosition : nullptr, state_.gravity,
                                          frame, dt, list.sweepPointScratch);
        checkPositionsFound(drifted->positionsBefore);
        list.sweepPointsGrowth = drifted->growth;
        driftFrame_ = drifted->meanVelocity;
        lastDisplacement_ = std::sqrt(drifted->moves.displacement2);
    } else {
        checkPositionsFound(positionSum(p, owned));
        driftFrame_.reset();
        halfKickAndDrift(p, owned, half, dt);
        if (p.hasShapes()) turnShapedParticles(half, dt);
        moveWithPrescribedMotion();
        if (state_.domain.anyPeriodic()) state_.domain.wrap(p.position.data(), owned);
    }
    state_.time += dt;
    ++state_.step;
    for (Boundary* b : boundaries_) b->afterDrift(*this);
    computeForces(recordContacts ? &records_ : nullptr,
                  recordContacts ? OverlapCheck::now : OverlapCheck::withNextStep, drifted ? &*drifted : nullptr);
    halfKick(p, p.owned(), half);
    if (p.hasShapes()) turnShapedParticles(half, 0);
    notePositionsLeft(drifted ? drifted->positionsAfter : positionSum(p, p.owned()));
}

// Particles/DriftPass.h: where nothing but the particles' own motion happens between the drift
// and the forces, and the pair list's sweep is the one of one rank.
bool Simulation::driftsInOnePass() const {
    const ParticleStore& p = state_.particles;
    return driftInOnePass_ && !onRanks() && p.ghostCount == 0 && !p.hasShapes() && state_.motions.empty() &&
           boundaries_.empty() && !state_.domain.oneWay.active && state_.pairList.noted().empty();
}

bool Simulation::defaultDriftInOnePass() {
    static const bool onePass = [] {
        const char* text = std::getenv("TALUS_DRIFT_PASS");
        if (!text) return true;
        const std::string value = text;
        require(value == "on" || value == "off", "TALUS_DRIFT_PASS must be 'on' or 'off', got '" + value + "'");
        return value == "on";
    }();
    return onePass;
}

// The rigid-body rotation of the non-spherical particles (Particles/RigidBodyRotation.h): a half
// kick of the angular momentum by the torque, then (drift > 0) the torque-free turn of the
// orientation over the step; the angular velocity the contacts see follows from both. In
// batches of lanes (Particles/RotationBatch.h).
void Simulation::turnShapedParticles(double kick, double drift) {
    ParticleStore& p = state_.particles;
    RotationBatch batch;
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (p.fixed[i] || p.shape[i] < 0) continue;
        batch.add(static_cast<std::uint32_t>(i), p);
        if (batch.full()) batch.flush(p, kick, drift);
    }
    batch.flush(p, kick, drift);
}

void Simulation::writeOutput() {
    if (onRanks()) return writeGatheredOutput();
    if (!files_) return;
    // Particles added since the forces (a driver's actionsAfterTimeStep) are relisted now, in the
    // run that goes on and, through the restart file, in the one that restarts from here.
    state_.pairList.relist(state_.particles, state_.domain, state_.walls);
    files_->writeFrame(state_, records_.each(), recordedContacts_, elasticEnergy_);
    saveKeptValues();
    files_->writeRestart(state_);
}

}  // namespace talus
