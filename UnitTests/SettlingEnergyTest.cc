// A frictionless packing settling under gravity in a box of walls, driven through
// talus::Simulation: with dissipative contacts (e < 1) the total energy
// (gravitational + kinetic + rotational + elastic, Simulation::energies()) can only decrease.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "ContactTestScenes.h"

using namespace talus;
using namespace talus::test;

TEST(SettlingPacking, TotalEnergyDecreasesMonotonically) {
    const double collisionTime = 0.005, timeStep = collisionTime / 50, spacing = 1.2, side = 3 * spacing;
    const double smallRadius = 0.4, largeRadius = 0.5;
    // The lightest pair sets the shortest collision time (Theory/ContactLaws.md eq. (9)-(10)
    // formulas with its m*).
    const double lightestPairMass = 0.5 * sphereMass(smallRadius);
    LinearSpringDashpot law = LinearSpringDashpot::fromCollision(collisionTime, 0.5, lightestPairMass);
    // Frictionless: no tangential spring at all. (With mu = 0 but kt > 0 the Coulomb cap would
    // store xi = -gt vt/kt and report 1/2 kt xi^2 as elastic energy although ft = 0.)
    law.tangentialStiffness = law.tangentialDamping = law.friction = 0;

    TestScene scene;
    scene.setup = [&](TestScene& s) {
        s.scene().setGravity(Vec3(0, 0, -1));
        s.scene().setDomain(Vec3::Zero(), Vec3(side, side, 7 * spacing));
        const auto species = s.scene().addSpecies("glass", unitMassDensity, law);
        addOpenBox(s, side, species);
        // 45 spheres on a loose lattice, polydisperse and with random velocities so that they
        // do not stack into a crystal.
        std::mt19937_64 random(7);
        std::uniform_real_distribution<double> radiusOf(smallRadius, largeRadius), velocityOf(-0.5, 0.5);
        for (int k = 0; k < 5; ++k)
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i)
                    s.scene().addParticle(spacing * Vec3(i + 0.5, j + 0.5, k + 0.5), radiusOf(random), species,
                                  Vec3(velocityOf(random), velocityOf(random), velocityOf(random)));
    };
    // The elastic energy is summed from the contact records, which the kernel makes only on
    // output steps: an output interval of one step (with files off) makes every step one.
    scene.settings().outputInterval = timeStep;
    // Check every 2 tc: each collision dissipates a fraction 1 - e^2 = 75% of its relative
    // kinetic energy within tc, far more than the O((dt/tc)^2) energy error of velocity Verlet
    // at contact onset and separation, which shorter intervals could catch alone.
    const int checkEvery = 100;
    // Velocity Verlet conserves a shadow energy, not the energy itself: in lasting contacts the
    // energy fluctuates by about (w dt)^2 = (pi dt/tc)^2 times the elastic energy stored. Once the
    // packing is nearly at rest, dissipation no longer outweighs that fluctuation, so an increase
    // counts only if it exceeds this bound (measured increases: below 1e-7 of it).
    const double fluctuation = std::pow(pi * timeStep / collisionTime, 2);
    std::vector<double> totals, allowed;
    scene.afterStep = [&](TestScene& s) {
        if (s.step() % checkEvery != 0) return;
        const Energies e = s.energies();
        totals.push_back(e.total());
        allowed.push_back(fluctuation * e.elastic);
    };
    scene.runFor(timeStep, 20);

    int increases = 0;
    double worstIncrease = 0;
    for (std::size_t k = 1; k < totals.size(); ++k) {
        const double increase = (totals[k] - totals[k - 1]) / std::abs(totals[k - 1]);
        if (totals[k] - totals[k - 1] > allowed[k] + 1e-12 * std::abs(totals[k - 1])) {
            if (increases == 0) std::printf("[ measured ] first increase at t = %.3f\n", k * checkEvery * timeStep);
            ++increases;
            worstIncrease = std::max(worstIncrease, increase);
        }
    }
    const Energies final = scene.energies();
    std::printf("[ measured ] settling: %d increases of %zu intervals, worst %.2e; E %.4f -> %.4f, final KE %.2e\n",
                increases, totals.size() - 1, worstIncrease, totals.front(), totals.back(), final.kinetic);
    EXPECT_EQ(increases, 0) << "worst relative increase " << worstIncrease;
    // It did settle: almost all of the initial energy above the final state is gone. A frictionless
    // packing keeps rearranging slowly for long (its energy still falling); trajectories that
    // differ only by round-off ended at t = 20 with KE from 7e-8 to 6e-4, that is 1e-9 to 1e-5 of
    // the energy dissipated, against a peak KE of 26.
    EXPECT_LT(final.kinetic, 1e-4 * (totals.front() - totals.back()));
}
