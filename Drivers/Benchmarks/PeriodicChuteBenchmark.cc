// Benchmark (Documentation/Performance.md): the periodic bidisperse chute of
// Theory/Chutes.md eq. (2)-(4) as the peer codes run it (shared/peers/README.md, scenes B and C),
// timed from a LAMMPS start file.
//
// A rough base of fixed spheres (type 1, d = 1) carries 1000 flowing spheres of d = 1 (type 2) and
// 2000 of d = 0.79 (type 3), density 6/pi, in a box periodic in x (20) and y (10), inclined at 24
// degrees: g = (sin 24, 0, -cos 24). Contacts are linear spring-dashpots with kn = 2e5,
// kt = 2/7 kn, mu = 0.5 and the peers' damping convention: gamma = 50 per unit effective mass
// (gn = 50 m*, with m* the mass of the flowing sphere against the base or the floor), or with
// --damping absolute gn = 25 for every pair. A frictional floor at z = -0.5 under the base is only
// a safety net. dt = 1e-4; the run prints the flowing particles, steps, wall seconds of the time
// loop, particle-steps per second, the peak memory per particle and the mean downslope velocity.
// --nx and --ny replicate the start bed to scale the scene (10^4 to 10^6 flowing particles).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <string>

#include "Contacts/PairSweep.h"
#include "IO/LammpsDataFile.h"
#include "Integration/Integrator.h"
#include "Sampling/Messages.h"
#include "Sampling/ParticleSums.h"
#include "Sampling/RankReport.h"
#include "Simulation.h"

using namespace talus;

namespace {

// Resident memory of this process in bytes, as the kernel counts it (a field of
// /proc/self/status: VmHWM, the peak; RssAnon, RssFile, RssShmem, the parts of the present).
double memoryBytes(const std::string& field) {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind(field + ":", 0) == 0) return 1024.0 * std::stod(line.substr(field.size() + 1));
    return 0;
}

}  // namespace

class PeriodicChuteBenchmark : public Simulation {
public:
    std::string startFile = TALUS_SHARED_DIR "/peers/data/chute_B_settled.data";
    double angle = 24, stiffness = 2e5, friction = 0.5, dampingPerMass = 50, absoluteDamping = 25;
    double perturbation = 0;  // amplitude of random start velocities, for an ensemble of trajectories
    int nx = 1, ny = 1, absolute = 0, plainVerlet = 0, seed = 1;

    PeriodicChuteBenchmark() {
        run().addFlag("nx", "copies of the start bed along x", nx);
        run().addFlag("ny", "copies of the start bed along y", ny);
        run().addFlag("angle", "inclination in degrees", angle);
        run().addFlag("absolute-damping", "1: gn = 25 for every pair; 0: gn = 50 m* (the peers' default)", absolute);
        run().addFlag("plain-verlet", "1: contacts integrated as the peers do (no treatment of contact ends)", plainVerlet);
        run().addTextFlag("data", "LAMMPS data file (atom style sphere) to start from", startFile);
        run().addFlag("perturbation", "add random velocities up to this speed to the flowing spheres", perturbation);
        run().addFlag("seed", "seed of the random velocities", seed);
        baselineMemory_ = memoryBytes("RssAnon");
    }

    void setupInitialConditions() override {
        require(nx >= 1 && ny >= 1, "--nx and --ny must be at least 1");
        const LammpsData bed = readLammpsData(startFile);
        require(bed.types == 3, startFile + ": expected 3 atom types (base, large, small)");
        const Vec3 size = bed.hi - bed.lo;
        scene().setDomain(bed.lo, bed.lo + Vec3(nx * size.x(), ny * size.y(), size.z()));
        scene().setPeriodic(true, true, false);
        scene().setGravity(Vec3(std::sin(degrees(angle)), 0, -std::cos(degrees(angle))));

        // One species per atom type, with the mass of its spheres.
        std::map<int, double> massOf, densityOf;
        for (const LammpsAtom& a : bed.atoms) {
            massOf.emplace(a.type, a.density * pi / 6 * std::pow(a.diameter, 3));
            densityOf.emplace(a.type, a.density);
        }
        const char* names[] = {"base", "large", "small"};
        for (int type = 1; type <= 3; ++type)
            scene().addSpecies(names[type - 1], densityOf.at(type), contactLaw(massOf.at(type) / 2));
        // Pairs: the effective mass of two flowing spheres, or of the flowing one against the base.
        const auto lawFor = [&](int a, int b) {
            const double ma = massOf.at(a), mb = massOf.at(b);
            if (a == 1) return contactLaw(mb);
            if (b == 1) return contactLaw(ma);
            return contactLaw(ma * mb / (ma + mb));
        };
        for (int a = 1; a <= 3; ++a)
            for (int b = a; b <= 3; ++b) scene().species().setPair(a - 1, b - 1, lawFor(a, b));
        scene().addWall(Vec3::UnitZ(), Vec3(0, 0, -0.5), /*base*/ 0);

        scene().particles().reserve(static_cast<std::size_t>(nx) * ny * bed.atoms.size());  // no growth slack
        scene().random().seed(static_cast<std::uint64_t>(seed));
        std::uniform_real_distribution<double> noise(-perturbation, perturbation);
        for (int ix = 0; ix < nx; ++ix)
            for (int iy = 0; iy < ny; ++iy)
                for (const LammpsAtom& a : bed.atoms) {
                    const Vec3 x = a.position + Vec3(ix * size.x(), iy * size.y(), 0);
                    if (a.type == 1)
                        scene().addFixedParticle(x, a.diameter / 2, 0);
                    else
                        scene().addParticle(x, a.diameter / 2, a.type - 1,
                                    a.velocity + Vec3(noise(scene().random()), noise(scene().random()), noise(scene().random())),
                                    a.angularVelocity);
                }
    }

    // Whole-scene sums (Kernel/Sampling): the same numbers whatever the rank count.
    void actionsAfterSolve() override {
        // The peak of the memory the run allocated: the peak resident set less the pages of files
        // and shared memory (code and libraries paged in as the run goes, MPI's segments: a large
        // part of the resident growth of a small scene; they only grow, so the end's are their
        // peak) and less the allocations before the set-up.
        const double allocated =
            memoryBytes("VmHWM") - memoryBytes("RssFile") - memoryBytes("RssShmem") - baselineMemory_;
        // What each process counts for itself (its memory, contacts, listed pairs), and the
        // particles.
        const std::vector<double> sums = sumOverScene(*this, {allocated, double(contactSummary().contacts),
            double(state().pairList.pairs.size()), double(state().pairList.interiorPairs)});
        const double particleCount = totalsOver(*this, allParticles()).count;
        const std::vector<double> flowing = sumsOver(*this, mobileParticles(), {
            [](const ParticleStore& p, std::size_t i) { return p.velocity[i].x(); },
            [](const ParticleStore&, std::size_t) { return 1.0; }});
        const std::string ranks = describeRanks(*this);
        const RunStatistics& run = lastRun();
        say(*this, "benchmark: flowing %.0f  steps %llu  wall %.3f s  %.4g particle-steps/s  "
            "peak memory %.0f bytes/particle  mean vx %.6g  contacts %.0f  listed pairs %.0f (%.0f interior)  rebuilds %llu  "
            "%s  sweep %s  in-waves %llu\n",
            flowing[1], static_cast<unsigned long long>(run.steps), run.wallSeconds, run.particleStepsPerSecond(),
            sums[0] / particleCount, flowing[0] / flowing[1], sums[1], sums[2], sums[3],
            static_cast<unsigned long long>(state().pairList.builds), ranks.c_str(), sweepFormName(sweepForm()),
            static_cast<unsigned long long>(integrator().statistics().waves.stepsInWaves));
    }

private:
    LinearSpringDashpot contactLaw(double effectiveMass) const {
        const double damping = absolute ? absoluteDamping : dampingPerMass * effectiveMass;
        LinearSpringDashpot law{stiffness, damping, 2.0 / 7.0 * stiffness, damping, friction};
        law.treatContactEnds = !plainVerlet;
        return law;
    }
    double baselineMemory_ = 0;
};

int main(int argc, char** argv) {
    PeriodicChuteBenchmark chute;
    chute.settings().name = "PeriodicChuteBenchmark";
    chute.settings().timeStep = 1e-4;
    chute.settings().endTime = 5;  // 50000 steps
    chute.settings().skin = 0.2;   // as the peers' neighbor 0.2
    chute.settings().setFileOutput(false);
    return chute.solve(argc, argv);
}
