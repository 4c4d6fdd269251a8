// The rotating drum of SPEC.md 5 (Documentation/Drums/RotatingDrum.md); the study is RotatingDrum.h.
#include "RotatingDrum.h"

int main(int argc, char** argv) {
    talus::RotatingDrum drum;
    drum.setName("RotatingDrum");
    drum.setTimeStep(talus::RotatingDrum::collisionTime / 50);  // SPEC.md 5: tc = 0.05
    drum.setEndTime(400);
    drum.setOutputInterval(10);
    return drum.solve(argc, argv);
}
