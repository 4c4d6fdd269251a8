// The silo discharge of the 2024 comparison of open-source DEM codes (Dosta et al. 2024;
// Documentation/Benchmarks/OpenSourceComparison.md), in SI units.
//
// A steel silo, a cylinder of radius 0.1 m over a 45-degree cone down to a circular orifice
// (--orifice small: radius 0.02 m; large: 0.03 m), smooth: a surface of revolution whose profile
// is the inner face of the published triangles, or those triangles themselves (--walls FILE: the
// comparison's Silo/walls-*-orifice.txt, or an STL file). Closed by a lid at the orifice, it is filled
// with --particles spheres of diameter 4 mm of --material M1 or M2 (100000 in the comparison),
// dropped from random places in a column above the cone (the comparison gives no start
// positions), which settle until --open-time. Then the lid is taken away and the silo drains;
// particles 2 cm below the orifice leave the run. Hertz-Mindlin contacts between the materials of
// the comparison (ComparisonInputs.h), gravity 9.8 m/s^2 along -z, the published step 1.5e-6 s
// for M1 (2e-6 s for M2: give --dt), 5 s of discharge. Every --sample-interval the run writes
// the discharged mass into NAME.discharge, the quantity the comparison reports (its slope the
// mass flow rate, which plotComparisonSilo.py sets against Beverloo's law).
#include <cmath>
#include <string>

#include "Boundaries/DeletionBoundary.h"
#include "Boundaries/Filling.h"
#include "ComparisonInputs.h"
#include "Sampling/Sampling.h"
#include "Simulation.h"

using namespace talus;

class ComparisonSilo : public Simulation {
public:
    std::string orifice = "small", material = "M1", walls = "smooth";
    int particles = 100000;
    double openTime = 0.5, sampleInterval = 0.01, fillingPacking = 0.2;
    int soft = 0;

    // The inner face of the published silo (Silo/walls-*-orifice.txt): the orifice plane's height
    // and radius; the cone rises at 45 degrees to the cylinder, which stands 0.3 m high.
    static constexpr double siloRadius = 0.1, siloHeight = 0.3, gravity = 9.8, diameter = 0.004, outletDrop = 0.02;
    double orificeRadius() const { return orifice == "small" ? 0.02 : 0.03; }
    double orificeHeight() const { return orifice == "small" ? -0.0593008 : -0.0554222; }
    double coneTop() const { return orificeHeight() + (siloRadius - orificeRadius()); }

    ComparisonSilo() {
        run().addTextFlag("orifice", "small (radius 0.02 m) or large (0.03 m)", orifice);
        run().addTextFlag("material", "M1 or M2, the particles' material", material);
        run().addTextFlag("walls", "smooth (a surface of revolution) or a file of the silo's triangles (table or STL)", walls);
        run().addFlag("particles", "spheres of diameter 4 mm to fill in", particles);
        run().addFlag("open-time", "when the lid is taken away (s): the filling settles until then", openTime);
        run().addFlag("sample-interval", "time between the discharged masses written to NAME.discharge (s)", sampleInterval);
        run().addFlag("filling-packing", "solid fraction of the column the spheres are dropped from", fillingPacking);
        run().addFlag("soft", "1: the soft materials (E 2e6 and 1e6 Pa) for a larger step, as the drum's soft variant",
                      soft);
        run().keepInRestart("silo.opened", opened_);
        discharge_.setPrecision(15);  // (the self-test adds the two masses up to round-off)
    }

    // The lid is the first wall, the silo's two segments follow it.
    static constexpr std::size_t lid = 0;

    void setupInitialConditions() override {
        require(orifice == "small" || orifice == "large", "--orifice must be small or large, got '" + orifice + "'");
        require(material == "M1" || material == "M2", "--material must be M1 or M2, got '" + material + "'");
        require(particles > 0, "--particles must be positive, got " + std::to_string(particles));
        require(openTime >= 0, "--open-time must not be negative, got " + str(openTime));
        require(sampleInterval > 0, "--sample-interval must be positive, got " + str(sampleInterval));
        require(fillingPacking > 0 && fillingPacking < 0.5,
                "--filling-packing must be in (0, 0.5), got " + str(fillingPacking));
        scene().setGravity(Vec3(0, 0, -gravity));
        // The column the spheres are dropped from: inside the cylinder, from the cone's top up.
        const double columnRadius = siloRadius - 0.5 * diameter, sphereVolume = pi / 6 * std::pow(diameter, 3);
        // (Its ends keep the centres a radius in: a diameter more than the spheres' volume asks.)
        const double columnHeight =
            particles * sphereVolume / (fillingPacking * pi * columnRadius * columnRadius) + diameter;
        const double top = std::max(coneTop() + siloHeight, coneTop() + columnHeight) + diameter;
        const double margin = 2 * diameter;
        scene().setDomain(Vec3(-siloRadius - margin, -siloRadius - margin, orificeHeight() - outletDrop - margin),
                          Vec3(siloRadius + margin, siloRadius + margin, top));
        // The fastest impacts: the spheres dropped from the top of the column onto the cone.
        const double impactSpeed = std::sqrt(2 * gravity * (top - orificeHeight()));
        const std::vector<std::size_t> species = comparison::materials(soft).addTo(scene().species(), impactSpeed);
        const std::size_t grains = species[material == "M1" ? 0 : 1], steel = species[2];
        scene().addWall(Vec3::UnitZ(), Vec3(0, 0, orificeHeight()), steel);
        const double rim = coneTop() + siloHeight;
        if (walls == "smooth") {
            scene().addRevolvedWall(Vec3::Zero(), Vec3::UnitZ(),
                                    {{orificeRadius(), orificeHeight()}, {siloRadius, coneTop()}, {siloRadius, rim}}, steel);
        } else {
            TriangleMesh mesh = comparison::readWallTriangles(walls);
            require(std::abs(mesh.lo().z() - orificeHeight()) < 1e-6,
                    "--walls " + walls + ": its lowest point (z = " + str(mesh.lo().z()) + " m) is not the orifice of the " +
                        orifice + " silo (z = " + str(orificeHeight()) + " m): give the matching --orifice");
            scene().addMeshWall(std::move(mesh), steel);
        }
        outlet_.setPlane(-Vec3::UnitZ(), Vec3(0, 0, orificeHeight() - outletDrop));
        const Filling column(Cylinder(Vec3(0, 0, coneTop()), 2, columnHeight, columnRadius));
        const SizeDistribution spheres = SizeDistribution::byNumber().add(grains, 0.5 * diameter);
        const InsertionReport report = column.fill(*this, spheres, InsertionReport::Target::count, particles);
        require(report.complete, "the filling column holds fewer spheres than --particles: " + report.describe() +
                                     " (lower --filling-packing)");
        say(*this, "silo: %s orifice (radius %.3f m at z = %.7f m), %d spheres of %s (%.4f kg) dropped from a column %.3f m"
                   " high; the lid opens at t = %.3f s\n",
            orifice.c_str(), orificeRadius(), orificeHeight(), particles, material.c_str(), report.mass, columnHeight, openTime);
        writeDischarge();
    }

    void actionsAfterTimeStep() override {
        if (!opened_ && time() >= openTime) {
            scene().removeWall(lid);
            opened_ = 1;
            say(*this, "silo: lid opened at t = %.6f s\n", time());
        }
        if (clock_.every(sampleInterval)) writeDischarge();
    }

    void actionsAfterSolve() override {
        const double left = totalsOver(*this).mass;
        say(*this, "silo: discharged %.5f kg (%.0f spheres) of %.5f kg; %.5f kg left in the silo\n", outlet_.mass(),
            outlet_.count(), outlet_.mass() + left, left);
    }

private:
    void writeDischarge() { discharge_.write({time(), outlet_.mass(), totalsOver(*this).mass}); }

    int opened_ = 0;
    // (Per species of M1, M2 and steel; the plane is set once the orifice is known.)
    DeletionBoundary& outlet_ = scene().addBoundary<DeletionBoundary>(*this, -Vec3::UnitZ(), Vec3::Zero(), 3, "outlet");
    SamplingClock clock_{*this, "discharge"};
    SeriesFile discharge_{*this, "discharge", {"t", "discharged", "inSilo"},
                          "the mass that left through the orifice and the mass still in the silo (kg); t in s"};
};

int main(int argc, char** argv) {
    ComparisonSilo silo;
    silo.settings().name = "ComparisonSilo";
    silo.settings().timeStep = 1.5e-6;
    silo.settings().endTime = 5.5;
    silo.settings().outputInterval = 0.05;
    return silo.solve(argc, argv);
}
