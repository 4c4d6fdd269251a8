// The test driver of in-run coarse graining in cylindrical coordinates (InRun/InRunFields.h;
// Documentation/CoarseGraining.md "Fields during a run"): the rotating drum of
// Drivers/Drum/RotatingDrum.h (its flags), with a field in coordinates RZ about the drum's axis
// (y through the origin; Lucy of width 1; r in (0, --radius) by 8 points, y in (0, --length) by
// 2) sampled at the output steps, fixed particles (the wall) as --fixed says, where the run also
// writes its .data/.fstat/.restart: talus-cg can coarse-grain the same frames
// (checkInRunAgainstFiles.py compares the two).
#include <string>

#include "InRun/InRunFields.h"
#include "RotatingDrum.h"

using namespace talus;

class InRunDrum : public RotatingDrum {
public:
    std::string fixed = "boundary";

    InRunDrum() { run().addTextFlag("fixed", "fixed particles in the fields: include, exclude or boundary", fixed); }

private:
    cg::InRunOptions cylinderOptions() const {
        require(fixed == "include" || fixed == "exclude" || fixed == "boundary", "--fixed: include, exclude or boundary");
        return {.name = settings().name + ".cylinder", .coordinates = "RZ", .axis = 1, .width = 1, .count = {8, 1, 2},
                .lo = cg::Vec3{0, 0, 0}, .hi = cg::Vec3{radius, 0, length}, .everyTime = settings().outputInterval,
                .averaging = cg::InRunAveraging::snapshots,
                .fixed = fixed == "include"   ? cg::FixedParticles::include
                         : fixed == "exclude" ? cg::FixedParticles::exclude
                                              : cg::FixedParticles::boundary};
    }
    cg::InRunFields cylinder_{*this, [this] { return cylinderOptions(); }};
};

int main(int argc, char** argv) {
    InRunDrum drum;
    drum.settings().name = "InRunDrum";
    drum.settings().timeStep = RotatingDrum::collisionTime / 50;
    drum.settings().skin = 0.4;
    drum.settings().endTime = 40;
    drum.settings().outputInterval = 5;
    drum.settings().writeVtu = false;
    return drum.solve(argc, argv);
}
