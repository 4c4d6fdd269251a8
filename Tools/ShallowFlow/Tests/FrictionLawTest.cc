// The basal friction law (Theory/DepthAveraged.md eq. (7)-(9)) and its implicit step.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "Model/FrictionLaw.h"
#include "Model/InputError.h"

namespace talus::shallow {
namespace {

double tanDegrees(double degrees) { return std::tan(degrees * std::numbers::pi / 180); }

// The steady speed against the closed form of Denissen (2019) app. 3.B.1: with
// b = tan t - phi tan d1S - (1 - phi) tan d1L, aS = phi (tan d2S - tan d1S),
// aL = (1 - phi)(tan d2L - tan d1L), c_v = beta_v / (A_v d_v), mu = tan t reads
// aS / (cS h / F + 1) + aL / (cL h / F + 1) = b, a quadratic in F / h whose positive root is
// (aL + aS - b) F = h/2 (B + sqrt(B^2 - 4 (b - aL - aS) b cL cS)), B = (b - aS) cL + (b - aL) cS,
// and u = F sqrt(h cos t) (eq. (3.49)-(3.50)).
TEST(FrictionLaw, SteadySpeedMatchesTheClosedForm) {
    const ModelParameters p;  // table 3.1
    const FrictionLaw law(p);
    for (double h : {5.0, 15.0, 30.0}) {
        for (double phi : {0.0, 0.3, 0.5, 1.0}) {
            const double b = tanDegrees(p.angleDegrees) - phi * tanDegrees(p.small.delta1Degrees) -
                             (1 - phi) * tanDegrees(p.large.delta1Degrees);
            const double aS = phi * (tanDegrees(p.small.delta2Degrees) - tanDegrees(p.small.delta1Degrees));
            const double aL = (1 - phi) * (tanDegrees(p.large.delta2Degrees) - tanDegrees(p.large.delta1Degrees));
            const double cS = p.small.beta / (p.small.lengthScale * p.small.diameter);
            const double cL = p.large.beta / (p.large.lengthScale * p.large.diameter);
            const double B = (b - aS) * cL + (b - aL) * cS;
            const double F = h / 2 * (B + std::sqrt(B * B - 4 * (b - aL - aS) * b * cL * cS)) / (aL + aS - b);
            const double expected = F * std::sqrt(h * p.cosAngle());
            const double speed = law.steadySpeed(h, phi);
            EXPECT_NEAR(speed, expected, 1e-12 * expected) << "h " << h << " phi " << phi;
            EXPECT_NEAR(law.coefficient(h, speed, phi), tanDegrees(p.angleDegrees), 1e-14);
        }
    }
    // The thesis's inflow (h 15, phi 0.5) with the mixture's diameters (dS = 2^(-1/3)): u = 3.8408.
    EXPECT_NEAR(law.steadySpeed(15, 0.5), 3.8408193, 1e-6);
}

TEST(FrictionLaw, NoSteadyFlowOutsideTheLawsRange) {
    ModelParameters p;
    p.angleDegrees = 15;  // below both d1: every flow stops
    EXPECT_THROW(FrictionLaw(p).steadySpeed(15, 0.5), InputError);
    p.angleDegrees = 40;  // above both d2: every flow accelerates
    EXPECT_THROW(FrictionLaw(p).steadySpeed(15, 0.5), InputError);
}

TEST(FrictionLaw, LimitsOfTheLaw) {
    const ModelParameters p;
    const FrictionLaw law(p);
    // F = 0: tan d1 of each constituent, mixed by phi (eq. (7)-(8)).
    EXPECT_NEAR(law.coefficient(10, 0, 0.25),
                0.25 * tanDegrees(p.small.delta1Degrees) + 0.75 * tanDegrees(p.large.delta1Degrees), 1e-15);
    // h -> 0 at a finite speed: F -> infinity, tan d2.
    EXPECT_NEAR(law.coefficient(1e-200, 1, 0), tanDegrees(p.large.delta2Degrees), 1e-15);
    // The law itself at one point, eq. (8) as printed: mu_L = tan d1 + (tan d2 - tan d1) / (beta h / (A F) + 1).
    const double h = 10, u = 2, F = u / std::sqrt(h * p.cosAngle());
    const double muL = tanDegrees(p.large.delta1Degrees) + (tanDegrees(p.large.delta2Degrees) - tanDegrees(p.large.delta1Degrees)) /
                                                               (p.large.beta * h / (p.large.lengthScale * F) + 1);
    EXPECT_NEAR(law.coefficient(h, u, 0), muL, 1e-15);
}

// The implicit step solves v + dt cos(t) mu(h, |v|, phi) sign(v) = u*: check the residual, the
// Coulomb stop and that the sign never flips.
TEST(FrictionLaw, ImplicitStepSolvesItsEquationAndNeverReverses) {
    const ModelParameters p;
    const FrictionLaw law(p);
    const double h = 12, phi = 0.4, c = p.cosAngle();
    for (double uStar : {-5.0, -0.3, 0.01, 0.5, 3.0, 40.0}) {
        for (double dt : {1e-3, 0.1, 1.0}) {
            const double v = law.velocityAfterFriction(h, phi, uStar, dt);
            EXPECT_GE(v * uStar, 0.0) << "u* " << uStar << " dt " << dt;
            EXPECT_LE(std::abs(v), std::abs(uStar));
            if (v == 0) {
                EXPECT_GE(dt * c * law.coefficient(h, 0, phi), std::abs(uStar));
            } else {
                const double residual = v + dt * c * law.coefficient(h, std::abs(v), phi) * (v > 0 ? 1 : -1) - uStar;
                EXPECT_NEAR(residual, 0.0, 1e-13 * std::abs(uStar)) << "u* " << uStar << " dt " << dt;
            }
        }
    }
}

TEST(FrictionLaw, ParametersAreChecked) {
    ModelParameters p;
    p.small.delta2Degrees = 10;  // d2 < d1
    try {
        p.validate();
        FAIL() << "d2 < d1 accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("--small"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("d2 = 10"), std::string::npos) << error.what();
    }
    p = ModelParameters{};
    p.basalSlip = 1.5;
    EXPECT_THROW(p.validate(), InputError);
}

}  // namespace
}  // namespace talus::shallow
