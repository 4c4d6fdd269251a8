// What a coarse-graining evaluation is set up with (Theory/CoarseGraining.md eq. (5)-(10)): the kernel (shape, width,
// coordinates), the periodic directions, the species densities, whether the contact stress is
// evaluated, and which particles are left out.
#pragma once

#include <array>
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
};

}  // namespace talus::cg
