#include "App/CoarseGrainingRun.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <numbers>
#include <sstream>

#include "App/CsvWriter.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/DepthAverage.h"
#include "Fields/DerivedFields.h"
#include "Fields/EvaluationPoints.h"
#include "Fields/MixingIndex.h"
#include "IO/DataFileReader.h"
#include "IO/FstatFileReader.h"
#include "IO/InputError.h"
#include "IO/RestartFileReader.h"

namespace talus::cg {

namespace {

bool exists(const std::string& path) {
    std::error_code error;
    return !path.empty() && std::filesystem::is_regular_file(path, error);
}

std::string list(const std::vector<double>& values) {
    std::string text;
    for (double v : values) {
        if (!text.empty()) text += ',';
        text += str(v);
    }
    return text;
}

std::string periodicText(const std::array<bool, 3>& periodic) {
    std::string text;
    for (int k = 0; k < 3; ++k) {
        if (!periodic[k]) continue;
        if (!text.empty()) text += ',';
        text += axisLetter(k);
    }
    return text.empty() ? "none" : text;
}

std::string seconds(double s) {
    std::ostringstream out;
    out.precision(s < 10 ? 2 : 3);
    out << s << " s";
    return out.str();
}

}  // namespace

int runCoarseGraining(const ProgramOptions& options, std::ostream& log) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const std::string dataPath = options.dataPath.empty() ? options.name + ".data" : options.dataPath;
    const std::string base = options.name.empty() ? dataPath.substr(0, dataPath.size() - (dataPath.ends_with(".data") ? 5 : 0))
                                                  : options.name;

    // Restart file: densities, periodic directions, fixed particles.
    std::string restartPath = options.restartPath;
    if (restartPath.empty() && exists(base + ".restart")) restartPath = base + ".restart";
    if (restartPath == "none") restartPath.clear();
    std::optional<RestartInfo> restart;
    if (!restartPath.empty()) {
        restart = readRestartFile(restartPath);
        log << "talus-cg: " << restartPath << " (" << restart->writer << "): densities " << list(restart->speciesDensity)
            << ", periodic " << periodicText(restart->periodic) << ", " << restart->fixed.size() << " particles\n";
    }

    CoarseGrainingSetup setup;
    setup.shape = options.shape;
    setup.coordinates = Coordinates::fromName(options.coordinates);
    if (options.widthMatrix) setup.width = WidthMatrix::full(*options.widthMatrix);
    else if (options.widths) setup.width = WidthMatrix::diagonal((*options.widths)[0], (*options.widths)[1], (*options.widths)[2]);
    else setup.width = WidthMatrix::isotropic(options.width.value_or(1.0));
    setup.speciesDensity = options.densities ? *options.densities
                           : restart         ? restart->speciesDensity
                                             : std::vector<double>{6.0 / std::numbers::pi};
    if (!options.densities && !restart) {
        // The default 6/pi (SPEC.md 1: d = 1 has mass 1) for every species the data will show.
        setup.speciesDensity.assign(16, 6.0 / std::numbers::pi);
    }
    setup.periodic = options.periodic ? *options.periodic : restart ? restart->periodic : std::array<bool, 3>{false, false, false};
    if (options.excludeFixed) {
        if (!restart) throw InputError("--fixed exclude: needs a restart file to know which particles are fixed (--restart FILE)");
        setup.excluded = restart->fixed;
    }

    std::string fstatPath = options.fstatPath;
    if (fstatPath.empty() && exists(base + ".fstat")) fstatPath = base + ".fstat";
    setup.contactStress = options.stress.value_or(!fstatPath.empty());
    if (setup.contactStress && fstatPath.empty()) {
        throw InputError("--stress on: no contact file (" + base + ".fstat not found; give --fstat FILE)");
    }

    DataFileReader data(dataPath);
    std::optional<FstatFileReader> fstat;
    if (setup.contactStress) fstat.emplace(fstatPath);

    CoarseGrainer grainer(setup);
    ParticleFrame frame;
    ContactFrame contacts;
    std::vector<Vec3> points;
    std::vector<double> sums, average;
    std::unique_ptr<CsvWriter> writer;
    std::vector<OutputColumn> columns;
    FieldSums layout = grainer.layout();
    int framesUsed = 0;
    long frameIndex = 0;
    double firstTime = 0, lastTime = 0;
    auto lastProgress = start;
    const std::string outputPath = options.outputPath.empty() ? base + ".cg.csv" : options.outputPath;
    // M and S go beside the fields: out.csv -> out.mixing.csv.
    const std::string mixingPath =
        !options.mixingPath.empty() ? options.mixingPath
                                    : (outputPath.ends_with(".csv") ? outputPath.substr(0, outputPath.size() - 4) : outputPath) +
                                          ".mixing.csv";

    std::vector<std::string> comments;
    // Depth averages: z points per column and their spacing (the grid's z is its last axis).
    long pointsPerColumn = 0;
    double dz = 0;
    bool coverageWarned = false;
    std::unique_ptr<CsvWriter> mixingWriter;

    auto writeAveragedOrFrame = [&](const std::vector<double>& rowSums, double time) {
        if (options.depthAverage) {
            std::vector<std::vector<double>> rows;
            const DepthAverageCoverage coverage = depthAverage(layout, rowSums, pointsPerColumn, dz, options.bulkDensity, rows);
            for (std::size_t c = 0; c < rows.size(); ++c) writer->writeRow(time, points[c * pointsPerColumn], rows[c]);
            if (coverage.topDensityRatio > 1e-3 && !coverageWarned) {
                coverageWarned = true;
                log << "talus-cg: warning: --depth-average: at the top of the z range the density is " << str(coverage.topDensityRatio)
                    << " of its column maximum (t = " << str(time) << "): the range -z does not cover the flow, so the mass per area and height are too small\n";
            }
        } else {
            std::vector<double> values;
            for (std::size_t p = 0; p < points.size(); ++p) {
                values.clear();
                appendDerivedFields(layout, rowSums.data() + p * layout.count(), values);
                writer->writeRow(time, points[p], values);
            }
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

    while (true) {
        const long headerLine = data.file().lineNumber() + 1;
        if (!data.readFrame(frame)) break;
        const double time = frame.time;
        ++frameIndex;
        if (fstat) {
            if (!fstat->readFrame(contacts)) {
                throw InputError(fstatPath + ": ends before the frame at t = " + str(time) + " of " + dataPath + " (line " +
                                 std::to_string(headerLine) + ")");
            }
            if (std::abs(contacts.time - time) > 1e-9 * std::max(1.0, std::abs(time))) {
                throw InputError(fstatPath + " line " + std::to_string(contacts.headerLine) + ": frame time " + str(contacts.time) +
                                 " differs from the time " + str(time) + " of frame " + std::to_string(frameIndex) + " of " +
                                 dataPath + " (line " + std::to_string(frame.headerLine) + ")");
            }
        }
        if (time < options.timeMin) continue;
        if (time > options.timeMax) break;

        if (!writer) {
            // The first frame used fixes the evaluation points and the output columns.
            if (!options.pointsPath.empty()) {
                points = readPointList(options.pointsPath, setup.coordinates);
            } else {
                const int d = setup.coordinates.dimension();
                std::array<long, 3> count{1, 1, 1};
                const long fallback = d == 1 ? 100 : d == 2 ? 50 : 20;
                const auto axes = setup.coordinates.kernelAxes();
                for (std::size_t c = 0; c < axes.size(); ++c) {
                    long n = fallback;
                    if (options.counts.size() == 1) n = options.counts[0];
                    else if (options.counts.size() == axes.size()) n = options.counts[c];
                    else if (options.counts.size() == 3) n = options.counts[axes[c]];
                    else if (!options.counts.empty()) {
                        throw InputError("-n: give 1 count, " + std::to_string(axes.size()) + " (one per resolved direction of " +
                                         setup.coordinates.name() + ") or 3");
                    }
                    count[axes[c]] = n;
                }
                Vec3 lo = frame.box.lo, hi = frame.box.hi;
                for (int k = 0; k < 3; ++k) {
                    if (options.range[k]) {
                        lo[k] = (*options.range[k])[0];
                        hi[k] = (*options.range[k])[1];
                    }
                }
                points = gridPoints(setup.coordinates, count, lo, hi);
                if (options.depthAverage) {
                    if (!setup.coordinates.resolves(2)) {
                        throw InputError("--depth-average: --coordinates " + setup.coordinates.name() +
                                         " does not resolve z (use XZ for a chute, Z for one column)");
                    }
                    pointsPerColumn = count[2];
                    dz = (hi[2] - lo[2]) / double(count[2]);
                }
            }
            // Species in the output: those with a density given (the default list is cut to the
            // species the first frame shows).
            if (!options.densities && !restart) {
                int species = 1;
                for (int s : frame.species) species = std::max(species, s + 1);
                if (species > 16) throw InputError(dataPath + ": species index " + std::to_string(species - 1) + " needs --density");
                setup.speciesDensity.resize(species);
                grainer = CoarseGrainer(setup);
                layout = grainer.layout();
            }
            if (options.mixingSpecies && layout.species < 2) {
                throw InputError("--mixing: needs a mixture of at least 2 species, the run has " + std::to_string(layout.species));
            }
            columns = options.depthAverage ? depthAveragedColumns(layout) : derivedColumns(layout);
            comments.push_back("talus-cg: coarse-grained fields (Documentation/CoarseGraining.md)");
            comments.push_back("input: " + dataPath + (setup.contactStress ? " and " + fstatPath : std::string()) +
                               (restartPath.empty() ? std::string() : ", " + restartPath));
            std::ostringstream kernel;
            const auto& b = setup.width.widths();
            kernel << "function " << kernelShapeName(setup.shape) << " (" << setup.coordinates.dimension()
                   << "-D), width matrix B = [" << str(b[0]) << " " << str(b[1]) << " " << str(b[2]) << "; " << str(b[3]) << " "
                   << str(b[4]) << " " << str(b[5]) << "; " << str(b[6]) << " " << str(b[7]) << " " << str(b[8]) << "]";
            comments.push_back(kernel.str());
            comments.push_back("coordinates " + setup.coordinates.name() +
                               (setup.coordinates.dimension() < 3 ? " (fields divided by the lengths of the averaged directions of the domain box)"
                                                                  : std::string()) +
                               ", periodic " + periodicText(setup.periodic) + ", densities " + list(setup.speciesDensity) +
                               (options.excludeFixed ? ", fixed particles excluded" : ", fixed particles included"));
            comments.push_back(std::to_string(points.size()) + " points" +
                               (options.pointsPath.empty() ? " (grid, cell centres)" : " from " + options.pointsPath) +
                               (options.timeAverage ? "; time average over the frames with " + str(options.timeMin) +
                                                          " <= t <= " + str(options.timeMax)
                                                    : "; one block of rows per frame"));
            if (options.depthAverage) {
                comments.push_back("depth averages over z (midpoint rule, dz = " + str(dz) + "): " +
                                   (options.bulkDensity ? "height = mass per area / bulk density " + str(*options.bulkDensity)
                                                        : std::string("bulk density = mass-weighted mean density")) +
                                   "; velocity and concentration mass-weighted (Fields/DepthAverage.h)");
                std::vector<int> axes = setup.coordinates.kernelAxes();
                axes.pop_back();  // z, integrated out
                writer = std::make_unique<CsvWriter>(outputPath, axes, !options.timeAverage, columns, comments);
            } else {
                writer = std::make_unique<CsvWriter>(outputPath, setup.coordinates, !options.timeAverage, columns, comments);
            }
            if (options.mixingSpecies) {
                std::vector<std::string> mixingComments = comments;
                mixingComments.push_back("mixing index M and segregation index S (SPEC.md 5) of species " +
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

        grainer.setFrame(frame, fstat ? &contacts : nullptr, dataPath, fstatPath);
        grainer.evaluate(points, sums);
        if (options.timeAverage) {
            for (std::size_t k = 0; k < sums.size(); ++k) average[k] += sums[k];
        } else {
            writeAveragedOrFrame(sums, time);
        }
        ++framesUsed;
        lastTime = time;

        const auto now = Clock::now();
        if (std::chrono::duration<double>(now - lastProgress).count() >= options.progressInterval) {
            lastProgress = now;
            const double elapsed = std::chrono::duration<double>(now - start).count();
            const double done = double(data.file().bytesRead()) / double(std::max<std::uintmax_t>(data.file().size(), 1));
            log << "talus-cg: " << framesUsed << " frames done (t = " << str(time) << "), " << seconds(elapsed) << " wall";
            if (done > 0 && done < 1) log << ", about " << seconds(elapsed * (1 - done) / done) << " left (" << int(100 * done) << "% of " << dataPath << ")";
            log << "\n" << std::flush;
        }
    }
    if (framesUsed == 0) {
        throw InputError(dataPath + ": no frame with " + str(options.timeMin) + " <= t <= " + str(options.timeMax) +
                         " (--time-min, --time-max)");
    }
    if (options.timeAverage) {
        for (double& v : average) v /= framesUsed;
        writeAveragedOrFrame(average, lastTime);
    }
    writer->close();
    if (mixingWriter) mixingWriter->close();
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    log << "talus-cg: " << framesUsed << " frames (t = " << str(firstTime) << " to " << str(lastTime) << ")"
        << (options.timeAverage ? " averaged" : "") << " at " << points.size() << " points in " << seconds(elapsed) << "; wrote "
        << outputPath << "\n";
    return framesUsed;
}

}  // namespace talus::cg
