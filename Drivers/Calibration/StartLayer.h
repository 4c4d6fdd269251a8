// How many spheres of each size a calibration point starts with (Documentation/Calibration.md
// "One point"): the small spheres' share of the flowing volume, and the total from a depth that
// they fill at solid fraction 0.6 over the base's area, or a given number.
#pragma once

#include <cmath>
#include <cstddef>

#include "Math/Vector.h"  // (pi)

namespace talus {

struct StartLayer {
    std::size_t large = 0, small = 0;
    double volume = 0;  // of all the spheres
};

inline StartLayer startLayer(double smallShare, double smallDiameter, int particles, double depth, double area) {
    const double volumeL = pi / 6, volumeS = volumeL * std::pow(smallDiameter, 3);
    const double meanVolume = 1 / (smallShare / volumeS + (1 - smallShare) / volumeL);  // per sphere
    const double count = particles > 0 ? particles : std::round(0.6 * area * depth / meanVolume);
    StartLayer layer;
    layer.small = static_cast<std::size_t>(std::round(count * meanVolume * smallShare / volumeS));
    layer.large = static_cast<std::size_t>(count) - layer.small;
    layer.volume = layer.large * volumeL + layer.small * volumeS;
    return layer;
}

}  // namespace talus
