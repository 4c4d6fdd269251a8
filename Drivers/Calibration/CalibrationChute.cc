// One point of the periodic-chute calibration (Documentation/Calibration.md; Weinhart et al. 2012,
// "Closure relations for shallow granular flows from particle simulations").
//
// Methods. A chute inclined at --angle degrees, periodic in x (--length) and y (--width), has a
// disordered rough base of fixed spheres of diameter --base-diameter (CalibrationBase.h). Spheres of
// the thesis's Table 3.C.1 (MaserChutePairLaws.h: large d = 1, small d = 2^(-1/3), friction 0.5, 0.25,
// 0.375 between), --species large, small or a mixture (--concentration: the small share of the
// volume), as many as fill the base to --depth at solid fraction 0.6 (StartLayer.h), start at rest in
// a loose layer and fall onto the base; with --start-time they flow at --start-angle first. Every
// --sample-interval FlowDecision.h decides from the kinetic energy per unit mass and the mass flux:
// arrested (energy below --arrest-energy g d for --arrest-time) or steady (both on a plateau over
// --window samples). A steady flow is averaged for --average-time: height h (twice the mass-weighted
// mean height above z = 0), velocity u, its depth profile, and the base's force on the flow over
// every step. Then the run ends and writes NAME.result.csv: h, u, F = u / sqrt(g h cos theta), alpha
// = <u^2>/<u>^2 over the depth, the basal friction mu = -Fx/Fz of the base's force and its normal
// part over the weight. A steady flow's momentum balance makes the last 1 and mu = tan(theta).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "../Chute/MaserChutePairLaws.h"
#include "Chute/Chute.h"
#include "CalibrationBase.h"
#include "Chute/ChuteStatistics.h"
#include "DepthAverage.h"
#include "FlowDecision.h"
#include "StartLayer.h"
#include "Sampling/Sampling.h"

using namespace talus;

namespace {

constexpr double smallDiameter = 0.79370052598409979;  // 2^(-1/3): half the volume of a large sphere
constexpr double density = 6 / pi;                      // a large sphere has mass 1

}  // namespace

class CalibrationChute : public Chute {
public:
    double angle = 24, depth = 6, concentration = 0.5, length = 10, width = 10, boxHeight = 60;
    double sampleInterval = 1, averageTime = 100, baseDiameter = 1, baseRoughness = 0.5, startAngle = 0, startTime = 0;
    FlowCriteria criteria;
    int particles = 0, seed = 1, window = static_cast<int>(criteria.window), baseOfSmall = 0;
    std::string species = "large";

    CalibrationChute() {
        run().addFlag("angle", "inclination in degrees, in (0, 90)", angle);
        run().addTextFlag("species", "large, small or mixture", species);
        run().addFlag("concentration", "mixture: the small spheres' share of the flowing volume", concentration);
        run().addFlag("depth", "flow depth (large diameters) the spheres fill at solid fraction 0.6", depth);
        run().addFlag("particles", "number of flowing spheres (0: from --depth)", particles);
        run().addFlag("length", "periodic length along x", length);
        run().addFlag("width", "periodic width along y", width);
        run().addFlag("box-height", "height of the box above the base, which the start layer must fit", boxHeight);
        run().addFlag("base-diameter", "diameter of the fixed base spheres (large diameters)", baseDiameter);
        run().addFlag("base-roughness", "spread of the base spheres' heights, in [0, 1] base diameters", baseRoughness);
        run().addFlag("base-of-small", "1: the base has the small spheres' friction (0.375, 0.25), 0: the large ones'", baseOfSmall);
        run().addFlag("start-angle", "inclination in degrees until --start-time (0: --angle)", startAngle);
        run().addFlag("start-time", "time the layer flows at --start-angle before the decision starts", startTime);
        run().addFlag("seed", "seed of the base and of the start positions", seed);
        run().addFlag("sample-interval", "time between samples", sampleInterval);
        run().addFlag("window", "samples on a plateau that make the flow steady", window);
        run().addFlag("tolerance", "largest relative change of a series' trend over the window", criteria.tolerance);
        run().addFlag("arrest-energy", "kinetic energy per unit mass (g d) below which the flow is at rest", criteria.arrestEnergy);
        run().addFlag("arrest-time", "time at rest that makes the flow arrested", criteria.arrestTime);
        run().addFlag("average-time", "time a steady flow is averaged over", averageTime);
        run().keepInRestart("run.species", [this] { return std::vector<double>{double(kind())}; },  // (a text flag)
                            [this](const std::vector<double>& v) { species = kinds.at(std::size_t(v.at(0))); });
        run().keepInRestart("run.flowMass", flowMass_);
        run().keepInRestart("run.averageFrom", averageFrom_);
        run().keepInRestart("run.samples", [this] { return snapshotNumbers(samples_); },
                            [this](const std::vector<double>& v) { samples_ = snapshotsFromNumbers(v); });
        run().keepInRestart("run.profile", [this] { return profile_.state(); }, [this](const std::vector<double>& v) {
            profile_ = profileOfThisChute();  // (the flags are back already)
            profile_.restore(v);
        });
    }

    void setupInitialConditions() override {
        require(angle > 0 && angle < 90, "--angle " + str(angle) + ": the chute angle must lie in (0, 90) degrees");
        require(kind() < kinds.size(),
                "--species must be large, small or mixture, got '" + species + "'");
        require(species != "mixture" || (concentration > 0 && concentration < 1),
                "--concentration " + str(concentration) + ": a mixture's small share must lie in (0, 1)");
        require(depth > 0 && particles >= 0, "--depth must be positive and --particles not negative");
        require(sampleInterval > 0 && averageTime > 0 && boxHeight > 0, "--sample-interval, --average-time and --box-height must be positive");
        require(baseOfSmall == 0 || baseOfSmall == 1, "--base-of-small must be 0 or 1, got " + std::to_string(baseOfSmall));
        require(startTime >= 0 && (startAngle == 0 || (startAngle > 0 && startAngle < 90)),
                "--start-time " + str(startTime) + ", --start-angle " + str(startAngle) +
                    ": the start time must not be negative and the start angle must lie in (0, 90) degrees (0: --angle)");
        criteria.window = static_cast<std::size_t>(std::max(window, 0));
        decision_.reset(criteria);
        setChuteAngle(startTime > 0 && startAngle > 0 ? startAngle : angle);
        setChuteGeometry({.length = length, .width = width, .height = boxHeight, .periodicEnds = true});
        addMaserChuteSpecies(*this, "table-3C1", 1, smallDiameter, 1, density * pi / 6 * std::pow(smallDiameter, 3),
                             density, baseDiameter, baseOfSmall == 1);
        addCalibrationBase(*this, baseDiameter, baseRoughness, baseSpecies, static_cast<std::uint64_t>(seed));

        const double smallShare = species == "small" ? 1 : species == "large" ? 0 : concentration;
        const auto [large, small, volume] = startLayer(smallShare, smallDiameter, particles, depth, length * width);
        const double top = 1 + volume / (0.2 * length * width);
        require(top <= boxHeight, (particles > 0 ? "--particles " + std::to_string(particles) : "--depth " + str(depth)) +
                                      " does not fit the box: the loose start layer (solid fraction 0.2) reaches z = " +
                                      str(top) + ", above --box-height " + str(boxHeight));
        scene().random().seed(static_cast<std::uint64_t>(seed));
        if (large > 0) insertAtRest(large, largeSpecies, 0.5, Vec3(0, 0, 1), Vec3(length, width, top), "the large spheres");
        if (small > 0)
            insertAtRest(small, smallSpecies, smallDiameter / 2, Vec3(0, 0, 1), Vec3(length, width, top), "the small spheres");
        profile_ = profileOfThisChute();
    }

    void actionsAfterTimeStep() override {
        if (averageFrom_ >= 0) {  // the base's force on the flow, minus the flow's force on the fixed spheres
            baseForce_.addStepIntegral(0, fixedSpheres(), [](const ParticleStore& p, std::size_t i) { return -p.force[i].x(); });
            baseForce_.addStepIntegral(1, fixedSpheres(), [](const ParticleStore& p, std::size_t i) { return -p.force[i].z(); });
        }
        if (!clock_.every(sampleInterval)) return;
        if (flowMass_ == 0) flowMass_ = totalsOver(*this).mass;
        const ChuteSnapshot s = last_ = measureChute(*this, length, width, smallSpecies);
        const double energyPerMass = s.kineticEnergy * length * width / flowMass_;
        series_.write({s.time, energyPerMass, s.massFlux, s.meanVelocity, s.height});
        if (time() < startTime - 0.5 * settings().timeStep) return;  // the start: flowing at --start-angle
        if (startTime > 0) setChuteAngle(angle);  // (the same gravity at every sample after the start)
        const FlowState state = decision_.add(time(), energyPerMass, s.massFlux);
        if (state == FlowState::arrested) {
            samples_ = {s};
            return finish();
        }
        if (state != FlowState::steady) return;
        if (averageFrom_ < 0) averageFrom_ = time();
        samples_.push_back(s);
        profile_.add(scene().particles(), this);
        if (time() - averageFrom_ >= averageTime - 0.5 * settings().timeStep) finish();
    }

    // A run that reached its end time undecided says so in its result line.
    void actionsAfterSolve() override { if (!finished_) writeResult(); }

private:
    static Selection fixedSpheres() { return [](const ParticleStore& p, std::size_t i) { return p.fixed[i] != 0; }; }
    DepthProfile profileOfThisChute() const { return DepthProfile(0.25, boxHeight, length, width, smallSpecies); }

    void finish() { writeResult(), finished_ = true, run().finishAfterNextStep(); }

    void writeResult() {
        std::vector<double> u, h;  // (an undecided run: its last sample)
        for (const ChuteSnapshot& s : samples_.empty() ? std::vector{last_} : samples_)
            u.push_back(s.meanVelocity), h.push_back(s.height);
        const MeanAndError velocity = batchMean(u), height = batchMean(h);
        const double theta = angle * pi / 180, froude = velocity.mean / std::sqrt(height.mean * std::cos(theta));
        const DepthAverage profile = depthAverage(profile_);
        const std::vector<double>& force = baseForce_.totals();  // time integrals of the base's force
        const double averaged = averageFrom_ >= 0 && decision_.state() == FlowState::steady ? time() - averageFrom_ : 0;
        const double mu = averaged > 0 ? -force[0] / force[1] : NAN;
        const double weightCarried = averaged > 0 ? force[1] / averaged / (flowMass_ * std::cos(theta)) : NAN;
        const double uChange = averaged > 0 ? changeAlongTrend(u) / velocity.mean : NAN;
        const FlowState state = decision_.state(); const char* name = flowStateName(state);
        writeFileOnce(*this, settings().name + ".result.csv", [&](std::ostream& out) {
            out << "species,concentration,angle,length,width,baseDiameter,baseRoughness,seed,particles,h,u,uError,uChange,F,"
                   "alpha,mu,weightCarried,state,decidedAt,averagedFor\n"
                << species << ',' << (species == "mixture" ? concentration : species == "small" ? 1 : 0) << ',' << angle << ','
                << length << ',' << width << ',' << baseDiameter << ',' << baseRoughness << ',' << seed << ',' << flowParticles()
                << ',' << height.mean << ',' << velocity.mean << ',' << velocity.error << ',' << uChange << ',' << froude << ','
                << profile.shapeFactor << ',' << mu << ',' << weightCarried << ',' << name << ','
                << (state == FlowState::undecided ? time() : decision_.decidedAt()) << ',' << averaged << '\n';
        });
        say(*this, "%s: %s at t = %g: h = %.4g, u = %.4g, F = %.4g, alpha = %.4g, mu = %.4g (tan theta = %.4g), "
                   "weight carried by the base %.4f (NAME.result.csv)\n", settings().name.c_str(), name, time(),
            height.mean, velocity.mean, froude, profile.shapeFactor, mu, std::tan(theta), weightCarried);
    }

    double flowParticles() const { return sumOver(*this, mobileParticles(), [](const ParticleStore&, std::size_t) { return 1.0; }); }

    enum : std::size_t { largeSpecies, smallSpecies, baseSpecies };  // (addMaserChuteSpecies's order)
    static constexpr std::array<std::string_view, 3> kinds{"large", "small", "mixture"};  // --species
    std::size_t kind() const { return std::size_t(std::find(kinds.begin(), kinds.end(), species) - kinds.begin()); }
    FlowDecision decision_{*this, "run.decision"};
    SamplingClock clock_{*this, "samples"};
    RunningSums baseForce_{*this, "run.baseForce", 2};
    SeriesFile series_{*this, "series", {"t", "kineticEnergyPerMass", "massFlux", "meanVelocity", "height"},
                       "(energy per unit mass in g d, flux per unit width)"};
    DepthProfile profile_{0.25, 60, 10, 10, smallSpecies};
    std::vector<ChuteSnapshot> samples_;  // the averaged samples (the last one for an arrested flow)
    ChuteSnapshot last_;                  // the last sample
    double flowMass_ = 0, averageFrom_ = -1;
    bool finished_ = false;
};

int main(int argc, char** argv) {
    CalibrationChute chute;
    chute.settings().name = "CalibrationChute";
    chute.settings().timeStep = 1e-4;  // Table 3.C.1: about tc/50 of two large spheres
    chute.settings().endTime = 2000;   // a bound: the run ends when the flow is decided
    chute.settings().outputInterval = 0;
    return chute.solve(argc, argv);
}
