// The command line of talus-shallow (Documentation/ShallowFlow.md lists every flag).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "Model/ModelParameters.h"
#include "Numerics/Boundary.h"
#include "Numerics/Solver.h"

namespace talus::shallow {

struct ProgramOptions {
    bool help = false;
    Grid grid{0, 2000, 2000};
    ModelParameters model;
    NumericsSettings numerics;
    BoundaryCondition::Kind left = BoundaryCondition::Kind::Inflow;
    BoundaryCondition::Kind right = BoundaryCondition::Kind::Transmissive;
    double inflowHeight = 15;
    double inflowConcentration = 0.5;
    std::optional<double> inflowVelocity;  // default: the steady speed, S(h_in, u, phi_in) = 0
    std::string initial = "empty";         // "empty", "inflow" or a csv file x,h,u,phi
    double endTime = 500;
    std::vector<double> outputTimes;       // default: the end time
    std::string output = "shallow";        // file prefix
    double frontHeight = 0.5;
    double shockConcentration = 0.25;
    double progressInterval = 0;           // simulated time between progress lines; 0: a tenth of the run
};

// Throws InputError naming the flag for an unknown flag, a missing or malformed value, or a value
// out of range (a negative height, phi outside [0, 1], a CFL outside (0, 1], ...).
ProgramOptions parseOptions(int argc, const char* const* argv);
std::string usage();

}  // namespace talus::shallow
