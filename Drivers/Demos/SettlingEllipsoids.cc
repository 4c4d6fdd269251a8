// Demo 4 (Documentation/Superquadrics/SettlingEllipsoids.md): ellipsoids of aspect ratio 2
// settling in a box (issue 6; Theory/Superquadrics.md).
//
// Methods. N prolate ellipsoids of semi-axes a = 0.5 and b = c = a/aspect (--aspect, default 2),
// density 6/pi, start on a loose lattice at random orientations with small random velocities in a
// square box with a floor and four side walls, and settle under gravity g = 1. The linear
// spring-dashpot law has tc = 0.005 and e = 0.5 for two ellipsoids (its stiffness and damping from
// their reduced mass), kt = 2/7 kn and sliding friction 0.5; contacts are found by the exact stage
// of Theory/Superquadrics.md eq. (5)-(8) (Contacts/SuperquadricContact.h) and the ellipsoids turn
// as rigid bodies (Particles/RigidBodyRotation.h). With --blockiness e < 1 the particles are
// superquadric blocks of the same semi-axes (e1 = e2 = e). The .ene file shows the kinetic energy
// decaying to rest; ParaView shows the .pvd file with the ShapeTensor glyphs
// (Documentation/FileFormats/vtu.md). --spheres 1 runs the same scene with spheres of the same
// volume, for the cost comparison of Documentation/Superquadrics/Superquadrics.md.
#include <cmath>
#include <random>

#include "Simulation.h"

using namespace talus;

class SettlingEllipsoids : public Simulation {
public:
    int particleCount = 500;
    double width = 6, aspect = 2, blockiness = 1;
    int spheres = 0;  // 1: spheres of the same volume instead (for the cost comparison)

    SettlingEllipsoids() {
        run().addFlag("particles", "number of particles", particleCount);
        run().addFlag("width", "width of the square box", width);
        run().addFlag("aspect", "ratio of the long semi-axis to the two short ones", aspect);
        run().addFlag("blockiness", "e1 = e2 of the superquadric (1: ellipsoids)", blockiness);
        run().addFlag("spheres", "1: spheres of the same volume instead, on the sphere path (cost comparison)", spheres);
    }

    void setupInitialConditions() override {
        require(particleCount > 0, "--particles must be positive, got " + std::to_string(particleCount));
        require(aspect >= 1, "--aspect must be at least 1, got " + str(aspect));
        require(width >= 2, "--width must be at least 2, got " + str(width));
        const Superquadric shape(0.5, 0.5 / aspect, 0.5 / aspect, blockiness, blockiness);
        const std::size_t particleShape = scene().addShape(shape);
        const double density = 6 / pi, mass = density * shape.volume();
        const auto grains = scene().addSpecies("grains", density,
                                       LinearSpringDashpot::fromCollision(0.005, 0.5, mass / 2).withFriction(0.5));

        scene().setGravity(Vec3(0, 0, -1));
        const double spacing = 2 * shape.boundingRadius() * 1.1;  // bounding spheres apart
        const int perLayer = static_cast<int>(std::floor(width / spacing));
        require(perLayer >= 1, "--width " + str(width) + " is narrower than one particle");
        const double height = spacing * (particleCount / (perLayer * perLayer) + 2);
        scene().setDomain(Vec3::Zero(), Vec3(width, width, height));
        scene().addOpenBox(Vec3::Zero(), Vec3(width, width, 0), grains);  // floor and four sides

        std::uniform_real_distribution<double> jiggle(-0.1, 0.1);
        std::normal_distribution<double> gauss;
        for (int k = 0; k < particleCount; ++k) {
            const int ix = k % perLayer, iy = (k / perLayer) % perLayer, iz = k / (perLayer * perLayer);
            const Vec3 position = Vec3(ix + 0.5, iy + 0.5, iz + 0.5) * spacing;
            const Quat orientation = Quat(gauss(scene().random()), gauss(scene().random()), gauss(scene().random()), gauss(scene().random())).normalized();
            const Vec3 velocity(jiggle(scene().random()), jiggle(scene().random()), jiggle(scene().random()));
            if (spheres)
                scene().addParticle(position, std::cbrt(shape.volume() * 3 / (4 * pi)), grains, velocity);
            else
                scene().addSuperquadric(position, particleShape, grains, orientation, velocity);
        }
    }
};

int main(int argc, char** argv) {
    SettlingEllipsoids packing;
    packing.settings().name = "SettlingEllipsoids";
    packing.settings().timeStep = 1e-4;  // tc / 50
    packing.settings().endTime = 10;
    packing.settings().outputInterval = 0.5;
    return packing.solve(argc, argv);
}
