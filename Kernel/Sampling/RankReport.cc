#include "Sampling/RankReport.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "Parallel/DomainSplit.h"
#include "Parallel/RankContext.h"
#include "Simulation.h"

namespace talus {

std::string describeRanks(const Simulation& simulation) {
    const DomainSplit::Timings& seconds = simulation.ranks().split()->seconds;
    const RankContext& context = simulation.ranks();
    std::vector<double> sums = {seconds.total(), double(simulation.scene().particles().ghostCount), seconds.ghosts,
                                seconds.agreement, double(context.overlappedSteps()), double(context.undoneOverlaps())};
    const double wall = std::max(simulation.lastRun().wallSeconds, 1e-300);
    // Each rank's own work (its wall time less its communication, waits included) and owned
    // particles, in slots of their own.
    const std::size_t first = sums.size(), ranks = static_cast<std::size_t>(context.count());
    sums.resize(first + 2 * ranks, 0.0);
    sums[first + static_cast<std::size_t>(context.rank())] = wall - seconds.total();
    sums[first + ranks + static_cast<std::size_t>(context.rank())] = double(simulation.scene().particles().owned());
    context.sum(sums);
    const auto work = std::minmax_element(sums.begin() + first, sums.begin() + first + ranks);
    const auto owned = std::minmax_element(sums.begin() + first + ranks, sums.end());
    char text[400];
    std::snprintf(text, sizeof text,
                  "ranks %d  communication %.1f%%  ghosts %.0f  (ghost exchange %.1f%%, agreement %.1f%%)  "
                  "overlapped %.0f  undone %.0f  work per rank %.3g-%.3g s  owned %.0f-%.0f",
                  context.count(), 100 * sums[0] / ranks / wall, sums[1], 100 * sums[2] / ranks / wall,
                  100 * sums[3] / ranks / wall, sums[4], sums[5], *work.first, *work.second, *owned.first,
                  *owned.second);
    return text;
}

}  // namespace talus
