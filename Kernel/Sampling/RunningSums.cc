#include "Sampling/RunningSums.h"

#include "Simulation.h"

namespace talus {

RunningSums::RunningSums(Simulation& simulation, const std::string& name, std::size_t count)
    : simulation_(simulation), totals_(count, 0.0), unsummed_(count, 0.0) {
    simulation_.run().keepInRestart(name, [this] { return sumParts(), totals_; },
                              [this, name](const std::vector<double>& saved) {
                                  require(saved.size() == totals_.size(),
                                          "restart file: '" + name + "' holds " + std::to_string(saved.size()) +
                                              " totals, not " + std::to_string(totals_.size()));
                                  totals_ = saved;
                                  unsummed_.assign(totals_.size(), 0.0);
                              });
}

const ParticleStore& RunningSums::particles() const { return simulation_.scene().particles(); }

double RunningSums::timeStep() const { return simulation_.settings().timeStep; }

void RunningSums::sumParts() {
    simulation_.ranks().sum(unsummed_);
    for (std::size_t k = 0; k < totals_.size(); ++k) totals_[k] += unsummed_[k];
    unsummed_.assign(totals_.size(), 0.0);
}

const std::vector<double>& RunningSums::totals() {
    sumParts();
    return totals_;
}

}  // namespace talus
