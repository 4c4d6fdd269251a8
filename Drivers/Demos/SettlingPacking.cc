// Demo 3 (Documentation/Tutorials/SettlingPacking.md): a polydisperse packing settling in a box.
//
// N spheres with diameters uniform in [0.8, 1.2] (density 6/pi, so a d = 1 sphere has mass 1)
// start on a loose cubic lattice with small random velocities in a box of four side walls
// and a floor, and settle under gravity g = 1. The linear spring-dashpot law has tc = 0.005 and
// e = 0.5 for two d = 1 spheres, kt = 2/7 kn and sliding friction --friction (0.5; 0: a
// frictionless packing, which runs the contacts without their tangential part). The .ene file shows the
// kinetic energy decaying to rest; ParaView shows the .pvd file.
#include <cmath>
#include <random>

#include "Simulation.h"

using namespace talus;

class SettlingPacking : public Simulation {
public:
    int particleCount = 2000;
    double width = 10;  // of the square box, in mean diameters
    double friction = 0.5;

    SettlingPacking() {
        run().addFlag("particles", "number of spheres", particleCount);
        run().addFlag("width", "width of the square box", width);
        run().addFlag("friction", "sliding friction of every contact, the walls' included", friction);
    }

    void setupInitialConditions() override {
        require(particleCount > 0, "--particles must be positive");
        require(width >= 2, "--width must be at least 2");
        require(friction >= 0, "--friction must not be negative, got " + str(friction));
        const double unitMass = 1;  // collision parameters for two d = 1 spheres
        auto law = LinearSpringDashpot::fromCollision(0.005, 0.5, unitMass / 2).withFriction(friction);
        const auto grains = scene().addSpecies("grains", 6 / pi, law);

        scene().setGravity(Vec3(0, 0, -1));
        const double spacing = 1.3;  // lattice spacing, above the largest diameter
        const int perLayer = static_cast<int>(std::floor(width / spacing));
        const double height = spacing * (particleCount / (perLayer * perLayer) + 2);
        scene().setDomain(Vec3::Zero(), Vec3(width, width, height));
        scene().addOpenBox(Vec3::Zero(), Vec3(width, width, 0), grains);  // floor and four sides

        std::uniform_real_distribution<double> diameter(0.8, 1.2), jiggle(-0.1, 0.1);
        for (int k = 0; k < particleCount; ++k) {
            const int ix = k % perLayer, iy = (k / perLayer) % perLayer, iz = k / (perLayer * perLayer);
            const Vec3 position = Vec3(ix + 0.5, iy + 0.5, iz + 0.5) * spacing + Vec3(0.1, 0.1, 0.1);
            const Vec3 velocity(jiggle(scene().random()), jiggle(scene().random()), jiggle(scene().random()));
            scene().addParticle(position, diameter(scene().random()) / 2, grains, velocity);
        }
    }
};

int main(int argc, char** argv) {
    SettlingPacking packing;
    packing.settings().name = "SettlingPacking";
    packing.settings().timeStep = 1e-4;  // about tc / 50 for the lightest pair
    packing.settings().endTime = 20;
    packing.settings().outputInterval = 0.5;
    return packing.solve(argc, argv);
}
