// What a coarse-graining evaluation is set up with (Theory/CoarseGraining.md eq. (5)-(10)): the
// kernel (shape, width, coordinates), the periodic directions, the species densities, whether the
// contact stress is evaluated, and which particles are left out.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "Fields/Coordinates.h"
#include "Kernels/KernelProfile.h"
#include "Kernels/WidthMatrix.h"

namespace talus::cg {

struct CoarseGrainingSetup {
    KernelShape shape = KernelShape::Lucy;
    WidthMatrix width = WidthMatrix::isotropic(1.0);
    Coordinates coordinates = Coordinates::fromName("XYZ");
    std::array<bool, 3> periodic{false, false, false};
    std::vector<double> speciesDensity{6.0 / 3.141592653589793};  // by species index
    bool contactStress = false;
    // Per .data line: true for particles left out of the particle fields (fixed base particles
    // with --fixed exclude); empty: none left out.
    std::vector<bool> excluded;
    // --fixed boundary: the excluded particles are a boundary, like walls (CoarseGrainer.h
    // "Boundaries"): a contact of a flowing particle with one contributes stress only along the
    // branch from the flowing particle's centre to the contact point, and its force to the
    // InteractionForce density; contacts among excluded particles are left out.
    bool excludedAreBoundary = false;
};

// How many periodic lengths a kernel may reach over along a periodic axis that it resolves. Every
// image of a particle whose support overlaps the box is a source, about 2 R / L of them along an
// axis for a reach R and a periodic length L, so a tiny L (or a huge width) would make the frame
// practically endless to build. A kernel reaching over many lengths sees a field that is uniform
// along the axis, which averaging over the axis gives at once. (A width scan up to 2.5 box
// lengths with the Gauss kernel, cut off at 3 widths, reaches over 7.5.)
inline constexpr double maxReachInPeriodicLengths = 20;

// The periodic images each side (shifts n L with 0 < |n| <= the count returned) that a source
// reaching `reach` from its centre along the periodic `axis` of length L = `length` may need:
// ceil(reach / length) + 1. Throws
// InputError beyond maxReachInPeriodicLengths, naming `where` (the file and line of the frame),
// the periodic length and the kernel's reach and cut-off.
long periodicImagesEachSide(double reach, double cutoff, double length, int axis, const std::string& where);

}  // namespace talus::cg
