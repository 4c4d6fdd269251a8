// Waves of steps (Integration/WaveStepper.h): the schedule made at each list build, and a wave.
#include "Integration/WaveStepper.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>

#include "Integration/DriftPassStepper.h"
#include "Integration/StepWorkspace.h"
#include "Particles/DriftPass.h"
#include "Particles/VelocityVerlet.h"
#include "SimulationState.h"

namespace talus {

// The cells of a list build of the given reach: as wide as the longest pair it can list,
// 2 rmax + reach.
std::optional<WaveCells> WaveStepper::cellsForBuild(const StepHost& host, double reach, std::string* why) const {
    const SimulationState& s = host.state();
    if (s.settings.stepper.waveSteps < 2) return std::nullopt;
    if (host.onRanks()) {
        if (why) *why = "waves run on one rank only";
        return std::nullopt;
    }
    double largest = 0;
    for (double r : s.particles.radius) largest = std::max(largest, r);
    return WaveCells::fit(s.domain, (2 * largest + reach) * (1 + 1e-9), s.settings.stepper.waveSteps,
                          s.settings.stepper.stripColumns(), why);
}

void WaveStepper::choose(StepHost& host, bool restarted) {
    SimulationState& s = host.state();
    StepperTuning& tuning = s.settings.stepper;
    using Waves = StepperTuning::Waves;
    const std::size_t particles = s.particles.size();
    bool take = tuning.waveSteps > 1;
    if (tuning.waveSteps < 2)
        choice_ = "not asked for (--wave-steps 1, or a restart of a run that took none)";
    else if (tuning.waves == Waves::off)
        take = false, choice_ = "turned off (--waves off)";
    else if (tuning.waves == Waves::on)
        choice_ = "asked for (--waves on)";
    else if (restarted)
        choice_ = "as the run that saved the restart file took them";
    else if (const std::string_view why = singleSteps_.whyNot(host); !why.empty())
        take = false, choice_ = "auto: " + std::string(why);
    else if (!(s.domain.periodic[0] && s.domain.periodic[1]))
        take = false, choice_ = "auto: the box is not periodic along x and y";
    else if (s.settings.idOrderedSums)
        take = false, choice_ = "auto: --id-ordered-sums";
    else if (particles < tuning.wavesFromParticles)
        take = false, choice_ = "auto: " + std::to_string(particles) + " particles, fewer than the " +
                                std::to_string(tuning.wavesFromParticles) + " from which waves pay (--waves-from, --waves on)";
    else
        choice_ = "auto: " + std::to_string(particles) + " particles in a periodic box, at least the " +
                  std::to_string(tuning.wavesFromParticles) + " from which waves pay (--waves off: single steps)";
    if (!take) tuning.waveSteps = 1;
}

void WaveStepper::makeSchedule(StepHost& host) {
    SimulationState& s = host.state();
    scheduleBuild_ = nearRunsMake_ = 0;
    refusal_.clear();
    if (s.settings.stepper.waveSteps < 2) return;
    if (s.settings.idOrderedSums) {  // (its sums follow the list's places: IdOrderedForceSums)
        refusal_ = "waves do not run with --id-ordered-sums";
        return;
    }
    PairList& list = s.pairList;
    const std::optional<WaveCells> cells = cellsForBuild(host, list.reach, &refusal_);
    // The list takes the schedule's order of pairs (a few runs of places per region).
    std::vector<std::uint32_t> order;
    if (cells && schedule_.make(*cells, list.pairs, list.interiorPairs, list.referencePosition,
                                s.particles.size(), &refusal_, list.wallPairs, &order)) {
        list.reorderPairs(order);
        scheduleBuild_ = list.builds;
        scheduleEdits_ = list.edits;
        scheduleWallRelistings_ = list.wallRelistings;
    }
    largestRadius_ = 0;
    for (double r : s.particles.radius) largestRadius_ = std::max(largestRadius_, r);
}

// The pairs the wave about to run computes (before its first drift, the sweep's growths taken in
// `frame`): those of the near list (NearPairs), as the near pairs of each run of the schedule
// (places in the near list), where the moves within the wave keep that whole, else all (null).
// The near list (made, if it is, at the positions before the first drift) holds
// every pair the sweep can pick while its particles have moved (the sum of the steps' growths,
// NearPairs::moved) less than half its skin less a step's growth (useNearPairs); within the wave
// that is asked of (levels + 1) growths, each predicted as a sweep point's in `frame` if the
// largest speed doubles (the assumption the list's reach is kept with: waveFits), and checked as
// the wave goes (integrateWave). The near list is made anew when the prediction does not fit in
// what is left of it. The force loop sweeps each run's near pairs as a single step sweeps the
// near list (ContactForceLoop::regionPairs): the forces of the whole list's waves, to the bit,
// for a sweep of the near pairs alone.
const PlaceRun* WaveStepper::nearPairsForWave(StepHost& host, const Vec3& frame) {
    SimulationState& s = host.state();
    PairList& list = s.pairList;
    NearPairs& near = list.near;
    const ParticleStore& p = s.particles;
    const double dt = s.settings.timeStep;
    const double nearSkin = list.nearSkinFraction * list.skin, nearLimit = nearAllowance(nearSkin);
    const double steps = s.settings.stepper.waveSteps;
    const double speed = 2 * list.maxSpeed + s.gravity.norm() * steps * dt + frame.norm();
    const double wave = (steps + 1) * (1.000001 * speed * dt + 1e-12 * largestRadius_);
    if (!(nearSkin > 0 && wave < nearLimit)) return nullptr;
    const bool whole = nearPairsAreCurrent(list, nearSkin) && near.moved + wave < nearLimit;
    if (!whole) {
        SweptPairs scratch;
        makeNearPairs(list, p.position.data(), p.size(), p.radius.data(), nearSkin, PeriodicImage(s.domain),
                      list.nearPointScratch, scratch);
    }
    if (nearRunsMake_ != near.makes) {
        // The near list is in the list's order: a run of places holds a run of near pairs.
        const auto at = [&](std::uint32_t place) {
            return static_cast<std::uint32_t>(
                std::lower_bound(near.pairs.begin(), near.pairs.end(), place,
                                 [](const NearPairs::Pair& a, std::uint32_t b) { return a.index < b; }) -
                near.pairs.begin());
        };
        const std::vector<PlaceRun>& runs = schedule_.placeRuns();
        nearRuns_.resize(runs.size());
        for (std::size_t u = 0; u < runs.size(); ++u) nearRuns_[u] = {at(runs[u].begin), at(runs[u].end)};
        nearRunsMake_ = near.makes;
        ++statistics_.nearRunsFound;
    }
    return nearRuns_.data();
}

// Waves go on as in the run that saved: the schedule of the list it kept, and the displacement
// the last step left, measured as the drift pass does.
void WaveStepper::continueAfterRestart(StepHost& host) {
    const SimulationState& s = host.state();
    const PairList& list = s.pairList;
    if (!list.comparable(s.particles) || host.onRanks()) return;
    host.workspace().lastDisplacement = largestDisplacement(s.particles, list.referencePosition, s.domain);
    if (s.settings.stepper.waveSteps > 1) makeSchedule(host);
}

void WaveStepper::report(const StepHost& host, std::ostream& out, const std::string& name, std::uint64_t steps) const {
    const SimulationState& s = host.state();
    const StepperTuning& tuning = s.settings.stepper;
    if (tuning.waveSteps < 2) return;
    out << name << ": " << statistics_.stepsInWaves << " of " << steps << " steps in waves of " << tuning.waveSteps;
    if (const std::optional<WaveCells> cells = cellsForBuild(host, s.pairList.reach, nullptr))
        out << " (" << cells->strips() << (cells->strips() == 1 ? " strip" : " strips") << " of about "
            << cells->columns() / cells->strips() << " columns, asked for " << tuning.stripColumns() << ")";
    if (statistics_.nearRunsFound > 0)
        out << ", over the near list (" << statistics_.nearRunsFound << " of them, the last of " << s.pairList.near.pairs.size()
            << " of " << s.pairList.pairs.size() << " pairs)";
    if (statistics_.offTheNearList > 0)
        out << "; " << statistics_.offTheNearList << " waves went on over the whole list when a particle sped up past the near list";
    if (statistics_.rolledBack > 0)
        out << "; " << statistics_.rolledBack << (statistics_.rolledBack == 1 ? " wave" : " waves")
            << " rolled back and redone in single steps when a particle outran the neighbour list";
    if (!refusal_.empty())
        out << "; the last list build has no wave schedule: " << refusal_;
    else if (statistics_.stepsInWaves == 0)
        out << " (waves need spheres in one rank's periodic box, no boundaries or prescribed motions: "
               "Documentation/TimeSkewing.md)";
    out << std::endl;
}

std::string_view WaveStepper::whyNot(const StepHost& host) const {
    const SimulationState& s = host.state();
    const PairList& list = s.pairList;
    if (s.settings.stepper.waveSteps < 2) return choice_.empty() ? std::string_view("not asked for") : std::string_view(choice_);
    if (const std::string_view why = singleSteps_.whyNot(host); !why.empty()) return why;
    if (s.settings.idOrderedSums) return "waves do not run with --id-ordered-sums";
    if (scheduleBuild_ == 0 || scheduleBuild_ != list.builds || schedule_.levels() != s.settings.stepper.waveSteps)
        return refusal_.empty() ? std::string_view("the neighbour list has no wave schedule") : std::string_view(refusal_);
    if (!list.comparable(s.particles) || list.edits != scheduleEdits_)
        return "particles were added or removed since the list's build";
    if (list.wallRelistings != scheduleWallRelistings_) return "a moving mesh's triangles were listed anew since the list's build";
    if (!list.oneWayPairs.empty()) return "pairs cross a one-way periodic face";
    return {};
}

// The scene allows a wave now (whyNot: one drift pass a step, spheres, one rank, no one-way box,
// the schedule is the current list's), and no output falls within it (one at its last step is
// written after it). Waves start at multiples of their steps, so that a restarted run takes
// them where the first run did, whatever the output steps.
bool WaveStepper::allowed(const StepHost& host, std::uint64_t stepsLeft, std::uint64_t saveEvery) const {
    const SimulationState& s = host.state();
    const auto steps = static_cast<std::uint64_t>(s.settings.stepper.waveSteps);
    if (steps < 2 || stepsLeft < steps || s.step % steps != 0) return false;
    if (saveEvery > 0 && s.step / saveEvery != (s.step + steps - 1) / saveEvery) return false;
    return whyNot(host).empty();
}

// A particle `displacement` from the list's positions, at the largest speed doubled (and gravity's
// gain), stays within half the list's `reach` through a wave and the step after it.
bool WaveStepper::hasRoom(const StepHost& host, double displacement, double reach) const {
    const SimulationState& s = host.state();
    const double steps = s.settings.stepper.waveSteps, dt = s.settings.timeStep;
    const double speed = 2 * s.pairList.maxSpeed + s.gravity.norm() * steps * dt;
    return displacement + (steps + 1) * speed * dt < 0.5 * reach;
}

// A wave where the scene allows it and no particle can have moved half the list's reach by its
// end, even if the largest speed doubles (hasRoom; checked as the wave goes: advance).
std::uint64_t WaveStepper::stepsNext(StepHost& host, std::uint64_t stepsLeft, std::uint64_t saveEvery) {
    const StepWorkspace& work = host.workspace();
    const PairList& list = host.state().pairList;
    if (allowed(host, stepsLeft, saveEvery) && !hasRoom(host, work.lastDisplacement, list.reach))
        buildListForWave(host);  // (instead of single steps until the list needs a build)
    if (!allowed(host, stepsLeft, saveEvery) || !hasRoom(host, work.lastDisplacement, list.reach)) return 0;
    return static_cast<std::uint64_t>(host.state().settings.stepper.waveSteps);
}

// Where a wave is allowed but the list has no room left for it, the list is built anew before
// it (at the positions between two steps, as a step's build would be after its drift), so that
// waves go on. Otherwise the list's last (N + 1) 2 vmax dt of room would go in single steps
// (about 20 of the 370 steps between builds in the benchmark's flow), which beyond the caches
// cost about twice a step in a wave (Documentation/TimeSkewing.md, "Using it"; the measured
// gain is in Documentation/Performance/History.md).
// Not when a new list would have no room either (a speed too large for waves: single steps go
// on, rebuilding as they need).
void WaveStepper::buildListForWave(StepHost& host) {
    SimulationState& s = host.state();
    StepWorkspace& work = host.workspace();
    PairList& list = s.pairList;
    const double dt = s.settings.timeStep;
    if (!hasRoom(host, 0, list.reachOfNextBuild(dt))) return;
    // (Between steps the forces to kick with are in p, not yet in previousForce.)
    if (s.settings.reorderParticles) host.reorderParticles(/*withPreviousForces*/ false);
    list.rebuild(s.particles, s.domain, s.walls, work.grid, dt);
    work.lastDisplacement = 0;
    makeSchedule(host);
}

namespace {

// Thrown within a wave where a particle has moved past the list's allowance (WaveStepper::advance).
struct OutranTheList {};

}  // namespace

// Where a particle outran the list within the wave: the state at its start put back (WaveUndo.h)
// and its steps redone in single steps, which build the list anew when the particle needs it.
void WaveStepper::rollBackAndRedo(StepHost& host, bool recordContacts) {
    undo_.restore(host.state(), host.workspace());
    const int levels = host.state().settings.stepper.waveSteps;
    for (int t = 1; t <= levels; ++t) singleSteps_.advance(host, recordContacts && t == levels);
    ++statistics_.rolledBack;
}

void WaveStepper::advance(StepHost& host, bool recordContacts) {
    SimulationState& s = host.state();
    StepWorkspace& work = host.workspace();
    ParticleStore& p = s.particles;
    PairList& list = s.pairList;
    const Domain& domain = s.domain;
    const double dt = s.settings.timeStep, half = 0.5 * dt;
    const int levels = s.settings.stepper.waveSteps;
    // The wave's first step starts as a single step's (the last step's forces become the ones to
    // kick with), its first half kick and drift going along with the first level's regions
    // (WaveRegion::driftBegin); the same frame for the sweep's growths all through the wave (any
    // frame common to both particles of a pair at a step keeps the sweep's bound, PairSweep.h).
    const Vec3 frame = sweepFrame(s, work);
    undo_.keep(s, work);
    work.positions.checkFound(positionSum(p, p.owned()), s);
    startFirstHalf(p, work.previousForce, list.sweepPointScratch);
    s.time += dt;
    ++s.step;
    // Over the near list: the growth of each step (its largest) for NearPairs::moved.
    const PlaceRun* near = nearPairsForWave(host, frame);
    const double nearMoved = list.near.moved, nearLimit = nearAllowance(list.near.skin);
    std::array<double, 256> levelGrowth{};  // (waves of at most 255 steps: StepperTuning::setWaves)
    double growth = 0;
    const double startSpeed = list.maxSpeed;
    double speed2 = 0, displacement2 = 0, finalDisplacement2 = 0;
    double velocitySum[3] = {0, 0, 0};
    std::size_t mobile = 0;
    std::uint64_t positionsAfter = 0;  // (positionSum of where the last drift leaves the particles)
    // A drift of the wave into step `step` (1: its first) at `time`, noted: the largest speed,
    // displacement and growth; the near list given up for the rest of the wave if a particle sped
    // up past it (the pairs swept so far were within it: every growth of their particles so far
    // fitted); the wave rolled back if a particle moved past the list's allowance (the check a
    // single step makes before its forces: PairList::needsRebuild).
    const auto noteDrift = [&](const DriftPassResult& moved, int step, double time) {
        if (!moved.moves.finite) list.needsRebuild(moved.moves, p, time, dt);  // (throws, naming the particle)
        speed2 = std::max(speed2, moved.moves.speed2);
        displacement2 = std::max(displacement2, moved.moves.displacement2);
        growth = std::max(growth, moved.growth);
        double& grown = levelGrowth[static_cast<std::size_t>(step) - 1];
        grown = std::max(grown, moved.growth);
        if (near && nearMoved + (levels + 1) * growth >= nearLimit) [[unlikely]] {
            near = nullptr;
            ++statistics_.offTheNearList;
        }
        if (std::sqrt(displacement2) + std::sqrt(speed2) * dt >= 0.5 * list.reach) [[unlikely]]
            throw OutranTheList{};
    };
    ContactSummary early;  // of the wave's steps before its last (only their largest overlap counts)
    ContactSummary& summary = work.summary;
    summary = ContactSummary{};
    if (recordContacts) work.records.start(/*keepEach*/ s.settings.writeFstat, p.owned());
    try {
        std::visit(
            [&]<class Law>(const PairTable<Law>& laws) {
                ContactForceLoop<Law> earlyLoop(p, laws, dt, startSpeed, work.previousForce, early, nullptr);
                ContactForceLoop<Law> lastLoop(p, laws, dt, startSpeed, work.previousForce, summary,
                                               recordContacts ? &work.records : nullptr);
                for (const WaveRegion& region : schedule_.regions()) {
                    const bool last = region.level + 1 == levels;
                    ContactForceLoop<Law>& loop = last ? lastLoop : earlyLoop;
                    for (std::uint32_t k = region.driftBegin; k < region.driftEnd; ++k) {
                        const PlaceRun run = schedule_.driftRuns()[k];
                        noteDrift(kickDriftAndStartForces(p, work.previousForce, domain, &list.referencePosition, s.gravity,
                                                          frame, dt, list.sweepPointScratch, run.begin, run.end),
                                  1, s.time);
                    }
                    loop.allowSpeed(std::sqrt(speed2));
                    loop.regionPairs(list, domain, schedule_, region, s.walls, near);
                    // The region's particles: the second half kick of this step, and unless it is the
                    // wave's last, the first half of the next (Particles/DriftPass.h on their slots).
                    for (int run = 0; run < 2; ++run) {
                        const std::size_t begin = region.runBegin[run], end = region.runEnd[run];
                        if (begin >= end) continue;
                        if (last) {
                            halfKick(p, begin, end, half);
                            continue;
                        }
                        const DriftPassResult moved =
                            closeKickDriftAndStartForces(p, work.previousForce, domain, &list.referencePosition, s.gravity,
                                                         frame, dt, list.sweepPointScratch, begin, end);
                        noteDrift(moved, region.level + 2, s.time + (region.level + 1) * dt);
                        if (region.level + 2 == levels) {  // (the last drift: where the wave ends, the next frame)
                            finalDisplacement2 = std::max(finalDisplacement2, moved.moves.displacement2);
                            for (int c = 0; c < 3; ++c) velocitySum[c] += moved.velocitySum[c];
                            mobile += moved.mobile;
                            positionsAfter += moved.positionsAfter;
                        }
                    }
                }
            },
            work.laws);
    } catch (const OutranTheList&) {
        return rollBackAndRedo(host, recordContacts);
    }
    for (int t = 1; t < levels; ++t) {
        s.time += dt;
        ++s.step;
    }
    // The largest speed in the wave (the next wave's prediction), and the displacement of where
    // the particles are, as a single step leaves it (and a restart finds it: largestDisplacement).
    list.maxSpeed = std::sqrt(speed2);
    work.lastDisplacement = std::sqrt(finalDisplacement2);
    work.positions.noteLeft(positionsAfter, p.owned());
    const Vec3 mean = Vec3(velocitySum[0], velocitySum[1], velocitySum[2]) / static_cast<double>(std::max<std::size_t>(mobile, 1));
    work.driftFrame = mean.allFinite() ? mean : Vec3::Zero();
    if (near)
        for (int t = 0; t < levels; ++t) list.near.moved += levelGrowth[static_cast<std::size_t>(t)];
    else
        list.near.made = false;  // (its bound of the displacements did not follow the wave)
    list.sweepPointsByDrift.reset();
    if (early.maxOverlapFraction > summary.maxOverlapFraction) {
        summary.maxOverlapFraction = early.maxOverlapFraction;
        summary.worstA = early.worstA, summary.worstB = early.worstB, summary.worstIsWall = early.worstIsWall;
    }
    if (recordContacts) {
        work.elasticEnergy = work.records.elasticEnergy();
        work.recordedContacts = work.records.count();
    }
    host.checkOverlaps(s.settings.maxOverlapFraction, /*initial*/ false, /*agreeNow*/ recordContacts);
    statistics_.stepsInWaves += static_cast<std::uint64_t>(levels);
}

}  // namespace talus
