#include "App/WidthScanRun.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "App/RunInputs.h"
#include "Fields/DerivedFields.h"
#include "Fields/EvaluationPoints.h"
#include "Fields/WidthScan.h"
#include "IO/InputError.h"

namespace talus::cg {

namespace {

std::string pointText(const Vec3& p) {
    std::ostringstream text;
    text << "(" << str(p[0]) << ", " << str(p[1]) << ", " << str(p[2]) << ")";
    return text.str();
}

std::string widthName(int axis) { return std::string("w") + axisLetter(axis); }

// The field's column in derivedColumns(layout); the default is the small-particle concentration
// of the chutes (species 1), or the density for one species.
int fieldIndex(const std::string& requested, const FieldSums& layout) {
    const std::vector<OutputColumn> columns = derivedColumns(layout);
    const std::string name = !requested.empty() ? requested : layout.species >= 2 ? "Concentration_s1" : "Density";
    for (std::size_t c = 0; c < columns.size(); ++c) {
        if (columns[c].name == name) return static_cast<int>(c);
    }
    std::string known;
    for (const OutputColumn& c : columns) known += (known.empty() ? "" : ", ") + c.name;
    throw InputError("--scan-field: unknown field '" + name + "' (one of " + known + ")");
}

bool needsContactStress(const std::string& field) {
    return field.starts_with("ContactStress") || field.starts_with("Stress");
}

}  // namespace

int runWidthScan(const ProgramOptions& options, std::ostream& log) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    RunInputs inputs = resolveRunInputs(options, log, needsContactStress(options.scanField));
    if (needsContactStress(options.scanField) && !inputs.setup.contactStress) {
        throw InputError("--scan-field " + options.scanField + ": needs the contact stress, but no contact file is read (" +
                         inputs.base + ".fstat not found or --stress off; give --fstat FILE)");
    }
    WidthScanRequest request;
    int scanned = 0;
    for (int k = 0; k < 3; ++k) {
        if (!options.scanRange[k]) continue;
        const std::string flag = std::string("--scan-") + axisLetter(k);
        if (!inputs.setup.coordinates.resolves(k)) {
            throw InputError(flag + ": " + std::string(1, axisLetter(k)) + " is averaged by --coordinates " +
                             inputs.setup.coordinates.name() + ": only resolved directions can be scanned");
        }
        request.axes[scanned] = k;
        request.widths[scanned] = logSpacedWidths(options.scanRange[k]->min, options.scanRange[k]->max, options.scanRange[k]->count);
        ++scanned;
    }
    const double base = options.width.value_or(1.0);
    request.baseWidths = options.widths ? *options.widths : Vec3{base, base, base};
    for (int k = 0; k < 3; ++k) {
        if (!(request.baseWidths[k] > 0)) throw InputError("--widths: widths must be positive, found " + str(request.baseWidths[k]));
    }

    // The frames of the window, kept: every width pair goes over all of them.
    std::vector<ParticleFrame> frames;
    std::vector<ContactFrame> contacts;
    {
        FrameStream stream(inputs, options);
        ParticleFrame frame;
        ContactFrame contact;
        while (stream.next(frame, contact)) {
            frames.push_back(frame);
            if (stream.withContacts()) contacts.push_back(contact);
        }
    }
    if (frames.empty()) {
        throw InputError(inputs.dataPath + ": no frame with " + str(options.timeMin) + " <= t <= " + str(options.timeMax) +
                         " (--time-min, --time-max)");
    }
    fitSpeciesToFrame(options, inputs, frames.front());
    request.setup = inputs.setup;
    const FieldSums layout = CoarseGrainer(inputs.setup).layout();
    request.field = fieldIndex(options.scanField, layout);
    const std::string fieldName = derivedColumns(layout)[request.field].name;
    request.fractionField = fieldName.starts_with("Concentration") || fieldName == "VolumeFraction";
    request.tolerance = options.scanTolerance;
    request.minParticles = options.scanMinParticles;
    if (options.scanMinWidth) {
        request.minWidth = *options.scanMinWidth;
    } else {
        // The mean diameter of the particles that enter the fields (first frame).
        double sum = 0;
        long n = 0;
        const ParticleFrame& first = frames.front();
        for (std::size_t p = 0; p < first.size(); ++p) {
            if (!inputs.setup.excluded.empty() && p < inputs.setup.excluded.size() && inputs.setup.excluded[p]) continue;
            sum += 2 * first.radius[p];
            ++n;
        }
        request.minWidth = n > 0 ? sum / double(n) : 0.0;
    }

    // Points: inside the domain box of the first frame on the resolved axes.
    const std::string pointFlag = options.pointsPath.empty() ? "--scan-point" : "--points " + options.pointsPath;
    request.points = options.pointsPath.empty() ? options.scanPoints : readPointList(options.pointsPath, inputs.setup.coordinates);
    if (request.points.empty()) throw InputError(pointFlag + ": no point to scan");
    const DomainBox& box = frames.front().box;
    for (Vec3& p : request.points) {
        for (int k = 0; k < 3; ++k) {
            if (!inputs.setup.coordinates.resolves(k)) {
                p[k] = 0;  // averaged: not in the kernel
            } else if (!(p[k] >= box.lo[k] && p[k] <= box.hi[k])) {
                throw InputError(pointFlag + ": the point " + pointText(p) + " is outside the data: " + std::string(1, axisLetter(k)) +
                                 " must be in [" + str(box.lo[k]) + ", " + str(box.hi[k]) + "] (the domain box of the frame at t = " +
                                 str(frames.front().time) + ")");
            }
        }
    }

    const long total = static_cast<long>(request.widths[0].size() * request.widths[1].size());
    log << "talus-cg: width scan of " << fieldName << ": " << request.widths[0].size() << " x " << request.widths[1].size() << " widths ("
        << widthName(request.axes[0]) << ", " << widthName(request.axes[1]) << ") at " << request.points.size() << " points over "
        << frames.size() << " frames\n";
    auto lastProgress = Clock::now();
    const auto progress = [&](long done, long all) {
        const auto now = Clock::now();
        if (std::chrono::duration<double>(now - lastProgress).count() < options.progressInterval) return;
        lastProgress = now;
        const double elapsed = std::chrono::duration<double>(now - start).count();
        char line[160];
        std::snprintf(line, sizeof line, "talus-cg: %ld of %ld width pairs, %.3g s wall, about %.3g s left\n", done, all, elapsed,
                      elapsed * double(all - done) / double(done));
        log << line << std::flush;
    };
    const WidthScanResult result = scanWidths(request, frames, contacts, progress);

    // The CSV file.
    const std::string path = options.outputPath.empty() ? inputs.base + ".widthscan.csv" : options.outputPath;
    std::FILE* file = std::fopen(path.c_str(), "w");
    if (file == nullptr) throw InputError("-o: cannot write " + path);
    const std::string a = widthName(request.axes[0]), b = widthName(request.axes[1]);
    std::fprintf(file, "# talus-cg --width-scan (Documentation/CoarseGraining.md \"Choosing the widths\")\n");
    std::fprintf(file, "# input: %s%s, frames t = %s to %s (%zu, sums averaged)\n", inputs.dataPath.c_str(),
                 inputs.restartPath.empty() ? "" : (", " + inputs.restartPath).c_str(), str(frames.front().time).c_str(),
                 str(frames.back().time).c_str(), frames.size());
    std::fprintf(file, "# field %s; function %s, coordinates %s, %s = %s, other widths %s %s %s\n", fieldName.c_str(),
                 kernelShapeName(inputs.setup.shape).c_str(), inputs.setup.coordinates.name().c_str(), "scanned", (a + " " + b).c_str(),
                 str(request.baseWidths[0]).c_str(), str(request.baseWidths[1]).c_str(), str(request.baseWidths[2]).c_str());
    std::fprintf(file, "# rule: trusted when density > 0, >= %ld particle centres in the support and both scanned widths >= %s; sensitivity = max over trusted "
                       "neighbours |df| per decade / scale; insensitive when <= %s; plateau = largest rectangle insensitive at every point; "
                       "chosen = its centre in log w\n",
                 request.minParticles, str(request.minWidth).c_str(), str(request.tolerance).c_str());
    for (std::size_t p = 0; p < request.points.size(); ++p) {
        std::fprintf(file, "# point %zu: %s %s %s scale %s\n", p, str(request.points[p][0]).c_str(), str(request.points[p][1]).c_str(),
                     str(request.points[p][2]).c_str(), str(result.points[p].scale).c_str());
    }
    const WidthPlateau& plateau = result.plateau;
    std::ostringstream summary;
    if (plateau.found) {
        summary << "plateau " << a << " in [" << str(request.widths[0][plateau.first[0]]) << ", " << str(request.widths[0][plateau.first[1]])
                << "], " << b << " in [" << str(request.widths[1][plateau.second[0]]) << ", "
                << str(request.widths[1][plateau.second[1]]) << "] (" << plateau.pairs << " of " << total << " width pairs); chosen "
                << a << " = " << str(plateau.chosen[0]) << ", " << b << " = " << str(plateau.chosen[1]);
        std::fprintf(file, "# %s\n", summary.str().c_str());
        std::fprintf(file, "# chosen %s %s %s %s\n", a.c_str(), str(plateau.chosen[0]).c_str(), b.c_str(), str(plateau.chosen[1]).c_str());
        for (std::size_t p = 0; p < request.points.size(); ++p) {
            std::fprintf(file, "# value at the chosen widths, point %zu: %.10g\n", p, result.chosenValue[p]);
        }
    } else {
        summary << "no width pair is insensitive at every point: raise --scan-tolerance, widen the ranges or lower --scan-min-particles";
        std::fprintf(file, "# %s\n", summary.str().c_str());
    }
    std::fprintf(file, "point,%s,%s,value,sensitivity,particles,insensitive,plateau\n", a.c_str(), b.c_str());
    const long nb = static_cast<long>(request.widths[1].size());
    for (std::size_t p = 0; p < request.points.size(); ++p) {
        const PointScan& scan = result.points[p];
        for (long i = 0; i < static_cast<long>(request.widths[0].size()); ++i) {
            for (long j = 0; j < nb; ++j) {
                const long c = i * nb + j;
                const bool inPlateau = plateau.found && i >= plateau.first[0] && i <= plateau.first[1] && j >= plateau.second[0] &&
                                       j <= plateau.second[1];
                std::fprintf(file, "%zu,%.10g,%.10g,%.12g,%.6g,%.6g,%d,%d\n", p, request.widths[0][i], request.widths[1][j], scan.value[c],
                             scan.sensitivity[c], scan.particles[c], scan.insensitive[c] ? 1 : 0, inPlateau ? 1 : 0);
            }
        }
    }
    const bool failed = std::ferror(file) != 0;
    if (std::fclose(file) != 0 || failed) throw InputError("-o: writing " + path + " failed (disk full?)");

    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    log << "talus-cg: " << summary.str() << "\n";
    if (plateau.found) {
        for (std::size_t p = 0; p < request.points.size(); ++p) {
            log << "talus-cg: " << fieldName << " at " << pointText(request.points[p]) << " with the chosen widths: " << str(result.chosenValue[p])
                << "\n";
        }
    }
    char line[200];
    std::snprintf(line, sizeof line, "talus-cg: %ld width pairs x %zu points x %zu frames in %.3g s; wrote %s\n", total,
                  request.points.size(), frames.size(), elapsed, path.c_str());
    log << line;
    return static_cast<int>(frames.size());
}

}  // namespace talus::cg
