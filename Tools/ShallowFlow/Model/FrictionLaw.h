// The basal friction of the bidisperse mixture: each pure constituent follows the rough-bed law of
// Weinhart et al. (2012), mu_v = tan d1 + (tan d2 - tan d1) / (beta h / (A d F) + 1) with the Froude
// number F = |u| / sqrt(h cos t), and the mixture mixes them by the small-particle concentration,
// mu = phi mu_S + (1 - phi) mu_L (Pouliquen & Vallance 1999); Theory/DepthAveraged.md eq. (7)-(9),
// Denissen (2019) eq. (3.10)-(3.11).
#pragma once

#include "Model/ModelParameters.h"

namespace talus::shallow {

class FrictionLaw {
public:
    explicit FrictionLaw(const ModelParameters& parameters);

    // mu(h, |u|, phi); mu = 0 for a frictionless model. h > 0, speed >= 0.
    double coefficient(double h, double speed, double phi) const;

    // The speed u > 0 of the steady uniform flow of height h and concentration phi, where friction
    // balances gravity: mu(h, u, phi) = tan(t) (Denissen 2019, app. 3.B.1). Throws InputError when
    // tan(t) is outside the range (mu(h, 0, phi), mu(h, infinity, phi)) of the law.
    double steadySpeed(double h, double phi) const;

    // The velocity after a friction step of length dt from the velocity uStar, implicit in the
    // velocity: v + dt cos(t) mu(h, |v|, phi) sign(v) = uStar. When dt cos(t) mu(h, 0, phi) >= |uStar|
    // the Coulomb friction at rest exceeds the driving impulse and the result is 0: friction stops a
    // flow but never reverses it.
    double velocityAfterFriction(double h, double phi, double uStar, double dt) const;

private:
    // mu_v = tan1 + (tan2 - tan1) v / (v0 + v), v0 = beta h sqrt(h cos t) / (A d): eq. (8) with F
    // written out, so that F = 0 gives tan1 without a division by F.
    struct Constituent {
        double tan1 = 0, tan2 = 0, scale = 0;  // scale = A d / beta
    };
    // What depends on h and phi only: the speeds v0 of both constituents and phi.
    struct AtHeight {
        double smallSpeed = 0, largeSpeed = 0, phi = 0;
    };
    AtHeight atHeight(double h, double phi) const;
    double mixedCoefficient(const AtHeight& local, double speed, double* derivative) const;
    double mixedCoefficient(double h, double speed, double phi, double* derivative) const;

    bool frictionless_;
    double cosAngle_, tanAngle_;
    Constituent small_, large_;
};

}  // namespace talus::shallow
