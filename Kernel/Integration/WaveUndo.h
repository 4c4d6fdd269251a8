// What a wave changes, kept at its start so that the wave can be undone (Integration/WaveStepper.h):
// a particle that speeds up within a wave past the neighbour list's allowance may have pairs the
// list lacks, so the wave is rolled back and its steps redone in single steps, which build the
// list anew where they need (Documentation/TimeSkewing.md, "Rolling a wave back").
//
// A wave of spheres (the drift pass's scenes) changes the particles' positions, velocities,
// angular velocities, forces and torques, the contact histories of the listed pairs and wall
// candidates, the time and the step, the near list (made anew, or its moves added up), the
// largest speed of the list, the workspace's forces of the last step, its position watch, its
// drift frame and largest displacement, and the records of an output step. The rest of the state
// (the particles' other arrays, the list's pairs, reference positions and reach, the species,
// walls and domain) it only reads. What the single steps read of it is put back: the particle
// arrays, the histories, the time and step, the list's largest speed, the position watch, drift
// frame and displacement. The rest they make anew before they read it: the forces of the last
// step (the drift pass swaps the forces in and overwrites them), the sweep's points, the records,
// and the near list, unmade here: the near list changes only which listed pairs are swept, not a
// force (Contacts/PairList.h NearPairs), so the single steps' results are those of single steps
// from the wave's start, to the bit.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "Contacts/ContactHistory.h"
#include "Integration/StepWorkspace.h"
#include "Math/Vector.h"

namespace talus {

struct SimulationState;

class WaveUndo {
public:
    // Keeps what the wave is about to change (into arrays kept from wave to wave: no allocation
    // once they have the particles' and pairs' sizes).
    void keep(const SimulationState& state, const StepWorkspace& work);
    // Puts it back (once: the kept arrays are swapped in).
    void restore(SimulationState& state, StepWorkspace& work);

private:
    std::vector<Vec3> position_, velocity_, angularVelocity_, force_, torque_;
    ContactHistories history_, wallHistory_;
    double time_ = 0, maxSpeed_ = 0, lastDisplacement_ = 0;
    std::uint64_t step_ = 0;
    std::optional<Vec3> driftFrame_;
    PositionWatch positions_;
};

}  // namespace talus
