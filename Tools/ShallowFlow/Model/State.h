// The state of one cell or face: the conserved variables (h, h u, h phi) of the depth-averaged model
// (Theory/DepthAveraged.md eq. (4)-(6)) and the primitive ones (h, u, phi), with the wet/dry
// treatment of Kurganov & Petrova (2007): below the dry height the velocity and concentration are
// desingularised instead of divided by a vanishing h.
#pragma once

namespace talus::shallow {

struct Conserved {
    double h = 0, hu = 0, hphi = 0;
};

struct Primitive {
    double h = 0, u = 0, phi = 0;
};

// u = 2 h (hu) / (h^2 + max(h^2, dry^2)), the same for phi (Kurganov & Petrova 2007, eq. (2.17)):
// u = hu / h where h >= dry, and tends to 0 with h in the dry cells. phi is clipped to [0, 1]:
// a concentration outside it (from round-off at a front) must not enter the fluxes.
Primitive toPrimitive(const Conserved& state, double dryHeight);

inline Conserved toConserved(const Primitive& p) { return {p.h, p.h * p.u, p.h * p.phi}; }

}  // namespace talus::shallow
