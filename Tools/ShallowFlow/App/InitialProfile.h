// The initial state of a talus-shallow run: an empty chute, the inflow state everywhere, or a csv
// file with the header x,h,u,phi and one line per cell (the format of PREFIX.profiles.csv without
// its time column, so a profile can be written by a script or cut from an earlier run).
#pragma once

#include <string>
#include <vector>

#include "Model/State.h"
#include "Numerics/Solver.h"

namespace talus::shallow {

// Throws InputError naming the file and line for a malformed line, a negative height, phi outside
// [0, 1] or a number of lines that differs from the grid's cells.
std::vector<Conserved> initialProfile(const std::string& what, const Grid& grid, const Primitive& inflow);

}  // namespace talus::shallow
