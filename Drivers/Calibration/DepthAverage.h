// The depth-averaged velocity and the velocity shape factor of a chute flow, from depth profiles
// (Documentation/Calibration.md, "What a point writes").
#pragma once

#include <cmath>
#include <vector>

#include "Chute/ChuteStatistics.h"

namespace talus {

// The depth-averaged velocity and its shape factor alpha = <u^2>/<u>^2 from a depth profile: the
// mass-weighted velocity of each slab u_k, then <u> = sum M_k u_k / sum M_k and <u^2> = sum M_k
// u_k^2 / sum M_k (the slabs' mean flow only: the velocity fluctuations are not part of alpha).
// The one place that reads the profile, to be replaced by in-run coarse graining.
struct DepthAverage {
    double velocity = NAN, shapeFactor = NAN;
};
inline DepthAverage depthAverage(const DepthProfile& profile) {
    double mass = 0, momentum = 0, momentumFlux = 0;
    for (std::size_t k = 0; k < profile.slabMass().size(); ++k) {
        const double m = profile.slabMass()[k], p = profile.slabMomentum()[k];
        if (m <= 0) continue;
        mass += m, momentum += p, momentumFlux += p * p / m;
    }
    if (!(mass > 0) || momentum == 0) return {};
    return {momentum / mass, momentumFlux * mass / (momentum * momentum)};
}

// The change of a series sampled at equal intervals from its first to its last sample along its
// least-squares line: slope (n - 1) with slope = sum (k - m) u_k / sum (k - m)^2, m = (n - 1)/2.
// (The difference of the two end samples themselves carries their whole fluctuation.) 0 for n < 2.
inline double changeAlongTrend(const std::vector<double>& u) {
    const double n = double(u.size()), mid = (n - 1) / 2;
    double moment = 0, spread = 0;
    for (std::size_t k = 0; k < u.size(); ++k) moment += (double(k) - mid) * u[k], spread += (double(k) - mid) * (double(k) - mid);
    return u.size() > 1 ? moment / spread * (n - 1) : 0;
}

}  // namespace talus
