// What a user of a chute-flow prediction looks at (Denissen 2019, sec. 3.3-3.5): where the front
// is, how high the head stands, where the small particles end (the concentration shock), and the
// conserved totals.
#pragma once

#include <vector>

#include "Model/State.h"
#include "Numerics/Solver.h"

namespace talus::shallow {

struct FlowDiagnostics {
    double frontPosition = 0;  // the largest x where h reaches the front height (linear between cells)
    double headHeight = 0;     // the largest h
    double headPosition = 0;   // the x of the largest h
    double shockPosition = 0;  // the largest x where phi reaches the shock concentration
    double volume = 0;         // integral of h dx
    double smallVolume = 0;    // integral of h phi dx
};

// frontHeight: the h that counts as the front (the height tends to 0 smoothly at a front when
// alpha > 1, so a threshold is needed); shockConcentration: the phi that counts as the shock.
// A position is the grid's start if no cell reaches the threshold.
FlowDiagnostics diagnose(const Grid& grid, const std::vector<Conserved>& cells, double dryHeight,
                         double frontHeight, double shockConcentration);

}  // namespace talus::shallow
