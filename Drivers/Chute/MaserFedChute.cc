// A long bidisperse chute fed by a maser: the chapter-4 setup of Theory/Chutes.md eq. (5)-(6) and
// Theory/Maser.md. Methods. Spheres of mean diameter 1 and size ratio S = dL/dS (--size-ratio,
// default 1.5; dL = 2S/(1+S), dS = 2/(1+S)), equal volumes of each size, density 6/pi, flow down a
// chute inclined at 23 degrees, periodic across (width 6), on a disordered rough base of fixed
// spheres of diameter 1 (--base-diameter). Contacts are linear spring-dashpots, kt = 2/7 kn,
// gt = gn, with e = 0.88 and tc = 0.005 for every pair type, or with --contact-law table-3C1 the
// law of the thesis's chapter-3 simulations (MaserChutePairLaws.h). dt = 1e-4. Phase 1: the maser,
// a periodic box [0, 20] (--maser-length), holds the spheres for an inflow height h
// (--inflow-height, default 6: a solids volume of 0.6 h 20 6), mixed or, with --segregated-start 1,
// small under large, and develops a flow. It is sampled every time unit; once its kinetic energy
// and mass flux have been on a plateau for --window samples (trend below --tolerance of the mean)
// and t >= --earliest-activation, or at --latest-activation at the latest, the maser is activated.
// Phase 2: the base is copied downstream to x = 20 + L (--chute-length, default 100; the thesis's
// full scale is 2000), every sphere leaving the box is copied into the chute, and spheres past the
// end are deleted; a run restarted after activation with a larger --chute-length extends the chute.
// NAME.series records every sample: the maser, the inflow (crossings, mass per size), the chute's
// contents, what left it, the front. At the end the run checks mass conservation to the particle
// (created = in the chute + deleted) and the inflow's composition against the maser's.
#include <algorithm>
#include <cmath>
#include <string>

#include "Boundaries/DeletionBoundary.h"
#include "Boundaries/MaserBoundary.h"
#include "Chute/Chute.h"
#include "Chute/ChuteStatistics.h"
#include "MaserChutePairLaws.h"
#include "Math/SummationRounding.h"
#include "Sampling/Sampling.h"

using namespace talus;

class MaserFedChute : public Chute {
public:
    double angle = 23, sizeRatio = 1.5, inflowHeight = 6, maserLength = 20, chuteLength = 100, width = 6;
    double sampleInterval = 1, tolerance = 0.02, earliestActivation = 50, latestActivation = 200, baseDiameter = 1;
    int seed = 1, window = 50, segregatedStart = 0;
    std::string contactLaw = "chapter-4";
    enum ChuteSpecies : std::size_t { large, small, base, chuteSpeciesCount };

    MaserFedChute() {
        run().addFlag("angle", "inclination in degrees", angle);
        run().addFlag("size-ratio", "dL / dS at mean diameter 1", sizeRatio);
        run().addFlag("inflow-height", "height of the flow in the maser (sets the number of spheres)", inflowHeight);
        run().addFlag("maser-length", "length of the maser box along x", maserLength);
        run().addFlag("chute-length", "length of the open chute downstream of the maser", chuteLength);
        run().addFlag("width", "periodic width along y", width);
        run().addFlag("base-diameter", "diameter of the fixed spheres of the disordered base", baseDiameter);
        run().addFlag("seed", "seed of the base and of the start positions", seed);
        run().addFlag("sample-interval", "time between samples", sampleInterval);
        run().addFlag("window", "samples on a plateau that make the maser's flow steady", window);
        run().addFlag("tolerance", "largest relative change of a series' trend over the window", tolerance);
        run().addFlag("earliest-activation", "the maser is not activated before this time", earliestActivation);
        run().addFlag("latest-activation", "the maser is activated at this time if not steady before", latestActivation);
        run().addFlag("segregated-start", "1: the maser's small spheres start below its large ones", segregatedStart);
        run().addTextFlag("contact-law", "chapter-4 (e = 0.88, tc = 0.005 for every pair) or table-3C1 (the thesis's chapter 3)", contactLaw);
        run().keepInRestart("run.activatedAt", activatedAt_);
        run().keepInRestart("run.boxParticles", boxParticles_);
    }

    void setupInitialConditions() override {
        require(sizeRatio >= 1, "--size-ratio must be at least 1, got " + str(sizeRatio));
        require(inflowHeight > 0, "--inflow-height must be positive, got " + str(inflowHeight));
        require(chuteLength > 0, "--chute-length must be positive, got " + str(chuteLength));
        require(segregatedStart == 0 || segregatedStart == 1, "--segregated-start must be 0 or 1, got " + str(segregatedStart));
        const double dL = 2 * sizeRatio / (1 + sizeRatio), dS = 2 / (1 + sizeRatio), density = 6 / pi;
        require(maserLength >= 2 * dL, "--maser-length " + str(maserLength) + " is shorter than two large-sphere "
                                       "diameters (" + str(2 * dL) + ")");
        setChuteAngle(angle);
        setChuteGeometry({.length = maserLength, .width = width, .height = 40, .periodicEnds = true});
        maser.setBox(0, maserLength);
        outlet.setPlane(Vec3::UnitX(), Vec3(maserLength + chuteLength, 0, 0));
        addMaserChuteSpecies(*this, contactLaw, dL, dS, density * pi / 6 * dL * dL * dL, density * pi / 6 * dS * dS * dS,
                             density, baseDiameter);
        maserLarge_ = maser.maserSpecies(*this, large), maserSmall_ = maser.maserSpecies(*this, small);
        maserBase_ = maser.maserSpecies(*this, base);
        addBase(ChuteBase::disordered, baseDiameter, maserBase_, static_cast<std::uint64_t>(seed));
        // The maser's spheres, at rest at random places in a loose layer (packing fraction 0.2),
        // mixed, or with --segregated-start the small ones in its lower half: a steady flow is
        // segregated (large on top), and a mixed start takes hundreds of time units to get there.
        scene().random().seed(static_cast<std::uint64_t>(seed));
        const double solids = 0.6 * inflowHeight * maserLength * width;
        const auto largeCount = static_cast<std::size_t>(std::lround(solids / 2 / (pi / 6 * dL * dL * dL)));
        const auto smallCount = static_cast<std::size_t>(std::lround(solids / 2 / (pi / 6 * dS * dS * dS)));
        const double top = 1 + solids / (0.2 * maserLength * width), middle = segregatedStart ? (1 + top) / 2 : 1;
        insertAtRest(largeCount, maserLarge_, dL / 2, Vec3(0, 0, middle), Vec3(maserLength, width, top), "the maser's spheres");
        insertAtRest(smallCount, maserSmall_, dS / 2, Vec3(0, 0, 1), Vec3(maserLength, width, segregatedStart ? middle : top),
                     "the maser's spheres");
        boxParticles_ = static_cast<double>(largeCount + smallCount);
        plateau_.reset(static_cast<std::size_t>(window), tolerance);
    }

    // Restarted after activation with a longer --chute-length: the base is copied on to the new
    // end, outlet and domain move there (what left stays deleted). A chute is not shortened: the
    // spheres past a new outlet would vanish uncounted as outflow of a chute they never left.
    void actionsBeforeTimeStep() override {
        const double oldEnd = outlet.point().x(), end = maserLength + chuteLength;
        if (activatedAt_ < 0 || end == oldEnd) return;
        require(end > oldEnd, "--chute-length " + str(chuteLength) + " is shorter than the chute of the restart file (" +
                                  str(oldEnd - maserLength) + "): a chute can be extended, not shortened");
        say(*this, "%s: chute extended from x = %g to %g at t = %g (%.0f base spheres added)\n", settings().name.c_str(), oldEnd,
            end, time(), continueBase(maserBase_, base, maserLength, oldEnd, end));
        outlet.setPlane(Vec3::UnitX(), Vec3(end, 0, 0));
        maser.setChuteEnd(*this, end);
    }

    void actionsAfterTimeStep() override {
        // m vx dt of the maser's spheres per size: over the box length, the mass crossing its face.
        const auto momentum = [](const ParticleStore& p, std::size_t i) { return p.mass[i] * p.velocity[i].x(); };
        if (activatedAt_ >= 0)
            for (std::size_t k : {0, 1}) carried_.addStepIntegral(k, ofSpecies(k == 0 ? maserLarge_ : maserSmall_), momentum);
        carried_.add(2, static_cast<double>(contactSummary().oneWayReactions));
        if (!clock_.every(sampleInterval)) return;
        carried_.totals();  // (this interval's sums join the totals at every sample)
        const ChuteSnapshot box = measureChute(*this, maserLength, width, maserSmall_, 0, maserLength);
        const Census c = census();
        series_.write({time(), activatedAt_ >= 0, box.kineticEnergy, box.massFlux, box.meanVelocity, box.height,
                       box.smallConcentration, maser.crossings(), maser.createdMass(large), maser.createdMass(small),
                       c.chute, c.chuteMass, outlet.count(), outlet.mass(), c.front, box.segregation});
        if (activatedAt_ >= 0) return;
        const bool steady = plateau_.add(time(), {box.kineticEnergy, box.massFlux}) || plateau_.steady();
        if (steady && time() >= earliestActivation - 0.5 * settings().timeStep)
            say(*this, "%s: maser flow steady (kinetic energy %.4g, mass flux %.4g on a plateau for %d samples): "
                "activating it at t = %g\n", settings().name.c_str(), box.kineticEnergy, box.massFlux, window, time());
        else if (time() >= latestActivation - 0.5 * settings().timeStep)
            say(*this, "%s: maser flow not steady by t = %g (--latest-activation): activating it anyway\n", settings().name.c_str(), time());
        else
            return;
        // Phase 2 with --chute-length as it is now (a maser saved before activation feeds any
        // chute).
        const double end = maserLength + chuteLength;
        outlet.setPlane(Vec3::UnitX(), Vec3(end, 0, 0));
        maser.activate(*this, end);
        activatedAt_ = time();
        say(*this, "%s: chute base of %.0f spheres up to x = %g; the first %g of the chute seeded with a copy of the "
            "maser's %.0f spheres\n", settings().name.c_str(), continueBase(maserBase_, base, maserLength, 0, end), end,
            maserLength, maser.seeded());
    }

    // Created = in the chute + deleted, to the particle; the maser keeps its spheres. The counts
    // must agree exactly; the masses are the same terms summed in another order, so they agree to
    // the rounding of a sum of `created` terms (Math/SummationRounding.h). Then the inflow's
    // composition: the small spheres' share of the created mass, against that of the mass the
    // maser's flow carried through its face (m vx dt / L).
    void actionsAfterSolve() override {
        if (activatedAt_ < 0) return say(*this, "%s: the maser was not activated by t = %g\n", settings().name.c_str(), time());
        const Census c = census();
        const double created = maser.seeded() + maser.crossings(), deleted = outlet.count();
        const double createdMass = maser.seededMass() + maser.createdMass(), accountedMass = c.chuteMass + outlet.mass();
        const bool conserved = created == c.chute + deleted && c.box == boxParticles_ &&
                               equalUpToSummationRounding(createdMass, accountedMass, created);
        say(*this, "%s: created %.0f (seeded %.0f + crossed %.0f) = in the chute %.0f + deleted %.0f; maser holds %.0f of "
            "%.0f; created mass %.10g, in the chute + deleted %.10g (apart by %.2g): mass conserved: %s\n", settings().name.c_str(),
            created, maser.seeded(), maser.crossings(), c.chute, deleted, c.box, boxParticles_, createdMass,
            accountedMass, std::abs(createdMass - accountedMass), conserved ? "yes" : "NO");
        const std::vector<double>& carried = carried_.totals();  // (m vx dt of the large, the small; one-way pair-steps)
        const double carriedLarge = carried[0] / maserLength, carriedSmall = carried[1] / maserLength;
        say(*this, "%s: since t = %g: inflow mass large %.6g small %.6g (small share %.4f); carried by the maser's "
            "flow: large %.6g small %.6g (small share %.4f)\n", settings().name.c_str(), activatedAt_, maser.createdMass(large),
            maser.createdMass(small), maser.createdMass(small) / std::max(1e-300, maser.createdMass()), carriedLarge,
            carriedSmall, carriedSmall / std::max(1e-300, carriedLarge + carriedSmall));
        say(*this, "%s: pairs across the maser's face beyond the one-way overlap limit (%g of the radius): %.0f "
            "pair-steps\n", settings().name.c_str(), OneWayPeriodicBox::reactionOverlap, carried[2]);
        requireOnAllRanks(*this, conserved, "mass is not conserved between the maser, the chute and the outlet");
    }

    MaserBoundary& maser = scene().addBoundary<MaserBoundary>(*this, 0, 20, chuteSpeciesCount);
    DeletionBoundary& outlet = scene().addBoundary<DeletionBoundary>(*this, Vec3::UnitX(), Vec3(120, 0, 0), chuteSpeciesCount, "outlet");

private:
    // The maser's spheres; the chute's (mobile) ones with their mass, and the front.
    struct Census { double box, chute, chuteMass, front; };
    Census census() const {
        const Selection inChute = [this](const ParticleStore& p, std::size_t i) {
            return !p.fixed[i] && p.species[i] != maserLarge_ && p.species[i] != maserSmall_; };
        const Totals chute = totalsOver(*this, inChute);
        const double front = maxOver(*this, inChute, [](const ParticleStore& p, std::size_t i) { return p.position[i].x(); });
        return {totalsOver(*this, ofSpecies(maserLarge_)).count + totalsOver(*this, ofSpecies(maserSmall_)).count,
                chute.count, chute.mass, std::max(0.0, front)};
    }

    std::size_t maserLarge_ = 3, maserSmall_ = 4, maserBase_ = 5;
    double activatedAt_ = -1, boxParticles_ = 0;
    RunningSums carried_{*this, "run.carried", 3};
    SteadyDetector plateau_{*this, "run.plateau"};
    SamplingClock clock_{*this, "samples"};
    SeriesFile series_{*this, "series", {"t", "active", "maserKineticEnergy", "maserMassFlux", "maserMeanVelocity",
                       "maserHeight", "maserSmallConcentration", "crossings", "createdMassLarge", "createdMassSmall",
                       "chuteParticles", "chuteMass", "deleted", "deletedMass", "front", "maserSegregation"}};
};

int main(int argc, char** argv) {
    MaserFedChute chute;
    chute.settings().name = "MaserFedChute";
    chute.settings().timeStep = 1e-4;
    chute.settings().endTime = 300;
    chute.settings().outputInterval = 5;
    return chute.solve(argc, argv);
}
