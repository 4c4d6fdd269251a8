#include "Particles/SpaceFillingCurve.h"

#include <algorithm>
#include <cmath>

#include "Error.h"

namespace talus {

namespace {

// Spreads the lowest 21 bits of v to every third bit (the standard "magic number" steps).
std::uint64_t spreadBits(std::uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffull;
    v = (v | v << 16) & 0x1f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
}

}  // namespace

std::uint64_t mortonKey(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    return spreadBits(x) | spreadBits(y) << 1 | spreadBits(z) << 2;
}

std::vector<std::size_t> spaceFillingCurveOrder(const std::vector<Vec3>& positions, const Vec3& lo, double cellSize,
                                                const std::vector<std::uint64_t>* ids) {
    require(cellSize > 0 && std::isfinite(cellSize),
            "space-filling curve: cell size must be positive and finite, got " + std::to_string(cellSize));
    constexpr double lastCell = (1 << 21) - 1;
    const auto cell = [&](double x, double origin) {
        return static_cast<std::uint32_t>(std::clamp(std::floor((x - origin) / cellSize), 0.0, lastCell));
    };
    struct Keyed {
        std::uint64_t key, tie;
        std::size_t slot;
        bool operator<(const Keyed& o) const { return key < o.key || (key == o.key && tie < o.tie); }
    };
    std::vector<Keyed> keyed(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const Vec3& x = positions[i];
        keyed[i] = {mortonKey(cell(x.x(), lo.x()), cell(x.y(), lo.y()), cell(x.z(), lo.z())), ids ? (*ids)[i] : i, i};
    }
    std::sort(keyed.begin(), keyed.end());  // ties broken by the id or the old slot (both unique)
    std::vector<std::size_t> order(positions.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = keyed[k].slot;
    return order;
}

}  // namespace talus
