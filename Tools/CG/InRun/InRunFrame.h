// The adapter between a run and the coarse-graining library: the simulation's particles and the
// contacts its force loop recorded, as the library's frame types (IO/ParticleFrame.h,
// IO/FstatFileReader.h's ContactFrame), holding the numbers the .data and .fstat writers write
// (Kernel/IO/MercuryFormats.cc, Formats/) at full precision: positions, velocities, radii,
// species, masses (of any shape: the store's), fixed flags, contact points, overlaps, normals and
// the force on particle i.
//
// Lines are the store's slots: the owned particles, then on ranks the ghosts (frame.ghosts), which
// only the contacts refer to. A contact is one line for the pair (the records hold each pair once:
// Contacts/ContactReport.h), with the weight 1 that talus-cg gives a pair written once; a wall
// contact is j = -(wall + 1) with the normal into the wall, as the .fstat reader gives it.
#pragma once

#include <vector>

#include "Contacts/ContactReport.h"
#include "IO/FstatFileReader.h"
#include "IO/ParticleFrame.h"

namespace talus {
struct SimulationState;
}

namespace talus::cg {

// Fills `frame` (and `contacts` from `records`, when given) from the state after a step; `fixed`
// gets one flag per line.
void fillInRunFrame(const SimulationState& state, const ContactRecordList* records, ParticleFrame& frame,
                    ContactFrame& contacts, std::vector<bool>& fixed);

}  // namespace talus::cg
