// The fluxes of the depth-averaged model and the HLL numerical flux (Harten, Lax & van Leer 1983)
// with which the finite volumes exchange them.
//   f(U) = (h u,  alpha h u^2 + h^2 cos(t) / 2,  h phi u (a_s + (1 - a_s) phi))
// (Theory/DepthAveraged.md eq. (4)-(6); the third is eq. (6)'s h phi u - (1 - a_s) h phi u (1 - phi),
// the small particles' flux of the fully segregated flow with the linear profile (2)).
#pragma once

#include "Model/State.h"

namespace talus::shallow {

struct FluxModel {
    double shapeFactor = 1;  // alpha, eq. (3)
    double basalSlip = 1;    // a_s
    double cosAngle = 1;     // the normal component of gravity (g = 1)
};

Conserved physicalFlux(const FluxModel& model, const Primitive& p);

// The smallest and largest signal speeds of a state: the bulk waves
// lambda_{1,2} = alpha u -+ sqrt((alpha^2 - alpha) u^2 + h cos t) and the concentration wave
// lambda_3 = u (a_s + 2 (1 - a_s) phi) (Denissen 2019, app. 3.A). lambda_1 <= u <= lambda_2 for
// alpha >= 1, which makes the HLL flux keep h non-negative.
struct SignalSpeeds {
    double slowest = 0, fastest = 0;
};
SignalSpeeds signalSpeeds(const FluxModel& model, const Primitive& p);

// HLL flux between the left and right face states; `maxSpeed` returns max(|a_L|, |a_R|).
Conserved hllFlux(const FluxModel& model, const Primitive& left, const Primitive& right, double& maxSpeed);

}  // namespace talus::shallow
