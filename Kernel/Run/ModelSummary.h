// What a run models, said in one line when it starts (Documentation/UserGuide/WritingADriver.md
// "What a run prints"): the particles and their shapes, the contact law and which of
// its parts act (friction and the tangential springs it keeps, rolling resistance, the treatment of
// the contact's ends), rotation, gravity, walls, periodic directions and the neighbour list's skin
// with where it came from. The stepper and lane form follow on the next line
// (Integrator::describeChoice).
#pragma once

#include <string>

#include "SimulationState.h"

namespace talus {

// The line, of the whole scene (call it before the scene is split over ranks); automaticSkin
// says that the run chose the skin (RunSettings::automaticSkin).
std::string describeModel(const SimulationState& state, bool automaticSkin);

}  // namespace talus
