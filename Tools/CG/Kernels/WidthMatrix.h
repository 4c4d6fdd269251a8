// The width of an anisotropic coarse-graining function (Theory/CoarseGraining.md eq. (1)):
// W(r) = det(A) W1(A r) with A symmetric positive definite. The user gives the width matrix
// B = A^{-1}, which has the widths along its eigenvectors: B = w I (isotropic), B = diag(wx, wy,
// wz) (widths per direction, the "w / lambda_k" of Theory/CoarseGraining.md eq. (1)), or any
// symmetric positive definite matrix (a kernel stretched along rotated axes). An isotropic kernel
// is the case A = I/w: one code path.
//
// Only the kernel's axes (the coordinates that are not averaged, Coordinates.h) take part: A is
// the inverse of B restricted to those axes, embedded in a 3x3 matrix with zero rows and columns
// for the averaged axes, so averaged coordinates never change u = A r.
#pragma once

#include <array>

#include "Fields/Coordinates.h"

namespace talus::cg {

class WidthMatrix {
public:
    // Isotropic width w.
    static WidthMatrix isotropic(double width);
    // Widths along x, y, z.
    static WidthMatrix diagonal(double wx, double wy, double wz);
    // A symmetric width matrix B (row-major 3x3; must be symmetric positive definite on the
    // kernel's axes: checked in restrictTo).
    static WidthMatrix full(const std::array<double, 9>& b);

    // A for the kernel axes of `coordinates`; throws InputError when B is not symmetric positive
    // definite there.
    void restrictTo(const Coordinates& coordinates);

    const std::array<double, 9>& a() const { return a_; }  // row-major, zero on averaged axes
    double determinant() const { return determinant_; }     // det(A) on the kernel axes
    bool isDiagonal() const { return diagonal_; }
    const std::array<double, 9>& widths() const { return b_; }  // B as given
    // Half-extent along lab axis k of the support {r : |A r| < R} = R |row k of B| (zero for
    // averaged axes): the box that holds the kernel, for binning and periodic images.
    double supportHalfExtent(int axis, double cutoff) const;

private:
    std::array<double, 9> b_{};
    std::array<double, 9> a_{};
    std::array<double, 9> bRestricted_{};
    double determinant_ = 1;
    bool diagonal_ = true;
};

}  // namespace talus::cg
