#include "Model/FrictionLaw.h"

#include <cmath>
#include <algorithm>
#include <numbers>
#include <tuple>

#include "Model/InputError.h"

namespace talus::shallow {

FrictionLaw::FrictionLaw(const ModelParameters& p)
    : frictionless_(p.frictionless), cosAngle_(p.cosAngle()), tanAngle_(p.sinAngle() / p.cosAngle()) {
    const auto constituent = [](const FrictionParameters& f) {
        const double toRadians = std::numbers::pi / 180.0;
        return Constituent{std::tan(f.delta1Degrees * toRadians), std::tan(f.delta2Degrees * toRadians),
                           f.lengthScale * f.diameter / f.beta};
    };
    small_ = constituent(p.small);
    large_ = constituent(p.large);
}

FrictionLaw::AtHeight FrictionLaw::atHeight(double h, double phi) const {
    // k v / (1 + k v) = v / (v0 + v) with v0 = 1 / k = beta h sqrt(h cos t) / (A d): no overflow as
    // h -> 0 (where mu -> tan2 for any v > 0); F = 0 (v = 0) gives tan1.
    const double heightScale = h * std::sqrt(h * cosAngle_);
    return {heightScale / small_.scale, heightScale / large_.scale, phi};
}

double FrictionLaw::mixedCoefficient(const AtHeight& a, double speed, double* derivative) const {
    double mu = 0, dmu = 0;
    for (const auto& [c, v0, weight] : {std::tuple{small_, a.smallSpeed, a.phi}, std::tuple{large_, a.largeSpeed, 1.0 - a.phi}}) {
        const double sum = v0 + speed;
        const double ratio = sum > 0 ? speed / sum : 0.0;
        mu += weight * (c.tan1 + (c.tan2 - c.tan1) * ratio);
        dmu += sum > 0 ? weight * (c.tan2 - c.tan1) * v0 / (sum * sum) : 0.0;
    }
    if (derivative) *derivative = dmu;
    return mu;
}

double FrictionLaw::mixedCoefficient(double h, double speed, double phi, double* derivative) const {
    return mixedCoefficient(atHeight(h, phi), speed, derivative);
}

double FrictionLaw::coefficient(double h, double speed, double phi) const {
    if (frictionless_) return 0;
    return mixedCoefficient(h, speed, phi, nullptr);
}

double FrictionLaw::steadySpeed(double h, double phi) const {
    if (frictionless_) throw InputError("a frictionless flow has no steady speed: give --inflow-velocity");
    const double atRest = mixedCoefficient(h, 0, phi, nullptr);
    const double fastest = phi * small_.tan2 + (1 - phi) * large_.tan2;
    if (!(tanAngle_ > atRest && tanAngle_ < fastest)) {
        throw InputError("no steady flow at h = " + str(h) + ", phi = " + str(phi) + ": tan(angle) = " +
                         str(tanAngle_) + " is outside the friction law's range (" + str(atRest) + ", " +
                         str(fastest) + ")");
    }
    // mu is increasing in u: bracket the root, then bisect to the last bit (a few dozen steps).
    double low = 0, high = 1;
    while (mixedCoefficient(h, high, phi, nullptr) < tanAngle_) high *= 2;
    while (true) {
        const double middle = 0.5 * (low + high);
        if (middle <= low || middle >= high) break;
        (mixedCoefficient(h, middle, phi, nullptr) < tanAngle_ ? low : high) = middle;
    }
    // Of the two neighbours, the one with the smaller residual.
    const double residualLow = std::abs(mixedCoefficient(h, low, phi, nullptr) - tanAngle_);
    const double residualHigh = std::abs(mixedCoefficient(h, high, phi, nullptr) - tanAngle_);
    return residualLow < residualHigh ? low : high;
}

double FrictionLaw::velocityAfterFriction(double h, double phi, double uStar, double dt) const {
    if (frictionless_) return uStar;
    const double drive = std::abs(uStar);
    const double impulse = dt * cosAngle_;
    // Coulomb stop: the friction at rest, mu(h, 0, phi) = phi tan d1S + (1 - phi) tan d1L, takes all
    // the momentum in this step.
    if (impulse * (phi * small_.tan1 + (1.0 - phi) * large_.tan1) >= drive) return 0.0;
    // g(v) = v + impulse mu(v) - drive is increasing and concave in v (mu is increasing and concave),
    // so Newton from a point left of the root climbs to it monotonically and quadratically. The
    // explicit step v = drive - impulse mu(drive) is such a point (mu(v) <= mu(drive) makes g(v) <= 0)
    // and is already close: one or two Newton steps reach round-off.
    const AtHeight local = atHeight(h, phi);
    double v = std::max(0.0, drive - impulse * mixedCoefficient(local, drive, nullptr));
    for (int iteration = 0; iteration < 50; ++iteration) {
        double dmu = 0;
        const double g = v + impulse * mixedCoefficient(local, v, &dmu) - drive;
        const double next = std::max(0.0, v - g / (1.0 + impulse * dmu));
        const bool converged = std::abs(next - v) <= 1e-15 * drive;
        v = next;
        if (converged) break;
    }
    return uStar > 0 ? v : -v;
}

}  // namespace talus::shallow
