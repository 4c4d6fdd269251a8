#include "Model/Flux.h"

#include <algorithm>
#include <cmath>

namespace talus::shallow {

Conserved physicalFlux(const FluxModel& m, const Primitive& p) {
    const double q = p.h * p.u;
    return {q, m.shapeFactor * q * p.u + 0.5 * m.cosAngle * p.h * p.h,
            q * p.phi * (m.basalSlip + (1.0 - m.basalSlip) * p.phi)};
}

SignalSpeeds signalSpeeds(const FluxModel& m, const Primitive& p) {
    const double a = m.shapeFactor;
    const double root = std::sqrt((a * a - a) * p.u * p.u + p.h * m.cosAngle);
    const double concentrationWave = p.u * (m.basalSlip + 2.0 * (1.0 - m.basalSlip) * p.phi);
    return {std::min(a * p.u - root, concentrationWave), std::max(a * p.u + root, concentrationWave)};
}

Conserved hllFlux(const FluxModel& m, const Primitive& left, const Primitive& right, double& maxSpeed) {
    const SignalSpeeds l = signalSpeeds(m, left), r = signalSpeeds(m, right);
    const double aL = std::min({l.slowest, r.slowest, 0.0});
    const double aR = std::max({l.fastest, r.fastest, 0.0});
    maxSpeed = std::max(-aL, aR);
    if (aR - aL <= 0) return {};  // both sides dry and at rest
    const Conserved fL = physicalFlux(m, left), fR = physicalFlux(m, right);
    if (aL >= 0) return fL;
    if (aR <= 0) return fR;
    const Conserved uL = toConserved(left), uR = toConserved(right);
    const double w = 1.0 / (aR - aL);
    const auto mix = [&](double fl, double fr, double ul, double ur) {
        return (aR * fl - aL * fr + aL * aR * (ur - ul)) * w;
    };
    return {mix(fL.h, fR.h, uL.h, uR.h), mix(fL.hu, fR.hu, uL.hu, uR.hu), mix(fL.hphi, fR.hphi, uL.hphi, uR.hphi)};
}

}  // namespace talus::shallow
