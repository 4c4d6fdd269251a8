// Accuracy, robustness and cost of superquadric contact detection (issue 6, Theory/Superquadrics.md
// eq. (5)-(8)).
//
// Methods. For each class of configuration (spheres; ellipsoids of aspect ratio 1-10; blocky
// shapes with blockiness down to 0.1; blocks with near-parallel flat faces; a block's edge on
// another's face; crossing needles of aspect ratio 10), --configurations random pairs are
// placed at overlaps up to a tenth of the smaller semi-axis (a tenth of them apart by up to
// 5% of it, inside their bounding spheres; UnitTests/SuperquadricReference.h). Each is solved
// by Talus's damped Newton method from a cold start (the bounding spheres), compared with the
// independent reference (dual bisection, same header), then solved again warm-started after
// a small move and turn, as in a time step. Printed per class: Newton iterations, how often
// plan B (morphing from the bounding spheres) was needed, failures, wrong touching verdicts,
// the worst overlap error relative to the smaller semi-axis, and the time per contact.
// Then the speed-against-error study: time per contact and overlap error against the Newton
// tolerance.
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "Error.h"
#include "IO/CommandLine.h"
#include "SuperquadricReference.h"

using namespace talus;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); }

struct Prepared {
    reference::Configuration configuration;
    reference::Contact expected;
};

// Wall seconds per contact of solving every configuration once (best of three passes: the
// machine is shared), and the worst overlap error against the reference.
struct Timing {
    double nanoseconds, worstError, meanIterations;
    int failures;
};
Timing time(const std::vector<Prepared>& set, const SuperquadricContactSettings& settings) {
    Timing t{INFINITY, 0, 0, 0};
    for (int pass = 0; pass < 3; ++pass) {
        const Clock::time_point start = Clock::now();
        double sink = 0;
        long iterations = 0;
        for (const Prepared& p : set) {
            const SuperquadricContact c = findSuperquadricContact(p.configuration.i, p.configuration.j, nullptr, settings);
            sink += c.overlap;
            iterations += c.iterations;
        }
        t.nanoseconds = std::min(t.nanoseconds, 1e9 * seconds(start) / static_cast<double>(set.size()));
        t.meanIterations = static_cast<double>(iterations) / static_cast<double>(set.size());
        if (sink < 0) std::printf("?");  // keeps the loop from being optimised away
    }
    for (const Prepared& p : set) {
        const SuperquadricContact c = findSuperquadricContact(p.configuration.i, p.configuration.j, nullptr, settings);
        if (!c.converged) {
            ++t.failures;
            continue;
        }
        const double size = std::min(p.configuration.shapeI.semiAxes().minCoeff(), p.configuration.shapeJ.semiAxes().minCoeff());
        if (c.touching == (p.expected.value < 0)) t.worstError = std::max(t.worstError, std::abs(c.overlap - p.expected.overlap) / size);
    }
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    int configurations = 1000, seed = 1;
    CommandLine flags;
    flags.add("configurations", "N", "random configurations per class (7 classes)",
              [&](const std::string& v) { configurations = CommandLine::toInt("--configurations", v); });
    flags.add("seed", "N", "random seed", [&](const std::string& v) { seed = CommandLine::toInt("--seed", v); });
    try {
        if (!flags.parse({argv + 1, argv + argc})) {
            std::printf("%s", flags.help("SuperquadricContactSweep").c_str());
            return 0;
        }
        require(configurations > 0, "--configurations must be positive, got " + std::to_string(configurations));
    } catch (const Error& e) {
        std::fprintf(stderr, "SuperquadricContactSweep: %s\n", e.what());
        return 1;
    }
    std::mt19937_64 random(static_cast<std::uint64_t>(seed));
    const reference::Case kinds[] = {reference::Case::spheres,       reference::Case::ellipsoids,
                                     reference::Case::blocky,        reference::Case::parallelFaces,
                                     reference::Case::edgeOnFace,    reference::Case::needles,
                                     reference::Case::sphereOnEllipsoid};
    std::vector<std::vector<Prepared>> sets;
    const Clock::time_point begin = Clock::now();
    Clock::time_point lastReport = begin;
    const long total = static_cast<long>(std::size(kinds)) * configurations;
    for (reference::Case kind : kinds) {
        std::vector<Prepared>& set = sets.emplace_back();
        for (int k = 0; k < configurations; ++k) {
            reference::Configuration c = reference::randomConfiguration(kind, random);
            const reference::Contact expected = reference::contact(c.i, c.j);
            set.push_back({c, expected});
            set.back().configuration.rebind();
            if (seconds(lastReport) > 10) {
                const double done = static_cast<double>(sets.size() - 1) * configurations + k + 1;
                const double wall = seconds(begin);
                std::fprintf(stderr, "SuperquadricContactSweep: %.0f / %ld configurations with their reference, wall %.0f s, ETA %.0f s\n",
                             done, total, wall, wall * (static_cast<double>(total) / done - 1));
                lastReport = Clock::now();
            }
        }
    }

    std::printf("\n| class | configurations | touching | mean iterations | max iterations | plan B | failures | wrong verdicts | worst overlap error / smaller semi-axis | warm-start iterations (mean, max) | ns per contact (cold) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (std::size_t k = 0; k < sets.size(); ++k) {
        long touching = 0, iterations = 0, planB = 0, failures = 0, wrong = 0, warmIterations = 0, warmCount = 0;
        int maxIterations = 0, maxWarm = 0;
        double worst = 0;
        const Mat3 turn = Eigen::AngleAxisd(1e-3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
        for (const Prepared& p : sets[k]) {
            const SuperquadricContact c = findSuperquadricContact(p.configuration.i, p.configuration.j);
            iterations += c.iterations;
            maxIterations = std::max(maxIterations, c.iterations);
            planB += c.morphStages > 0;
            if (!c.converged) {
                ++failures;
                continue;
            }
            const bool expectTouching = p.expected.value < 0;
            if (c.touching != expectTouching) {
                if (std::abs(p.expected.value) > 1e-12) ++wrong;
                continue;
            }
            if (!c.touching) continue;
            ++touching;
            const double size = std::min(p.configuration.shapeI.semiAxes().minCoeff(), p.configuration.shapeJ.semiAxes().minCoeff());
            worst = std::max(worst, std::abs(c.overlap - p.expected.overlap) / size);
            // The next step: j moved by 1e-4 and turned by a milliradian.
            PlacedSuperquadric j = p.configuration.j;
            j.centre += Vec3(1e-4, -2e-4, 1e-4);
            j.rotation = turn * j.rotation;
            const SuperquadricContact warm = findSuperquadricContact(p.configuration.i, j, &c.solution);
            warmIterations += warm.iterations;
            maxWarm = std::max(maxWarm, warm.iterations);
            ++warmCount;
        }
        const Timing t = time(sets[k], {});
        std::printf("| %s | %zu | %ld | %.2f | %d | %ld | %ld | %ld | %.2g | %.2f, %d | %.0f |\n", reference::name(kinds[k]),
                    sets[k].size(), touching, static_cast<double>(iterations) / static_cast<double>(sets[k].size()),
                    maxIterations, planB, failures, wrong, worst,
                    warmCount ? static_cast<double>(warmIterations) / static_cast<double>(warmCount) : 0.0, maxWarm,
                    t.nanoseconds);
        std::fflush(stdout);
    }

    std::printf("\nSpeed against error (every class together): Newton tolerance, ns per contact, mean iterations, worst overlap error / smaller semi-axis, failures\n\n");
    std::printf("| tolerance | ns per contact | mean iterations | worst overlap error | failures |\n|---|---|---|---|---|\n");
    std::vector<Prepared> all;
    for (const auto& set : sets)
        for (const Prepared& p : set) {
            all.push_back(p);
            all.back().configuration.rebind();
        }
    for (double tolerance : {1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
        SuperquadricContactSettings settings;
        settings.tolerance = tolerance;
        const Timing t = time(all, settings);
        std::printf("| %.0e | %.0f | %.2f | %.2g | %d |\n", tolerance, t.nanoseconds, t.meanIterations, t.worstError, t.failures);
        std::fflush(stdout);
    }
    std::printf("\nSuperquadricContactSweep: %ld configurations in %.0f s wall\n", total, seconds(begin));
    return 0;
}
