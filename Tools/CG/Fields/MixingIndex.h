// Mixing index M and segregation index S of a binary mixture
// (Theory/CoarseGraining.md eq. (13)-(16); Denissen 2019, sec. 5.2.2, eqs. 5.1-5.9), from
// coarse-grained fields at the points of a regular grid (equal cell sizes, so the midpoint rule's
// weights cancel in the ratios):
//
//   phi  = rho_k / rho                         fraction of the chosen species k ("the spheres")
//   m    = phi ln phi + (1 - phi) ln(1 - phi)  local mixing entropy (0 at phi = 0 or 1)
//   M    = -int rho m / (ln 2 int rho)         1: phi = 1/2 everywhere; 0: fully segregated
//   S    = 1 - M   if species k is at the periphery,
//          M - 1   if species k is at the core.
//
// Sign rule (Theory/CoarseGraining.md eq. (13)-(16) leaves "core" to the reader; this is ours): the
// core is the centre of mass c of the material (rho-weighted mean of the points' resolved
// coordinates). Species k is at the core when its mass-weighted mean distance from c is smaller
// than that of all the material, D_k < D; otherwise (D_k >= D, ties included) at the periphery. In
// a rotating drum (Theory/RotatingDrum.md) c is the centre of the circulating bed. M is symmetric
// in the two species (m(phi) = m(1 - phi)); only the sign of S depends on k.
//
// M is normalised by the state phi = 1/2 (the thesis's eq. 5.7): a perfectly mixed mixture of
// another composition phi_0 has M = -m(phi_0)/ln 2 < 1. One kind alone (species k has no mass
// at the points, or all of it) has M = 0 and S undefined: NaN.
#pragma once

#include <array>
#include <vector>

#include "Fields/CoarseGrainingSetup.h"
#include "Fields/Coordinates.h"
#include "Fields/FieldSums.h"
#include "IO/ParticleFrame.h"

namespace talus::cg {

struct MixingIndices {
    double mixing = 0;       // M
    double segregation = 0;  // S
    bool speciesAtCore = false;
    Vec3 centre{0, 0, 0};          // centre of mass c (resolved coordinates; 0 on averaged axes)
    double speciesDistance = 0;    // D_k
    double materialDistance = 0;   // D
};

// `sums[p * layout.count() + f]` at `points` (equal quadrature weights). Throws InputError
// (naming --mixing) when `species` is not one of the layout's species or there is no mass.
MixingIndices mixingIndices(const FieldSums& layout, const std::vector<Vec3>& points, const std::vector<double>& sums,
                            const Coordinates& coordinates, int species);

// M and S of one frame: its particles coarse-grained by `setup` (masses as the frame gives them,
// ParticleFrame::massOf) at the cell centres of the regular grid of `count` cells over [lo, hi]
// (EvaluationPoints.h gridPoints): the steps talus-cg --mixing takes for a frame (`-n`, `-x`, `-y`,
// `-z`), for a driver to call on its particles in memory (Drivers/Drum/DrumAnalysis.h).
MixingIndices frameMixingIndices(const ParticleFrame& frame, const CoarseGrainingSetup& setup,
                                 const std::array<long, 3>& count, const Vec3& lo, const Vec3& hi, int species);

}  // namespace talus::cg
