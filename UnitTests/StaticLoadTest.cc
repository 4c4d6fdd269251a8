// A pair at rest under load feels no damping: the dashpot's implicit end-of-step speed includes
// the other forces on the pair (ContactKinematics::otherAcceleration). Without them a column of
// spheres resting on a floor would carry a spurious damping force of order gn dt g and sit at the
// wrong overlaps (0.7% for the contacts below, as the first version of the law did).
#include <gtest/gtest.h>

#include "ContactTestScenes.h"

using namespace talus;
using namespace talus::test;

// Three unit spheres (d = 1, m = 1) stacked on a floor under g = 1, started at the static
// overlaps: contact k from the top carries k m g, so its overlap is k m g / kn. They must stay.
TEST(StaticLoad, ColumnOfSpheresCarriesItsWeight) {
    const auto law = LinearSpringDashpot::fromCollision(0.005, 0.5, 0.5);  // strong damping
    const double kn = law.normalStiffness, weight = 1.0;
    const double floorOverlap = 3 * weight / kn, middleOverlap = 2 * weight / kn, topOverlap = weight / kn;
    TestScene scene;
    scene.setup = [&](TestScene& s) {
        s.scene().setGravity(Vec3(0, 0, -1));
        const auto species = s.scene().addSpecies("grain", unitMassDensity, law);
        s.scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species);
        const double z0 = 0.5 - floorOverlap, z1 = z0 + 1 - middleOverlap, z2 = z1 + 1 - topOverlap;
        for (double z : {z0, z1, z2}) s.scene().addParticle(Vec3(0, 0, z), 0.5, species);
    };
    scene.runFor(1e-4, 1.0);
    const auto& p = scene.scene().particles();
    EXPECT_NEAR(0.5 - p.position[0].z(), floorOverlap, 1e-6 * floorOverlap);
    EXPECT_NEAR(1 - (p.position[1].z() - p.position[0].z()), middleOverlap, 1e-6 * middleOverlap);
    EXPECT_NEAR(1 - (p.position[2].z() - p.position[1].z()), topOverlap, 1e-6 * topOverlap);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_LT(p.velocity[i].norm(), 1e-9);
}
