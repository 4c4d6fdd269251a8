#include "Numerics/Boundary.h"

#include "Model/InputError.h"

namespace talus::shallow {

BoundaryCondition::Kind parseBoundaryKind(const std::string& text, const std::string& option) {
    using Kind = BoundaryCondition::Kind;
    if (text == "inflow") return Kind::Inflow;
    if (text == "transmissive") return Kind::Transmissive;
    if (text == "wall") return Kind::Wall;
    if (text == "periodic") return Kind::Periodic;
    throw InputError(option + ": unknown boundary '" + text + "' (inflow, transmissive, wall or periodic)");
}

namespace {

// The ghost at distance k (1 or 2) outside the end whose last interior cell is `inner`, and whose
// interior cell at distance k - 1 from the end is `mirror`; `wrapped` is the periodic image.
Primitive ghost(const BoundaryCondition& b, const Primitive& inner, const Primitive& mirror, const Primitive& wrapped) {
    using Kind = BoundaryCondition::Kind;
    switch (b.kind) {
        case Kind::Inflow: return b.inflow;
        case Kind::Transmissive: return inner;
        case Kind::Wall: return {mirror.h, -mirror.u, mirror.phi};
        case Kind::Periodic: return wrapped;
    }
    return inner;
}

}  // namespace

void fillGhostCells(std::vector<Primitive>& c, const BoundaryCondition& left, const BoundaryCondition& right) {
    const std::size_t n = c.size(), g = ghostCells;
    const std::size_t first = g, last = n - g - 1;  // the interior cells at the two ends
    for (std::size_t k = 1; k <= g; ++k) {
        c[first - k] = ghost(left, c[first], c[first + k - 1], c[last + 1 - k]);
        c[last + k] = ghost(right, c[last], c[last - k + 1], c[first + k - 1]);
    }
}

}  // namespace talus::shallow
