#include "InRun/InRunFields.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "Fields/EvaluationPoints.h"
#include "IO/InputError.h"
#include "InRun/InRunFrame.h"
#include "Sampling/Messages.h"
#include "Simulation.h"

namespace talus::cg {

namespace {

// The library's errors name talus-cg's flags and files; in a run they name this object.
template <class Action>
auto refusingAs(const std::string& name, Action action) {
    try {
        return action();
    } catch (const InputError& e) {
        throw talus::Error("in-run coarse graining '" + name + "': " + e.what());
    }
}

}  // namespace

InRunFields::InRunFields(Simulation& simulation, InRunOptions options) : options_(std::move(options)) {
    simulation.addSampler(*this);
}

InRunFields::InRunFields(Simulation& simulation, std::function<InRunOptions()> makeOptions)
    : makeOptions_(std::move(makeOptions)) {
    simulation.addSampler(*this);
}

InRunFields::~InRunFields() = default;

void InRunFields::startRun(Simulation& simulation) {
    forgetSharedInRunFrame();
    if (makeOptions_) options_ = makeOptions_();
    const InRunOptions& o = options_;
    const std::string label = o.name.empty() ? std::string("(unnamed)") : o.name;
    const double dt = simulation.settings().timeStep;
    require((o.everySteps > 0) != (o.everyTime > 0),
            "in-run coarse graining '" + label + "': give the sample interval by everySteps or by everyTime (one of them)");
    every_ = o.everySteps > 0 ? o.everySteps : std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(o.everyTime / dt)));
    halfStep_ = 0.5 * dt;
    require(!(o.timeMin > o.timeMax), "in-run coarse graining '" + label + "': timeMin " + talus::str(o.timeMin) +
                                          " lies after timeMax " + talus::str(o.timeMax));
    refusingAs(label, [&] {
        CoarseGrainingSetup setup;
        setup.shape = o.shape;
        setup.coordinates = Coordinates::fromName(o.coordinates);
        if (setup.coordinates.isCylindrical()) {
            if (o.axis < 0 || o.axis > 2)
                throw InputError("coordinates " + o.coordinates + ": give the drum axis (axis 0, 1 or 2: x, y or z) through axisPoint");
            if (o.points.empty() && !(o.lo && o.hi))
                throw InputError("coordinates " + o.coordinates + ": give the grid's lo and hi (r in the first slot, the coordinate along the axis in the third) or points");
            setup.coordinates.setAxis(o.axis, o.axisPoint);
        }
        setup.width = o.widths ? WidthMatrix::diagonal((*o.widths)[0], (*o.widths)[1], (*o.widths)[2])
                               : WidthMatrix::isotropic(o.width);
        const Domain& domain = simulation.scene().domain();
        setup.periodic = domain.periodic;
        setup.speciesDensity.clear();
        const SpeciesTable& species = simulation.scene().species();
        for (std::size_t s = 0; s < species.size(); ++s) setup.speciesDensity.push_back(species[s].density);
        setup.contactStress = o.contactStress;
        setup.excludedAreBoundary = o.fixed == FixedParticles::boundary;
        grainer_ = std::make_unique<CoarseGrainer>(setup);
        layout_ = grainer_->layout();

        const Vec3 lo = o.lo ? *o.lo : Vec3{domain.lo.x(), domain.lo.y(), domain.lo.z()};
        const Vec3 hi = o.hi ? *o.hi : Vec3{domain.hi.x(), domain.hi.y(), domain.hi.z()};
        std::array<long, 3> count{1, 1, 1};
        for (int a : setup.coordinates.kernelAxes()) {
            if (o.count[a] < 1) throw InputError("count: at least one point along each resolved axis");
            count[a] = o.count[a];
        }
        points_ = o.points.empty() ? gridPoints(setup.coordinates, count, lo, hi) : o.points;
        grainer_->restrictTo(points_);  // (an object's points stay; sources that reach none are skipped)
        writes_ = !o.name.empty() && simulation.ranks().rank() == 0;
        if (!writes_) return 0;
        FieldOutputSetup output;
        output.path = defaultOutputPath(o.format, o.name);
        output.coordinates = setup.coordinates;
        output.layout = layout_;
        output.points = points_;
        output.grid = o.points.empty();
        output.count = count;
        output.lo = lo;
        output.hi = hi;
        output.timeAverage = o.averaging != InRunAveraging::snapshots;
        output.shape = setup.shape;
        output.width = setup.width;
        const char* averaging[] = {"every sample", "the samples between output steps averaged",
                                   "the samples of the run averaged"};
        output.comments = {"talus-cg in a run: coarse-grained fields of " + simulation.settings().name +
                               " (Documentation/CoarseGraining.md \"Fields during a run\")",
                           "function " + kernelShapeName(setup.shape) + ", coordinates " + setup.coordinates.name() +
                               ", sampled every " + std::to_string(every_) + " steps, " +
                               averaging[static_cast<int>(o.averaging)] + ", fixed particles " +
                               (o.fixed == FixedParticles::include   ? "included"
                                : o.fixed == FixedParticles::exclude ? "excluded"
                                                                     : "a boundary"),
                           std::to_string(points_.size()) + " points"};
        writer_ = makeFieldWriter(o.format, output);
        return 0;
    });
    sum_.assign(points_.size() * layout_.count(), 0.0);
    last_.clear();
    samples_ = averaged_ = 0;
    written_ = false;
    seconds_ = 0;
}

bool InRunFields::wantsSteps(const Simulation& simulation, std::uint64_t first, std::uint64_t last) const {
    if (last / every_ * every_ < first) return false;  // no multiple of the interval among them
    const double time = simulation.time() + static_cast<double>(last - simulation.step()) * 2 * halfStep_;
    return time >= options_.timeMin - halfStep_ && time <= options_.timeMax + halfStep_;
}

void InRunFields::sample(Simulation& simulation, const ContactRecordList& contacts) {
    const auto start = std::chrono::steady_clock::now();
    const SimulationState& state = simulation.state();
    const InRunFrame& frame = sharedInRunFrame(simulation, options_.contactStress ? &contacts : nullptr);
    refusingAs(options_.name, [&] {
        if (options_.fixed != FixedParticles::include) grainer_->setExcluded(frame.fixed);
        grainer_->setFrame(frame.particles, options_.contactStress ? &frame.contacts : nullptr, "the run's particles",
                           "the run's contacts");
        grainer_->evaluate(points_, last_);
        return 0;
    });
    simulation.ranks().sum(last_);  // (the fields of the whole scene on every rank)
    ++samples_;
    if (options_.averaging == InRunAveraging::snapshots) {
        if (writes_) refusingAs(options_.name, [&] { return writer_->writeFrame(state.time, state.time, last_), 0; });
    } else {
        if (written_) {
            sum_.assign(sum_.size(), 0.0);
            averaged_ = 0;
            written_ = false;
        }
        if (averaged_ == 0) firstTime_ = state.time;
        lastTime_ = state.time;
        for (std::size_t k = 0; k < sum_.size(); ++k) sum_[k] += last_[k];
        ++averaged_;
    }
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<double> InRunFields::averageSums() const {
    if (options_.averaging == InRunAveraging::snapshots || averaged_ == 0) return last_;
    std::vector<double> mean = sum_;
    for (double& v : mean) v /= averaged_;
    return mean;
}

void InRunFields::writeAverage() {
    if (averaged_ == 0 || written_) return;
    if (writes_) refusingAs(options_.name, [&] { return writer_->writeFrame(firstTime_, lastTime_, averageSums()), 0; });
    written_ = true;
}

void InRunFields::afterOutput(Simulation&) {
    if (options_.averaging == InRunAveraging::perOutput) writeAverage();
}

void InRunFields::finishRun(Simulation& simulation) {
    if (options_.averaging != InRunAveraging::snapshots) writeAverage();
    if (writer_) refusingAs(options_.name, [&] { return writer_->close(), 0; });
    const double seconds = simulation.ranks().max(seconds_);
    say(simulation, "%s: in-run coarse graining %s: %d samples at %zu points in %.3g s (the slowest rank)%s%s\n",
        simulation.settings().name.c_str(), options_.name.empty() ? "(unnamed)" : options_.name.c_str(), samples_, points_.size(), seconds,
        options_.name.empty() ? "" : "; wrote ", options_.name.empty() ? "" : defaultOutputPath(options_.format, options_.name).c_str());
}

double InRunFields::fieldAt(const std::vector<double>& sums, std::size_t p, const std::string& name) const {
    const std::vector<OutputColumn> names = columns();
    const auto it = std::find_if(names.begin(), names.end(), [&](const OutputColumn& c) { return c.name == name; });
    require(it != names.end(), "in-run coarse graining '" + options_.name + "': no field " + name);
    require(p < points_.size() && sums.size() == points_.size() * layout_.count(),
            "in-run coarse graining '" + options_.name + "': point " + std::to_string(p) + " is not among the " +
                std::to_string(points_.size()) + " points of these sums");
    std::vector<double> values;
    appendDerivedFields(layout_, sums.data() + p * layout_.count(), values);
    return values[static_cast<std::size_t>(it - names.begin())];
}

}  // namespace talus::cg
