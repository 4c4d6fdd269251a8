// Demo 1 (Documentation/Tutorials/BouncingBall.md): a sphere dropped on a flat floor.
//
// A ball of diameter 1 and mass 1 (density 6/pi) falls from height 2 under g = 1 onto an
// infinite plane. The linear spring-dashpot contact has collision time tc = 0.005 and
// restitution e = 0.8 against the floor, so each bounce keeps e^2 = 64% of the energy and the
// rebound heights shrink geometrically; the .ene file shows it.
#include "Simulation.h"

using namespace talus;

class BouncingBall : public Simulation {
    double restitution_ = 0.8;

public:
    BouncingBall() { run().addFlag("restitution", "restitution coefficient against the floor", restitution_); }

    void setupInitialConditions() override {
        const double mass = 1, collisionTime = 0.005;
        // A wall contact's reduced mass is the particle's mass.
        auto law = LinearSpringDashpot::fromCollision(collisionTime, restitution_, mass);
        const auto steel = scene().addSpecies("ball", 6 / pi, law);
        scene().setGravity(Vec3(0, 0, -1));
        scene().setDomain(Vec3(-1, -1, 0), Vec3(1, 1, 3));
        scene().addWall(Vec3::UnitZ(), Vec3::Zero(), steel);
        scene().addParticle(Vec3(0, 0, 2), 0.5, steel);
    }
};

int main(int argc, char** argv) {
    BouncingBall ball;
    ball.settings().name = "BouncingBall";
    ball.settings().timeStep = 1e-4;  // tc / 50
    ball.settings().endTime = 10;
    ball.settings().outputInterval = 0.05;
    return ball.solve(argc, argv);
}
