#include "Simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "Integration/Integrator.h"
#include "Integration/StepWorkspace.h"
#include "IO/CommandLine.h"
#include "IO/OutputFiles.h"
#include "IO/Progress.h"
#include "IO/RestartFile.h"
#include "Parallel/Communicator.h"
#include "Parallel/RankContext.h"
#include "Run/ModelSummary.h"
#include "Sampling/RankReport.h"
#include "Particles/DriftPass.h"
#include "Particles/SpaceFillingCurve.h"
#include "Particles/VelocityVerlet.h"
#include "Sampling/StepSampler.h"
#include "SimulationHost.h"

namespace talus {

namespace {

// Whether the step numbered `step` writes output (and records its contacts): every `every`
// steps and the run's last; k: that step's count in the run, steps: the run's length.
bool isOutputStep(std::uint64_t step, std::uint64_t k, std::uint64_t steps, std::uint64_t every) {
    return step % every == 0 || k == steps;
}

}  // namespace

Simulation::~Simulation() = default;

const ContactSummary& Simulation::contactSummary() const { return work_->summary; }

Energies Simulation::energies() const {
    Energies e = particleEnergies(state_.particles, state_.gravity);
    e.elastic = work_->elasticEnergy;
    if (!ranks_->isSplit()) return e;
    const Vec3 moment = e.mass > 0 ? Vec3(e.mass * e.centreOfMass) : Vec3::Zero();
    std::vector<double> sums = {e.gravitational, e.kinetic, e.rotational, e.mass, moment.x(), moment.y(), moment.z()};
    ranks_->sum(sums);
    e.gravitational = sums[0], e.kinetic = sums[1], e.rotational = sums[2], e.mass = sums[3];
    e.centreOfMass = e.mass > 0 ? Vec3(Vec3(sums[4], sums[5], sums[6]) / e.mass) : Vec3::Constant(NAN);
    return e;  // elastic: summed over ranks when the contacts were recorded
}

std::size_t Simulation::mobileParticleCount() const {
    const ParticleStore& p = state_.particles;
    double mobile = 0;
    for (std::size_t i = 0; i < p.owned(); ++i) mobile += !p.fixed[i];
    return static_cast<std::size_t>(ranks_->sum(mobile));
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
        const bool replicated = !ranks_->isSplit() && ranks_->rank() != 0;
        if ((!collective || !collective->silent()) && !replicated)
            std::cerr << (argc > 0 ? argv[0] : "talus") << ": error: " << e.what() << std::endl;
        // An error that only this rank saw would leave the others waiting for it: end them all.
        if (!collective && ranks_->count() > 1) worldCommunicator().abort(1);
        return 1;
    }
}

void Simulation::solveOrThrow(const std::vector<std::string>& flags) {
    run_->restartFile_.clear();
    if (!run_->commandLine().parse(flags)) {
        std::cout << run_->commandLine().help(state_.settings.name);
        return;
    }
    state_.settings.validate(/*started*/ false);
    const std::string restartFile = run_->restartFile();
    if (!restartFile.empty()) {
        readRestartFile(restartFile, state_);
        run_->restoreKeptValues(state_);
    } else
        setupInitialConditions();
    // The command line has the last word: over the settings of the restart file, and over run
    // settings that setupInitialConditions may have made; a restarted run's time step and
    // summation mode excepted.
    const RunSettings saved = state_.settings;
    run_->commandLine().parse(flags);
    if (state_.settings.timeStep == RunSettings::automaticTimeStep) chooseTimeStep();
    state_.settings.validate();
    if (!restartFile.empty()) refuseContradictions(saved, restartFile);
    initialise(!restartFile.empty());

    const double dt = state_.settings.timeStep;
    const double remaining = state_.settings.endTime - state_.time;
    auto steps = remaining > 0 ? static_cast<std::uint64_t>(std::llround(remaining / dt)) : 0;
    run_->finishing_ = false;
    std::size_t mobile = mobileParticleCount();
    std::ostringstream quiet;  // ranks other than 0 print nothing
    std::ostream& out = ranks_->rank() == 0 ? std::cout : quiet;
    Progress progress(out, state_.settings.progressInterval);
    progress.start(state_.settings.name, state_.time, state_.settings.endTime, steps, mobile);
    double plannedEnd = state_.settings.endTime;
    const std::uint64_t every = saveEvery();
    std::size_t counted = state_.particles.size();
    const std::uint64_t buildsAtStart = state_.pairList.builds;
    const std::uint64_t relistedAtStart = state_.pairList.relistedParticles;
    const std::uint64_t wallRelistingsAtStart = state_.pairList.wallRelistings;
    const std::uint64_t nearMakesAtStart = state_.pairList.near.makes;
    integrator_->startRun();
    if (steps > 0) integrator_->describeChoice(*host_, out, state_.settings.name);
    for (std::uint64_t k = 1; k <= steps; ++k) {
        // A step, or a wave of several (Integration/Integrator.h); output after its last step.
        const std::uint64_t advance = integrator_->stepsNext(*host_, steps - k + 1, every);
        const std::uint64_t last = k + advance - 1;
        const bool finish = run_->finishing_;  // (asked for before this step: it is the run's last)
        const bool saving = finish || isOutputStep(state_.step + advance, last, steps, every);
        const bool sampling = samplersWant(state_.step + 1, state_.step + advance);
        actionsBeforeTimeStep();
        integrator_->advance(*host_, saving || sampling);
        k = last;
        if (finish) steps = k;
        // (Sampled before the boundaries' end of step, which may remove particles the step's
        // contact records name, and before the driver's hook, which may read the samples.)
        if (sampling) sampleStep();
        for (const auto& b : scene_->boundaries()) b->afterStep(*this);
        actionsAfterTimeStep();
        // A driver that learns when its run will end may bring the end time forward (a drum
        // that stops after its turns): the loop and the progress lines end there, after one more
        // step at least (which saves the output as a run's last step does).
        if (state_.settings.endTime < plannedEnd) [[unlikely]] {
            plannedEnd = state_.settings.endTime;
            const double left = plannedEnd - state_.time;
            steps = k + std::max<std::uint64_t>(1, left > 0 ? static_cast<std::uint64_t>(std::llround(left / dt)) : 0);
            progress.moveEnd(plannedEnd, steps);
        }
        if (saving) {
            writeOutput();
            for (StepSampler* sampler : samplers_.attached) sampler->afterOutput(*this);
        }
        if (saving || sampling) work_->records.release();  // (the next output or sampled step records anew)
        // Boundaries may add and delete particles (waves run without them): count again when the
        // number changed (on ranks, where that takes all ranks, every 256 steps).
        if (advance == 1 && (ranks_->isSplit() ? (k & 255) == 0 : state_.particles.size() != counted)) {
            counted = state_.particles.size();
            mobile = mobileParticleCount();
        }
        progress.update(state_.time, k, mobile);
        if (finish) break;
    }
    progress.finish(state_.time, steps);
    if (steps > 0) {
        std::uint64_t& positionsChanged = work_->positions.changedBetweenSteps;
        positionsChanged = static_cast<std::uint64_t>(ranks_->sum(static_cast<double>(positionsChanged)));
        // Rebuilds cost a full neighbour search; boundaries that delete particles force one,
        // those that add or move a few have their pairs relisted.
        const std::uint64_t builds = state_.pairList.builds - buildsAtStart;
        out << state_.settings.name << ": neighbour list built " << builds << " times, every "
                  << (builds ? static_cast<double>(steps) / static_cast<double>(builds) : 0.0) << " steps on average";
        if (const std::uint64_t near = state_.pairList.near.makes - nearMakesAtStart; near > 0)
            out << "; its near list (the pairs within " << state_.pairList.nearSkinFraction << " x the skin) made "
                << near << " times, every " << static_cast<double>(steps) / static_cast<double>(near) << " steps";
        const double relisted = static_cast<double>(state_.pairList.relistedParticles - relistedAtStart);
        if (const double all = ranks_->sum(relisted); all > 0)
            out << "; the pairs of " << all << " added or moved particles relisted";
        if (const std::uint64_t walls = state_.pairList.wallRelistings - wallRelistingsAtStart; walls > 0)
            out << "; the moving meshes' triangles listed anew " << walls << " times";
        if (positionsChanged > 0 && state_.pairList.nearSkinFraction > 0)
            out << "; particles moved between steps (by hand) found at " << positionsChanged
                << (positionsChanged == 1 ? " step" : " steps") << ": the near list made anew";
        out << std::endl;
        integrator_->report(*host_, out, state_.settings.name, steps);
    }
    lastRun_ = {steps, mobile, progress.wallSeconds()};
    if (steps > 0 && ranks_->isSplit())  // (how the ranks shared the work: Sampling/RankReport.h)
        out << state_.settings.name << ": " << describeRanks(*this) << std::endl;
    for (StepSampler* sampler : samplers_.attached) sampler->finishRun(*this);
    actionsAfterSolve();
}

// A restarted run continues the saved one: the flags that would make it another run are refused
// when they contradict the restart file (Documentation/FileFormats/restart.md, "What a restart
// keeps"). The time step changes the discretisation, and so does the tolerance of superquadric
// contacts (--shape-tolerance); --id-ordered-sums promises results that
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
    if (now.shapeTolerance != saved.shapeTolerance)
        refuse("shape-tolerance", text(now.shapeTolerance), text(saved.shapeTolerance));
    if (now.idOrderedSums != saved.idOrderedSums)
        refuse("id-ordered-sums", now.idOrderedSums ? "on" : "off", saved.idOrderedSums ? "on" : "off");
}

// --dt auto: the step from the scene as it starts (Scene::automaticTimeStep), said with its reason.
void Simulation::chooseTimeStep() {
    RunSettings& c = state_.settings;
    std::string reason;
    c.timeStep = scene_->automaticTimeStep(c.stepsPerCollision, c.impactSpeed, &reason);
    if (ranks_->rank() == 0) std::cout << c.name << ": time step " << c.timeStep << " (--dt auto): " << reason << std::endl;
}

std::uint64_t Simulation::saveEvery() const {
    const RunSettings& c = state_.settings;
    if (c.outputInterval <= 0) return ~std::uint64_t{0};
    return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(c.outputInterval / c.timeStep)));
}

void Simulation::initialise(bool restarted) {
    RunSettings& c = state_.settings;
    // Half a step of slack: the time is a sum of steps, so a run that reached its end time may sit
    // a few ulps past it.
    require(c.endTime >= state_.time - 0.5 * c.timeStep,
            "end time " + str(c.endTime) + " lies before the current time " + str(state_.time));
    scene_->validate(c.timeStep, c.largestStepFraction, c.impactSpeed);
    work_->laws = state_.species.tables();
    if (state_.species.keepsRollingSprings()) state_.pairList.enableRollingSprings();
    ranks_->start(state_);
    work_->grid = HGrid(c.cellSizeRatio);
    const bool automaticSkin = c.skin < 0;
    if (automaticSkin) {
        double rmin = INFINITY;
        for (double r : state_.particles.radius) rmin = std::min(rmin, r);
        c.skin = std::isfinite(rmin) ? 0.2 * rmin : 0;
    }
    state_.pairList.skin = c.skin;
    if (ranks_->rank() == 0) std::cout << c.name << ": " << describeModel(state_, automaticSkin) << std::endl;
    if (state_.settings.idOrderedSums) {
        require(state_.domain.oneWay.outflowSpecies.empty(), "--id-ordered-sums is for scenes without a maser");
        state_.pairList.valid = false;  // the list is built anew with every pair oriented by ids
    }
    state_.pairList.orientById = c.idOrderedSums;
    state_.pairList.maxRelisted = c.relist ? PairList::defaultMaxRelisted : 0;
    files_.reset();
    const bool anyFile = c.writeData || c.writeFstat || c.writeEne || c.writeVtu || c.writeRestart;
    if (anyFile && ranks_->rank() == 0) files_ = std::make_unique<OutputFiles>(state_, restarted);
    if (ranks_->isSplit()) {
        bool boundariesRunOnRanks = true;
        for (const auto& b : scene_->boundaries()) boundariesRunOnRanks = boundariesRunOnRanks && b->runsOnRanks();
        ranks_->splitScene(state_, boundariesRunOnRanks, c.name);
    }
    integrator_->tune(*host_, restarted);  // (before the first list build: waves order it)
    PositionWatch& positions = work_->positions;
    positions.changedBetweenSteps = 0;
    for (StepSampler* sampler : samplers_.attached) sampler->startRun(*this);
    if (restarted) {
        integrator_->afterRestart(*host_);
        positions.noteLeft(positionSum(state_.particles, state_.particles.owned()), state_.particles.owned());
        return;
    }

    // Initial forces, and overlaps checked against the stricter initial limit.
    for (Vec3& x : state_.particles.position) state_.domain.wrap(x);
    const bool sampling = samplersWant(state_.step, state_.step);
    computeForces(/*recordContacts*/ true, OverlapCheck::none);
    checkOverlaps(c.maxInitialOverlapFraction, /*initial*/ true);
    positions.noteLeft(positionSum(state_.particles, state_.particles.owned()), state_.particles.owned());
    if (sampling) sampleStep();
    writeOutput();
    for (StepSampler* sampler : samplers_.attached) sampler->afterOutput(*this);
    work_->records.release();
}

bool Simulation::samplersWant(std::uint64_t first, std::uint64_t last) {
    std::vector<StepSampler*>& now = samplers_.sampling;
    now.clear();
    for (StepSampler* sampler : samplers_.attached)
        if (sampler->wantsSteps(*this, first, last)) now.push_back(sampler);
    work_->records.keepEachForSampler(!now.empty());
    return !now.empty();
}

void Simulation::sampleStep() {
    for (StepSampler* sampler : samplers_.sampling) sampler->sample(*this, work_->records.each());
}

void Simulation::computeForces(bool recordContacts, OverlapCheck check, const DriftPassResult* drifted) {
    StepWorkspace& work = *work_;
    ContactRecords* records = recordContacts ? &work.records : nullptr;
    ParticleStore& p = state_.particles;
    PairList& list = state_.pairList;
    std::vector<CarriedHistory>& carried = work.carriedHistories;  // (on ranks; kept for its memory)
    carried.clear();
    bool rebuild;
    std::unique_ptr<AnyContactForceLoop> begun;  // on ranks: the interior pairs done while the ghosts travelled
    if (ranks_->isSplit()) {
        rebuild = ranks_->updateNeighbourhood(state_, work.positions.changedThisStep, drifted, carried,
                                              [this] { reorderParticles(/*withPreviousForces*/ false); }, &work,
                                              records || drifted ? nullptr : &begun);
    } else {
        list.relist(p, state_.domain, state_.walls);  // particles added or moved by boundaries
        rebuild = drifted ? list.needsRebuild(drifted->moves, p, state_.time, state_.settings.timeStep)
                          : list.needsRebuild(p, state_.domain, state_.time, state_.settings.timeStep);
        if (rebuild && state_.settings.reorderParticles) reorderParticles(/*withPreviousForces*/ drifted != nullptr);
    }
    // The forces of the last step become previousForce by a swap (no copy: at 10^6 particles a
    // step is bound by memory bandwidth), and the old array is overwritten with gravity (done by
    // the drift pass if there was one, unless a rebuild on ranks put the last forces back).
    const bool forcesStarted = begun || (drifted && !(rebuild && ranks_->isSplit()));
    if (!forcesStarted) {
        work.previousForce.swap(p.force);
        startForcesWithGravity(p, state_.gravity);
    }
    // A moving mesh that travelled half the reach since its triangles were listed has them listed
    // anew, the particles' pairs kept (on each rank alike: every rank moves the meshes alike).
    const bool relistWalls = !rebuild && list.wallsNeedRelisting();
    if (rebuild || relistWalls)  // (the moving meshes' grids over where they are now)
        for (const auto& mesh : state_.meshes)
            if (mesh->moves()) mesh->regrid();
    if (rebuild && ranks_->isSplit())
        list.rebuild(p, state_.domain, state_.walls, work.grid, state_.settings.timeStep, carried);
    else if (rebuild)
        list.rebuild(p, state_.domain, state_.walls, work.grid, state_.settings.timeStep);
    else if (relistWalls)
        list.relistWalls(p, state_.walls);
    const bool idOrdered = state_.settings.idOrderedSums;
    if (rebuild && idOrdered) work.idOrderedForceSums.rebuild(list, p);
    if (rebuild) integrator_->afterListBuild(*host_);  // (the wave schedule of the new list)
    PairContribution* perPair = idOrdered ? work.idOrderedForceSums.contributions(list.pairs.size()).data() : nullptr;
    if (begun) {  // (the rest of the step's contact forces as addContactForces computes them)
        begun->allowSpeed(list.maxSpeed);
        begun->restPairs(list, state_.domain, state_.motions.empty());
        begun->oneWayPairs(list, state_.domain);
        begun->wallPairs(list, state_.walls, state_.motions);
    } else {
        work.summary = ContactSummary{};
        if (records) records->start(/*keepEach*/ state_.settings.writeFstat, p.owned());
        std::visit(
            [&](const auto& laws) {
                addContactForces(p, state_.pairList, state_.walls, state_.motions, laws, state_.domain,
                                 state_.settings.timeStep, state_.pairList.maxSpeed, work.previousForce, work.summary,
                                 records, &state_.shapes, perPair, {.tolerance = state_.settings.shapeTolerance});
            },
            work.laws);
    }
    if (idOrdered) work.idOrderedForceSums.addTo(p);
    if (records) {
        work.elasticEnergy = records->elasticEnergy();
        work.recordedContacts = records->count();
        if (ranks_->isSplit()) {  // (one reduction for both)
            std::vector<double> totals{work.elasticEnergy, static_cast<double>(work.recordedContacts)};
            ranks_->sum(totals);
            work.elasticEnergy = totals[0];
            work.recordedContacts = static_cast<std::size_t>(totals[1]);
        }
    }
    if (check != OverlapCheck::none)
        checkOverlaps(state_.settings.maxOverlapFraction, /*initial*/ false, check == OverlapCheck::now);
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
        integrator_->cellsForBuild(*host_, state_.pairList.reachOfNextBuild(state_.settings.timeStep));
    const std::vector<std::size_t> order =
        cells ? cells->order(p.position)
              : spaceFillingCurveOrder(p.position, state_.domain.lo, 2 * largest, ranks_->isSplit() ? &p.id : nullptr);
    bool unchanged = true;
    for (std::size_t k = 0; k < order.size() && unchanged; ++k) unchanged = order[k] == k;
    if (unchanged) return;
    p.permute(order);
    if (withPreviousForces) {  // (the drift pass has made them the last step's already)
        std::vector<Vec3> sorted;
        sorted.reserve(order.size());
        for (std::size_t k : order) sorted.push_back(work_->previousForce[k]);
        work_->previousForce.swap(sorted);
    }
    state_.pairList.followPermutation(order);
}

void Simulation::writeOutput() {
    if (ranks_->isSplit()) {
        run_->saveKeptValues(state_);
        return ranks_->writeGatheredOutput(state_, files_.get(), *work_);
    }
    if (!files_) return;
    // Particles added since the forces (a driver's actionsAfterTimeStep) are relisted now, in the
    // run that goes on and, through the restart file, in the one that restarts from here.
    state_.pairList.relist(state_.particles, state_.domain, state_.walls);
    files_->writeFrame(state_, work_->records.each(), work_->recordedContacts, work_->elasticEnergy);
    run_->saveKeptValues(state_);
    files_->writeRestart(state_);
}

}  // namespace talus
