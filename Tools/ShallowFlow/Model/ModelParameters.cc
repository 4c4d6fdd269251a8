#include "Model/ModelParameters.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "Model/InputError.h"

namespace talus::shallow {

std::string str(double value) {
    std::ostringstream out;
    out.precision(12);
    out << value;
    return out.str();
}

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

void validateFriction(const FrictionParameters& f, const std::string& name) {
    if (!(f.delta1Degrees >= 0 && f.delta1Degrees < 90)) {
        throw InputError(name + ": d1 = " + str(f.delta1Degrees) + " deg must be in [0, 90)");
    }
    if (!(f.delta2Degrees > f.delta1Degrees && f.delta2Degrees < 90)) {
        throw InputError(name + ": d2 = " + str(f.delta2Degrees) + " deg must be larger than d1 = " +
                         str(f.delta1Degrees) + " deg and below 90");
    }
    if (!(f.lengthScale > 0)) throw InputError(name + ": A = " + str(f.lengthScale) + " must be positive");
    if (!(f.beta > 0)) throw InputError(name + ": beta = " + str(f.beta) + " must be positive");
    if (!(f.diameter > 0)) throw InputError(name + ": diameter = " + str(f.diameter) + " must be positive");
}

}  // namespace

double ModelParameters::sinAngle() const { return std::sin(radians(angleDegrees)); }
double ModelParameters::cosAngle() const { return std::cos(radians(angleDegrees)); }
double ModelParameters::shapeFactor() const { return 1.0 + (1.0 - basalSlip) * (1.0 - basalSlip) / 3.0; }

void ModelParameters::validate() const {
    if (!(angleDegrees >= 0 && angleDegrees < 90)) {
        throw InputError("--angle: " + str(angleDegrees) + " deg must be in [0, 90)");
    }
    if (!(basalSlip >= 0 && basalSlip <= 1)) {
        throw InputError("--basal-slip: a_s = " + str(basalSlip) + " must be in [0, 1]");
    }
    if (frictionless) return;
    validateFriction(small, "--small (friction of the small particles)");
    validateFriction(large, "--large (friction of the large particles)");
}

}  // namespace talus::shallow
