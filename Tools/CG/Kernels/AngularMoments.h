// The angular average of an isotropic coarse-graining function over a circle around an axis, for
// fields in cylindrical coordinates (Documentation/CoarseGraining.md "Cylindrical coordinates";
// Theory/RotatingDrum.md drums, Theory/CoarseGraining.md eq. (5)-(10) fields). A particle at
// distance ri from the axis contributes to the field at (r, s) the mean of W over the circle of
// radius r:
//
//   C_n = (1/2 pi) int_0^{2 pi} cos(n phi) W1(u(phi)) dphi,   n = 0, 1, 2,
//   u^2(phi) = m2 + 4 a sin^2(phi/2),   m2 = ((r - ri)/wp)^2 + ((s - si)/wa)^2,   a = r ri / wp^2,
//
// (the law of cosines, |x - xi|^2 = (r - ri)^2 + 2 r ri (1 - cos phi) + (s - si)^2, written with
// sin^2 so that it does not cancel near r = ri). C0 spreads scalars (mass, volume); C1 and C2 turn
// the particle's own radial and azimuthal velocity into those at the point (the derivation in
// CoarseGraining.md). The result includes the normalisation c_d of the profile but not the width
// factor det(A) = 1/(wp^2 wa).
#pragma once

#include "Kernels/KernelProfile.h"

namespace talus::cg {

struct AngularMoments {
    double c0 = 0, c1 = 0, c2 = 0;
};

// The integral is zero outside the support (m2 >= R^2). Otherwise it runs over |phi| < phi_c, the
// arc inside the support (phi_c = pi when the whole circle is inside, and C1 = C2 = 0 exactly on
// the axis, a = 0), by adaptive Gauss-Kronrod (7/15 points) quadrature with an absolute error
// estimate below 1e-13 c_d (summed over panels; the true error is usually far smaller).
AngularMoments angularMoments(const KernelProfile& profile, double m2, double a);

}  // namespace talus::cg
