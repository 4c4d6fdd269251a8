// The test driver of in-run coarse graining (InRun/InRunFields.h; Documentation/CoarseGraining.md
// "Fields during a run"): a small periodic chute whose fields are coarse-grained during the run.
//
// A chute inclined at --angle degrees (24), periodic in x (--length 8) and y (--width 4), with a
// disordered rough base of fixed spheres of diameter 1 and --particles spheres of diameter 1 and
// density 6/pi (mass 1) that start at rest in a loose layer, fall onto the base and flow: linear
// spring-dashpot with kn = 2e5, gn = 25 (tc = 5e-3, e = 0.88), kt = 2/7 kn, friction 0.5,
// dt = 1e-4. Coarse-graining objects sample it: a depth profile (coordinates Z, Lucy of width
// --cg-width, --cg-points points over -1 < z < 11) and an XZ field (Gauss of width 1, 8 x 6
// points), every --sample-steps steps (0: at the output steps), fixed particles as --fixed says,
// averaged as --averaging says; and, with fixed options, the stress at the top of the base every
// 100 steps, averaged over the run (the example of Documentation/CoarseGraining.md). With the
// files on (the default), the run also writes .data/.fstat/.restart at its output steps, so that
// talus-cg can coarse-grain the same frames (checkInRunAgainstFiles.py compares the two). At the
// end it prints the depth-averaged velocity of the last sample's profile and the basal friction
// -sigma_xz/sigma_zz, read in a hook as a calibration would.
#include <cmath>
#include <cstdint>
#include <string>

#include "Chute/Chute.h"
#include "InRun/InRunFields.h"
#include "Sampling/Sampling.h"

using namespace talus;

class InRunChute : public Chute {
public:
    double angle = 24, length = 8, width = 4, cgWidth = 0.5;
    int particles = 150, sampleSteps = 0, cgPoints = 96, withField = 1, contactStress = 1;
    std::string fixed = "boundary", averaging = "snapshots";

    InRunChute() {
        run().addFlag("angle", "inclination in degrees", angle);
        run().addFlag("length", "periodic length along x", length);
        run().addFlag("width", "periodic width along y", width);
        run().addFlag("particles", "number of flowing spheres (d = 1)", particles);
        run().addFlag("sample-steps", "steps between in-run samples (0: every output interval)", sampleSteps);
        run().addFlag("cg-width", "width of the depth profile's Lucy kernel", cgWidth);
        run().addFlag("cg-points", "points of the depth profile over -1 < z < 11", cgPoints);
        run().addFlag("with-field", "1: sample the XZ field too; 0: the depth profile alone (for timings)", withField);
        run().addFlag("contact-stress", "1: with the contact stress; 0: particle fields only (for timings)", contactStress);
        run().addTextFlag("fixed", "fixed particles in the fields: include, exclude or boundary", fixed);
        run().addTextFlag("averaging", "snapshots, per-output or whole-run", averaging);
    }

    void setupInitialConditions() override {
        setChuteAngle(angle);
        setChuteGeometry({.length = length, .width = width, .height = 20, .periodicEnds = true});
        const LinearSpringDashpot law{2e5, 25, 2.0 / 7.0 * 2e5, 25, 0.5};
        const std::size_t grains = scene().addSpecies("grains", 6 / pi, law);
        addBase(ChuteBase::disordered, 1, grains, 1);
        scene().random().seed(1);
        const double top = 1 + particles * pi / 6 / (0.2 * length * width);
        insertAtRest(static_cast<std::size_t>(particles), grains, 0.5, Vec3(0, 0, 1), Vec3(length, width, top),
                     "the start configuration");
    }

    void actionsAfterSolve() override {
        // The depth-averaged velocity of the last sample: int p_x dz / int rho dz (midpoint rule on
        // the grid), the mass-weighted mean of Fields/DepthAverage.h.
        if (profile_.samples() == 0) return;
        const std::vector<double>& sums = profile_.lastSums();
        double mass = 0, momentum = 0;
        for (std::size_t p = 0; p < profile_.points().size(); ++p) {
            mass += profile_.fieldAt(sums, p, "Density");
            momentum += profile_.fieldAt(sums, p, "MomentumX");
        }
        say(*this, "%s: depth-averaged velocity %.6g, mass per area %.6g (last sample of the in-run profile)\n",
            settings().name.c_str(), momentum / mass, mass * 12.0 / cgPoints);
        // The basal friction: the stress ratio at the base, averaged over the run's samples.
        const std::vector<double> base = base_.averageSums();
        say(*this, "%s: at the base -sigma_xz/sigma_zz = %.4g over %d samples (tan %g = %.4g in a steady flow)\n",
            settings().name.c_str(), -base_.fieldAt(base, 0, "StressXZ") / base_.fieldAt(base, 0, "StressZZ"),
            base_.samplesAveraged(), angle, std::tan(angle * pi / 180));
    }

private:
    // The options of both objects, completed from the flags (made when the run starts, restarts
    // included).
    cg::InRunOptions withFlags(cg::InRunOptions o, const char* name) const {
        require(fixed == "include" || fixed == "exclude" || fixed == "boundary", "--fixed: include, exclude or boundary");
        require(averaging == "snapshots" || averaging == "per-output" || averaging == "whole-run",
                "--averaging: snapshots, per-output or whole-run");
        o.name = settings().name + name;
        o.fixed = fixed == "include" ? cg::FixedParticles::include
                  : fixed == "exclude" ? cg::FixedParticles::exclude
                                       : cg::FixedParticles::boundary;
        o.averaging = averaging == "snapshots"    ? cg::InRunAveraging::snapshots
                      : averaging == "per-output" ? cg::InRunAveraging::perOutput
                                                  : cg::InRunAveraging::wholeRun;
        o.everySteps = static_cast<std::uint64_t>(sampleSteps);
        o.everyTime = sampleSteps > 0 ? 0 : settings().outputInterval;
        o.contactStress = contactStress != 0;
        return o;
    }
    cg::InRunOptions profileOptions() const {
        return withFlags({.coordinates = "Z", .width = cgWidth, .count = {1, 1, cgPoints}, .lo = cg::Vec3{0, 0, -1},
                          .hi = cg::Vec3{0, 0, 11}},
                         ".profile");
    }
    cg::InRunOptions fieldOptions() const {
        cg::InRunOptions o = withFlags({.coordinates = "XZ", .shape = cg::KernelShape::Gauss, .width = 1, .count = {8, 1, 6},
                                        .lo = cg::Vec3{0, 0, -1}, .hi = cg::Vec3{length, 0, 11}},
                                       ".field");
        if (withField == 0) o.timeMax = -1;  // (never sampled)
        return o;
    }

    // The stress at the base: one point at z = 0.5 (the top of the base), a Z kernel of width 1, the
    // base a boundary, every 100 steps, averaged over the run, no file.
    cg::InRunFields base_{*this, {.coordinates = "Z", .width = 1, .points = {{0, 0, 0.5}}, .everySteps = 100,
                                  .averaging = cg::InRunAveraging::wholeRun, .fixed = cg::FixedParticles::boundary}};
    cg::InRunFields profile_{*this, [this] { return profileOptions(); }};
    cg::InRunFields field_{*this, [this] { return fieldOptions(); }};
};

int main(int argc, char** argv) {
    InRunChute chute;
    chute.settings().name = "InRunChute";
    chute.settings().timeStep = 1e-4;
    chute.settings().endTime = 4;
    chute.settings().outputInterval = 0.5;
    chute.settings().writeVtu = false;
    return chute.solve(argc, argv);
}
