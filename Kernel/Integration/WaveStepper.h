// Several steps per pass over the particles (time skewing; Contacts/WaveSchedule.h,
// Documentation/TimeSkewing.md): the particles in the order of the wave's cells and the schedule
// of the waves made at each list build, and a wave of steps: the same physics as single steps,
// the forces of a particle summed in another order (round-off). For spheres in a box periodic
// along x and y, on one rank, with nothing but the particles' own motion between steps (the
// scenes of the drift pass), when no output falls within the wave. A wave in which a particle
// outruns the neighbour list is rolled back to its start and redone in single steps (WaveUndo).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "Contacts/WaveSchedule.h"
#include "Integration/Stepper.h"
#include "Integration/WaveUndo.h"
#include "Math/Vector.h"

namespace talus {

class WaveStepper final : public Stepper {
public:
    // singleSteps: the stepper whose scenes waves take (the drift pass), which redoes a wave
    // rolled back.
    explicit WaveStepper(Stepper& singleSteps) : singleSteps_(singleSteps) {}
    std::string_view name() const override { return "waves"; }
    std::string_view whyNot(const StepHost& host) const override;
    std::uint64_t stepsNext(StepHost& host, std::uint64_t stepsLeft, std::uint64_t saveEvery) override;
    void advance(StepHost& host, bool recordContacts) override;

    // At the start of a run, before its first list build: whether it takes waves
    // (StepperTuning::waves; automatic: where they pay, or in a restarted run as the saved run
    // did), written back as the steps of its tuning (1: none), with the reason for the run's
    // first line (choice).
    void choose(StepHost& host, bool restarted);
    const std::string& choice() const { return choice_; }
    // At a list build: the schedule of its waves over every listed pair (the particles are in the
    // order of its cells: cellsForBuild), the list's pairs put in the schedule's order.
    void makeSchedule(StepHost& host);
    // A restarted run goes on in waves as the run that saved did.
    void continueAfterRestart(StepHost& host);
    // The cells of a list build of the given reach (the order of the particles), where the scene
    // has them; else why not (why: may be null).
    std::optional<WaveCells> cellsForBuild(const StepHost& host, double reach, std::string* why) const;
    // The run's summary line of its waves, with why a scene takes none.
    void report(const StepHost& host, std::ostream& out, const std::string& name, std::uint64_t steps) const;

    struct Statistics {
        std::uint64_t stepsInWaves = 0;
        std::uint64_t nearRunsFound = 0;   // the near list's runs found anew for the schedule
        std::uint64_t offTheNearList = 0;  // waves that went on over the whole list (given up mid-wave)
        std::uint64_t rolledBack = 0;      // waves undone (a particle outran the list) and redone in single steps
    };
    const Statistics& statistics() const { return statistics_; }
    void resetStatistics() { statistics_ = {}; }

private:
    bool allowed(const StepHost& host, std::uint64_t stepsLeft, std::uint64_t saveEvery) const;
    bool hasRoom(const StepHost& host, double displacement, double reach) const;
    void buildListForWave(StepHost& host);
    const PlaceRun* nearPairsForWave(StepHost& host, const Vec3& frame);
    // The wave's steps from its start (undo_) in single steps.
    void rollBackAndRedo(StepHost& host, bool recordContacts);

    Stepper& singleSteps_;
    WaveSchedule schedule_;           // over every listed pair
    std::uint64_t scheduleBuild_ = 0;  // the list build it was made for (0: none)
    std::uint64_t scheduleEdits_ = 0;  // and the list's edits then (PairList::edits)
    std::uint64_t scheduleWallRelistings_ = 0;  // and its wall relistings (PairList::wallRelistings)
    std::string refusal_;             // why the last build has none
    std::string choice_;              // whether and why the run takes waves (choose)
    double largestRadius_ = 0;        // at that build
    std::vector<PlaceRun> nearRuns_;  // per run of the schedule, its pairs' places in the near list
    std::uint64_t nearRunsMake_ = 0;  // the near list they were found in (NearPairs::makes)
    Statistics statistics_;
    WaveUndo undo_;  // the state at the wave's start
};

}  // namespace talus
