// Coarse-grained fields during a run (Documentation/CoarseGraining.md "Fields during a run"): an
// object a driver attaches to its simulation that samples the particles and contacts every N
// steps, coarse-grains them with the library talus-cg uses (Fields/CoarseGrainer.h: the same
// sums) and writes the fields talus-cg would write from .data and .fstat files of the same steps
// (csv or MercuryDPM's .stat layout, App/FieldWriter.h), at every output step or at the end of
// the run, without writing .data or .fstat. A driver makes one as a member,
//
//     cg::InRunFields depth_{*this, {.name = "depth", .coordinates = "Z", .width = 0.5,
//                                    .count = {1, 1, 80}, .everySteps = 100}};
//
// and may read the fields in its hooks (lastSums(), averageSums(), fieldAt()). The kernel calls it
// through Kernel/Sampling/StepSampler.h; it lives in its own library, talus-cg-inrun, which links
// the kernel and the coarse-graining library, neither of which depends on the other.
//
// On MPI ranks every rank coarse-grains the particles it owns and the contacts whose first
// particle it owns (each contact is recorded on one rank: Contacts/ContactReport.h); the sums at
// the points are then added over the ranks before anything is derived or written, so every rank
// holds the fields of the whole scene and rank 0 writes them. Fields are additive sums
// (Fields/FieldSums.h), so the ranks' parts add up to the one-rank sums but for round-off.
//
// Averaging (as talus-cg's --time-average, the sums averaged and the fields derived from them):
// over the samples between two output steps, written at each output step (perOutput); over all
// samples of the run within [timeMin, timeMax], written at its end (wholeRun); or none, every
// sample written as it is taken (snapshots, like talus-cg without averaging). A restarted run
// starts its averages afresh.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "App/FieldWriter.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/DerivedFields.h"
#include "Sampling/StepSampler.h"

namespace talus {
class Simulation;
}

namespace talus::cg {

enum class InRunAveraging { snapshots, perOutput, wholeRun };
// Fixed particles as talus-cg's --fixed: include them as particles, exclude them from the
// particle fields, or treat them as a boundary (Fields/CoarseGrainer.h "Boundaries").
enum class FixedParticles { include, exclude, boundary };

struct InRunOptions {
    // Output file NAME.cg.csv (NAME.stat for the stat format) beside the run's files; empty: no
    // file (the driver reads the fields itself).
    std::string name{};
    std::string coordinates = "XYZ";  // as talus-cg --coordinates (Fields/Coordinates.h)
    // Cylindrical coordinates (RZ, R): the drum axis along x, y or z (0, 1, 2) through axisPoint;
    // a grid then needs lo and hi: r in their first slot, the coordinate along the axis in the third.
    int axis = -1;
    Vec3 axisPoint{0, 0, 0};
    KernelShape shape = KernelShape::Lucy;
    double width = 1;                 // isotropic width w (Theory/CoarseGraining.md)
    std::optional<std::array<double, 3>> widths{};  // per axis, instead of `width`
    // A grid of count[a] points along each resolved lab axis a, at the cell centres of [lo, hi]
    // (Fields/EvaluationPoints.h; the domain box where not given), or listed `points`.
    std::array<long, 3> count{20, 20, 20};
    std::optional<Vec3> lo{}, hi{};
    std::vector<Vec3> points{};
    // Sample every `everySteps` steps (steps numbered as Simulation::step(); the step 0 of a run
    // from its set-up included), or every `everyTime` of simulated time (rounded to steps).
    std::uint64_t everySteps = 0;
    double everyTime = 0;
    double timeMin = -std::numeric_limits<double>::infinity();
    double timeMax = std::numeric_limits<double>::infinity();
    InRunAveraging averaging = InRunAveraging::wholeRun;
    bool contactStress = true;
    FixedParticles fixed = FixedParticles::include;
    OutputFormat format = OutputFormat::Csv;
};

class InRunFields final : public StepSampler {
public:
    // Attaches itself to `simulation` (Simulation::addSampler); call from the driver's
    // constructor. Options are checked when the run starts (a talus::Error names them).
    InRunFields(Simulation& simulation, InRunOptions options);
    // The same with options made when each run starts, after the command line was read (also in
    // a restarted run, which skips setupInitialConditions): for options that follow the driver's
    // flags.
    InRunFields(Simulation& simulation, std::function<InRunOptions()> makeOptions);
    ~InRunFields() override;
    InRunFields(const InRunFields&) = delete;
    InRunFields& operator=(const InRunFields&) = delete;

    const InRunOptions& options() const { return options_; }
    // After the run started: the evaluation points, the layout of a row of sums (one row per
    // point), the derived fields' column names.
    const std::vector<Vec3>& points() const { return points_; }
    const FieldSums& layout() const { return layout_; }
    std::vector<OutputColumn> columns() const { return derivedColumns(layout_); }
    // The sums of the last sample (summed over the ranks), and the mean of the samples of the
    // current average (perOutput: since the last output; wholeRun: since the run began; snapshots:
    // the last sample); empty before the first sample. A written average stays readable (in the
    // driver's actionsAfterSolve, say) until the next sample starts a new one.
    const std::vector<double>& lastSums() const { return last_; }
    std::vector<double> averageSums() const;
    int samplesAveraged() const { return averaged_; }
    int samples() const { return samples_; }
    // Derived field `name` (a column of columns(), e.g. "VelocityX", "StressXZ") at point p of `sums`.
    double fieldAt(const std::vector<double>& sums, std::size_t p, const std::string& name) const;
    // Seconds this object spent sampling (all its samples, this rank).
    double seconds() const { return seconds_; }

    // --- StepSampler ---
    void startRun(Simulation& simulation) override;
    bool wantsSteps(const Simulation& simulation, std::uint64_t first, std::uint64_t last) const override;
    void sample(Simulation& simulation, const ContactRecordList& contacts) override;
    void afterOutput(Simulation& simulation) override;
    void finishRun(Simulation& simulation) override;

private:
    void writeAverage();

    InRunOptions options_;
    std::function<InRunOptions()> makeOptions_;
    std::uint64_t every_ = 1;
    double halfStep_ = 0;
    std::unique_ptr<CoarseGrainer> grainer_;
    FieldSums layout_;
    std::vector<Vec3> points_;
    bool writes_ = false;
    std::unique_ptr<FieldWriter> writer_;
    std::vector<double> last_, sum_;
    int samples_ = 0, averaged_ = 0;
    bool written_ = false;  // the average was written: the next sample starts a new one
    double firstTime_ = 0, lastTime_ = 0;
    double seconds_ = 0;
};

}  // namespace talus::cg
