// Self-test of the filling on MPI ranks (Boundaries/Filling.h, Documentation/Parallel.md): a
// filling during the run, while the scene is split, places the same particles as on one rank.
//
// In a drum-like box (periodic along y, open along x and z; no gravity) setupInitialConditions
// fills an annulus (radii 2 and 4) with spheres from a size distribution (every rank runs it on
// the whole scene). After step 2, when the scene is split, a second filling puts spheres and
// ellipsoids in turn into the cylinder of radius 4.5 that holds the annulus, so that its overlap
// test must see the particles the other ranks own (Sampling/ParticleSums.h gatherParticles).
// Nothing moves: no gravity, no velocities, and the filling leaves no overlaps, hence no forces.
// At the end rank 0 prints every particle, in id order: id, species, position and orientation
// with 17 digits. fillingOnRanks.sh requires that the runs on 1 and 2 ranks print the same lines.
#include <algorithm>
#include <cstdio>
#include <numeric>
#include <vector>

#include "Boundaries/Filling.h"
#include "Sampling/Messages.h"
#include "Sampling/ParticleSums.h"
#include "Simulation.h"

using namespace talus;

class FillingOnRanks : public Simulation {
public:
    FillingOnRanks() { ranks().setRunsOnRanks(true); }

    void setupInitialConditions() override {
        scene().setDomain(Vec3(-5, 0, -5), Vec3(5, 6, 5));
        scene().setPeriodic(false, true, false);
        scene().setGravity(Vec3::Zero());
        const auto law = LinearSpringDashpot::fromCollision(0.05, 0.5, 0.5);
        spheres_ = scene().addSpecies("spheres", 6 / pi, law);
        ellipsoids_ = scene().addSpecies("ellipsoids", 6 / pi, law);
        shape_ = static_cast<int>(scene().addShape(Superquadric::ellipsoid(0.5, 0.3, 0.3)));
        scene().random().seed(7);
        const Filling annulus(Annulus(Vec3::Zero(), 1, 6, 2, 4));
        const InsertionReport report = annulus.fill(*this, SizeDistribution::byNumber().addRange(spheres_, 0.3, 0.4),
                                                    InsertionReport::Target::count, 60);
        require(report.complete, report.describe());
    }

    void actionsAfterTimeStep() override {
        if (step() != 2) return;
        require(ranks().count() == 1 || ranks().isSplit(), "the scene is not split at step 2");
        std::vector<int> inserted = {0, 0};
        const InsertionReport report = Filling(Cylinder(Vec3::Zero(), 1, 6, 4.5))
                                           .fillInTurn(*this, {{.species = spheres_, .radius = 0.35, .target = 40},
                                                               {.species = ellipsoids_, .shape = shape_, .target = 40}},
                                                       inserted);
        say(*this, "filled during the run on %d ranks: %s\n", ranks().count(), report.describe().c_str());
    }

    void actionsAfterSolve() override {
        const ParticleStore p = gatherParticles(*this, allParticles());
        std::vector<std::size_t> order(p.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
        for (std::size_t i : order) {
            const Quat q = p.isShaped(i) ? p.orientation[i] : Quat::Identity();
            say(*this, "particle %llu species %u at %.17g %.17g %.17g turned %.17g %.17g %.17g %.17g\n",
                static_cast<unsigned long long>(p.id[i]), static_cast<unsigned>(p.species[i]), p.position[i].x(),
                p.position[i].y(), p.position[i].z(), q.w(), q.x(), q.y(), q.z());
        }
    }

private:
    std::size_t spheres_ = 0, ellipsoids_ = 0;
    int shape_ = -1;
};

int main(int argc, char** argv) {
    FillingOnRanks run;
    run.settings().name = "FillingOnRanks";
    run.settings().timeStep = 0.001;  // tc / 50
    run.settings().endTime = 0.005;
    return run.solve(argc, argv);
}
