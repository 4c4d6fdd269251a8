// The scheme is conservative: with closed ends (walls: zero mass flux through them, Boundary.h)
// the volumes integral h dx and integral h phi dx stay what they were, to round-off, whatever the
// flow does (here a bidisperse dam break with friction that runs into the wall and splashes back,
// with dry regions on both sides, including steps redone at a CFL above 1/2).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "Numerics/Solver.h"

namespace talus::shallow {
namespace {

using Kind = BoundaryCondition::Kind;

void expectConservedVolumes(double cfl, Limiter limiter) {
    const ModelParameters model;  // table 3.1, 24 deg
    NumericsSettings numerics;
    numerics.cfl = cfl;
    numerics.limiter = limiter;
    const Grid grid{0, 60, 240};
    Solver solver(grid, model, numerics, {Kind::Wall, {}}, {Kind::Wall, {}});
    std::vector<Conserved> cells(grid.cells);
    for (std::size_t i = 0; i < grid.cells; ++i) {
        const double x = grid.centre(i);
        if (x > 5 && x < 25) {
            const double h = 8 + 2 * std::sin(x), phi = 0.5 + 0.4 * std::sin(0.7 * x);
            cells[i] = {h, h * 1.5, h * phi};
        }
    }
    solver.setCells(cells);
    const auto totals = [&] {
        double h = 0, hphi = 0;
        for (const Conserved& c : solver.cells()) {
            h += c.h;
            hphi += c.hphi;
        }
        return std::pair{h * grid.spacing(), hphi * grid.spacing()};
    };
    const auto [volume, smallVolume] = totals();
    double worst = 0, worstSmall = 0;
    while (solver.time() < 40) {
        solver.step(1e9);
        const auto [v, s] = totals();
        worst = std::max(worst, std::abs(v - volume) / volume);
        worstSmall = std::max(worstSmall, std::abs(s - smallVolume) / smallVolume);
    }
    std::printf("cfl %.2f %s: %lld steps (%lld redone), largest relative change of the volume %.2e, of the small "
                "volume %.2e\n", cfl, name(limiter).c_str(), solver.steps(), solver.retriedSteps(), worst, worstSmall);
    // Each step adds a few ulp of the total per cell sum: 1e-12 is round-off for 240 cells and a
    // few thousand steps; a lost flux or a clipped height would be orders larger.
    EXPECT_LT(worst, 1e-12);
    EXPECT_LT(worstSmall, 1e-12);
    // The flow reached the downstream wall (the test is not passed by a flow that did not move).
    EXPECT_GT(solver.cells().back().h, 1.0);
}

TEST(Conservation, ClosedEndsKeepBothVolumes) { expectConservedVolumes(0.45, Limiter::VanLeer); }
TEST(Conservation, ClosedEndsKeepBothVolumesMinmod) { expectConservedVolumes(0.45, Limiter::Minmod); }
TEST(Conservation, ClosedEndsKeepBothVolumesAtCflOne) { expectConservedVolumes(1.0, Limiter::VanLeer); }

}  // namespace
}  // namespace talus::shallow
