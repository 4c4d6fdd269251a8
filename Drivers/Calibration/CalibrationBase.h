// The rough base of the calibration chute (Documentation/Calibration.md "One point"): a disordered
// layer of fixed spheres of one diameter, their centres within +-roughness diameter/2 of z = 0
// (Theory/Chutes.md "The rough base"), on a square layer of the same spheres 0.75 diameters below
// it, which plugs the random layer's rare holes: a flowing sphere that fell into one would rest on
// the safety wall, whose force the base's force (the sum over the fixed spheres) would miss (in a
// 6 x 6 point that happened, and the base seemed to carry 0.87 of the weight).
#pragma once

#include <cstdint>
#include <string>

#include "Chute/Chute.h"

namespace talus {

inline void addCalibrationBase(Chute& chute, double diameter, double roughness, std::size_t species, std::uint64_t seed) {
    const ChuteGeometry& box = chute.chuteGeometry();
    require(diameter > 0 && diameter <= 2,
            "--base-diameter " + str(diameter) + ": the base spheres' diameter must lie in (0, 2] large diameters");
    require(roughness >= 0 && roughness <= 1,
            "--base-roughness " + str(roughness) + ": the base spheres' heights must spread over [0, 1] diameters");
    chute.addBase(ChuteBase::disordered, diameter, species, seed, roughness);
    const int nx = static_cast<int>(box.length / diameter), ny = static_cast<int>(box.width / diameter);
    for (int i = 0; i < nx * ny; ++i)
        chute.scene().addFixedParticle(
            Vec3((i % nx + 0.5) * box.length / nx, (i / nx + 0.5) * box.width / ny, -0.75 * diameter), diameter / 2, species);
}

}  // namespace talus
