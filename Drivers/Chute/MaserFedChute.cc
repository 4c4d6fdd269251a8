// A long bidisperse chute fed by a maser: the chapter-4 setup of Theory/Chutes.md eq. (5)-(6) and Theory/Maser.md.
//
// Methods. Spheres of mean diameter 1 and size ratio S = dL/dS (--size-ratio, default 1.5; dL =
// 2S/(1+S), dS = 2/(1+S)), equal volumes of each size, density 6/pi, flow down a chute inclined
// at 23 degrees, periodic across (width 6), with a disordered rough base of fixed spheres of
// diameter 1 (--base-diameter). Contacts are linear spring-dashpots with e = 0.88 and tc = 0.005 for every pair
// type (Theory/ContactLaws.md eq. (10)-(12)), kt = 2/7 kn, gt = gn, friction 0.5 for large, 0.25 for small spheres and
// 0.375 between them (a sphere on the base: its own). dt = 1e-4. With --contact-law table-3C1,
// the law of the thesis's chapter-3 simulations instead (Theory/ContactLaws.md "Bidisperse mixtures", the thesis's table 3.C.1): kn = 2e5
// and gamma_n = 25 for two large spheres in units of dL, mL and g (tc = 4.97e-3, e = 0.883), the
// same e and tc/sqrt(d/g) for every pair type (d: dL, dS, their mean; a base pair the mean of
// its two diameters), and the base behaving as large spheres (friction 0.375 for a small sphere
// on it).
// Phase 1: the maser, a periodic box [0, 20] (--maser-length), holds the spheres for an inflow
// height h (--inflow-height, default 6: a solids volume of 0.6 h 20 6), mixed or, with
// --segregated-start 1, small under large, and develops a flow. It
// is sampled every time unit; once its kinetic energy and mass flux have been on a plateau for
// --window samples (trend below --tolerance of the mean) and t >= --earliest-activation, or at
// --latest-activation at the latest, the maser is activated. Phase 2: the base is copied
// downstream to x = 20 + L (--chute-length, default 100; the thesis's full scale is 2000), every
// sphere leaving the box is copied into the chute, and spheres past the end are deleted. A run
// restarted after activation with a larger --chute-length extends the chute (base and outlet).
// NAME.series records, every sample, the maser's state, the inflow (crossings and mass per
// size), the chute's contents, what left it, and the front. At the end the run checks mass
// conservation to the particle (created = in the chute + deleted) and compares the inflow's
// composition with the maser's.
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <tuple>

#include "Boundaries/DeletionBoundary.h"
#include "Boundaries/InsertionBoundary.h"
#include "Boundaries/MaserBoundary.h"
#include "Chute/Chute.h"
#include "Chute/ChuteStatistics.h"
#include "IO/SeriesFile.h"
#include "Math/SummationRounding.h"

using namespace talus;

class MaserFedChute : public Chute {
public:
    double angle = 23, sizeRatio = 1.5, inflowHeight = 6, maserLength = 20, chuteLength = 100, width = 6;
    double sampleInterval = 1, tolerance = 0.02, earliestActivation = 50, latestActivation = 200, baseDiameter = 1;
    int seed = 1, window = 50, segregatedStart = 0;
    std::string contactLaw = "chapter-4";
    enum ChuteSpecies : std::size_t { large, small, base, chuteSpeciesCount };

    MaserFedChute() {
        addFlag("angle", "inclination in degrees", angle);
        addFlag("size-ratio", "dL / dS at mean diameter 1", sizeRatio);
        addFlag("inflow-height", "height of the flow in the maser (sets the number of spheres)", inflowHeight);
        addFlag("maser-length", "length of the maser box along x", maserLength);
        addFlag("chute-length", "length of the open chute downstream of the maser", chuteLength);
        addFlag("width", "periodic width along y", width);
        addFlag("base-diameter", "diameter of the fixed spheres of the disordered base", baseDiameter);
        addFlag("seed", "seed of the base and of the start positions", seed);
        addFlag("sample-interval", "time between samples", sampleInterval);
        addFlag("window", "samples on a plateau that make the maser's flow steady", window);
        addFlag("tolerance", "largest relative change of a series' trend over the window", tolerance);
        addFlag("earliest-activation", "the maser is not activated before this time", earliestActivation);
        addFlag("latest-activation", "the maser is activated at this time if not steady before", latestActivation);
        addFlag("segregated-start", "1: the maser's small spheres start below its large ones", segregatedStart);
        addTextFlag("contact-law", "chapter-4 (e = 0.88, tc = 0.005 for every pair type) or table-3C1 (the thesis's "
                    "chapter-3 law: kn = 2e5, gamma_n = 25 for large spheres, the other pair types derived)", contactLaw);
        keepInRestart("run.activatedAt", activatedAt_);
        keepInRestart("run.boxParticles", boxParticles_);
        keepInRestart("run.oneWayReactions", oneWayReactions_);
        for (std::size_t s = 0; s < 2; ++s) keepInRestart("run.boxMassDisplacement." + std::to_string(s), boxMassDisplacement_[s]);
        // A maser saved before activation goes on watching for its plateau where it stopped.
        keepInRestart("run.plateau", [this] { return plateau_.state(); },
                      [this](const std::vector<double>& v) { plateau_.restore(v); });
        setRunsOnRanks(true);  // under mpirun: sums over ranks, files and messages from rank 0
    }

    void setupInitialConditions() override {
        require(sizeRatio >= 1, "--size-ratio must be at least 1, got " + str(sizeRatio));
        require(inflowHeight > 0, "--inflow-height must be positive, got " + str(inflowHeight));
        require(chuteLength > 0, "--chute-length must be positive, got " + str(chuteLength));
        const double largeDiameter = 2 * sizeRatio / (1 + sizeRatio);
        require(maserLength >= 2 * largeDiameter, "--maser-length " + str(maserLength) +
                                                      " is shorter than two large-sphere diameters (" +
                                                      str(2 * largeDiameter) + ")");
        setChuteAngle(angle);
        setChuteGeometry({.length = maserLength, .width = width, .height = 40, .periodicEnds = true});
        maser.setBox(0, maserLength);
        outlet.setPlane(Vec3::UnitX(), Vec3(maserLength + chuteLength, 0, 0));
        const double dL = 2 * sizeRatio / (1 + sizeRatio), dS = 2 / (1 + sizeRatio), density = 6 / pi;
        const double mL = density * pi / 6 * dL * dL * dL, mS = density * pi / 6 * dS * dS * dS;
        setPairLaws(dL, dS, mL, mS, density);
        maserLarge_ = maser.maserSpecies(*this, large);
        maserSmall_ = maser.maserSpecies(*this, small);
        maserBase_ = maser.maserSpecies(*this, base);
        addBase(ChuteBase::disordered, baseDiameter, maserBase_, static_cast<std::uint64_t>(seed));
        // The maser's spheres, at rest at random places in a loose layer (packing fraction 0.2),
        // mixed, or with --segregated-start the small ones in its lower half: a steady flow is
        // segregated (large on top), and a mixed start takes hundreds of time units to get there.
        require(segregatedStart == 0 || segregatedStart == 1, "--segregated-start must be 0 or 1, got " + str(segregatedStart));
        random().seed(static_cast<std::uint64_t>(seed));
        const double solids = 0.6 * inflowHeight * maserLength * width;
        const auto largeCount = static_cast<std::size_t>(std::lround(solids / 2 / (pi / 6 * dL * dL * dL)));
        const auto smallCount = static_cast<std::size_t>(std::lround(solids / 2 / (pi / 6 * dS * dS * dS)));
        const double top = 1 + solids / (0.2 * maserLength * width), middle = segregatedStart ? (1 + top) / 2 : 1;
        for (auto [count, s, d, bottom, ceiling] : {std::tuple{largeCount, maserLarge_, dL, middle, top},
                                                    {smallCount, maserSmall_, dS, 1.0, segregatedStart ? middle : top}}) {
            InsertionBoundary box(Vec3(0, 0, bottom), Vec3(maserLength, width, ceiling), SizeDistribution::byNumber().add(s, d / 2));
            const InsertionReport report = box.insertCount(*this, count);
            if (rank() == 0) std::printf("%s\n", report.describe().c_str());
            require(report.complete, "could not place the maser's spheres: " + report.describe());
        }
        boxParticles_ = static_cast<double>(largeCount + smallCount);
        plateau_ = PlateauDetector(static_cast<std::size_t>(window), tolerance);
    }

    void actionsBeforeTimeStep() override {
        if (activatedAt_ >= 0 && maserLength + chuteLength != outlet.point().x()) extendChute();
    }

    void actionsAfterTimeStep() override {
        outlet.apply(*this);
        if (activatedAt_ >= 0) accumulateBoxFlux();
        unsummed_[2] += static_cast<double>(contactSummary().oneWayReactions);
        if (std::abs(time() - sampleInterval * std::round(time() / sampleInterval)) > 0.5 * timeStep()) return;
        // This rank's sums since the last sample join the totals (on ranks: summed over them).
        sumOverRanks(unsummed_);
        boxMassDisplacement_[0] += unsummed_[0];
        boxMassDisplacement_[1] += unsummed_[1];
        oneWayReactions_ += unsummed_[2];
        unsummed_.assign(3, 0.0);
        const ChuteSnapshot box = measureChute(*this, maserLength, width, maserSmall_, 0, maserLength);
        sample(box);
        if (activatedAt_ >= 0) return;
        const bool steady = plateau_.add(time(), {box.kineticEnergy, box.massFlux});
        if ((steady || plateau_.steady()) && time() >= earliestActivation - 0.5 * timeStep()) {
            if (rank() == 0)
                std::printf("%s: maser flow steady (kinetic energy %.4g, mass flux %.4g on a plateau for %d samples): "
                        "activating it at t = %g\n", name().c_str(), box.kineticEnergy, box.massFlux, window, time());
            activate();
        } else if (time() >= latestActivation - 0.5 * timeStep()) {
            if (rank() == 0)
                std::printf("%s: maser flow not steady by t = %g (--latest-activation): activating it anyway\n",
                        name().c_str(), time());
            activate();
        }
    }

    void actionsAfterSolve() override { checkConservation(); }

    MaserBoundary maser{*this, 0, 20, chuteSpeciesCount};
    DeletionBoundary outlet{*this, Vec3::UnitX(), Vec3(120, 0, 0), chuteSpeciesCount, "outlet"};

private:
    // Phase 2: the maser feeds the chute, whose base is the maser's, copied downstream.
    // The chute (base and outlet) is laid out here, with --chute-length as it is now: a maser
    // saved in a restart file before activation can feed chutes of any length.
    void activate() {
        const double end = maserLength + chuteLength;
        outlet.setPlane(Vec3::UnitX(), Vec3(end, 0, 0));
        maser.activate(*this, end);
        activatedAt_ = time();
        const double added = layBase(0, end);
        if (rank() == 0)
            std::printf("%s: chute base of %.0f spheres up to x = %g; the first %g of the chute seeded with a copy of the "
                    "maser's %.0f spheres\n", name().c_str(), added, end, maserLength, maser.seeded());
    }

    // The species and their pair laws. chapter-4 (Theory/Chutes.md eq. (5)-(6)): e and tc the same for every pair
    // type, so each pair's stiffness and damping follow from its reduced mass (a fixed base sphere
    // has infinite mass: the reduced mass is the other's). table-3C1 (Theory/ContactLaws.md "Bidisperse mixtures", the thesis's table
    // 3.C.1): tc and e of two large spheres from kn = 2e5 and gamma_n = 25 in the thesis's units
    // (dL = mL = g = 1, so m* = 1/2), tc/sqrt(d/g) and e the same for every pair type, and the
    // base, fixed large particles there, with the large spheres' friction towards both sizes.
    void setPairLaws(double dL, double dS, double mL, double mS, double density) {
        require(contactLaw == "chapter-4" || contactLaw == "table-3C1",
                "--contact-law must be chapter-4 or table-3C1, got '" + contactLaw + "'");
        const bool thesis = contactLaw == "table-3C1";
        const double kn = 2e5, gn = 25, m = 0.5;
        const double tcPerRootDiameter = pi / std::sqrt(kn / m - gn * gn / (4 * m * m)), eThesis = std::exp(-tcPerRootDiameter * gn / (2 * m));
        auto law = [&](double reducedMass, double diameter, double friction) {
            return (thesis ? LinearSpringDashpot::fromCollision(tcPerRootDiameter * std::sqrt(diameter), eThesis, reducedMass)
                           : LinearSpringDashpot::fromCollision(0.005, 0.88, reducedMass))
                .withFriction(friction);
        };
        // Each pair type once: its reduced mass, the diameter its tc scales with, its friction.
        const double dB = baseDiameter, muLS = 0.375;
        struct PairType {
            const char* label;
            ChuteSpecies a, b;
            double reducedMass, diameter, friction;
        };
        const PairType pairs[] = {{"large-large", large, large, mL / 2, dL, 0.5},
                                  {"small-small", small, small, mS / 2, dS, 0.25},
                                  {"large-small", large, small, mL * mS / (mL + mS), (dL + dS) / 2, muLS},
                                  {"base-large", base, large, mL, (dB + dL) / 2, 0.5},
                                  {"base-small", base, small, mS, (dB + dS) / 2, thesis ? muLS : 0.25}};
        auto lawOf = [&](const PairType& t) { return law(t.reducedMass, t.diameter, t.friction); };
        addSpecies("large", density, lawOf(pairs[0]));
        addSpecies("small", density, lawOf(pairs[1]));
        addSpecies("base", density, law(mL, dL, 0.5));  // (base with base: both fixed, never in contact)
        for (const PairType& t : pairs)
            if (t.a != t.b) species().setPair(t.a, t.b, lawOf(t));
        if (rank() != 0) return;
        std::printf("%s: contact law %s\n", name().c_str(), contactLaw.c_str());
        for (const PairType& t : pairs) {
            const auto l = std::get<LinearSpringDashpot>(species().pairLaw(t.a, t.b));
            std::printf("  %-11s reduced mass %.10g  kn %.10g  gamma_n %.10g  kt %.10g  gamma_t %.10g  mu %.10g\n", t.label,
                        t.reducedMass, l.normalStiffness, l.normalDamping, l.tangentialStiffness, l.tangentialDamping,
                        l.friction);
        }
    }

    // A run restarted after activation with another --chute-length: a longer chute gets the base
    // copied on to its new end, and the outlet and the domain move there. The spheres that left
    // through the old outlet stay counted as deleted. A chute is not shortened: the spheres past
    // a new outlet would vanish uncounted as outflow of a chute they never reached the end of.
    void extendChute() {
        const double oldEnd = outlet.point().x(), end = maserLength + chuteLength;
        require(end > oldEnd, "--chute-length " + str(chuteLength) + " is shorter than the chute of the restart file (" +
                                  str(oldEnd - maserLength) + "): a chute can be extended, not shortened");
        const double added = layBase(oldEnd, end);
        outlet.setPlane(Vec3::UnitX(), Vec3(end, 0, 0));
        maser.setChuteEnd(*this, end);
        if (rank() == 0)
            std::printf("%s: chute extended from x = %g to %g at t = %g (%.0f base spheres added)\n", name().c_str(),
                    oldEnd, end, time(), added);
    }

    // Copies of the maser's base spheres, shifted downstream by whole box lengths, that fall in
    // [from, to); returns their number (summed over ranks: each rank copies the base it owns).
    double layBase(double from, double to) {
        const std::size_t n = particles().owned();
        double added = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (particles().species[i] != maserBase_) continue;
            const Vec3 x = particles().position[i];
            const double r = particles().radius[i];
            for (int k = 1; x.x() + k * maserLength < to; ++k) {
                if (x.x() + k * maserLength < from) continue;
                addFixedParticle(x + Vec3(k * maserLength, 0, 0), r, base);
                ++added;
            }
        }
        return sumOverRanks(added);
    }

    // The mass that the maser's flow carries through a section, per size, integrated over time:
    // divided by the box length, it is what should have crossed its downstream face.
    void accumulateBoxFlux() {
        const ParticleStore& p = particles();
        for (std::size_t i = 0; i < p.owned(); ++i) {
            if (p.species[i] == maserLarge_) unsummed_[0] += p.mass[i] * p.velocity[i].x() * timeStep();
            if (p.species[i] == maserSmall_) unsummed_[1] += p.mass[i] * p.velocity[i].x() * timeStep();
        }
    }

    struct Census {
        std::size_t box = 0, chute = 0;
        double chuteMass = 0, front = 0;
    };
    Census census() const {
        const ParticleStore& p = particles();
        std::vector<double> sum(3, 0.0);  // box, chute, chute mass
        double front = 0;
        for (std::size_t i = 0; i < p.owned(); ++i) {
            if (p.fixed[i]) continue;
            if (p.species[i] == maserLarge_ || p.species[i] == maserSmall_) {
                sum[0] += 1;
                continue;
            }
            sum[1] += 1;
            sum[2] += p.mass[i];
            front = std::max(front, p.position[i].x());
        }
        sumOverRanks(sum);
        return {static_cast<std::size_t>(sum[0]), static_cast<std::size_t>(sum[1]), sum[2], maxOverRanks(front)};
    }

    void sample(const ChuteSnapshot& box) {
        const Census c = census();
        if (rank() != 0) return;
        std::ostringstream line;
        line << time() << ' ' << (activatedAt_ >= 0) << ' ' << box.kineticEnergy << ' ' << box.massFlux << ' '
                << box.meanVelocity << ' ' << box.height << ' ' << box.smallConcentration << ' ' << maser.crossings() << ' '
                << maser.createdMass(large) << ' ' << maser.createdMass(small) << ' ' << c.chute << ' ' << c.chuteMass
                << ' ' << outlet.count() << ' ' << outlet.mass() << ' ' << c.front << ' ' << box.segregation << '\n';
        series_.append(line.str());
    }

    // Created = in the chute + deleted, to the particle; the maser keeps its spheres.
    void checkConservation() {
        if (activatedAt_ < 0) {
            if (rank() == 0)
                std::printf("%s: the maser was not activated by t = %g\n", name().c_str(), time());
            return;
        }
        const Census c = census();
        const double created = maser.seeded() + maser.crossings(), deleted = outlet.count();
        if (!conservationReported(c, created, deleted)) throw CollectiveError("mass is not conserved between the maser, the chute and the outlet", rank() != 0);
    }

    // Prints the balance (on rank 0); returns whether it holds. The counts must agree exactly; the
    // masses are the same terms summed in another order, so they agree to the rounding of a sum of
    // `created` terms (Math/SummationRounding.h), far below one particle's mass.
    bool conservationReported(const Census& c, double created, double deleted) const {
        const double createdMass = maser.seededMass() + maser.createdMass();
        const double accountedMass = c.chuteMass + outlet.mass();
        const bool conserved = created == static_cast<double>(c.chute) + deleted &&
                               c.box == static_cast<std::size_t>(boxParticles_) &&
                               equalUpToSummationRounding(createdMass, accountedMass, created);
        if (rank() != 0) return conserved;
        std::printf("%s: created %.0f (seeded %.0f + crossed %.0f) = in the chute %zu + deleted %.0f; maser holds %zu of "
                    "%.0f; created mass %.10g, in the chute + deleted %.10g (apart by %.2g): mass conserved: %s\n", name().c_str(),
                    created, maser.seeded(), maser.crossings(), c.chute, deleted, c.box, boxParticles_, createdMass,
                    accountedMass, std::abs(createdMass - accountedMass), conserved ? "yes" : "NO");
        // The inflow's composition: the small spheres' share of the created mass, against the
        // share of the mass the maser's flow carried through its face (the integral of m vx / L).
        const double carried[2] = {boxMassDisplacement_[0] / maserLength, boxMassDisplacement_[1] / maserLength};
        std::printf("%s: since t = %g: inflow mass large %.6g small %.6g (small share %.4f); carried by the maser's "
                    "flow: large %.6g small %.6g (small share %.4f)\n", name().c_str(), activatedAt_,
                    maser.createdMass(large), maser.createdMass(small),
                    maser.createdMass(small) / std::max(1e-300, maser.createdMass()), carried[0], carried[1],
                    carried[1] / std::max(1e-300, carried[0] + carried[1]));
        std::printf("%s: pairs across the maser's face beyond the one-way overlap limit (%g of the radius): %.0f pair-steps\n",
                    name().c_str(), OneWayPeriodicBox::reactionOverlap, oneWayReactions_);
        return conserved;
    }

    std::size_t maserLarge_ = 3, maserSmall_ = 4, maserBase_ = 5;
    double activatedAt_ = -1, boxParticles_ = 0, boxMassDisplacement_[2] = {0, 0};
    double oneWayReactions_ = 0;  // pair-steps across the maser's face past the reaction overlap
    std::vector<double> unsummed_ = std::vector<double>(3, 0.0);  // this rank's sums since the last sample
    PlateauDetector plateau_{50, 0.02};
    SeriesFile series_{*this, "series",
                       "# t active maserKineticEnergy maserMassFlux maserMeanVelocity maserHeight maserSmallConcentration"
                       " crossings createdMassLarge createdMassSmall chuteParticles chuteMass deleted deletedMass front"
                       " maserSegregation\n"};
};

int main(int argc, char** argv) {
    MaserFedChute chute;
    chute.setName("MaserFedChute");
    chute.setTimeStep(1e-4);
    chute.setEndTime(300);
    chute.setOutputInterval(5);
    return chute.solve(argc, argv);
}
