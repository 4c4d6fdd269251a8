#include "Sampling/RankReport.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "Parallel/DomainSplit.h"
#include "Simulation.h"

namespace talus {

std::string describeRanks(const Simulation& simulation) {
    const DomainSplit::Timings& seconds = simulation.ranks().split()->seconds;
    std::vector<double> sums = {seconds.total(), double(simulation.scene().particles().ghostCount), seconds.ghosts,
                                seconds.agreement};
    simulation.ranks().sum(sums);
    const double ranks = simulation.ranks().count(), wall = std::max(simulation.lastRun().wallSeconds, 1e-300);
    char text[200];
    std::snprintf(text, sizeof text, "ranks %d  communication %.1f%%  ghosts %.0f  (ghost exchange %.1f%%, agreement %.1f%%)",
                  simulation.ranks().count(), 100 * sums[0] / ranks / wall, sums[1], 100 * sums[2] / ranks / wall,
                  100 * sums[3] / ranks / wall);
    return text;
}

}  // namespace talus
