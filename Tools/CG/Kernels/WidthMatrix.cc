#include "Kernels/WidthMatrix.h"

#include <Eigen/Dense>
#include <cmath>

#include "IO/InputError.h"

namespace talus::cg {

WidthMatrix WidthMatrix::isotropic(double width) {
    if (!(width > 0) || !std::isfinite(width)) throw InputError("--width must be positive, found " + str(width));
    return diagonal(width, width, width);
}

WidthMatrix WidthMatrix::diagonal(double wx, double wy, double wz) {
    for (double w : {wx, wy, wz}) {
        if (!(w > 0) || !std::isfinite(w)) throw InputError("--widths must be positive, found " + str(w));
    }
    WidthMatrix m;
    m.b_ = {wx, 0, 0, 0, wy, 0, 0, 0, wz};
    m.diagonal_ = true;
    return m;
}

WidthMatrix WidthMatrix::full(const std::array<double, 9>& b) {
    WidthMatrix m;
    m.b_ = b;
    m.diagonal_ = b[1] == 0 && b[2] == 0 && b[3] == 0 && b[5] == 0 && b[6] == 0 && b[7] == 0;
    return m;
}

void WidthMatrix::restrictTo(const Coordinates& coordinates) {
    const auto axes = coordinates.kernelAxes();
    const int d = static_cast<int>(axes.size());
    Eigen::MatrixXd b(d, d);
    for (int r = 0; r < d; ++r) {
        for (int c = 0; c < d; ++c) b(r, c) = b_[3 * axes[r] + axes[c]];
    }
    const double scale = b.cwiseAbs().maxCoeff();
    if (!((b - b.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale)) {
        throw InputError("--width-matrix must be symmetric");
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(b);
    if (!(eigen.eigenvalues().minCoeff() > 0)) {
        throw InputError("--width-matrix must be positive definite (smallest eigenvalue " +
                         str(eigen.eigenvalues().minCoeff()) + ")");
    }
    const Eigen::MatrixXd a = b.inverse();
    a_.fill(0);
    bRestricted_.fill(0);
    for (int r = 0; r < d; ++r) {
        for (int c = 0; c < d; ++c) {
            // Diagonal widths: exactly 1/w, not the cofactor formula's rounding of it.
            a_[3 * axes[r] + axes[c]] = !diagonal_ ? a(r, c) : r == c ? 1.0 / b(r, r) : 0.0;
            bRestricted_[3 * axes[r] + axes[c]] = b(r, c);
        }
    }
    // det(A) = 1/det(B); for the diagonal case the exact product of the inverse widths.
    determinant_ = 1;
    if (diagonal_) {
        for (int k : axes) determinant_ *= 1.0 / b_[4 * k];
    } else {
        determinant_ = 1.0 / b.determinant();
    }
}

double WidthMatrix::supportHalfExtent(int axis, double cutoff) const {
    // max e_k . r over |A r| <= R: r = B v with |v| <= R gives R |B^T e_k| = R |row k of B|.
    double sum = 0;
    for (int c = 0; c < 3; ++c) sum += bRestricted_[3 * axis + c] * bRestricted_[3 * axis + c];
    return cutoff * std::sqrt(sum);
}

}  // namespace talus::cg
