// Demo 2 (Documentation/Tutorials/TwoParticleCollision.md): a head-on collision of two spheres,
// compared with the analytic restitution coefficient and collision time of Theory/ContactLaws.md
// eq. (10)-(11).
//
// Two unit-mass spheres (d = 1, density 6/pi) approach each other at relative speed 1 with no
// gravity. The linear spring-dashpot law is set from the wanted collision time tc and
// restitution e with the reduced mass m* = 1/2, so the contact must last tc and send the
// spheres apart at relative speed e. The driver measures both and prints the relative errors.
#include <cmath>
#include <cstdio>

#include "Sampling/Messages.h"
#include "Sampling/ParticleSums.h"
#include "Simulation.h"

using namespace talus;

class TwoParticleCollision : public Simulation {
public:
    double restitution = 0.88;
    double collisionTime = 0.005;
    double gap = 0.1;
    int plainVerlet = 0;

    TwoParticleCollision() {
        run().addFlag("restitution", "restitution coefficient e", restitution);
        run().addFlag("collision-time", "collision time tc", collisionTime);
        run().addFlag("gap", "initial distance between the surfaces", gap);
        run().addFlag("plain-verlet", "1: integrate the contact as LAMMPS and LIGGGHTS do (no treatment of its ends)",
                plainVerlet);
    }

    void setupInitialConditions() override {
        settings().timeStep = collisionTime / 50;  // --dt still overrides this
        const double reducedMass = 0.5;
        auto law = LinearSpringDashpot::fromCollision(collisionTime, restitution, reducedMass);
        law.treatContactEnds = !plainVerlet;
        const auto glass = scene().addSpecies("glass", 6 / pi, law);
        scene().setGravity(Vec3::Zero());
        scene().setDomain(Vec3(-2, -1, -1), Vec3(2, 1, 1));
        // Surfaces a gap apart, closing at speed 1: contact starts at t = gap exactly.
        scene().addParticle(Vec3(-0.5 - gap / 2, 0, 0), 0.5, glass, Vec3(0.5, 0, 0));
        scene().addParticle(Vec3(0.5 + gap / 2, 0, 0), 0.5, glass, Vec3(-0.5, 0, 0));
    }

    void actionsAfterTimeStep() override {
        const double gap = distance() - 1.0;
        if (gap < 0 && !touching_) touching_ = true;
        if (gap >= 0 && touching_ && !separated_) {
            separated_ = true;
            // The overlap -gap fell from previousGap_ to gap within this step: linear
            // interpolation.
            const double fraction = -previousGap_ / (gap - previousGap_);
            contactEnd_ = time() - settings().timeStep * (1 - fraction);
        }
        previousGap_ = gap;
    }

    void actionsAfterSolve() override {
        const auto v = gatherParticles(*this, allParticles()).velocity;
        const double restitutionMeasured = (v[1].x() - v[0].x()) / 1.0;
        const double durationMeasured = contactEnd_ - gap;
        const double errorE = std::abs(restitutionMeasured / restitution - 1);
        const double errorT = std::abs(durationMeasured / collisionTime - 1);
        say(*this, "restitution: measured %.6f, analytic %.6f, relative error %.2e\n", restitutionMeasured,
                    restitution, errorE);
        say(*this, "collision time: measured %.6e, analytic %.6e, relative error %.2e\n", durationMeasured,
                    collisionTime, errorT);
        say(*this, "agrees with the analytic tc and e to 1e-3: %s\n", separated_ && errorE < 1e-3 && errorT < 1e-3 ? "yes" : "no");
    }

private:
    double distance() const {
        const auto x = gatherParticles(*this, allParticles()).position;  // (both, whatever the rank count)
        return (x[1] - x[0]).norm();
    }
    bool touching_ = false, separated_ = false;
    double previousGap_ = INFINITY, contactEnd_ = 0;
};

int main(int argc, char** argv) {
    TwoParticleCollision collision;
    collision.settings().name = "TwoParticleCollision";
    collision.settings().endTime = 0.2;
    collision.settings().outputInterval = 0.002;
    return collision.solve(argc, argv);
}
