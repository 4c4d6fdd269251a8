// Totals that grow every step (the mass a flow carries through a section, integrated over time;
// events counted per step), for a driver: each rank adds what its own particles contribute, and
// the ranks' parts are summed into the totals when the driver reads them (at a sample), so that
// a step costs no collective. The totals are kept in the restart file (keepInRestart, "NAME"):
// at a save the parts not yet summed are summed in first, on every rank at once, so that the run
// and its restart go on from the same totals.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "Sampling/ParticleSums.h"

namespace talus {

class Simulation;

class RunningSums {
public:
    // `count` totals, all 0 at the start; call from the driver's constructor.
    RunningSums(Simulation& simulation, const std::string& name, std::size_t count);
    RunningSums(const RunningSums&) = delete;
    RunningSums& operator=(const RunningSums&) = delete;

    // Adds a number to this rank's part of total k (a number this rank alone knows).
    void add(std::size_t k, double value) { unsummed_.at(k) += value; }
    // Adds the time integral over this step, dt q, of quantity q of each selected particle this
    // rank owns (dt: the simulation's time step), to this rank's part of total k. Any callables
    // with the signatures of Selection and ParticleQuantity: lambdas are inlined into the loop (a
    // step's pass over every particle then costs no call per particle; a std::function costs two).
    template <class Select, class Quantity>
    void addStepIntegral(std::size_t k, const Select& selection, const Quantity& quantity) {
        const ParticleStore& p = particles();
        const double dt = timeStep();
        double& part = unsummed_.at(k);
        for (std::size_t i = 0; i < p.owned(); ++i)
            if (selection(p, i)) part += quantity(p, i) * dt;
    }
    // The totals over all ranks (collective: every rank calls it at the same point).
    const std::vector<double>& totals();

private:
    void sumParts();
    const ParticleStore& particles() const;
    double timeStep() const;

    Simulation& simulation_;
    std::vector<double> totals_, unsummed_;
};

}  // namespace talus
