#include "Benchmarks/SpeedBenchmark.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "Benchmarks/SyntheticFrames.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/EvaluationPoints.h"

namespace talus::cg::benchmark {

namespace {

struct Timing {
    double setFrame = 0;
    double evaluate = 0;
    double total() const { return setFrame + evaluate; }
};

Timing timeOnce(CoarseGrainer& grainer, const ParticleFrame& frame, const std::vector<Vec3>& points,
                std::vector<double>& sums) {
    Timing t;
    auto start = std::chrono::steady_clock::now();
    grainer.setFrame(frame, nullptr);
    t.setFrame = secondsSince(start);
    start = std::chrono::steady_clock::now();
    grainer.evaluate(points, sums);
    t.evaluate = secondsSince(start);
    return t;
}

}  // namespace

void runSpeedBenchmark(const SpeedSettings& settings, std::ostream& out, ProgressLog& progress) {
    const double particleVolume = 4.0 / 3.0 * std::numbers::pi * 0.125;
    const double side = std::cbrt(double(settings.referenceCount) * particleVolume / settings.referenceVolumeFraction);
    const Coordinates xyz = Coordinates::fromName("XYZ");
    const long n = settings.pointsPerAxis;
    const std::vector<Vec3> points = gridPoints(xyz, {n, n, n}, {0, 0, 0}, {side, side, side});
    const double supportVolume = 4.0 / 3.0 * std::numbers::pi * std::pow(settings.width, 3);

    CoarseGrainingSetup setup;
    setup.width = WidthMatrix::isotropic(settings.width);
    setup.speciesDensity.assign(settings.speciesCount, 6.0 / std::numbers::pi);
    CoarseGrainer grainer(setup);
    std::vector<double> sums;

    char line[256];
    std::snprintf(line, sizeof line, "# speed: Lucy, 3-D, w = %g, %zu points (%ld^3) in the cube [0, %.2f]^3, %d species, best of %d\n",
                  settings.width, points.size(), n, side, settings.speciesCount, settings.repeats);
    out << line
        << "# particles  setFrame_s  evaluate_s  total_s  points_x_particles_per_s  us_per_particle  pairs_in_support_per_point\n";
    for (long count : settings.particleCounts) {
        const ParticleFrame frame = uniformRandomFrame(count, side, settings.speciesCount);
        Timing best;
        for (int r = 0; r < settings.repeats; ++r) {
            const Timing t = timeOnce(grainer, frame, points, sums);
            if (r == 0 || t.total() < best.total()) best = t;
            progress.report("speed: " + std::to_string(count) + " particles, repetition " + std::to_string(r + 1) +
                            " of " + std::to_string(settings.repeats));
        }
        // Expected (point, particle) pairs closer than w, for a point away from the faces: the
        // work of a cell-list evaluation, against the N per point of a plain double loop.
        const double pairsPerPoint = double(count) * supportVolume / (side * side * side);
        std::snprintf(line, sizeof line, "%11ld  %10.4f  %10.4f  %7.4f  %24.3e  %15.4f  %26.1f\n", count, best.setFrame,
                      best.evaluate, best.total(), double(points.size()) * double(count) / best.total(),
                      1e6 * best.total() / double(count), pairsPerPoint);
        out << line << std::flush;
    }
}

}  // namespace talus::cg::benchmark
