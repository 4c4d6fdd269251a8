// The contacts of a frame as branches carrying a tensor (Theory/CoarseGraining.md eq. (10);
// Fields/CoarseGrainer.h "Boundaries"): what the Cartesian (CoarseGrainer) and the cylindrical
// (CylindricalCoarseGrainer) coarse graining both spread, built once from the .fstat lines.
//
// For a pair the branch b runs from the partner's centre (its periodic image next to i) to the
// centre of i and f is the force on i; for a contact of a flowing particle with the boundary (a
// wall, or a fixed particle under --fixed boundary) it runs from the contact point c to the
// flowing particle's centre and f is the boundary's force on it, which is also spread from c as
// the InteractionForce. Each line carries the weight 1/(lines of its pair in the frame), so a
// pair written from both sides counts once. Contacts within the boundary are left out.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "Fields/CoarseGrainingSetup.h"
#include "IO/FstatFileReader.h"
#include "IO/ParticleFrame.h"

namespace talus::cg {

struct ContactBranch {
    Vec3 centre{};                   // x_m, the centre of the flowing particle (i of the line, or j)
    Vec3 branch{};                   // b: the segment runs from centre - b to centre
    std::array<double, 9> tensor{};  // w f (x) b, row-major
    bool boundary = false;           // a boundary contact: its force w f acts at centre - b
    Vec3 force{};                    // w f, the force on the flowing particle
};

// Throws InputError naming the file and line for contacts of particles beyond the frame and for
// contact points that do not lie on the particle's surface (the files of different runs).
void contactBranches(const ParticleFrame& frame, const ContactFrame& contacts, const CoarseGrainingSetup& setup,
                     const std::string& dataPath, const std::string& fstatPath, std::vector<ContactBranch>& branches);

}  // namespace talus::cg
