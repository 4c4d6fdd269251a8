// How a run used its ranks, for a benchmark's summary line: the rank count, the share of the
// time loop's wall time spent on the domain split's communication (its mean over the ranks),
// of it the ghost exchange and the agreement of all ranks, the ghosts over all ranks, and the
// steps of all ranks that computed their interior pairs while the ghosts travelled, and of those
// the ones undone because another rank rebuilt the list (RankContext::updateNeighbourhood);
// the least and most work of a rank (its wall time less its communication: the imbalance) and
// the fewest and most particles a rank owns at the end.
// Collective: every rank calls it; the text is the same on all.
#pragma once

#include <string>

namespace talus {

class Simulation;

// "ranks N  communication C%  ghosts G  (ghost exchange X%, agreement A%)  overlapped S  undone U
//  work per rank W0-W1 s  owned P0-P1"
std::string describeRanks(const Simulation& simulation);

}  // namespace talus
