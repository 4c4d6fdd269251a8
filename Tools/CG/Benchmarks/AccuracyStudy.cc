#include "Benchmarks/AccuracyStudy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "Benchmarks/SlabProfile.h"
#include "Benchmarks/SyntheticFrames.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/EvaluationPoints.h"

namespace talus::cg::benchmark {

namespace {

struct Errors {
    double mass = 0;     // |midpoint integral - total mass| / total mass
    double bulk = 0;     // max |rho - rho_b| / rho_b where the slab profile is flat (w <= z <= H - w)
    double profile = 0;  // max |rho - slab profile| / rho_b over all grid points
};

Errors measureErrors(const std::vector<Vec3>& points, const std::vector<double>& sums, int fields, double cellVolume,
                     double totalMass, double height, double width) {
    const double bulkDensity = 1;  // unit-mass spheres on a unit lattice (SyntheticFrames.h)
    Errors e;
    double mass = 0;
    for (std::size_t p = 0; p < points.size(); ++p) {
        const double rho = sums[p * fields + FieldSums::density];
        const double z = points[p][2];
        mass += rho * cellVolume;
        e.profile = std::max(e.profile, std::abs(rho - lucySlabDensity(z, height, width, bulkDensity)) / bulkDensity);
        if (z >= width && z <= height - width) e.bulk = std::max(e.bulk, std::abs(rho - bulkDensity) / bulkDensity);
    }
    e.mass = std::abs(mass - totalMass) / totalMass;
    return e;
}

}  // namespace

void runAccuracyStudy(const AccuracySettings& settings, std::ostream& out, ProgressLog& progress) {
    const ParticleFrame frame = latticeSlabFrame(settings.side, settings.height);
    const double totalMass = double(frame.size());  // each sphere has mass 1
    const Vec3 lo{0, 0, -settings.margin};
    const Vec3 hi{double(settings.side), double(settings.side), settings.height + settings.margin};

    char line[256];
    std::snprintf(line, sizeof line, "# accuracy: Lucy, 3-D, %zu spheres on a cubic lattice, slab %d x %d x %d, periodic x y, grid z in [%g, %g]\n",
                  frame.size(), settings.side, settings.side, settings.height, lo[2], hi[2]);
    out << line << "# width  spacing  points  seconds  mass_error  bulk_error  profile_error\n";
    for (double width : settings.widths) {
        CoarseGrainingSetup setup;
        setup.width = WidthMatrix::isotropic(width);
        setup.periodic = {true, true, false};
        CoarseGrainer grainer(setup);
        std::vector<double> sums;
        for (double h : settings.spacings) {
            const std::array<long, 3> count{std::lround(settings.side / h), std::lround(settings.side / h),
                                            std::lround((hi[2] - lo[2]) / h)};
            const std::vector<Vec3> points = gridPoints(setup.coordinates, count, lo, hi);
            const auto start = std::chrono::steady_clock::now();
            grainer.setFrame(frame, nullptr);
            grainer.evaluate(points, sums);
            const double seconds = secondsSince(start);
            const double cellVolume = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]) / double(points.size());
            const Errors e = measureErrors(points, sums, grainer.layout().count(), cellVolume, totalMass,
                                           settings.height, width);
            std::snprintf(line, sizeof line, "%7.3g  %7.4g  %7zu  %7.4f  %10.2e  %10.2e  %13.2e\n", width, h, points.size(),
                          seconds, e.mass, e.bulk, e.profile);
            out << line << std::flush;
            progress.report("accuracy: w = " + std::to_string(width) + ", h = " + std::to_string(h) + " done");
        }
    }
}

}  // namespace talus::cg::benchmark
