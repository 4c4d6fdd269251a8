// A sphere let go just touching a floor under gravity comes to rest where the normal spring
// carries its weight: kn (r - z) = m g, so z = r - m g / kn. The linear spring-dashpot's damping
// (restitution 0.5) takes the oscillation about that height down by a factor 0.5 every collision
// time tc = 0.005, so after 400 tc of a run of 2 time units it is far below round-off: the
// height must equal r - m g / kn to 1e-12 (the statics alone, not the integrator, give it).
#include <cmath>
#include <cstdio>

#include "Simulation.h"

class RestingSphere : public talus::Simulation {
public:
    bool atRest = false;

private:
    static constexpr double radius = 0.5, gravity = 1;
    talus::LinearSpringDashpot law_ = talus::LinearSpringDashpot::fromCollision(0.005, 0.5, 1.0);

    void setupInitialConditions() override {
        scene().setGravity(talus::Vec3(0, 0, -gravity));
        const auto species = scene().addSpecies("grain", 6 / talus::pi, law_);  // (mass 1 for radius 0.5)
        scene().addWall(talus::Vec3::UnitZ(), talus::Vec3::Zero(), species);
        scene().addParticle(talus::Vec3(0, 0, radius), radius, species);
    }
    void actionsAfterSolve() override {
        const double mass = scene().particles().mass[0];
        const double expected = radius - mass * gravity / law_.normalStiffness;
        const double height = scene().particles().position[0].z();
        std::printf("resting height %.15f, statics %.15f, difference %.1e\n", height, expected, height - expected);
        atRest = std::abs(height - expected) < 1e-12;
    }
};

int main(int argc, char** argv) {
    RestingSphere sphere;
    sphere.settings().name = "RestingSphere";
    sphere.settings().timeStep = 1e-4;
    sphere.settings().endTime = 2;
    const int status = sphere.solve(argc, argv);
    if (status != 0) return status;
    std::puts(sphere.atRest ? "at rest on its spring" : "not at the height of the statics");
    return sphere.atRest ? 0 : 2;
}
