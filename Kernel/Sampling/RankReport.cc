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
    context.sum(sums);
    const double ranks = context.count(), wall = std::max(simulation.lastRun().wallSeconds, 1e-300);
    char text[300];
    std::snprintf(text, sizeof text,
                  "ranks %d  communication %.1f%%  ghosts %.0f  (ghost exchange %.1f%%, agreement %.1f%%)  "
                  "overlapped %.0f  undone %.0f",
                  context.count(), 100 * sums[0] / ranks / wall, sums[1], 100 * sums[2] / ranks / wall,
                  100 * sums[3] / ranks / wall, sums[4], sums[5]);
    return text;
}

}  // namespace talus
