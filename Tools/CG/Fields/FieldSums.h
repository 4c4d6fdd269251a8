// The additive coarse-grained sums evaluated at each point (Theory/CoarseGraining.md; Goldhirsch
// 2010; Weinhart et al. 2012), stored as one row of doubles per point:
//
//   Density            rho      = sum_i m_i W(r - r_i)
//   VolumeFraction     nu       = sum_i V_i W(r - r_i)           (V_i particle volume)
//   Momentum (3)       p        = sum_i m_i v_i W(r - r_i)
//   MomentumFlux (6)   K        = sum_i m_i v_i v_i W(r - r_i)   (xx xy xz yy yz zz)
//   Density of species s (S)    = sum over particles of species s of m_i W(r - r_i)
//   ContactStress (9, optional) = sum_contacts w_c f_c (x) b_c int_0^1 W(r - r_c + s b_c) ds
//   InteractionForce (3, with the contact stress) = sum over boundary contacts of w_c f_c W(r - c):
//                   the force density the boundary (walls; fixed particles with --fixed
//                   boundary) exerts on the flowing particles, spread from the contact points c
//                   (Weinhart et al. 2012; CoarseGrainer.h "Boundaries")
//   cylindrical only (2):  AngularMomentum  sum_i m_i r_i u_theta,i <W>,
//                          MomentOfInertia  sum_i m_i r_i^2 <W>   (about the drum axis)
//
// Sums are what time averaging averages; velocity, kinetic stress and concentration are
// derived from them afterwards (DerivedFields.h). In cylindrical coordinates (RZ, R) the vector
// and tensor slots hold the radial, azimuthal and axial components instead of x, y, z
// (Fields/CylindricalCoarseGrainer.h).
#pragma once

#include <array>

namespace talus::cg {

struct FieldSums {
    static constexpr int density = 0;
    static constexpr int volumeFraction = 1;
    static constexpr int momentum = 2;      // 3 components
    static constexpr int momentumFlux = 5;  // 6 components: xx xy xz yy yz zz
    static constexpr int speciesDensity = 11;

    int species = 1;
    bool contactStress = false;
    bool cylindrical = false;  // components (r, theta, s) instead of (x, y, z)

    int speciesDensityIndex(int s) const { return speciesDensity + s; }
    int contactStressIndex() const { return speciesDensity + species; }  // 9 components, row-major
    int interactionForceIndex() const { return contactStressIndex() + 9; }  // 3 components
    int angularMomentumIndex() const { return speciesDensity + species + (contactStress ? 12 : 0); }  // then inertia
    int count() const { return angularMomentumIndex() + (cylindrical ? 2 : 0); }

    // Adds one particle's terms to a row: mw = m_i W, vw = V_i W, velocity v, species s.
    static void addParticle(double* row, double mw, double vw, const std::array<double, 3>& v, int s) {
        row[density] += mw;
        row[volumeFraction] += vw;
        for (int c = 0; c < 3; ++c) row[momentum + c] += mw * v[c];
        row[momentumFlux + 0] += mw * v[0] * v[0];
        row[momentumFlux + 1] += mw * v[0] * v[1];
        row[momentumFlux + 2] += mw * v[0] * v[2];
        row[momentumFlux + 3] += mw * v[1] * v[1];
        row[momentumFlux + 4] += mw * v[1] * v[2];
        row[momentumFlux + 5] += mw * v[2] * v[2];
        row[speciesDensity + s] += mw;
    }
};

}  // namespace talus::cg
