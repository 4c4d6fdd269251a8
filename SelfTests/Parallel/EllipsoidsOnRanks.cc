// Self-test of superquadrics on MPI ranks (Documentation/Parallel.md): what the physics conserves
// stays conserved when the scene is split.
//
// A cloud of ellipsoids (semi-axes 0.5, 0.25, 0.25) in open space: no gravity, no walls, no
// periodic face, frictional contacts. They start on a loose lattice at random orientations and
// spins, moving towards the cloud's centre (velocity -2 (x - centre), which would shrink the cloud
// to a point at t = 0.5, plus a random part), so that they collide within a few hundred steps,
// and the rank boundaries cut the crowd. Only contact forces act, each applied with its reaction at
// one contact point: the total momentum and the total angular momentum about any point (orbital
// m x × v plus each body's spin, the lab angular momentum of Particles/RigidBodyRotation.h) are
// constants of the motion, and velocity Verlet keeps both exactly but for round-off (a step's half
// kicks use forces and torques at one set of positions, where the pair sums cancel; the drift
// changes x × v by dt v × v = 0; the torque-free turn keeps the lab angular momentum). Walls,
// gravity or a periodic image would each exert a net torque, which is why the scene has none. After
// every step, summed over the ranks:
//  - the particle count and the sums of ids and squared ids equal their initial values exactly,
//    and every owned particle's mass is the one it started with, to the bit (so the mass is
//    conserved exactly, whatever order the ranks sum it in);
//  - momentum and angular momentum stay within round-off, relative to the sums of |m v| and of
//    |m x × v| + |L|. Measured over the 1000 steps on 1, 2 and 3 ranks alike: momentum within
//    3e-16 (tolerance 1e-14); angular momentum drifts by 1.7e-16 a step from the first step on,
//    before any contact, the same on one rank: the rounding of x + v dt in the drift changes
//    x × v. It reaches 7.3e-14 at step 500 and falls back as the contacts mix the rounding
//    errors; the tolerance is 1e-14 + 4e-16 per step, twice and a half the drift's slope.
// A chain of 19 ellipsoids at rest, tip to tip, lies far below the cloud (see below): its slow
// lasting contacts take the batched ellipsoid path (EllipsoidContactBatch.h), which the cloud's
// fast collisions never do. Measured: 1344, 1437 and 1548 contacts in the lanes on 1, 2 and 3
// ranks. The ranks' trajectories are compared with the serial run's by ellipsoidsOnRanks.sh. The
// run fails unless contacts happened, some of them in the batched lanes, and, on ranks, particles
// changed rank.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "Parallel/DomainSplit.h"
#include "Simulation.h"

using namespace talus;

class EllipsoidsOnRanks : public Simulation {
public:
    int perSide = 5;  // the lattice is perSide^3 ellipsoids

    EllipsoidsOnRanks() {
        run().addFlag("per-side", "ellipsoids along each side of the starting lattice", perSide);
        ranks().setRunsOnRanks(true);
    }

    void setupInitialConditions() override {
        require(perSide >= 2 && perSide <= 12, "--per-side must be 2 to 12");
        const Superquadric shape(0.5, 0.25, 0.25, 1, 1);
        const std::size_t ellipsoid = scene().addShape(shape);
        const double density = 6 / pi, mass = density * shape.volume();
        const auto grains =
            scene().addSpecies("grains", density, LinearSpringDashpot::fromCollision(0.005, 0.7, mass / 2).withFriction(0.5));
        scene().setGravity(Vec3::Zero());
        const double spacing = 1.05, side = 20;
        scene().setDomain(Vec3::Zero(), Vec3::Constant(side));
        const Vec3 centre = Vec3::Constant(side / 2);
        std::normal_distribution<double> gauss;
        for (int k = 0; k < perSide * perSide * perSide; ++k) {
            const Vec3 cell(k % perSide, (k / perSide) % perSide, k / (perSide * perSide));
            const Vec3 x = centre + spacing * (cell - Vec3::Constant(0.5 * (perSide - 1)));
            const Quat q = Quat(gauss(scene().random()), gauss(scene().random()), gauss(scene().random()), gauss(scene().random())).normalized();
            const Vec3 v = -2 * (x - centre) + 0.3 * Vec3(gauss(scene().random()), gauss(scene().random()), gauss(scene().random()));
            const Vec3 w(gauss(scene().random()), gauss(scene().random()), gauss(scene().random()));
            scene().addSuperquadric(x, ellipsoid, grains, q, v, w);
            initialMass_.push_back(scene().particles().mass.back());
        }
        // A chain at rest along x, far below the cloud, tip to tip with overlaps of 1e-9: every
        // rank boundary across x cuts one of its contacts, and the chain relaxes so slowly (speeds
        // of order 1e-6) that its lasting contacts go through the batched ellipsoid lanes, which
        // take a contact only when the last step's solution is within one Newton iteration.
        const double overlap = 1e-9;
        for (int k = 0; k < 19; ++k) {
            scene().addSuperquadric(Vec3(1 + k * (1 - overlap), 2, 2), ellipsoid, grains, Quat::Identity());
            initialMass_.push_back(scene().particles().mass.back());
        }
    }

    void actionsAfterTimeStep() override {
        const ParticleStore& p = scene().particles();
        bool massesKept = true;
        for (std::size_t i = 0; i < p.owned(); ++i) massesKept &= p.mass[i] == initialMass_.at(p.id[i]);
        const Vec3 centre = Vec3::Constant(10);
        // count, id sums (2), masses changed, momentum (3), angular momentum (3), their scales (2),
        // contacts, contacts in EllipsoidContactBatch's lanes, kinetic energy, mass
        std::vector<double> t(16, 0.0);
        for (std::size_t i = 0; i < p.owned(); ++i) {
            const double id = static_cast<double>(p.id[i]);
            const Vec3 momentum = p.mass[i] * p.velocity[i];
            const Vec3 orbital = (p.position[i] - centre).cross(momentum);
            t[0] += 1, t[1] += id, t[2] += id * id;
            for (int a = 0; a < 3; ++a) t[4 + a] += momentum[a], t[7 + a] += orbital[a] + p.angularMomentum[i][a];
            t[10] += momentum.norm();
            t[11] += orbital.norm() + p.angularMomentum[i].norm();
            t[14] += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
            t[15] += p.mass[i];
        }
        t[3] = massesKept ? 0 : 1;
        t[12] = static_cast<double>(contactSummary().contacts);
        t[13] = static_cast<double>(contactSummary().contactsInLanes);
        ranks().sum(t);
        contacts_ += t[12];
        contactsInLanes_ += t[13];
        if (initial_.empty()) initial_ = t;
        const double dp = (Vec3(t[4], t[5], t[6]) - Vec3(initial_[4], initial_[5], initial_[6])).norm() / t[10];
        const double dl = (Vec3(t[7], t[8], t[9]) - Vec3(initial_[7], initial_[8], initial_[9])).norm() / t[11];
        worstMomentum_ = std::max(worstMomentum_, dp);
        worstAngularMomentum_ = std::max(worstAngularMomentum_, dl);
        // Simulation::energies() over the whole scene: the owned particles of every rank, no ghost
        // counted twice (the same sums in the same order as t's, so to round-off of the order of
        // the ranks' sum at most).
        const Energies e = energies();
        const bool energiesOfTheScene =
            std::abs(e.kinetic - t[14]) <= 1e-12 * t[14] && std::abs(e.mass - t[15]) <= 1e-12 * t[15];
        const bool ok = energiesOfTheScene && t[0] == initial_[0] && t[1] == initial_[1] && t[2] == initial_[2] && t[3] == 0 &&
                        dp <= momentumTolerance && dl <= angularMomentumTolerance(step());
        if (!ok) {
            char m[500];
            std::snprintf(m, sizeof m,
                          "conservation broken at step %llu: energies() kinetic %.17g, mass %.17g against %.17g, %.17g; count %.0f (was %.0f), id sums %.0f %.0f (were %.0f %.0f), "
                          "%s, momentum change %.3g and angular momentum change %.3g of their scales (tolerances %.0g, %.2g)",
                          static_cast<unsigned long long>(step()), e.kinetic, e.mass, t[14], t[15], t[0], initial_[0], t[1], t[2], initial_[1],
                          initial_[2], t[3] == 0 ? "masses kept" : "a mass changed", dp, dl, momentumTolerance,
                          angularMomentumTolerance(step()));
            throw CollectiveError(m, ranks().rank() != 0);
        }
    }

    void actionsAfterSolve() override {
        const DomainSplit& split = *ranks().split();
        const double moved = ranks().sum(static_cast<double>(split.migrated));
        if (ranks().rank() == 0)
            std::printf("EllipsoidsOnRanks: %d ranks, %llu steps, %.0f contacts summed over steps (%.0f of them in the "
                        "batched ellipsoid lanes), %.0f particles changed rank: count, ids and masses kept exactly; "
                        "worst change of momentum %.2g, of angular momentum %.2g (of their scales)\n",
                        ranks().count(), static_cast<unsigned long long>(lastRun().steps), contacts_, contactsInLanes_,
                        moved, worstMomentum_, worstAngularMomentum_);
        if (contacts_ == 0) throw CollectiveError("no contacts: the test tested nothing", ranks().rank() != 0);
        if (contactsInLanes_ == 0)
            throw CollectiveError("no contact went through the batched ellipsoid lanes (EllipsoidContactBatch)",
                                  ranks().rank() != 0);
        if (ranks().count() > 1 && moved == 0)
            throw CollectiveError("no particle changed rank: the test tested little", ranks().rank() != 0);
    }

private:
    // (Measured and chosen: see the top of the file.)
    static constexpr double momentumTolerance = 1e-14;
    static double angularMomentumTolerance(std::uint64_t steps) { return 1e-14 + 4e-16 * static_cast<double>(steps); }
    std::vector<double> initialMass_;  // by id
    std::vector<double> initial_;
    double contacts_ = 0, contactsInLanes_ = 0, worstMomentum_ = 0, worstAngularMomentum_ = 0;
};

int main(int argc, char** argv) {
    EllipsoidsOnRanks cloud;
    cloud.settings().name = "EllipsoidsOnRanks";
    cloud.settings().timeStep = 2e-4;  // tc / 25
    cloud.settings().endTime = 0.2;
    cloud.settings().outputInterval = 0.1;
    cloud.settings().writeVtu = false;
    return cloud.solve(argc, argv);
}
