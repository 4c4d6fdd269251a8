// Which directions the coarse-graining function resolves (SPEC.md 6 with averaging, Weinhart et
// al. 2012 for depth profiles): `XYZ` is a 3-D field; `XZ` averages over y, `Z` over x and y
// (a depth profile). The kernel then has the dimension of the resolved directions and each
// field is divided by the lengths of the averaged directions, taken from the domain box of the
// .data header, so that a depth profile of density integrates over z to mass per unit area.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "IO/ParticleFrame.h"

namespace talus::cg {

class Coordinates {
public:
    // "XYZ", "XY", "XZ", "YZ", "X", "Y", "Z" (any case, letters in any order); throws InputError.
    static Coordinates fromName(const std::string& name);

    std::string name() const;
    bool resolves(int axis) const { return resolved_[axis]; }
    const std::array<bool, 3>& resolvesAxes() const { return resolved_; }
    int dimension() const;
    // The resolved axes in increasing order (0 = x, 1 = y, 2 = z).
    std::vector<int> kernelAxes() const;
    // Product of the box lengths of the averaged directions (1 for XYZ).
    double averagedLength(const DomainBox& box) const;

private:
    std::array<bool, 3> resolved_{true, true, true};
};

char axisLetter(int axis);

}  // namespace talus::cg
