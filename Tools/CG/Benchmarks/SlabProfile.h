// The density profile of a uniform slab 0 < z < H of density rho_b coarse-grained by the 3-D
// Lucy kernel of width w, the "known profile" of the accuracy study (cgBenchmark.cc):
//
//   rho(z) = rho_b [G(z / w) - G((z - H) / w)],
//
// G the distribution function of the kernel's marginal along z. The marginal of the unit Lucy
// kernel is p(t) = 2 pi c_3 int_|t|^1 f(q) q dq = 2 pi c_3 (P(1) - P(|t|)) with
// P(q) = q^2/2 - 3q^4/2 + 8q^5/5 - q^6/2, P(1) = 1/10, 2 pi c_3 = 105/8, so
//
//   G(t) = 1/2 + sign(t) (105/8) (|t|/10 - Q(|t|)),  Q(s) = s^3/6 - 3s^5/10 + 4s^6/15 - s^7/14,
//
// for |t| < 1 (G(1) = 1 since int_0^1 (1/10 - P) = 4/105). A lattice of spheres differs from the
// uniform slab at the scale of the spacing, which is the error the study measures.
#pragma once

namespace talus::cg::benchmark {

double lucyMarginalDistribution(double t);

double lucySlabDensity(double z, double height, double width, double bulkDensity);

}  // namespace talus::cg::benchmark
