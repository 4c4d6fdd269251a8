// Self-test of the MPI domain split (Documentation/Parallel.md): nothing is lost or duplicated.
//
// A frictional granular gas in a box periodic along x, y and z, without gravity, drifting along
// x at ten times its thermal speed: over the run every particle crosses the periodic face in x
// and the boundaries between ranks several times, and the ranks keep exchanging particles,
// ghosts and contact histories. After every step the sums over ranks of the particle count,
// the sums of ids and of squared ids (a lost particle and a duplicated one would change them),
// the mass and the momentum must equal their initial values: the count and id sums exactly, the
// mass to round-off, and the momentum to round-off of the sum of |m v| (contact forces come in
// equal and opposite pairs, also across ranks, so momentum is conserved up to summation order).
// The run fails unless particles did change rank along every split axis (--rank-grid), and,
// with three ranks or more along x, across the periodic face too.
#include <cmath>
#include <cstdio>
#include <random>

#include "Boundaries/InsertionBoundary.h"
#include "Parallel/DomainSplit.h"
#include "Simulation.h"

using namespace talus;

class ParallelConservation : public Simulation {
public:
    int particleCount = 600;
    double drift = 10;

    ParallelConservation() {
        run().addFlag("particles", "number of spheres", particleCount);
        run().addFlag("drift", "mean velocity along x (thermal speed 1)", drift);
        ranks().setRunsOnRanks(true);
    }

    void setupInitialConditions() override {
        const Vec3 box(16, 5, 5);  // a packing fraction of 0.17 for 600 spheres
        scene().setDomain(Vec3::Zero(), box);
        scene().setPeriodic(true, true, true);
        scene().setGravity(Vec3::Zero());
        const double meanMass = 6 / pi * pi / 6 * 0.6 * 0.6 * 0.6;
        const auto grains =
            scene().addSpecies("grains", 6 / pi, LinearSpringDashpot::fromCollision(0.01, 0.8, meanMass / 2).withFriction(0.5));
        InsertionBoundary fill(Vec3::Zero(), box, SizeDistribution::byNumber().addRange(grains, 0.25, 0.35));
        const InsertionReport report = fill.insertCount(*this, static_cast<std::size_t>(particleCount));
        require(report.complete, report.describe());
        std::normal_distribution<double> thermal(0, 1);
        ParticleStore& p = scene().particles();
        for (std::size_t i = 0; i < p.size(); ++i)
            p.velocity[i] = Vec3(drift + thermal(scene().random()), thermal(scene().random()), thermal(scene().random()));
    }

    void actionsAfterTimeStep() override {
        const std::vector<double> now = totals();
        if (initial_.empty()) initial_ = now;  // after the first step (the forces have not moved mass yet)
        const double momentumScale = now[7];
        const bool ok = now[0] == initial_[0] && now[1] == initial_[1] && now[2] == initial_[2] &&
                        std::abs(now[3] - initial_[3]) <= 1e-13 * initial_[3] &&
                        (Vec3(now[4], now[5], now[6]) - Vec3(initial_[4], initial_[5], initial_[6])).norm() <=
                            1e-12 * momentumScale;
        worstMomentumError_ =
            std::max(worstMomentumError_,
                     (Vec3(now[4], now[5], now[6]) - Vec3(initial_[4], initial_[5], initial_[6])).norm() / momentumScale);
        if (!ok) {
            char m[400];
            std::snprintf(m, sizeof m,
                          "conservation broken at step %llu: count %.0f (was %.0f), id sums %.0f %.0f (were %.0f %.0f), "
                          "mass %.17g (was %.17g), momentum (%.17g %.17g %.17g) (was (%.17g %.17g %.17g))",
                          static_cast<unsigned long long>(step()), now[0], initial_[0], now[1], now[2], initial_[1],
                          initial_[2], now[3], initial_[3], now[4], now[5], now[6], initial_[4], initial_[5],
                          initial_[6]);
            throw CollectiveError(m, ranks().rank() != 0);
        }
    }

    void actionsAfterSolve() override {
        const DomainSplit& split = *ranks().split();
        std::vector<double> moved = {double(split.migrated), double(split.migratedFar), double(split.ghostsSent()),
                                     double(split.migratedAlong[0]), double(split.migratedAlong[1]),
                                     double(split.migratedAlong[2])};
        ranks().sum(moved);
        const auto [gx, gy, gz] = split.grid();
        if (ranks().rank() == 0)
            std::printf("ParallelConservation: %d ranks (%dx%dx%d), %llu steps: count, ids, mass and momentum kept every "
                        "step (worst momentum change %.2g of sum |m v|); %.0f particles changed rank (cell along x, "
                        "y, z: %.0f, %.0f, %.0f), %.0f of them across the periodic face, %.0f ghosts at the end\n",
                        ranks().count(), gx, gy, gz, static_cast<unsigned long long>(lastRun().steps),
                        worstMomentumError_, moved[0], moved[3], moved[4], moved[5], moved[1], moved[2]);
        if (ranks().count() > 1 && moved[0] == 0)
            throw CollectiveError("no particle changed rank: the test tested nothing", ranks().rank() != 0);
        for (int a = 0; a < 3; ++a)
            if (split.grid()[a] > 1 && moved[3 + a] == 0)
                throw CollectiveError("no particle changed cell along axis " + std::to_string(a), ranks().rank() != 0);
        if (gx > 2 && moved[1] == 0)
            throw CollectiveError("no particle crossed the periodic face between ranks", ranks().rank() != 0);
    }

private:
    // count, sum of ids, sum of squared ids, mass, momentum (3), sum of |m v|; over all ranks.
    std::vector<double> totals() const {
        const ParticleStore& p = scene().particles();
        std::vector<double> t(8, 0.0);
        for (std::size_t i = 0; i < p.owned(); ++i) {
            const double id = static_cast<double>(p.id[i]);
            t[0] += 1;
            t[1] += id;
            t[2] += id * id;
            t[3] += p.mass[i];
            const Vec3 momentum = p.mass[i] * p.velocity[i];
            t[4] += momentum.x(), t[5] += momentum.y(), t[6] += momentum.z();
            t[7] += momentum.norm();
        }
        ranks().sum(t);
        return t;
    }
    std::vector<double> initial_;
    double worstMomentumError_ = 0;
};

int main(int argc, char** argv) {
    ParallelConservation gas;
    gas.settings().name = "ParallelConservation";
    gas.settings().timeStep = 2e-4;  // tc / 50
    gas.settings().endTime = 3.2;    // the drift carries every particle twice through the box
    gas.settings().setFileOutput(false);
    return gas.solve(argc, argv);
}
