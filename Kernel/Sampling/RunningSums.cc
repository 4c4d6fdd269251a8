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

void RunningSums::addStepIntegral(std::size_t k, const Selection& selection, const ParticleQuantity& quantity) {
    const ParticleStore& p = simulation_.scene().particles();
    const double dt = simulation_.settings().timeStep;
    double& part = unsummed_.at(k);
    for (std::size_t i = 0; i < p.owned(); ++i)
        if (selection(p, i)) part += quantity(p, i) * dt;
}

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
