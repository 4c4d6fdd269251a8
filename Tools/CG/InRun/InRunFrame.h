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
class Simulation;
}

namespace talus::cg {

struct InRunFrame {
    ParticleFrame particles;
    ContactFrame contacts;     // empty unless withContacts
    bool withContacts = false;
    std::vector<bool> fixed;   // one flag per line
};

// The frame of the simulation's current step, filled at the first call of the step and shared by
// the objects that sample the same step (each would otherwise copy the same numbers): with the
// contacts of `records` when given (a frame filled without them is filled again). The frame is
// kept per thread; forgetSharedInRunFrame(), called as each object starts a run, drops it, so a
// run never sees the frame of another.
const InRunFrame& sharedInRunFrame(const Simulation& simulation, const ContactRecordList* records);
void forgetSharedInRunFrame();

}  // namespace talus::cg
