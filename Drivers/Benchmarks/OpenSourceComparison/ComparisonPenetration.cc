// The penetration test of the 2024 comparison of open-source DEM codes (Dosta et al. 2024;
// Documentation/Benchmarks/OpenSourceComparison.md), in SI units.
//
// A steel box open at the top, its inner faces those of the published triangles (x = -0.049 and
// 0.049 m, y = -0.03 and 0.03 m, the floor at z = -0.0902431 m; planes, or the triangles themselves
// with --walls FILE: the comparison's Penetration/walls.txt, or an STL file), holds the published bed
// (--start-file: 25000 or 50000 spheres of M1 of diameter 2 mm, as placed, not settled again). A
// steel sphere of diameter 20 mm starts at (0, 0, 0.06) m, 0.15 m above the floor, moving down at
// 5 m/s (the published beds end with a line that describes it: skipped). Hertz-Mindlin contacts
// between the materials of the comparison (ComparisonInputs.h), gravity 9.8 m/s^2 along -z, the
// published step of 5e-7 s, for 0.1 s. Every --sample-interval the run writes the sphere's height
// above the floor and its vertical velocity into NAME.penetration, the quantity the comparison
// reports; at the end it says how deep the sphere went into the bed and when it came to rest.
#include <algorithm>
#include <cmath>
#include <string>

#include "ComparisonInputs.h"
#include "Sampling/Sampling.h"
#include "Simulation.h"

using namespace talus;

class ComparisonPenetration : public Simulation {
public:
    std::string startFile = std::string(TALUS_SHARED_DIR) + "/peers/os-benchmark/Penetration/25KParticles.txt";
    std::string walls = "smooth";
    double sampleInterval = 5e-4;
    double restSpeed = 0.01;

    static constexpr double halfWidthX = 0.049, halfWidthY = 0.03, floor = -0.0902431, gravity = 9.8;
    static constexpr double sphereRadius = 0.01, startHeight = 0.06, startSpeed = 5;

    ComparisonPenetration() {
        run().addTextFlag("start-file", "the published bed: a header, then 'radius x y z' per line (m), then the sphere's line",
                          startFile);
        run().addFlag("sample-interval", "time between the sphere's heights written to NAME.penetration (s)", sampleInterval);
        run().addFlag("rest-speed", "the sphere is at rest once its speed stays below this (m/s)", restSpeed);
        run().addTextFlag("walls", "smooth (planes) or a file of the box's triangles (table or STL)", walls);
        heights_.setPrecision(10);  // (the free flight to round-off in the self-test)
        run().keepInRestart("penetration.bedSurface", bedSurface_);
        run().keepInRestart("penetration.lowest", lowest_);
        run().keepInRestart("penetration.lowestTime", lowestTime_);
        run().keepInRestart("penetration.restSince", restSince_);
    }

    void setupInitialConditions() override {
        require(sampleInterval > 0, "--sample-interval must be positive, got " + str(sampleInterval));
        require(restSpeed > 0, "--rest-speed must be positive, got " + str(restSpeed));
        scene().setGravity(Vec3(0, 0, -gravity));
        scene().setDomain(Vec3(-halfWidthX, -halfWidthY, floor), Vec3(halfWidthX, halfWidthY, startHeight + 2 * sphereRadius));
        // The fastest impact: the steel sphere's, 5 m/s and a little more after its fall.
        const std::vector<std::size_t> species = comparison::materials(false).addTo(scene().species(), 5.5);
        const std::size_t M1 = species[0], steel = species[2];
        if (walls == "smooth") {
            scene().addOpenBox(Vec3(-halfWidthX, -halfWidthY, floor),
                               Vec3(halfWidthX, halfWidthY, startHeight + 2 * sphereRadius), steel);
        } else {
            TriangleMesh box = comparison::readWallTriangles(walls);
            require(std::abs(box.lo().z() - floor) < 0.005, "--walls " + walls + ": its lowest point (z = " +
                                                                str(box.lo().z()) + " m) is not under the floor (z = " +
                                                                str(floor) + " m)");
            scene().addMeshWall(std::move(box), steel);
        }
        double bedTop = floor;
        for (const comparison::StartParticle& p : comparison::readStartParticles(startFile, /*lastLineIsNotABead*/ true)) {
            scene().addParticle(p.position, p.radius, M1);
            // The bed's surface under the sphere: the highest bead top within its footprint.
            if (std::hypot(p.position[0], p.position[1]) < sphereRadius) bedTop = std::max(bedTop, p.position[2] + p.radius);
        }
        bedSurface_ = bedTop - floor;
        steel_ = steel;
        scene().addParticle(Vec3(0, 0, startHeight), sphereRadius, steel, Vec3(0, 0, -startSpeed));
        writeHeight();  // (t = 0)
    }

    void actionsAfterTimeStep() override {
        const auto [height, velocity] = sphere();
        if (height < lowest_) lowest_ = height, lowestTime_ = time();
        if (std::abs(velocity) >= restSpeed || height > bedSurface_) restSince_ = -1;
        else if (restSince_ < 0) restSince_ = time();
        if (clock_.every(sampleInterval)) writeHeight();
    }

    void actionsAfterSolve() override {
        const auto [height, velocity] = sphere();
        say(*this, "penetration: bed surface under the sphere %.5f m above the floor; the sphere's bottom went %.5f m into it"
                   " (deepest at t = %.5f s); at the end its centre is %.5f m above the floor, moving at %.4f m/s; %s\n",
            bedSurface_, bedSurface_ - (lowest_ - sphereRadius), lowestTime_, height, velocity,
            restSince_ >= 0 ? ("at rest (speed below " + str(restSpeed) + " m/s) since t = " + str(restSince_) + " s").c_str()
                            : "not at rest");
    }

private:
    // The steel sphere's height above the floor and its vertical velocity (a sum over the one
    // steel particle, on whichever rank holds it).
    std::pair<double, double> sphere() const {
        const std::vector<double> s = sumsOver(*this, ofSpecies(steel_),
                                               {[](const ParticleStore& p, std::size_t i) { return p.position[i][2]; },
                                                [](const ParticleStore& p, std::size_t i) { return p.velocity[i][2]; }});
        return {s[0] - floor, s[1]};
    }
    void writeHeight() {
        const auto [height, velocity] = sphere();
        heights_.write({time(), height, velocity});
    }

    std::size_t steel_ = 2;
    double bedSurface_ = 0, lowest_ = 1e300, lowestTime_ = 0, restSince_ = -1;
    SamplingClock clock_{*this, "penetration"};
    SeriesFile heights_{*this, "penetration", {"t", "height", "vz"},
                        "the steel sphere's centre above the floor (m) and its vertical velocity (m/s); t in s"};
};

int main(int argc, char** argv) {
    ComparisonPenetration penetration;
    penetration.settings().name = "ComparisonPenetration";
    penetration.settings().timeStep = 5e-7;
    penetration.settings().endTime = 0.1;
    penetration.settings().outputInterval = 0.01;
    // On the shallow bed the sphere reaches the floor and presses beads of 1 GPa onto the steel:
    // Hertz's law then asks overlaps beyond the default limit of a quarter of the bead's radius
    // (the energy of the sphere's 30 g at 2 m/s, taken by one bead on the floor, is an overlap of
    // about half its radius), though every collision is resolved by the step. Up to the radius.
    penetration.settings().maxOverlapFraction = 1;
    return penetration.solve(argc, argv);
}
