// Which directions the coarse-graining function resolves (Theory/CoarseGraining.md eq. (11)-(12)
// with averaging, Weinhart et al. 2012 for depth profiles): `XYZ` is a 3-D field; `XZ` averages
// over y, `Z` over x and y (a depth profile). The kernel then has the dimension of the resolved
// directions and each field is divided by the lengths of the averaged directions, taken from the
// domain box of the .data header, so that a depth profile of density integrates over z to mass per
// unit area.
//
// Cylindrical coordinates about a drum axis along x, y or z (Theory/RotatingDrum.md): `RZ` resolves
// the distance r from the axis and the coordinate s along it and averages over the angle; `R` also
// averages along the axis (divided by the box length along it). Their points keep r in slot 0 and s
// (the lab coordinate along the axis) in slot 2 of a Vec3; the fields are angular averages of the
// 3-D (RZ) or cross-section 2-D (R) kernel (Fields/CylindricalCoarseGrainer.h).
//
// `O` (MercuryCG's domain average) resolves nothing and has no kernel: one value per frame, each
// field the sum over the particles (and contacts) of the frame divided by the volume of the
// domain box (Fields/CoarseGrainer.h "The domain average").
#pragma once

#include <array>
#include <string>
#include <vector>

#include "IO/ParticleFrame.h"

namespace talus::cg {

class Coordinates {
public:
    // "XYZ", "XY", "XZ", "YZ", "X", "Y", "Z" (any case, letters in any order), "RZ", "R"
    // (cylindrical: the axis is set by setAxis), or "O" (the domain average); throws InputError.
    static Coordinates fromName(const std::string& name);

    std::string name() const;
    bool resolves(int axis) const { return resolved_[axis]; }
    const std::array<bool, 3>& resolvesAxes() const { return resolved_; }
    // Resolved coordinates: 3 for XYZ, 2 for XZ and RZ, 1 for Z and R, 0 for O.
    int dimension() const;
    // Dimension of the coarse-graining function: dimension() for Cartesian coordinates; 3 for RZ
    // (the 3-D kernel averaged over the angle), 2 for R (the kernel in the cross-section); 0 for O.
    int kernelDimension() const;
    // The resolved slots in increasing order (0 = x, 1 = y, 2 = z; cylindrical: 0 = r, 2 = s).
    std::vector<int> kernelAxes() const;
    // The column name of slot k: "x", "y", "z"; cylindrical: "r" and the axis letter for s.
    std::string coordinateName(int slot) const;
    // Product of the box lengths of the averaged directions (1 for XYZ and RZ; the length along
    // the axis for R; the box's volume for O).
    double averagedLength(const DomainBox& box) const;

    bool isCylindrical() const { return cylindrical_; }
    bool isDomainAverage() const { return dimension() == 0; }
    // The drum axis: direction 0, 1, 2 (x, y, z; -1 until set) through `point`.
    void setAxis(int axis, const Vec3& point);
    int axis() const { return axis_; }
    const Vec3& axisPoint() const { return axisPoint_; }

private:
    std::array<bool, 3> resolved_{true, true, true};
    bool cylindrical_ = false;
    int axis_ = -1;
    Vec3 axisPoint_{0, 0, 0};
};

char axisLetter(int axis);

}  // namespace talus::cg
