// The rotating drum of the 2024 comparison of open-source DEM codes (Dosta et al. 2024;
// Documentation/Benchmarks/OpenSourceComparison.md), in SI units.
//
// A drum of radius 0.1 m with its axis along y, closed by plane walls at y = -0.03 and 0.03 m, all
// of steel, turns at 2 rad/s about -y (the bottom moves towards +x): smooth walls (a cylinder and
// two planes), or the published triangles turning with the drum (--walls FILE: the comparison's
// Drum/walls.txt, or an STL file). It holds the published start
// positions (--start-file): 30000 spheres of M1 of diameter 2 mm and 8000 of M2 of diameter 4 mm,
// Hertz-Mindlin contacts between the materials of the comparison (ComparisonInputs.h), gravity
// 9.8 m/s^2 along -z. The soft variant (E = 2e6 and 1e6 Pa, the default) runs at dt = 5e-5 s, half
// the published step, at which Talus's run blows up (Documentation/Benchmarks/OpenSourceComparison.md;
// --dt 1e-4 repeats it); the stiff one (E = 1e9 and 0.5e9 Pa) at the published 8e-7 s
// (--variant stiff --dt 8e-7); for 5 s.
// Every 0.1 s the run counts the particles of each size in zone 1 (x > 0 and z > 0) and zone 2
// (x < 0 and z < 0), the quantity the comparison reports, into NAME.zones.
#include <cmath>
#include <string>

#include "ComparisonInputs.h"
#include "Sampling/Sampling.h"
#include "Simulation.h"

using namespace talus;

class ComparisonDrum : public Simulation {
public:
    std::string startFile = std::string(TALUS_SHARED_DIR) + "/peers/os-benchmark/Drum/PartCoordinates.txt";
    std::string variant = "soft", walls = "smooth";
    double sampleInterval = 0.1;

    static constexpr double radius = 0.1, halfLength = 0.03, angularSpeed = 2, gravity = 9.8;

    ComparisonDrum() {
        run().addTextFlag("start-file", "the published start positions: a header, then 'radius x y z' per line (m)",
                          startFile);
        run().addTextFlag("variant", "soft (E = 2e6 and 1e6 Pa) or stiff (E = 1e9 and 0.5e9 Pa, needs --dt 8e-7)",
                          variant);
        run().addFlag("sample-interval", "time between the zone counts written to NAME.zones (s)", sampleInterval);
        run().addTextFlag("walls", "smooth (a cylinder and two planes) or a file of the drum's triangles (table or STL)", walls);
    }

    void setupInitialConditions() override {
        require(variant == "soft" || variant == "stiff", "--variant must be soft or stiff, got '" + variant + "'");
        require(sampleInterval > 0, "--sample-interval must be positive, got " + str(sampleInterval));
        scene().setGravity(Vec3(0, 0, -gravity));
        scene().setDomain(Vec3(-1.1 * radius, -halfLength - 0.005, -1.1 * radius),
                          Vec3(1.1 * radius, halfLength + 0.005, 1.1 * radius));
        // The fastest impacts: the drum's rim (0.2 m/s) and a bead dropping across the bed's
        // surface layer, well under 0.5 m/s.
        const std::vector<std::size_t> species = comparison::materials(variant == "soft").addTo(scene().species(), 0.5);
        const std::size_t M1 = species[0], M2 = species[1], steel = species[2];
        const int turning = static_cast<int>(scene().addMotion({.angularVelocity = Vec3(0, -angularSpeed, 0)}));
        if (walls == "smooth") {
            scene().addCylinderWall(Vec3::Zero(), Vec3::UnitY(), radius, steel, turning);
            scene().addWall(Vec3::UnitY(), Vec3(0, -halfLength, 0), steel, turning);
            scene().addWall(-Vec3::UnitY(), Vec3(0, halfLength, 0), steel, turning);
        } else {
            TriangleMesh mesh = comparison::readWallTriangles(walls);
            require(std::abs(mesh.lo().y() + halfLength) < 0.01 && std::abs(mesh.hi().y() - halfLength) < 0.01,
                    "--walls " + walls + ": its triangles span y = " + str(mesh.lo().y()) + " to " + str(mesh.hi().y()) +
                        " m, not the drum's " + str(-halfLength) + " to " + str(halfLength) + " m");
            scene().addMeshWall(std::move(mesh), steel, turning);
        }
        for (const comparison::StartParticle& p : comparison::readStartParticles(startFile))
            scene().addParticle(p.position, p.radius, p.radius < 1.5e-3 ? M1 : M2);
        small_ = M1, large_ = M2;
        writeZoneCounts();  // (t = 0: the start file's)
    }

    void actionsAfterTimeStep() override {
        if (clock_.every(sampleInterval)) writeZoneCounts();
    }

private:
    void writeZoneCounts() {
        const auto count = [&](std::size_t species, const Vec3& lo, const Vec3& hi) {
            return static_cast<long long>(std::lround(totalsOver(*this, both(ofSpecies(species), inBox(lo, hi))).count));
        };
        const Vec3 upperRight(0, -1, 0), farUpperRight(1, 1, 1), farLowerLeft(-1, -1, -1), lowerLeft(0, 1, 0);
        zones_.write({time(), count(small_, upperRight, farUpperRight), count(large_, upperRight, farUpperRight),
                      count(small_, farLowerLeft, lowerLeft), count(large_, farLowerLeft, lowerLeft)});
    }

    std::size_t small_ = 0, large_ = 1;  // (the species of M1 and M2: the first two addTo adds)
    SamplingClock clock_{*this, "zones"};
    SeriesFile zones_{*this, "zones", {"t", "zone1_d2mm", "zone1_d4mm", "zone2_d2mm", "zone2_d4mm"},
                      "particles per size in zone 1 (x > 0, z > 0) and zone 2 (x < 0, z < 0); t in s"};
};

int main(int argc, char** argv) {
    ComparisonDrum drum;
    drum.settings().name = "ComparisonDrum";
    drum.settings().timeStep = 5e-5;
    drum.settings().endTime = 5;
    drum.settings().outputInterval = 0.1;
    // The published soft step (1e-4 s) is a quarter of the shortest collision (an M1 bead on steel
    // at 0.5 m/s, 4.0e-4 s), beyond Talus's default bound of a tenth: allowed up to 0.3, so that
    // the comparison's step can be run.
    drum.settings().largestStepFraction = 0.3;
    // Beads move up to 0.2 m/s, 2e-5 m a step: a skin of the small radius (the automatic one is
    // 0.2 of it) lists the pairs anew every 30 steps rather than every 6, 1.5 times faster.
    drum.settings().skin = 1e-3;
    return drum.solve(argc, argv);
}
