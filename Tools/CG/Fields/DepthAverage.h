// Depth-averaged fields of chute flows (issue 5 item 4; the depth-averaged model of
// Theory/DepthAveraged.md eq. (4)-(9) and Denissen 2019, sec. 3.2.1): per column of a grid whose
// last resolved axis is z, the coarse-grained fields are integrated over z by the midpoint rule of
// the grid,
//
//   mass per area     m_A   = int rho dz              (exact total mass per area when the z range
//                                                      covers the flow: CG conserves mass)
//   bulk density      rho_b = --bulk-density, else the mass-weighted mean density
//                             int rho^2 dz / m_A
//   height            h     = m_A / rho_b             (Denissen 2019, sec. 3.2.1: "the bulk density
//                                                      of the flow is assumed constant")
//   velocity          u_bar = int p dz / m_A          (mass-weighted: h rho_b u_bar is the flux)
//   concentration     phi_bar_s = int rho_s dz / m_A  (mass fraction of species s in the column)
//   solid height      int nu dz                       (volume of the particles per area)
//
// The thesis defines u_bar = (1/h) int_0^h u dz and phi_bar likewise (Denissen 2019, sec. 3.2.1), a
// volume average; at constant bulk density it equals the mass-weighted one used here, which is also
// the one that conserves mass and momentum for any density profile. With the mass-weighted mean
// density, h = m_A^2 / int rho^2 dz is exact for a layer of uniform density; the smoothing of the
// free surface and of the base over the kernel width lowers int rho^2 and raises h by a fraction of
// the width (Documentation/CoarseGraining.md gives the size for Lucy).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "Fields/DerivedFields.h"
#include "Fields/FieldSums.h"

namespace talus::cg {

// Column names and units of the depth-averaged fields.
std::vector<OutputColumn> depthAveragedColumns(const FieldSums& layout);

struct DepthAverageCoverage {
    // Largest ratio, over the columns, of the density at the top z point to the column's maximum:
    // well above 0 means the z range cuts the flow (the mass per area is then too small).
    double topDensityRatio = 0;
};

// `sums` holds columns of `pointsPerColumn` consecutive points along z (the grid order of
// EvaluationPoints.h: z is the last resolved axis, so it varies fastest), spaced `dz`. Appends
// one row of values (the columns of depthAveragedColumns) per column to `rows`.
DepthAverageCoverage depthAverage(const FieldSums& layout, const std::vector<double>& sums, long pointsPerColumn,
                                  double dz, std::optional<double> bulkDensity, std::vector<std::vector<double>>& rows);

}  // namespace talus::cg
