// The smallest useful driver: one sphere resting on a floor (compiled out of tree by a self-test).
#include "Simulation.h"

class RestingSphere : public talus::Simulation {
    void setupInitialConditions() override {
        const auto law = talus::LinearSpringDashpot::fromCollision(0.005, 0.5, 1.0);
        const auto species = scene().addSpecies("grain", 6 / talus::pi, law);
        scene().addWall(talus::Vec3::UnitZ(), talus::Vec3::Zero(), species);
        scene().addParticle(talus::Vec3(0, 0, 0.5), 0.5, species);
    }
};

int main(int argc, char** argv) {
    RestingSphere sphere;
    sphere.settings().name = "RestingSphere";
    sphere.settings().timeStep = 1e-4;
    sphere.settings().endTime = 1;
    return sphere.solve(argc, argv);
}
