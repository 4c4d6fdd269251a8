// The dam break on a frictionless inclined plane against Ritter's solution, and the order of
// convergence of the scheme measured on it.
//
// Ritter's solution in the frame falling with the plane. With alpha = 1 (a_s = 1, plug flow) and
// mu = 0 the model is h_t + (h u)_x = 0, (h u)_t + (h u^2 + c h^2 / 2)_x = s h with c = cos(t),
// s = sin(t). In X = x - s t^2 / 2, V = u - s t (and T = t), d/dt|x = d/dT|X - s T d/dX and
// d/dx = d/dX, so the mass equation becomes h_T + (h (V + s T))_X - s T h_X = h_T + (h V)_X = 0,
// and the momentum equation, written for u as u_t + u u_x + c h_x = s, becomes
// V_T + s - s T V_X + (V + s T) V_X + c h_X = s, i.e. V_T + V V_X + c h_X = 0: the flat-bed
// shallow-water equations with gravity c. A dam at X = 0 holding h0 at rest on a dry bed
// (Ritter 1892) then gives, with c0 = sqrt(c h0):
//   X <= -c0 T:           h = h0,                        V = 0
//   -c0 T < X < 2 c0 T:   h = (2 c0 - X / T)^2 / (9 c),  V = 2 (X / T + c0) / 3
//   X >= 2 c0 T:          h = 0
// (the rarefaction along which V + 2 sqrt(c h) = 2 c0 and X / T = V - sqrt(c h)).
//
// The expected order: the solution has kinks at the rarefaction's tail and at the dry front,
// where h vanishes like (2 c0 T - X)^2 and its characteristic speed is not smooth; a MUSCL
// scheme there is first order, away from them second order, and the L1 error of h is dominated by
// a few cells at the kinks. The literature's orders for this problem lie between 1 and 2
// (LeVeque 2002, sec. 8.5; Kurganov & Petrova 2007 report about 1 to 1.5 for dry fronts).
// Measured here (orders printed by the test): van Leer 1.06, 1.02, 1.01 and minmod 0.99, 1.01, 0.99
// from 100 to 800 cells, first order (no reconstruction) 0.52, 0.58, 0.64; the finest errors are
// 1.99e-3 (van Leer), 3.06e-3 (minmod) and 1.31e-2 (first order). The bounds below assert an order
// of at least 0.9 (0.45 for first order) at every halving and the finest errors with 10% margin.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "Numerics/Solver.h"

namespace talus::shallow {
namespace {

constexpr double angleDegrees = 30, damHeight = 1, endTime = 1;

double ritterHeight(double x, double t) {
    const double c = std::cos(angleDegrees * std::numbers::pi / 180), s = std::sin(angleDegrees * std::numbers::pi / 180);
    const double X = x - 0.5 * s * t * t, c0 = std::sqrt(c * damHeight);
    if (X <= -c0 * t) return damHeight;
    if (X >= 2 * c0 * t) return 0;
    const double root = 2 * c0 - X / t;
    return root * root / (9 * c);
}

// The L1 error of h at endTime on n cells over [-2, 3] (the rarefaction's tail reaches x = -0.68,
// the front x = 2.11: both boundaries see the uniform states they copy).
double damBreakError(std::size_t n, Limiter limiter) {
    ModelParameters model;
    model.angleDegrees = angleDegrees;
    model.basalSlip = 1;  // alpha = 1: Ritter's equations
    model.frictionless = true;
    NumericsSettings numerics;
    numerics.limiter = limiter;
    numerics.dryHeight = 1e-10;  // the front of Ritter's solution to 1e-10 of the dam's height
    const Grid grid{-2, 5, n};
    const BoundaryCondition open{BoundaryCondition::Kind::Transmissive, {}};
    Solver solver(grid, model, numerics, open, open);
    std::vector<Conserved> cells(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (grid.centre(i) < 0) cells[i] = {damHeight, 0, 0.5 * damHeight};
    }
    solver.setCells(cells);
    solver.advanceTo(endTime);
    EXPECT_EQ(solver.time(), endTime);
    // The exact cell averages by the midpoint rule on 64 sub-cells (error << the scheme's).
    double error = 0;
    const double dx = grid.spacing();
    for (std::size_t i = 0; i < n; ++i) {
        double average = 0;
        for (int k = 0; k < 64; ++k) average += ritterHeight(grid.start + (i + (k + 0.5) / 64) * dx, endTime) / 64;
        error += std::abs(solver.cells()[i].h - average) * dx;
    }
    return error;
}

void expectConvergence(Limiter limiter, double minimumOrder, double finestError) {
    const std::vector<std::size_t> resolutions{100, 200, 400, 800};
    std::vector<double> errors;
    for (std::size_t n : resolutions) errors.push_back(damBreakError(n, limiter));
    for (std::size_t k = 0; k < errors.size(); ++k) {
        std::printf("dam break, %s, %4zu cells: L1 error of h %.3e", name(limiter).c_str(), resolutions[k], errors[k]);
        if (k > 0) {
            const double order = std::log2(errors[k - 1] / errors[k]);
            std::printf(", order %.2f", order);
            EXPECT_GT(order, minimumOrder) << "between " << resolutions[k - 1] << " and " << resolutions[k] << " cells";
        }
        std::printf("\n");
    }
    EXPECT_LT(errors.back(), finestError);
}

TEST(DamBreak, RitterSolutionVanLeer) { expectConvergence(Limiter::VanLeer, 0.9, 2.2e-3); }
TEST(DamBreak, RitterSolutionMinmod) { expectConvergence(Limiter::Minmod, 0.9, 3.4e-3); }
TEST(DamBreak, RitterSolutionFirstOrder) { expectConvergence(Limiter::FirstOrder, 0.45, 1.45e-2); }

}  // namespace
}  // namespace talus::shallow
