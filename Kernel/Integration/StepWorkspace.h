// What the steppers and the force computation keep from step to step that is not the run's saved
// state (SimulationState, which a restart file holds): the contact laws' pair tables, the forces
// of the last step, the contacts recorded at the last output step, the summary of the last force
// evaluation, the HGrid of the list builds, and what the drift pass and the near list need to
// know about the motion since the last step. All of it follows from the saved state, or is
// measured anew by the next step (a restart rebuilds it: Simulation::initialise).
#pragma once

#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "Contacts/ContactForces.h"
#include "Contacts/HGrid.h"
#include "Contacts/IdOrderedForceSums.h"

namespace talus {

struct SimulationState;

// The near list (NearPairs) holds while the particles move by the steps' drifts alone: a step
// that finds the positions other than the last step left them (a driver's hook moved particles
// by hand) unmakes it, to be made anew at the positions as they are. The positions are compared
// by their positionSum (Particles/DriftPass.h). (The neighbour list itself measures the
// particles' real displacements: PairList::needsRebuild.)
class PositionWatch {
public:
    // The positions a step or the set-up left, as positionSum of the owned particles.
    void noteLeft(std::uint64_t sum, std::size_t owned) {
        left_ = sum;
        particlesLeft_ = owned;
    }
    // The positions a step found: if not those left, the near list is unmade.
    void checkFound(std::uint64_t found, SimulationState& state);
    // Steps that found positions moved by hand (counted where the near list would have held).
    std::uint64_t changedBetweenSteps = 0;
    // This step found them moved (on ranks, every rank's near list is unmade: their ghosts moved).
    bool changedThisStep = false;

private:
    std::optional<std::uint64_t> left_;
    std::size_t particlesLeft_ = 0;
};

struct StepWorkspace {
    using LawTables = SpeciesTable::PairTables;  // (one per law of Species/ContactLaws.h)
    LawTables laws;
    HGrid grid;
    ContactSummary summary;         // of the last force evaluation
    ContactRecords records;         // of the last output step (each contact only with .fstat)
    double elasticEnergy = 0;       // of the recorded contacts
    std::size_t recordedContacts = 0;  // their number (on ranks, over all ranks)
    IdOrderedForceSums idOrderedForceSums;  // used with settings().idOrderedSums
    std::vector<Vec3> previousForce;  // the forces of the last step (ContactKinematics::otherAcceleration)
    // The frame velocity of the sweep's growths (PairSweep.h) the last drift pass or wave measured
    // (the mean velocity of the mobile particles); none after a step pass by pass.
    std::optional<Vec3> driftFrame;
    // The largest displacement since the list's build of the positions now (as the drift pass
    // measures it), for whether a wave has room.
    double lastDisplacement = 0;
    PositionWatch positions;
    // The contact histories a list build on ranks carries over (filled by the rank context; kept
    // from build to build for its memory, as PairList keeps its own).
    std::vector<CarriedHistory> carriedHistories;
};

}  // namespace talus
