// MUSCL reconstruction (van Leer 1979): the primitive variables h, u, phi are taken linear in each
// cell with a limited slope, which makes the scheme second order where the solution is smooth and
// keeps it free of new extrema at jumps. Both limiters bound |slope| dx / 2 by the smaller of the
// two one-sided differences, so the face values lie between the neighbouring cell values: h >= 0
// and 0 <= phi <= 1 at the faces wherever they hold in the cells.
#pragma once

#include <string>
#include <vector>

#include "Model/State.h"

namespace talus::shallow {

enum class Limiter {
    FirstOrder,  // no slope: Godunov's first-order scheme
    Minmod,      // the smaller one-sided difference, 0 at an extremum (the most dissipative)
    VanLeer      // the harmonic mean of the one-sided differences (van Leer 1974)
};

Limiter parseLimiter(const std::string& name);  // "first-order", "minmod", "van-leer"
std::string name(Limiter limiter);

// The slope (per cell, times dx) of a variable from its one-sided differences.
double limitedDifference(Limiter limiter, double backward, double forward);

// The face states of cells 1 .. n-2 of `cells` (cells 0 and n-1 only serve as neighbours):
// west[i] and east[i] are the values of cell i at its west and east faces.
void reconstruct(Limiter limiter, const std::vector<Primitive>& cells, std::vector<Primitive>& west,
                 std::vector<Primitive>& east);

}  // namespace talus::shallow
