// A profile along one axis (coordinates X, Y or Z, a diagonal width): the sums of
// CoarseGrainer::evaluate with each source added to the points its support covers. Along one axis
// a source's support is an interval, and the points it covers are a run of the points sorted
// along the axis, found by bisection: every source met is one that reaches a point (the cell
// lists of the general path hand a point every source that reaches its cell, about twice as
// many along one axis), and no cell lists are built. A point's sums run over the sources in
// their order in the frame whatever the other points are, so a point of a grid and the same
// point alone get bitwise the same value. The terms are those of the general path
// (Theory/CoarseGraining.md eq. (5)-(10)); only their order differs.
#include <algorithm>
#include <cstdint>
#include <numeric>

#include "Fields/CoarseGrainer.h"
#include "Kernels/RadialShapes.h"

namespace talus::cg {

// The points sorted along one axis: index j of the sorted order is point order[j] at along[j].
struct PointsAlongAxis {
    std::vector<std::uint32_t> order;
    std::vector<double> along;

    PointsAlongAxis(const std::vector<Vec3>& points, int axis) : order(points.size()), along(points.size()) {
        std::iota(order.begin(), order.end(), 0u);
        std::stable_sort(order.begin(), order.end(),
                         [&](std::uint32_t a, std::uint32_t b) { return points[a][axis] < points[b][axis]; });
        for (std::size_t j = 0; j < order.size(); ++j) along[j] = points[order[j]][axis];
    }

    // The sorted indices [first, last) of the points in [lo, hi], widened by a few units of
    // round-off: the kernel itself decides at the ends, as on the general path.
    std::pair<std::size_t, std::size_t> within(double lo, double hi) const {
        const double slack = 1e-12 * std::max({std::abs(lo), std::abs(hi), hi - lo});
        const auto first = std::lower_bound(along.begin(), along.end(), lo - slack);
        const auto last = std::upper_bound(first, along.end(), hi + slack);
        return {static_cast<std::size_t>(first - along.begin()), static_cast<std::size_t>(last - along.begin())};
    }
};

bool CoarseGrainer::alongOneAxis() const {
    return !cylindrical_ && !setup_.coordinates.isDomainAverage() && setup_.coordinates.kernelDimension() == 1 &&
           setup_.width.isDiagonal();
}

template <class Profile>
void CoarseGrainer::scatterParticlesAlongAxis(const std::vector<Vec3>& points, const PointsAlongAxis& byAxis,
                                              std::vector<double>& sums) const {
    const Profile shape;
    const int fields = layout_.count();
    const int k = setup_.coordinates.kernelAxes()[0];
    const auto& a = setup_.width.a();
    const double weightScale = scale_ * profile_.normalisation();
    for (std::size_t i = 0; i < position_.size(); ++i) {
        const Vec3& x = position_[i];
        const auto [first, last] = byAxis.within(x[k] - halfExtent_[k], x[k] + halfExtent_[k]);
        const Vec3& v = velocity_[i];
        for (std::size_t j = first; j < last; ++j) {
            const std::uint32_t p = byAxis.order[j];
            const Vec3& r = points[p];
            // (A = diag(1/w) with zeros on the averaged axes: the general path's q^2 to the bit.)
            const double u0 = a[0] * (r[0] - x[0]), u1 = a[4] * (r[1] - x[1]), u2 = a[8] * (r[2] - x[2]);
            const double q2 = u0 * u0 + u1 * u1 + u2 * u2;
            if (q2 >= Profile::cutoffSquared) continue;
            const double w = weightScale * shape(q2);
            const double mw = mass_[i] * w;
            FieldSums::addParticle(sums.data() + static_cast<std::size_t>(p) * fields, mw, volume_[i] * w, v, species_[i]);
        }
    }
}

// Contact segments: from start_ along segment_, the line integral of the kernel along the axis
// (KernelProfile::lineIntegralAlongAxis), compiled once per shape.
template <class Profile>
void CoarseGrainer::scatterContactsAlongAxis(const std::vector<Vec3>& points, const PointsAlongAxis& byAxis,
                                             std::vector<double>& sums) const {
    const int fields = layout_.count();
    const int k = setup_.coordinates.kernelAxes()[0];
    const double ak = setup_.width.a()[4 * k];
    const double h = halfExtent_[k];
    for (std::size_t c = 0; c < contactStart_.size(); ++c) {
        const Vec3& segment = contactSegment_[c];
        const double start = contactStart_[c][k], end = start + segment[k];
        const auto [first, last] = byAxis.within(std::min(start, end) - h, std::max(start, end) + h);
        double tensor[9];  // (once per contact, not per point)
        contactTensor(c, tensor);
        const double e = -ak * segment[k];
        for (std::size_t j = first; j < last; ++j) {
            const std::uint32_t p = byAxis.order[j];
            const double line = profile_.lineIntegralAlongAxisOf<Profile>(ak * (points[p][k] - start), e);
            if (line == 0) continue;
            const double w = scale_ * line;
            double* row = sums.data() + static_cast<std::size_t>(p) * fields + layout_.contactStressIndex();
            for (int t = 0; t < 9; ++t) row[t] += w * tensor[t];
        }
    }
}

void CoarseGrainer::evaluateAlongOneAxis(const std::vector<Vec3>& points, std::vector<double>& sums) const {
    const int k = setup_.coordinates.kernelAxes()[0];
    const PointsAlongAxis byAxis(points, k);
    switch (setup_.shape) {
        case KernelShape::Lucy: scatterParticlesAlongAxis<LucyShape>(points, byAxis, sums); break;
        case KernelShape::Gauss: scatterParticlesAlongAxis<GaussShape>(points, byAxis, sums); break;
        case KernelShape::Heaviside: scatterParticlesAlongAxis<HeavisideShape>(points, byAxis, sums); break;
    }
    if (!setup_.contactStress) return;
    switch (setup_.shape) {
        case KernelShape::Lucy: scatterContactsAlongAxis<LucyShape>(points, byAxis, sums); break;
        case KernelShape::Gauss: scatterContactsAlongAxis<GaussShape>(points, byAxis, sums); break;
        case KernelShape::Heaviside: scatterContactsAlongAxis<HeavisideShape>(points, byAxis, sums); break;
    }
    // Boundary forces: the force at the contact point, spread by the kernel.
    const int fields = layout_.count();
    const double ak = setup_.width.a()[4 * k], h = halfExtent_[k];
    for (std::size_t c = 0; c < boundaryPoint_.size(); ++c) {
        const double at = boundaryPoint_[c][k];
        const auto [first, last] = byAxis.within(at - h, at + h);
        for (std::size_t j = first; j < last; ++j) {
            const std::uint32_t p = byAxis.order[j];
            const double u = ak * (points[p][k] - at);
            const double w = scale_ * profile_.value(u * u);
            double* row = sums.data() + static_cast<std::size_t>(p) * fields + layout_.interactionForceIndex();
            for (int d = 0; d < 3; ++d) row[d] += w * boundaryForce_[c][d];
        }
    }
}

}  // namespace talus::cg
