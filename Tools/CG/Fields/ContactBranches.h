// The contacts of a frame as branches carrying a tensor (Theory/CoarseGraining.md eq. (10);
// Fields/CoarseGrainer.h "Boundaries"): what the Cartesian (CoarseGrainer) and the cylindrical
// (CylindricalCoarseGrainer) coarse graining both spread, built once from the .fstat lines.
//
// For a pair the branch b runs from the partner's centre (its periodic image next to i) to the
// centre of i and f is the force on i; for a contact of a flowing particle with the boundary (a
// wall, or a fixed particle under --fixed boundary) it runs from the contact point c to the
// flowing particle's centre and f is the boundary's force on it, which is also spread from c as
// the InteractionForce. The lines of one pair (written once, or from both sides) make one branch
// whose force is their mean, so every contact counts once. Contacts within the boundary are left
// out. The tensor spread along the branch is f (x) b.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "Fields/CoarseGrainingSetup.h"
#include "IO/FstatFileReader.h"
#include "IO/ParticleFrame.h"

namespace talus::cg {

struct ContactBranch {
    Vec3 centre{};          // x_m, the centre of the flowing particle (i of the line, or j)
    Vec3 branch{};          // b: the segment runs from centre - b to centre
    Vec3 force{};           // f, the force on the particle at centre (the mean over the pair's lines)
    bool boundary = false;  // a boundary contact: its force f acts at centre - b
};

// Calls visit(branch) for every contact of the flow, ordered by pair (no list of branches is kept:
// a frame of 10^5 particles has about 6 10^5 lines). Throws InputError naming the file and line for
// contacts of particles beyond the frame and for contact points that do not lie on the particle's
// surface (the files of different runs). With `wanted`, a line whose contact point it declines is
// skipped before its branch is formed (a caller that needs only the branches near some points: a
// branch's ends lie within a bounding radius and an overlap of its contact point).
void forEachContactBranch(const ParticleFrame& frame, const ContactFrame& contacts, const CoarseGrainingSetup& setup,
                          const std::string& dataPath, const std::string& fstatPath,
                          const std::function<void(const ContactBranch&)>& visit,
                          const std::function<bool(const Vec3&)>& wanted = nullptr);

}  // namespace talus::cg
