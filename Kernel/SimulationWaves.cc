// Several steps per pass over the particles (time skewing; Contacts/WaveSchedule.h,
// Documentation/TimeSkewing.md), Simulation's side: the particles in the order of the wave's
// cells and the schedule made at each list build, and a wave of steps.
#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>
#include <sstream>

#include "Particles/VelocityVerlet.h"
#include "Simulation.h"

namespace talus {

void Simulation::setWaves(int steps, int stripColumns) {
    require(stripColumns >= 1, "strips of waves need at least one column, got " + std::to_string(stripColumns));
    setWaves(steps);
    state_.settings.waveStripColumns = stripColumns;
}

void Simulation::setWaves(int steps) {
    require(steps >= 1 && steps <= 255, "waves of 1 to 255 steps, got " + std::to_string(steps));
    state_.settings.waveSteps = steps;
    waveScheduleBuild_ = 0;
}

// The cells of a list build of the given reach: as wide as the longest pair it can list,
// 2 rmax + reach.
std::optional<WaveCells> Simulation::waveCellsForBuild(double reach, std::string* why) const {
    if (state_.settings.waveSteps < 2) return std::nullopt;
    if (onRanks()) {
        if (why) *why = "waves run on one rank only";
        return std::nullopt;
    }
    double largest = 0;
    for (double r : state_.particles.radius) largest = std::max(largest, r);
    return WaveCells::fit(state_.domain, (2 * largest + reach) * (1 + 1e-9), state_.settings.waveSteps,
                          waveStripColumns(), why);
}

// At a list build: the schedule of its waves over every listed pair (the particles are in the
// order of its cells: reorderParticles), the list's pairs put in the schedule's order.
void Simulation::makeWaveSchedule() {
    waveScheduleBuild_ = waveNearRunsMake_ = 0;
    waveScheduleRefusal_.clear();
    if (state_.settings.waveSteps < 2) return;
    if (state_.settings.idOrderedSums) {  // (its sums follow the list's places: IdOrderedForceSums)
        waveScheduleRefusal_ = "waves do not run with --id-ordered-sums";
        return;
    }
    PairList& list = state_.pairList;
    const std::optional<WaveCells> cells = waveCellsForBuild(list.reach, &waveScheduleRefusal_);
    // The list takes the schedule's order of pairs (a few runs of places per region).
    std::vector<std::uint32_t> order;
    if (cells && waveSchedule_.make(*cells, list.pairs, list.interiorPairs, list.referencePosition,
                                    state_.particles.size(), &waveScheduleRefusal_, list.wallPairs, &order)) {
        list.reorderPairs(order);
        waveScheduleBuild_ = list.builds;
    }
    waveLargestRadius_ = 0;
    for (double r : state_.particles.radius) waveLargestRadius_ = std::max(waveLargestRadius_, r);
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
const PlaceRun* Simulation::nearPairsForWave(const Vec3& frame) {
    PairList& list = state_.pairList;
    NearPairs& near = list.near;
    const ParticleStore& p = state_.particles;
    const double dt = state_.settings.timeStep;
    const double nearSkin = list.nearSkinFraction * list.skin, nearLimit = nearAllowance(nearSkin);
    const double steps = state_.settings.waveSteps;
    const double speed = 2 * list.maxSpeed + state_.gravity.norm() * steps * dt + frame.norm();
    const double wave = (steps + 1) * (1.000001 * speed * dt + 1e-12 * waveLargestRadius_);
    if (!(nearSkin > 0 && wave < nearLimit)) return nullptr;
    const bool whole = nearPairsAreCurrent(list, nearSkin) && near.moved + wave < nearLimit;
    if (!whole) {
        SweptPairs scratch;
        makeNearPairs(list, p.position.data(), p.size(), p.radius.data(), nearSkin, PeriodicImage(state_.domain),
                      list.nearPointScratch, scratch);
    }
    if (waveNearRunsMake_ != near.makes) {
        // The near list is in the list's order: a run of places holds a run of near pairs.
        const auto at = [&](std::uint32_t place) {
            return static_cast<std::uint32_t>(
                std::lower_bound(near.pairs.begin(), near.pairs.end(), place,
                                 [](const NearPairs::Pair& a, std::uint32_t b) { return a.index < b; }) -
                near.pairs.begin());
        };
        const std::vector<PlaceRun>& runs = waveSchedule_.placeRuns();
        waveNearRuns_.resize(runs.size());
        for (std::size_t u = 0; u < runs.size(); ++u) waveNearRuns_[u] = {at(runs[u].begin), at(runs[u].end)};
        waveNearRunsMake_ = near.makes;
        ++waveNearRunsFound_;
    }
    return waveNearRuns_.data();
}

// Waves go on as in the run that saved: the schedule of the list it kept, and the displacement
// the last step left, measured as the drift pass does.
void Simulation::continueWavesAfterRestart() {
    const PairList& list = state_.pairList;
    if (!list.comparable(state_.particles) || onRanks()) return;
    lastDisplacement_ = largestDisplacement(state_.particles, list.referencePosition, state_.domain);
    if (state_.settings.waveSteps > 1) makeWaveSchedule();
}

// The run's summary line of its waves, with why a scene takes none.
void Simulation::reportWaves(std::ostream& out, std::uint64_t steps) const {
    if (state_.settings.waveSteps < 2) return;
    out << name() << ": " << stepsInWaves_ << " of " << steps << " steps in waves of " << state_.settings.waveSteps;
    if (const std::optional<WaveCells> cells = waveCellsForBuild(state_.pairList.reach, nullptr))
        out << " (" << cells->strips() << (cells->strips() == 1 ? " strip" : " strips") << " of about "
            << cells->columns() / cells->strips() << " columns, asked for " << waveStripColumns() << ")";
    if (waveNearRunsFound_ > 0)
        out << ", over the near list (" << waveNearRunsFound_ << " of them, the last of " << state_.pairList.near.pairs.size()
            << " of " << state_.pairList.pairs.size() << " pairs)";
    if (waveNearGivenUp_ > 0)
        out << "; " << waveNearGivenUp_ << " waves went on over the whole list when a particle sped up past the near list";
    if (!waveScheduleRefusal_.empty())
        out << "; the last list build has no wave schedule: " << waveScheduleRefusal_;
    else if (stepsInWaves_ == 0)
        out << " (waves need spheres in one rank's periodic box, no boundaries or prescribed motions: "
               "Documentation/TimeSkewing.md)";
    out << std::endl;
}

// Whether the next steps can be a wave: the scene allows it (waveAllowed), and no particle can
// have moved half the list's reach by its end, even if the largest speed doubles (waveHasRoom;
// checked as the wave goes: integrateWave).
bool Simulation::waveFits(std::uint64_t stepsLeft, std::uint64_t saveEvery) const {
    return waveAllowed(stepsLeft, saveEvery) && waveHasRoom(lastDisplacement_, state_.pairList.reach);
}

// The scene allows a wave now: one drift pass a step, spheres, one rank, no one-way box
// (driftsInOnePass), the schedule is the current list's, and no output falls within it (one at
// its last step is written after it). Waves start at multiples of their steps, so that a
// restarted run takes them where the first run did, whatever the output steps.
bool Simulation::waveAllowed(std::uint64_t stepsLeft, std::uint64_t saveEvery) const {
    const auto steps = static_cast<std::uint64_t>(state_.settings.waveSteps);
    const PairList& list = state_.pairList;
    if (steps < 2 || stepsLeft < steps || state_.step % steps != 0) return false;
    if (saveEvery > 0 && state_.step / saveEvery != (state_.step + steps - 1) / saveEvery) return false;
    return driftsInOnePass() && !state_.settings.idOrderedSums && waveScheduleBuild_ != 0 &&
           waveScheduleBuild_ == list.builds && list.comparable(state_.particles) && list.oneWayPairs.empty();
}

// A particle `displacement` from the list's positions, at the largest speed doubled (and gravity's
// gain), stays within half the list's `reach` through a wave and the step after it.
bool Simulation::waveHasRoom(double displacement, double reach) const {
    const double steps = state_.settings.waveSteps, dt = state_.settings.timeStep;
    const double speed = 2 * state_.pairList.maxSpeed + state_.gravity.norm() * steps * dt;
    return displacement + (steps + 1) * speed * dt < 0.5 * reach;
}

// Where a wave is allowed but the list has no room left for it, the list is built anew before
// it (at the positions between two steps, as a step's build would be after its drift), so that
// waves go on. Otherwise the list's last (N + 1) 2 vmax dt of room went in single steps (about
// 20 of the 370 steps between builds in the benchmark's flow), which beyond the caches cost
// about twice a step in a wave: in the flow, waves of 8, best of five interleaved rounds, 41.8
// against 44.1 ns per particle-step at 108000 particles, 49.1 against 50.3 at 972000
// (Documentation/TimeSkewing.md).
// Not when a new list would have no room either (a speed too large for waves: single steps go
// on, rebuilding as they need).
void Simulation::buildListForWave() {
    PairList& list = state_.pairList;
    const double dt = state_.settings.timeStep;
    if (!waveHasRoom(0, list.reachOfNextBuild(dt))) return;
    ParticleStore& p = state_.particles;
    // (Between steps the forces to kick with are in p, not yet in previousForce_.)
    if (state_.settings.reorderParticles) reorderParticles(/*withPreviousForces*/ false);
    list.rebuild(p, state_.domain, state_.walls, grid_, dt);
    lastDisplacement_ = 0;
    makeWaveSchedule();
}

std::uint64_t Simulation::integrateWave(bool recordContacts) {
    ParticleStore& p = state_.particles;
    PairList& list = state_.pairList;
    const Domain& domain = state_.domain;
    const double dt = state_.settings.timeStep, half = 0.5 * dt;
    const int levels = state_.settings.waveSteps;
    // The wave's first step starts as a single step's (the last step's forces become the ones to
    // kick with), its first half kick and drift going along with the first level's regions
    // (WaveRegion::driftBegin); the same frame for the sweep's growths all through the wave (any
    // frame common to both particles of a pair at a step keeps the sweep's bound, PairSweep.h).
    const Vec3 frame = sweepFrame();
    checkPositionsFound(positionSum(p, p.owned()));
    startFirstHalf(p, previousForce_, list.sweepPointScratch);
    state_.time += dt;
    ++state_.step;
    // Over the near list: the growth of each step (its largest) for NearPairs::moved.
    const PlaceRun* near = nearPairsForWave(frame);
    const double nearMoved = list.near.moved, nearLimit = nearAllowance(list.near.skin);
    std::array<double, 256> levelGrowth{};  // (waves of at most 255 steps: setWaves)
    double growth = 0;
    const double startSpeed = list.maxSpeed;
    double speed2 = 0, displacement2 = 0, finalDisplacement2 = 0;
    double velocitySum[3] = {0, 0, 0};
    std::size_t mobile = 0;
    std::uint64_t positionsAfter = 0;  // (positionSum of where the last drift leaves the particles)
    // A drift of the wave into step `step` (1: its first) at `time`, noted: the largest speed,
    // displacement and growth; the near list given up for the rest of the wave if a particle sped
    // up past it (the pairs swept so far were within it: every growth of their particles so far
    // fitted); the run stopped if past the list's allowance.
    const auto noteDrift = [&](const DriftPassResult& moved, int step, double time) {
        if (!moved.moves.finite) list.needsRebuild(moved.moves, p, time, dt);  // (throws, naming the particle)
        speed2 = std::max(speed2, moved.moves.speed2);
        displacement2 = std::max(displacement2, moved.moves.displacement2);
        growth = std::max(growth, moved.growth);
        double& grown = levelGrowth[static_cast<std::size_t>(step) - 1];
        grown = std::max(grown, moved.growth);
        if (near && nearMoved + (levels + 1) * growth >= nearLimit) [[unlikely]] {
            near = nullptr;
            ++waveNearGivenUp_;
        }
        if (std::sqrt(displacement2) + std::sqrt(speed2) * dt >= 0.5 * list.reach) {
            std::ostringstream m;
            m << "a wave of " << levels << " steps at t = " << time << ": a particle moved "
              << std::sqrt(displacement2) << " since the neighbour list was built, which with the largest "
              << "speed " << std::sqrt(speed2) << " (" << startSpeed << " when the wave began) reaches half "
              << "the list's reach " << list.reach << " within the wave; its pairs may be missing. Run "
              << "with --wave-steps 1, or a larger --skin";
            throw Error(m.str());
        }
    };
    ContactSummary early;  // of the wave's steps before its last (only their largest overlap counts)
    summary_ = ContactSummary{};
    if (recordContacts) records_.start(/*keepEach*/ state_.settings.writeFstat, p.owned());
    std::visit(
        [&]<class Law>(const PairTable<Law>& laws) {
            ContactForceLoop<Law> earlyLoop(p, laws, dt, startSpeed, previousForce_, early, nullptr);
            ContactForceLoop<Law> lastLoop(p, laws, dt, startSpeed, previousForce_, summary_,
                                           recordContacts ? &records_ : nullptr);
            for (const WaveRegion& region : waveSchedule_.regions()) {
                const bool last = region.level + 1 == levels;
                ContactForceLoop<Law>& loop = last ? lastLoop : earlyLoop;
                for (std::uint32_t k = region.driftBegin; k < region.driftEnd; ++k) {
                    const PlaceRun run = waveSchedule_.driftRuns()[k];
                    noteDrift(kickDriftAndStartForces(p, previousForce_, domain, &list.referencePosition, state_.gravity,
                                                      frame, dt, list.sweepPointScratch, run.begin, run.end),
                              1, state_.time);
                }
                loop.allowSpeed(std::sqrt(speed2));
                loop.regionPairs(list, domain, waveSchedule_, region, state_.walls, near);
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
                        closeKickDriftAndStartForces(p, previousForce_, domain, &list.referencePosition, state_.gravity,
                                                     frame, dt, list.sweepPointScratch, begin, end);
                    noteDrift(moved, region.level + 2, state_.time + (region.level + 1) * dt);
                    if (region.level + 2 == levels) {  // (the last drift: where the wave ends, the next frame)
                        finalDisplacement2 = std::max(finalDisplacement2, moved.moves.displacement2);
                        for (int c = 0; c < 3; ++c) velocitySum[c] += moved.velocitySum[c];
                        mobile += moved.mobile;
                        positionsAfter += moved.positionsAfter;
                    }
                }
            }
        },
        laws_);
    for (int t = 1; t < levels; ++t) {
        state_.time += dt;
        ++state_.step;
    }
    // The largest speed in the wave (the next wave's prediction), and the displacement of where
    // the particles are, as a single step leaves it (and a restart finds it: largestDisplacement).
    list.maxSpeed = std::sqrt(speed2);
    lastDisplacement_ = std::sqrt(finalDisplacement2);
    notePositionsLeft(positionsAfter);
    const Vec3 mean = Vec3(velocitySum[0], velocitySum[1], velocitySum[2]) / static_cast<double>(std::max<std::size_t>(mobile, 1));
    driftFrame_ = mean.allFinite() ? mean : Vec3::Zero();
    if (near)
        for (int t = 0; t < levels; ++t) list.near.moved += levelGrowth[static_cast<std::size_t>(t)];
    else
        list.near.made = false;  // (its bound of the displacements did not follow the wave)
    list.sweepPointsGrowth.reset();
    if (early.maxOverlapFraction > summary_.maxOverlapFraction) {
        summary_.maxOverlapFraction = early.maxOverlapFraction;
        summary_.worstA = early.worstA, summary_.worstB = early.worstB, summary_.worstIsWall = early.worstIsWall;
    }
    if (recordContacts) {
        elasticEnergy_ = records_.elasticEnergy();
        recordedContacts_ = records_.count();
    }
    checkOverlaps(state_.settings.maxOverlapFraction, /*initial*/ false, /*agreeNow*/ recordContacts);
    stepsInWaves_ += static_cast<std::uint64_t>(levels);
    return static_cast<std::uint64_t>(levels);
}

}  // namespace talus
