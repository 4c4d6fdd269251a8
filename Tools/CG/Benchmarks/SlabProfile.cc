#include "Benchmarks/SlabProfile.h"

#include <cmath>

namespace talus::cg::benchmark {

double lucyMarginalDistribution(double t) {
    if (t <= -1) return 0;
    if (t >= 1) return 1;
    const double s = std::abs(t);
    const double s2 = s * s, s3 = s2 * s, s5 = s3 * s2, s6 = s5 * s, s7 = s6 * s;
    const double q = s3 / 6 - 3 * s5 / 10 + 4 * s6 / 15 - s7 / 14;
    return 0.5 + std::copysign(105.0 / 8.0 * (s / 10 - q), t);
}

double lucySlabDensity(double z, double height, double width, double bulkDensity) {
    return bulkDensity * (lucyMarginalDistribution(z / width) - lucyMarginalDistribution((z - height) / width));
}

}  // namespace talus::cg::benchmark
