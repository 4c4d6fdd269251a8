// The fields written by talus-cg, computed from the (time-averaged) sums of FieldSums.h:
//
//   Velocity        V = p / rho                                   (0 where rho = 0)
//   KineticStress   sigma_k = K - p p / rho = sum_i m_i v'_i v'_i W(r - r_i), v'_i = v_i - V(r):
//                   the fluctuation relative to the coarse-grained velocity AT THE EVALUATION
//                   POINT (Goldhirsch 2010; Weinhart et al. 2012), not at the particle.
//                   Under time averaging K, p and rho are averaged first, so sigma_k also holds
//                   the temporal fluctuations about the mean velocity (momentum balance of the
//                   averaged fields).
//   ContactStress   sigma_c (9 components, compressive positive: the force on i along the
//                   branch from its partner to i gives a positive normal stress)
//   Stress          sigma_k + sigma_c (when contact stress is evaluated)
//   InteractionForce  the boundary's force density on the flow (with the contact stress;
//                   Fields/CoarseGrainer.h "Boundaries"), so that in a steady state
//                   -div(Stress) + rho g + InteractionForce = 0 (with rho V V for a mean flow)
//   Concentration   phi_s = rho_s / rho, in [0, 1] (0 where rho = 0)
//   AngularVelocity (cylindrical coordinates) angular momentum / moment of inertia about the axis
#pragma once

#include <string>
#include <vector>

#include "Fields/FieldSums.h"

namespace talus::cg {

struct OutputColumn {
    std::string name;
    std::string unit;  // in DEM units: M mass, L length, T time
};

// Column names and units of the derived fields (without coordinates and time).
std::vector<OutputColumn> derivedColumns(const FieldSums& layout);

// The columns grouped into the arrays of a VTK file (App/VtkFieldWriter.h): a scalar column
// alone, a vector's 3 columns, a tensor's 9 in row-major order. The symmetric KineticStress is
// filled out to 9 components from its 6 columns (XY serves XY and YX, ...).
struct FieldArray {
    std::string name;                         // Density, Momentum, KineticStress, Density_s0, ...
    std::vector<int> columns;                 // per component, the index into derivedColumns()
    std::vector<std::string> componentNames;  // X Y Z, XX XY ... ZZ, R Theta Axial; empty for scalars
};
std::vector<FieldArray> fieldArrays(const FieldSums& layout);

// Appends the derived fields of one point (its sums row) to `values`.
void appendDerivedFields(const FieldSums& layout, const double* sums, std::vector<double>& values);

}  // namespace talus::cg
