// Measurements of a rotating drum's bed (Theory/RotatingDrum.md eq. (5)-(8)), made by the driver
// while it runs:
//  - the mixing index M and segregation index S of the sphere fraction, coarse-grained in the
//    drum's cross-section (x, z), averaged along the periodic axis y;
//  - the dynamic angle of repose of the free surface.
// Both read only the mobile particles (the wall's fixed particles are not part of the bed).
#pragma once

#include <array>
#include <span>

#include <cstddef>

#include "Fields/MixingIndex.h"
#include "Particles/ParticleStore.h"

namespace talus::drum {

// Theory/RotatingDrum.md eq. (5)-(8): the mixing index M and segregation index S of
// talus-cg's --mixing (Tools/CG/Fields/MixingIndex.h, Theory/CoarseGraining.md eq. (13)-(16)),
// computed by the coarse-graining library (cg::frameMixingIndices: the CoarseGrainer, grid points
// and mixingIndices of talus-cg --mixing) on the bed's mobile particles with their own masses:
//   rho(p)   = sum_i m_i W(p - x_i) / L,  rho_s(p) the same over the spheres, phi = rho_s / rho,
//   m        = phi ln phi + (1 - phi) ln(1 - phi),
//   M        = -sum_p rho m / (ln 2 sum_p rho)   over the cell centres p of a regular grid,
//   S        = 1 - M if the spheres are at the periphery, M - 1 if at the core.
// W is the 2-D Lucy polynomial of Theory/CoarseGraining.md eq. (2) with cut-off `width` in the
// (x, z) plane, averaged along y; the grid is `cells` x `cells` cell centres on
// [-extent, extent]^2, as talus-cg's `--coordinates XZ -n cells cells -x -e e -z -e e`.
// (No mobile particle: M = S = 0.)
using cg::MixingIndices;
MixingIndices mixingIndices(const ParticleStore& particles, std::size_t sphereSpecies, double extent, int cells,
                            double width);

// "spheres at the core", "spheres at the periphery", or "one kind only" (S is NaN).
const char* whereTheSpheresAre(const MixingIndices& indices);

// Dynamic angle of repose, in degrees, of the free surface of a bed turning counter-clockwise
// in the (x, z) plane: the surface rises towards +x. Method: the bed's mobile particles are
// sorted into columns of width `binWidth` along x; a column's surface particle is the one with the
// highest centre. A least-squares line z = a + b x is fitted to the surface particles of the
// columns in the middle `centralFraction` of the bed's x-extent (near the drum wall the surface
// bends into the wall); the angle is atan(b). NaN with fewer than three columns.
double surfaceAngle(const ParticleStore& particles, double binWidth = 1, double centralFraction = 0.6);
// The same from the centres (x, z) of the mobile particles alone (frames of a .data file:
// talus-drum-angle).
double surfaceAngle(std::span<const std::array<double, 2>> mobileCentres, double binWidth = 1,
                    double centralFraction = 0.6);

}  // namespace talus::drum
