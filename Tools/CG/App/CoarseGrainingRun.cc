#include "App/CoarseGrainingRun.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "App/CsvWriter.h"
#include "App/FieldWriter.h"
#include "App/RunInputs.h"
#include "App/VtkFieldWriter.h"
#include "App/WidthScanRun.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/DepthAverage.h"
#include "Fields/DerivedFields.h"
#include "Fields/EvaluationPoints.h"
#include "Fields/MixingIndex.h"
#include "Fields/TimeSmoothing.h"
#include "IO/InputError.h"

namespace talus::cg {

namespace {

std::string seconds(double s) {
    std::ostringstream out;
    out.precision(s < 10 ? 2 : 3);
    out << s << " s";
    return out.str();
}

// The grid of -n, -x/-y/-z over the domain box of the first frame used.
struct Grid {
    std::array<long, 3> count{1, 1, 1};
    Vec3 lo{0, 0, 0}, hi{0, 0, 0};
};

Grid gridFromOptions(const ProgramOptions& options, const Coordinates& coordinates, const DomainBox& box) {
    Grid grid;
    const int d = coordinates.dimension();
    const long fallback = d == 1 ? 100 : d == 2 ? 50 : 20;
    const auto axes = coordinates.kernelAxes();
    for (std::size_t c = 0; c < axes.size(); ++c) {
        long n = fallback;
        if (options.counts.size() == 1) n = options.counts[0];
        else if (options.counts.size() == axes.size()) n = options.counts[c];
        else if (options.counts.size() == 3) n = options.counts[axes[c]];
        else if (!options.counts.empty()) {
            throw InputError("-n: give 1 count, " + std::to_string(axes.size()) + " (one per resolved direction of " +
                             coordinates.name() + ") or 3");
        }
        grid.count[axes[c]] = n;
    }
    grid.lo = box.lo;
    grid.hi = box.hi;
    for (int k = 0; k < 3; ++k) {
        if (options.range[k]) {
            grid.lo[k] = (*options.range[k])[0];
            grid.hi[k] = (*options.range[k])[1];
        }
    }
    return grid;
}

// Cylindrical coordinates (Fields/CylindricalCoarseGrainer.h): r from -r, else from 0 to the drum
// radius of the restart file, else to the farthest particle surface from the axis; the
// coordinate along the axis from the range flag of the axis direction, else the box when
// periodic along it, else the particles' centres widened by the kernel's reach R wa.
void setCylindricalRange(const ProgramOptions& options, const RunInputs& inputs, const ParticleFrame& frame, Grid& grid) {
    const Coordinates& c = inputs.setup.coordinates;
    const int axis = c.axis();
    const int across1 = (axis + 1) % 3, across2 = (axis + 2) % 3;
    double farthest = 0, sMin = 1e300, sMax = -1e300;
    for (std::size_t p = 0; p < frame.size(); ++p) {
        const Vec3& x = frame.position[p];
        farthest = std::max(farthest, std::hypot(x[across1] - c.axisPoint()[across1], x[across2] - c.axisPoint()[across2]) + frame.radius[p]);
        sMin = std::min(sMin, x[axis]);
        sMax = std::max(sMax, x[axis]);
    }
    grid.lo = {0, 0, 0};
    grid.hi = {0, 0, 0};
    if (options.radiusRange) {
        grid.lo[0] = (*options.radiusRange)[0];
        grid.hi[0] = (*options.radiusRange)[1];
    } else {
        grid.hi[0] = inputs.drumRadius ? *inputs.drumRadius : farthest;
        if (!(grid.hi[0] > 0)) throw InputError("-r: every particle is on the axis; give the radius range -r MIN MAX");
    }
    if (!c.resolves(2)) return;
    if (options.range[axis]) {
        grid.lo[2] = (*options.range[axis])[0];
        grid.hi[2] = (*options.range[axis])[1];
    } else if (inputs.setup.periodic[axis] && frame.box.length(axis) > 0) {
        grid.lo[2] = frame.box.lo[axis];
        grid.hi[2] = frame.box.hi[axis];
    } else {
        const double reach = KernelProfile(inputs.setup.shape, 3).cutoff() * inputs.setup.width.widths()[4 * axis];
        grid.lo[2] = sMin - reach;
        grid.hi[2] = sMax + reach;
    }
}

}  // namespace

int runCoarseGraining(const ProgramOptions& options, std::ostream& log) {
    if (options.widthScan) return runWidthScan(options, log);
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const OutputFormat format = outputFormatFromName(options.outputFormat);
    requireOutputFormatAvailable(format);  // before reading anything
    RunInputs inputs = resolveRunInputs(options, log);
    const CoarseGrainingSetup& setup = inputs.setup;
    FrameStream frames(inputs, options);

    CoarseGrainer grainer(setup);
    ParticleFrame frame;
    ContactFrame contacts;
    std::vector<Vec3> points;
    std::vector<double> sums, average;
    // The frame's sources into the grainer, its fixed particles first when --fixed-species names
    // them (frame by frame: the frames may differ in size).
    auto setFrame = [&] {
        if (!options.fixedSpecies.empty()) grainer.setExcluded(fixedBySpecies(frame, options.fixedSpecies));
        grainer.setFrame(frame, frames.withContacts() ? &contacts : nullptr, inputs.dataPath, inputs.fstatPath);
    };
    std::unique_ptr<FieldWriter> fieldWriter;
    std::unique_ptr<CsvWriter> depthWriter;
    std::unique_ptr<VtkFieldWriter> depthVtkWriter;  // (--output-format vtk)
    FieldSums layout = grainer.layout();
    int framesUsed = 0;
    // --time-smoothing (Fields/TimeSmoothing.h): the smoothed fields of the output times that no
    // later frame changes are written as each frame arrives.
    std::optional<TimeSmoother> smoother;
    if (options.timeSmoothing) smoother.emplace(options.timeShape, *options.timeSmoothing, options.outputTimes, options.outputStep);
    std::vector<SmoothedFields> smoothed;
    int outputTimes = 0;
    double firstTime = 0, lastTime = 0;
    auto lastProgress = start;
    const std::string outputPath = options.outputPath.empty() ? defaultOutputPath(format, inputs.base) : options.outputPath;
    // M and S go beside the fields: out.csv -> out.mixing.csv.
    const std::string mixingPath =
        !options.mixingPath.empty() ? options.mixingPath
                                    : (outputPath.ends_with(".csv") ? outputPath.substr(0, outputPath.size() - 4) : outputPath) +
                                          ".mixing.csv";

    // Depth averages: z points per column and their spacing (the grid's z is its last axis).
    long pointsPerColumn = 0;
    double dz = 0;
    bool coverageWarned = false;
    std::unique_ptr<CsvWriter> mixingWriter;

    auto writeAveragedOrFrame = [&](const std::vector<double>& rowSums, double frameFirstTime, double time) {
        if (options.depthAverage) {
            std::vector<std::vector<double>> rows;
            const DepthAverageCoverage coverage = depthAverage(layout, rowSums, pointsPerColumn, dz, options.bulkDensity, rows);
            if (depthVtkWriter) {
                std::vector<double> table;
                for (const std::vector<double>& r : rows) table.insert(table.end(), r.begin(), r.end());
                depthVtkWriter->writeValues(frameFirstTime, time, table);
            } else {
                for (std::size_t c = 0; c < rows.size(); ++c) depthWriter->writeRow(time, points[c * pointsPerColumn], rows[c]);
            }
            if (coverage.topDensityRatio > 1e-3 && !coverageWarned) {
                coverageWarned = true;
                log << "talus-cg: warning: --depth-average: at the top of the z range the density is " << str(coverage.topDensityRatio)
                    << " of its column maximum (t = " << str(time) << "): the range -z does not cover the flow, so the mass per area and height are too small\n";
            }
        } else {
            fieldWriter->writeFrame(frameFirstTime, time, rowSums);
        }
        if (mixingWriter) {
            const MixingIndices mixing = mixingIndices(layout, points, rowSums, setup.coordinates, *options.mixingSpecies);
            mixingWriter->writeRow(time, Vec3{0, 0, 0},
                                   {mixing.mixing, mixing.segregation, mixing.speciesAtCore ? 1.0 : 0.0, mixing.centre[0],
                                    mixing.centre[1], mixing.centre[2], mixing.speciesDistance, mixing.materialDistance});
            log << "talus-cg: t = " << str(time) << ": mixing index M = " << str(mixing.mixing) << ", segregation index S = "
                << str(mixing.segregation) << " (species " << *options.mixingSpecies << " at the "
                << (mixing.speciesAtCore ? "core" : "periphery") << ")\n";
        }
    };

    while (frames.next(frame, contacts)) {
        const double time = frame.time;
        if (framesUsed == 0) {
            // The first frame used fixes the evaluation points and the output columns.
            Grid grid;
            if (!options.pointsPath.empty()) {
                points = readPointList(options.pointsPath, setup.coordinates);
                grid.lo = frame.box.lo;
                grid.hi = frame.box.hi;
            } else {
                grid = gridFromOptions(options, setup.coordinates, frame.box);
                if (setup.coordinates.isCylindrical()) setCylindricalRange(options, inputs, frame, grid);
                points = gridPoints(setup.coordinates, grid.count, grid.lo, grid.hi);
                if (options.depthAverage) {
                    if (!setup.coordinates.resolves(2)) {
                        throw InputError("--depth-average: --coordinates " + setup.coordinates.name() +
                                         " does not resolve z (use XZ for a chute, Z for one column)");
                    }
                    pointsPerColumn = grid.count[2];
                    dz = (grid.hi[2] - grid.lo[2]) / double(grid.count[2]);
                }
            }
            // Species in the output: those with a density given (the default list is cut to the
            // species the first frame shows).
            fitSpeciesToFrame(options, inputs, frame);
            grainer = CoarseGrainer(setup);
            layout = grainer.layout();
            // The first frame's sources before any output is opened: its input errors leave no
            // file.
            setFrame();
            if (options.mixingSpecies && layout.species < 2) {
                throw InputError("--mixing: needs a mixture of at least 2 species, the run has " + std::to_string(layout.species));
            }
            std::vector<std::string> comments;
            comments.push_back("talus-cg: coarse-grained fields (Documentation/CoarseGraining.md)");
            comments.push_back("input: " + inputs.dataPath + (setup.contactStress ? " and " + inputs.fstatPath : std::string()) +
                               (inputs.restartPath.empty() ? std::string() : ", " + inputs.restartPath));
            std::ostringstream kernel;
            const auto& b = setup.width.widths();
            kernel << "function " << kernelShapeName(setup.shape) << " (" << setup.coordinates.kernelDimension()
                   << "-D), width matrix B = [" << str(b[0]) << " " << str(b[1]) << " " << str(b[2]) << "; " << str(b[3]) << " "
                   << str(b[4]) << " " << str(b[5]) << "; " << str(b[6]) << " " << str(b[7]) << " " << str(b[8]) << "]";
            const bool domainAverage = setup.coordinates.isDomainAverage();
            comments.push_back(domainAverage ? std::string("no kernel: the domain average") : kernel.str());
            comments.push_back("coordinates " + setup.coordinates.name() +
                               (domainAverage ? " (sums over the particles and contacts of each frame divided by the volume of its domain box)"
                                : setup.coordinates.kernelDimension() < 3 ? " (fields divided by the lengths of the averaged directions of the domain box)"
                                                                          : std::string()) +
                               ", periodic " + periodicText(setup.periodic) + ", densities " + commaList(setup.speciesDensity) +
                               (options.fixedAsBoundary ? ", fixed particles a boundary" : options.excludeFixed ? ", fixed particles excluded" : ", fixed particles included"));
            if (setup.coordinates.isCylindrical()) {
                const Coordinates& c = setup.coordinates;
                comments.push_back("cylindrical coordinates: r = distance from the axis along " + c.coordinateName(2) + " through (" +
                                   str(c.axisPoint()[0]) + ", " + str(c.axisPoint()[1]) + ", " + str(c.axisPoint()[2]) +
                                   "); fields averaged over the angle" + (c.resolves(2) ? "" : " and along the axis") +
                                   "; components R (radial), Theta (azimuthal, right-handed about +" + c.coordinateName(2) +
                                   "), Axial (Fields/CylindricalCoarseGrainer.h)");
            }
            comments.push_back(std::to_string(points.size()) + " points" +
                               (options.pointsPath.empty() ? " (grid, cell centres)" : " from " + options.pointsPath) +
                               (options.timeAverage ? "; time average over the frames with " + str(options.timeMin) +
                                                          " <= t <= " + str(options.timeMax)
                               : options.timeSmoothing
                                   ? "; time smoothing over the frames with " + str(options.timeMin) + " <= t <= " + str(options.timeMax) +
                                         " by " + kernelShapeName(options.timeShape) + " of width " + str(*options.timeSmoothing) +
                                         ", weights normalised at each output time (Fields/TimeSmoothing.h); one block per output time"
                                   : "; one block of rows per frame"));
            // What every writer of the fields needs (the depth averages' VTK image: see below).
            FieldOutputSetup output;
            output.path = outputPath;
            output.coordinates = setup.coordinates;
            output.layout = layout;
            output.points = points;
            output.grid = options.pointsPath.empty();
            output.count = grid.count;
            output.lo = grid.lo;
            output.hi = grid.hi;
            output.timeAverage = options.timeAverage;
            output.shape = setup.shape;
            output.width = setup.width;
            if (options.depthAverage) {
                comments.push_back("depth averages over z (midpoint rule, dz = " + str(dz) + "): " +
                                   (options.bulkDensity ? "height = mass per area / bulk density " + str(*options.bulkDensity)
                                                        : std::string("bulk density = mass-weighted mean density")) +
                                   "; velocity and concentration mass-weighted (Fields/DepthAverage.h)");
            }
            output.comments = comments;
            if (!options.depthAverage) {
                fieldWriter = makeFieldWriter(format, output);
            } else if (format == OutputFormat::Vtk) {
                // The columns' base points, one point along z at z = 0 (a cell of height 1 about it).
                output.points.clear();
                for (std::size_t p = 0; p < points.size(); p += static_cast<std::size_t>(pointsPerColumn))
                    output.points.push_back({points[p][0], points[p][1], 0.0});
                output.count[2] = 1;
                output.lo[2] = -0.5;
                output.hi[2] = 0.5;
                depthVtkWriter = std::make_unique<VtkFieldWriter>(output, depthAveragedColumns(layout));
            } else {
                std::vector<int> axes = setup.coordinates.kernelAxes();
                axes.pop_back();  // z, integrated out
                depthWriter = std::make_unique<CsvWriter>(outputPath, axes, !options.timeAverage, depthAveragedColumns(layout), comments);
            }
            if (options.mixingSpecies) {
                std::vector<std::string> mixingComments = comments;
                mixingComments.push_back("mixing index M and segregation index S (Theory/CoarseGraining.md eq. (13)-(16)) of species " +
                                         std::to_string(*options.mixingSpecies) +
                                         "; SpeciesAtCore 1 when its mean distance from the centre of mass is below the material's (Fields/MixingIndex.h)");
                mixingWriter = std::make_unique<CsvWriter>(
                    mixingPath, std::vector<int>{}, true,
                    std::vector<OutputColumn>{{"MixingIndex", "1"}, {"SegregationIndex", "1"}, {"SpeciesAtCore", "1"},
                                              {"CentreX", "L"}, {"CentreY", "L"}, {"CentreZ", "L"},
                                              {"SpeciesDistance", "L"}, {"MaterialDistance", "L"}},
                    mixingComments);
            }
            average.assign(points.size() * layout.count(), 0.0);
            firstTime = time;
        }

        if (framesUsed > 0) setFrame();
        grainer.evaluate(points, sums);
        if (options.timeAverage) {
            for (std::size_t k = 0; k < sums.size(); ++k) average[k] += sums[k];
        } else if (smoother) {
            smoothed.clear();
            smoother->addFrame(time, sums, smoothed);
            for (const SmoothedFields& out : smoothed) writeAveragedOrFrame(out.sums, out.time, out.time);
            outputTimes += static_cast<int>(smoothed.size());
        } else {
            writeAveragedOrFrame(sums, time, time);
        }
        ++framesUsed;
        lastTime = time;

        const auto now = Clock::now();
        if (std::chrono::duration<double>(now - lastProgress).count() >= options.progressInterval) {
            lastProgress = now;
            const double elapsed = std::chrono::duration<double>(now - start).count();
            const double done = frames.fractionRead();
            log << "talus-cg: " << framesUsed << " frames done (t = " << str(time) << "), " << seconds(elapsed) << " wall";
            if (done > 0 && done < 1) log << ", about " << seconds(elapsed * (1 - done) / done) << " left (" << int(100 * done) << "% of " << inputs.dataPath << ")";
            log << "\n" << std::flush;
        }
    }
    if (framesUsed == 0) {
        throw InputError(inputs.dataPath + ": no frame with " + str(options.timeMin) + " <= t <= " + str(options.timeMax) +
                         " (--time-min, --time-max)");
    }
    if (options.timeAverage) {
        for (double& v : average) v /= framesUsed;
        writeAveragedOrFrame(average, firstTime, lastTime);
    }
    if (smoother) {
        smoothed.clear();
        smoother->finish(smoothed);
        for (const SmoothedFields& out : smoothed) writeAveragedOrFrame(out.sums, out.time, out.time);
        outputTimes += static_cast<int>(smoothed.size());
    }
    if (fieldWriter) fieldWriter->close();
    if (depthWriter) depthWriter->close();
    if (depthVtkWriter) depthVtkWriter->close();
    if (mixingWriter) mixingWriter->close();
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    log << "talus-cg: " << framesUsed << " frames (t = " << str(firstTime) << " to " << str(lastTime) << ")"
        << (options.timeAverage ? " averaged" : smoother ? " smoothed in time to " + std::to_string(outputTimes) + " output times" : "")
        << " at " << points.size() << " points in " << seconds(elapsed) << "; wrote "
        << outputPath << (format == OutputFormat::Hdf5 && !options.depthAverage ? " and its .xmf" : "")
        << (format == OutputFormat::Vtk ? (options.pointsPath.empty() ? " and its .vti frames" : " and its .vtu frames") : "") << "\n";
    return framesUsed;
}

}  // namespace talus::cg
