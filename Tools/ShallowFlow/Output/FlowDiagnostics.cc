#include "Output/FlowDiagnostics.h"

namespace talus::shallow {

namespace {

// The largest x at which the cell values `value(i)` fall through `threshold` going downstream,
// linear between cell centres.
template <typename Value>
double lastCrossing(const Grid& grid, std::size_t n, double threshold, Value value) {
    for (std::size_t i = n; i-- > 0;) {
        if (value(i) < threshold) continue;
        if (i + 1 == n) return grid.centre(i);
        const double here = value(i), next = value(i + 1);
        return grid.centre(i) + grid.spacing() * (here - threshold) / (here - next);
    }
    return grid.start;
}

}  // namespace

FlowDiagnostics diagnose(const Grid& grid, const std::vector<Conserved>& cells, double dryHeight,
                         double frontHeight, double shockConcentration) {
    FlowDiagnostics d;
    const std::size_t n = cells.size();
    for (std::size_t i = 0; i < n; ++i) {
        d.volume += cells[i].h * grid.spacing();
        d.smallVolume += cells[i].hphi * grid.spacing();
        if (cells[i].h > d.headHeight) {
            d.headHeight = cells[i].h;
            d.headPosition = grid.centre(i);
        }
    }
    d.frontPosition = lastCrossing(grid, n, frontHeight, [&](std::size_t i) { return cells[i].h; });
    d.shockPosition = lastCrossing(grid, n, shockConcentration,
                                   [&](std::size_t i) { return toPrimitive(cells[i], dryHeight).phi; });
    return d;
}

}  // namespace talus::shallow
