// Hard cases for the stability limits of the time integration (Documentation/SpeedVsError.md,
// "Where the integration fails"; Drivers/Benchmarks/SpeedVsError/stabilityLimits.py):
//   --case size-ratio: a sphere --size-ratio times the diameter of the others (default 20, so
//     8000 times their mass) lowered onto two layers of them on a floor (--drop above them),
//     periodic along x and y;
//   --case fast-impact: spheres thrown onto a floor and onto each other at --impact 10 (ten times
//     the speed of a dense flow), with the Hertz-Mindlin law, whose collisions shorten as the
//     impact speed rises (its collision time for the time step is the one at speed 1 unless
//     --impact-speed says otherwise);
//   --case rattlers: a jammed packing, a simple cubic lattice of d = 1 spheres pressed together
//     (spacing 0.98, fully periodic, no gravity), with a sphere of diameter --rattler (0.3, 37
//     times lighter) loose in every cage, thrown about at speed 1. A sphere of the lattice has
//     six stiff contacts at once, so the lattice's fastest vibration is quicker than one pair's
//     collision (every pair type here collides in tc = --collision-time with e = 0.5).
// All with e = 0.5 and friction 0.5 between spheres of density 6/pi (d = 1 but the large sphere
// and the rattlers).
#include <cmath>
#include <string>

#include "Simulation.h"

using namespace talus;

class HardCases : public Simulation {
public:
    std::string which = "size-ratio";
    double sizeRatio = 20;
    double impact = 10;
    double drop = 0.01;
    double collisionTime = 0.001;
    double rattler = 0.3;
    double friction = 0.5;

    HardCases() {
        run().addTextFlag("case", "size-ratio, fast-impact or rattlers", which);
        run().addFlag("rattler", "rattlers case: the rattlers' diameter (default 0.3; the cage holds up to 0.7)", rattler);
        run().addFlag("friction", "rattlers case: the friction coefficient of every pair (default 0.5)", friction);
        run().addFlag("size-ratio", "size-ratio case: diameter of the large sphere (default 20)", sizeRatio);
        run().addFlag("impact", "fast-impact case: the speed of the thrown spheres (default 10)", impact);
        run().addFlag("drop", "size-ratio case: the gap under the large sphere at the start (default 0.01)", drop);
        run().addFlag("collision-time",
                      "size-ratio case: tc of two small spheres (default 0.001: stiff enough for the large one's weight)",
                      collisionTime);
    }

    void setupInitialConditions() override {
        require(which == "size-ratio" || which == "fast-impact" || which == "rattlers",
                "--case must be size-ratio, fast-impact or rattlers, got '" + which + "'");
        require(rattler > 0 && rattler < 0.7, "--rattler must lie in (0, 0.7): the cage of the lattice holds 0.73");
        require(friction >= 0, "--friction must not be negative");
        require(sizeRatio >= 1, "--size-ratio must be at least 1");
        require(impact > 0, "--impact must be positive");
        require(drop >= 0, "--drop must not be negative");
        require(collisionTime > 0, "--collision-time must be positive");
        if (which == "size-ratio")
            largeOnSmall();
        else if (which == "fast-impact")
            fastImpacts();
        else
            rattlersInAJammedLattice();
    }

private:
    // A lattice of d = 1 spheres, `layers` high from height z0, over the periodic square of side
    // `width`, each with velocity v plus a small random part.
    void lattice(std::size_t species, double width, int layers, double z0, const Vec3& v) {
        const double spacing = 1.05;
        const int side = static_cast<int>(std::floor(width / spacing));
        std::uniform_real_distribution<double> jiggle(-0.05, 0.05);
        for (int k = 0; k < side * side * layers; ++k) {
            const Vec3 site(k % side + 0.5, (k / side) % side + 0.5, k / (side * side));
            const Vec3 random(jiggle(scene().random()), jiggle(scene().random()), jiggle(scene().random()));
            scene().addParticle(Vec3(site.x() * spacing, site.y() * spacing, z0 + site.z() * spacing), 0.5, species,
                                v + random);
        }
    }

    void largeOnSmall() {
        const auto grains = scene().addSpecies(
            "grains", 6 / pi, LinearSpringDashpot::fromCollision(collisionTime, 0.5, 0.5).withFriction(0.5));
        const double width = 2 * sizeRatio + 2;  // (a periodic box twice the large diameter)
        scene().setDomain(Vec3::Zero(), Vec3(width, width, 4 * sizeRatio));
        scene().setPeriodic(true, true, false);
        scene().addWall(Vec3::UnitZ(), Vec3::Zero(), grains);
        lattice(grains, width, 2, 0.55, Vec3::Zero());
        // Lowered onto the bed (a gap of --drop): dropped from higher, its impact alone presses the
        // small spheres under it beyond the overlap check, whatever the step (SpeedVsError.md).
        scene().addParticle(Vec3(width / 2, width / 2, 0.55 + 1.05 + 0.5 + drop + sizeRatio / 2), sizeRatio / 2, grains);
    }

    void fastImpacts() {
        const auto grains = scene().addSpecies("grains", 6 / pi, HertzMindlin::fromMaterial(1e6, 0.3, 0.5).withFriction(0.5));
        const double width = 8;
        scene().setDomain(Vec3::Zero(), Vec3(width, width, 40));
        scene().setPeriodic(true, true, false);
        scene().addWall(Vec3::UnitZ(), Vec3::Zero(), grains);
        lattice(grains, width, 2, 0.55, Vec3::Zero());                 // a bed at rest
        lattice(grains, width, 4, 4, Vec3(0.3, 0.2, -1) * impact);     // thrown onto it
    }

    void rattlersInAJammedLattice() {
        // Every pair type collides in tc = --collision-time with e = 0.5 (each law timed for its
        // reduced mass), so N counts steps per collision alike for the lattice and the rattlers.
        const double rattlerMass = std::pow(rattler, 3);  // (density 6/pi; the lattice's spheres weigh 1)
        auto law = [&](double reducedMass) {
            return LinearSpringDashpot::fromCollision(collisionTime, 0.5, reducedMass).withFriction(friction);
        };
        const auto lattice = scene().addSpecies("lattice", 6 / pi, law(0.5));
        const auto rattlers = scene().addSpecies("rattlers", 6 / pi, law(rattlerMass / 2));
        scene().species().setPair(lattice, rattlers, law(rattlerMass / (1 + rattlerMass)));
        const int side = 5;
        const double spacing = 0.98;  // (each contact of the lattice 0.02 deep)
        scene().setGravity(Vec3::Zero());
        scene().setDomain(Vec3::Zero(), Vec3::Constant(side * spacing));
        scene().setPeriodic(true, true, true);
        std::normal_distribution<double> thermal(0, 1 / std::sqrt(3.0));
        for (int k = 0; k < side * side * side; ++k) {
            const Vec3 site = spacing * Vec3(k % side + 0.5, (k / side) % side + 0.5, k / (side * side) + 0.5);
            scene().addParticle(site, 0.5, lattice);
            const Vec3 throw_(thermal(scene().random()), thermal(scene().random()), thermal(scene().random()));
            scene().addParticle(site + Vec3::Constant(0.5 * spacing), rattler / 2, rattlers, throw_);
        }
    }
};

int main(int argc, char** argv) {
    HardCases cases;
    cases.settings().name = "HardCases";
    cases.settings().timeStep = RunSettings::automaticTimeStep;
    cases.settings().endTime = 4;
    cases.settings().outputInterval = 0.5;
    return cases.solve(argc, argv);
}
