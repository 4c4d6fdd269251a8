// The periodic calibration chute of Theory/Chutes.md eq. (2)-(4) with the mixture of the thesis's
// table 3.C.1.
//
// Methods. A chute inclined at 24 degrees, periodic in x (length 20) and y (width 10), has a
// disordered rough base of fixed spheres of diameter 1 (--base-diameter). 1000 large spheres
// (d = 1) and 2000 small ones (d = 2^(-1/3), half the volume) of density 6/pi are placed at random
// above it and flow under gravity g (sin 24, 0, -cos 24). Contacts are linear spring-dashpots with
// Coulomb friction: kn = 2e5 and gn = 25 for two large spheres (tc = 4.97e-3, e = 0.883), the same
// e and tc ~ sqrt(d) for every pair type (Theory/ContactLaws.md "Bidisperse mixtures"), kt = 2/7
// kn, gt = gn, friction 0.5 (LL), 0.25 (SS), 0.375 (LS); the base is of the large material. With
// --softer F every stiffness is divided by F and every damping by sqrt(F): each collision lasts
// sqrt(F) times as long with the same restitution (the softer particles of common practice).
// With --law hertz the contacts are Hertz-Mindlin instead (Theory/ContactLaws.md eq. (16)-(20)),
// one material of Poisson ratio 0.3 for every sphere and the base, with the same restitution
// and friction coefficients, its Young's modulus such that two large spheres meeting at speed 1
// (sqrt(g d)) collide for the linear law's tc; the other pair types then follow from Hertz's law.
// dt = 1e-4. Every time unit the run samples the kinetic energy and the mass flux; once both have
// been on a plateau for the last 200 samples (their trend over them below 2% of their mean) the
// flow is steady, and from then on the run averages depth profiles and the flow's mean velocity,
// height and flux, written at the end with their standard errors (NAME.profile, NAME.steady). Every
// sample is also appended to NAME.series. (The statistics are the driver's own: a restarted run
// starts them afresh.)
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "Chute/Chute.h"
#include "Chute/ChuteStatistics.h"
#include "Sampling/Sampling.h"
#include "Species/BidisperseRule.h"

using namespace talus;

class PeriodicBidisperseChute : public Chute {
public:
    double angle = 24, length = 20, width = 10, sampleInterval = 1, tolerance = 0.02, baseDiameter = 1, softer = 1;
    int large = 1000, small = 2000, seed = 1, window = 200;
    std::string law = "linear";

    PeriodicBidisperseChute() {
        run().addFlag("angle", "inclination in degrees", angle);
        run().addFlag("length", "periodic length along x", length);
        run().addFlag("width", "periodic width along y", width);
        run().addFlag("large", "number of large spheres (d = 1)", large);
        run().addFlag("small", "number of small spheres (d = 0.7937)", small);
        run().addFlag("base-diameter", "diameter of the fixed spheres of the disordered base", baseDiameter);
        run().addFlag("seed", "seed of the base and of the start positions", seed);
        run().addFlag("softer", "divide the stiffnesses by F and the dampings by sqrt(F) (collisions sqrt(F) longer)", softer);
        run().addTextFlag("law", "linear (the thesis's spring-dashpot) or hertz (Hertz-Mindlin, the same collision at speed 1)", law);
        run().addFlag("sample-interval", "time between samples of the bulk flow", sampleInterval);
        run().addFlag("window", "samples on a plateau that make the flow steady", window);
        run().addFlag("tolerance", "largest relative change of a series' trend over the window", tolerance);
        // A restarted run goes on detecting the plateau and averaging where it stopped.
        run().keepInRestart("run.steadySamples", [this] { return snapshotNumbers(steadySamples_); },
                      [this](const std::vector<double>& v) { steadySamples_ = snapshotsFromNumbers(v); });
        run().keepInRestart("run.profile", [this] { return profile_.state(); },
                      [this](const std::vector<double>& v) {
                          profile_ = profileOfThisChute();  // (the flags are back already)
                          profile_.restore(v);
                      });
    }

    void setupInitialConditions() override {
        require(large >= 0 && small >= 0 && large + small > 0, "--large and --small: at least one sphere");
        setChuteAngle(angle);
        setChuteGeometry({.length = length, .width = width, .height = 60, .periodicEnds = true});
        // The thesis's table 3.C.1: the LL law from kn and gn, then the bidisperse rule for the
        // others.
        require(softer >= 1 && std::isfinite(softer), "--softer must be at least 1, got " + str(softer));
        const double k = 2e5 / softer, g = 25 / std::sqrt(softer);
        const LinearSpringDashpot largeLaw{k, g, 2.0 / 7.0 * k, g, 0.5};
        const double density = 6 / pi;
        require(law == "linear" || law == "hertz", "--law: linear or hertz, got " + law);
        require(law == "linear" || softer == 1, "--softer goes with --law linear only");
        if (law == "hertz") {
            const HertzMindlin hertz = HertzMindlin::fromCollision(largeLaw.collisionTime(0.5), largeLaw.restitution(0.5),
                                                                   /*m* of two large*/ 0.5, /*R**/ 0.25, /*speed*/ 1, 0.3);
            largeSpecies_ = scene().addSpecies("large", density, HertzMindlin(hertz).withFriction(0.5));
            smallSpecies_ = scene().addSpecies("small", density, HertzMindlin(hertz).withFriction(0.25));
            scene().species().setPair(largeSpecies_, smallSpecies_, HertzMindlin(hertz).withFriction(0.375));
        } else {
            largeSpecies_ = scene().addSpecies("large", density, largeLaw);
            smallSpecies_ = scene().addSpecies("small", density, LinearSpringDashpot(largeLaw).withFriction(0.25));
            applyBidisperseRule(scene().species(), {.large = largeSpecies_, .small = smallSpecies_, .largeDiameter = 1,
                                            .smallDiameter = smallDiameter, .largeCollisionTime = largeLaw.collisionTime(0.5),
                                            .restitution = largeLaw.restitution(0.5), .mixedFriction = 0.375});
        }
        addBase(ChuteBase::disordered, baseDiameter, largeSpecies_, static_cast<std::uint64_t>(seed));
        // The spheres start at rest at random places in a loose layer above the base (packing
        // fraction about 0.2, so the insertion never jams).
        scene().random().seed(static_cast<std::uint64_t>(seed));
        const double volume = large * pi / 6 + small * pi / 6 * std::pow(smallDiameter, 3);
        const double top = 1 + volume / (0.2 * length * width);
        for (auto [count, species, diameter] : {std::tuple{large, largeSpecies_, 1.0}, {small, smallSpecies_, smallDiameter}})
            insertAtRest(static_cast<std::size_t>(count), species, diameter / 2, Vec3(0, 0, 1), Vec3(length, width, top),
                         "the start configuration");
        plateau_.reset(static_cast<std::size_t>(window), tolerance);
        profile_ = profileOfThisChute();
    }

    void actionsAfterTimeStep() override {
        if (!clock_.every(sampleInterval)) return;
        const ChuteSnapshot s = measureChute(*this, length, width, smallSpecies_);
        series_.write({s.time, s.kineticEnergy, s.massFlux, s.meanVelocity, s.height, s.smallConcentration});
        // No sphere may pass through the base (its centres lie within +-0.25 of z = 0).
        const double lowest = minOver(*this, mobileParticles(), [](const ParticleStore& p, std::size_t i) { return p.position[i].z(); });
        requireOnAllRanks(*this, !(lowest < -0.5), "a sphere fell through the base (z = " + str(lowest) + " at t = " +
                                                       str(time()) + ")");
        if (!plateau_.steady()) {
            if (plateau_.add(time(), {s.kineticEnergy, s.massFlux}))
                say(*this, "%s: steady flow at t = %g (kinetic energy %.4g and mass flux %.4g per unit area and width "
                            "on a plateau for %d samples)\n", settings().name.c_str(), time(), s.kineticEnergy, s.massFlux, window);
            return;
        }
        steadySamples_.push_back(s);
        profile_.add(scene().particles(), this);
    }

    void actionsAfterSolve() override {
        if (steadySamples_.empty()) {
            say(*this, "%s: the flow did not become steady by t = %g (%zu samples); run longer (--end-time)\n",
                        settings().name.c_str(), time(), plateau_.samples());
            return;
        }
        std::vector<double> velocity, height, flux, concentration;
        for (const ChuteSnapshot& s : steadySamples_) {
            velocity.push_back(s.meanVelocity);
            height.push_back(s.height);
            flux.push_back(s.massFlux);
            concentration.push_back(s.smallConcentration);
        }
        const MeanAndError u = batchMean(velocity), h = batchMean(height), q = batchMean(flux);
        profile_.write(settings().name + ".profile", this);
        writeFileOnce(*this, settings().name + ".steady", [&](std::ostream& out) {
            out << "# steady since t = " << plateau_.steadySince() << ", " << steadySamples_.size()
                << " samples until t = " << time() << "; mean and standard error (5 batch means)\n";
            out << "meanVelocity " << u.mean << ' ' << u.error << "\nheight " << h.mean << ' ' << h.error
                << "\nmassFlux " << q.mean << ' ' << q.error << '\n';
        });
        say(*this, "%s: steady from t = %g; over %zu samples: mean velocity %.4f +- %.4f, height %.3f +- %.3f, "
                    "mass flux %.4f +- %.4f (NAME.steady, depth profiles in NAME.profile)\n",
                    settings().name.c_str(), plateau_.steadySince(), steadySamples_.size(), u.mean, u.error, h.mean, h.error,
                    q.mean, q.error);
    }

private:
    DepthProfile profileOfThisChute() const { return DepthProfile(0.25, 40, length, width, smallSpecies_); }

    static constexpr double smallDiameter = 0.79370052598409979;  // 2^(-1/3): half the volume
    std::size_t largeSpecies_ = 0, smallSpecies_ = 1;
    SteadyDetector plateau_{*this, "run.plateau", 200, 0.02};
    SamplingClock clock_{*this, "samples"};
    std::vector<ChuteSnapshot> steadySamples_;
    SeriesFile series_{*this, "series", {"t", "kineticEnergy", "massFlux", "meanVelocity", "height", "smallConcentration"},
                       "(per unit area/width)"};
    DepthProfile profile_{0.25, 40, 20, 10, 1};
};

int main(int argc, char** argv) {
    PeriodicBidisperseChute chute;
    chute.settings().name = "PeriodicBidisperseChute";
    chute.settings().timeStep = 1e-4;
    chute.settings().endTime = 1500;
    chute.settings().outputInterval = 10;
    return chute.solve(argc, argv);
}
