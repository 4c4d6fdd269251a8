// Speed against error (Documentation/SpeedVsError.md, "Energy of an elastic packing"): spheres
// of diameters 0.8 to 1.2 in a periodic box without gravity, frictionless and perfectly elastic
// (linear law, e = 1: no dashpot), started on a lattice with random velocities, so that they
// collide tens of times each while the total energy (kinetic and elastic, NAME.ene) must stay
// what it was. How far it strays over the run measures the time integration alone; the contact's
// ends treated (the default) or integrated as plain velocity Verlet (--plain-verlet 1).
#include <cmath>

#include "Simulation.h"

using namespace talus;

class ElasticPacking : public Simulation {
public:
    int particleCount = 500;
    double spacing = 1.3;          // of the lattice, in mean diameters (solid fraction about 0.24)
    double collisionTime = 0.005;  // between two d = 1 spheres
    int plainVerlet = 0;

    ElasticPacking() {
        run().addFlag("particles", "number of spheres (default 500)", particleCount);
        run().addFlag("spacing", "lattice spacing at the start, in mean diameters (default 1.3)", spacing);
        run().addFlag("collision-time", "collision time tc between two d = 1 spheres (default 0.005)", collisionTime);
        run().addFlag("plain-verlet", "1: integrate the contact's ends as plain velocity Verlet", plainVerlet);
    }

    void setupInitialConditions() override {
        require(particleCount > 0, "--particles must be positive");
        require(spacing >= 1.25, "--spacing must be at least 1.25 (the largest diameter 1.2 and a gap)");
        auto law = LinearSpringDashpot::fromCollision(collisionTime, 1.0, 0.5);
        law.treatContactEnds = !plainVerlet;
        const auto grains = scene().addSpecies("grains", 6 / pi, law);
        scene().setGravity(Vec3::Zero());
        const int side = static_cast<int>(std::ceil(std::cbrt(particleCount)));
        const double width = side * spacing;
        scene().setDomain(Vec3::Zero(), Vec3(width, width, width));
        scene().setPeriodic(true, true, true);
        std::uniform_real_distribution<double> diameter(0.8, 1.2), speed(-1, 1);
        for (int k = 0; k < particleCount; ++k) {
            const Vec3 site(k % side, (k / side) % side, k / (side * side));
            const Vec3 velocity(speed(scene().random()), speed(scene().random()), speed(scene().random()));
            scene().addParticle((site + Vec3(0.5, 0.5, 0.5)) * spacing, diameter(scene().random()) / 2, grains, velocity);
        }
    }
};

int main(int argc, char** argv) {
    ElasticPacking packing;
    packing.settings().name = "ElasticPacking";
    packing.settings().timeStep = RunSettings::automaticTimeStep;  // tc/50 of the lightest pair, or --dt
    packing.settings().endTime = 2;
    packing.settings().outputInterval = 0.1;
    return packing.solve(argc, argv);
}
