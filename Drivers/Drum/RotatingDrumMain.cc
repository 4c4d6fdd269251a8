// The rotating drum of Theory/RotatingDrum.md (Documentation/Drums/RotatingDrum.md); the study is
// RotatingDrum.h.
#include "RotatingDrum.h"

int main(int argc, char** argv) {
    talus::RotatingDrum drum;
    drum.settings().name = "RotatingDrum";
    drum.settings().timeStep = talus::RotatingDrum::collisionTime / 50;  // Theory/RotatingDrum.md eq. (1): tc = 0.05
    // The automatic skin (0.2 x the smallest radius) would follow the wall's small spheres: 0.05,
    // which the flowing layer crosses in some 20 steps, each crossing a new neighbour list; an
    // ellipsoid's list build (the contacts' histories carried over, bounding spheres of radius up
    // to 0.79 at R = 2) costs more than a sphere's, so the list is kept longer still
    // (Documentation/Drums/RotatingDrum.md "Cost").
    drum.settings().skin = 0.4;
    // Contacts of moving ellipsoids end their Newton solve after one iteration at this tolerance,
    // two at the kernel's 1e-10; the overlap then differs by some 5e-9 of a radius
    // (Theory/Superquadrics.md eq. (7a); Documentation/Drums/RotatingDrum.md "Cost").
    drum.settings().shapeTolerance = 1e-6;
    drum.settings().endTime = 400;
    drum.settings().outputInterval = 10;
    return drum.solve(argc, argv);
}
