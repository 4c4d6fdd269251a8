// The parameters of the depth-averaged bidisperse model (Documentation/Theory/DepthAveraged.md):
// the chute's inclination, the basal slip of the velocity profile and the friction law of each
// constituent. Units: lengths in large-particle diameters, time in sqrt(dL/g) (so g = 1).
#pragma once

namespace talus::shallow {

// The friction law of one pure constituent, Theory/DepthAveraged.md eq. (8).
struct FrictionParameters {
    double delta1Degrees = 0;  // the smallest inclination at which the constituent flows
    double delta2Degrees = 0;  // the largest inclination with steady flows
    double lengthScale = 1;    // A
    double beta = 0;           // the empirical constant beta
    double diameter = 1;       // d, in large diameters
};

struct ModelParameters {
    double angleDegrees = 24;  // chute inclination theta
    double basalSlip = 0.17;   // a_s of the velocity profile, Theory/DepthAveraged.md eq. (2)
    bool frictionless = false; // mu = 0 (the dam-break test)
    FrictionParameters small{17.92, 36.53, 0.71, 0.148, 0.7937005259840998};  // table 3.1 of
    FrictionParameters large{18.60, 30.06, 3.07, 0.146, 1.0};                // Denissen (2019)

    double sinAngle() const;
    double cosAngle() const;
    // alpha = 1 + (1 - a_s)^2 / 3, Theory/DepthAveraged.md eq. (3).
    double shapeFactor() const;
    // Throws InputError naming the parameter: angle outside [0, 90), a_s outside [0, 1],
    // d1 outside [0, 90), d2 <= d1 or >= 90, A, beta or d not positive.
    void validate() const;
};

}  // namespace talus::shallow
