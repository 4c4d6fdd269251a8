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
#include <cmath>
#include <cstdint>
#include <numeric>

#include "Fields/CoarseGrainer.h"
#include "Fields/VectorClones.h"
#include "Kernels/RadialShapes.h"

namespace talus::cg {

// The points sorted along one axis: index j of the sorted order is point order[j] at along[j].
struct PointsAlongAxis {
    std::vector<std::uint32_t> order;
    std::vector<double> along;
    double first = 0, spacing = 0;  // a grid's points: along[j] near first + j spacing (else spacing 0)

    PointsAlongAxis(const std::vector<Vec3>& points, int axis) : order(points.size()), along(points.size()) {
        std::iota(order.begin(), order.end(), 0u);
        std::stable_sort(order.begin(), order.end(),
                         [&](std::uint32_t a, std::uint32_t b) { return points[a][axis] < points[b][axis]; });
        for (std::size_t j = 0; j < order.size(); ++j) along[j] = points[order[j]][axis];
        if (along.size() < 2 || !(along.back() > along.front())) return;
        first = along.front();
        spacing = (along.back() - along.front()) / static_cast<double>(along.size() - 1);
        for (std::size_t j = 0; j < along.size(); ++j) {
            if (std::abs(along[j] - (first + static_cast<double>(j) * spacing)) > 0.25 * spacing) spacing = 0;
        }
    }

    // The sorted indices [first, last) of the points in [lo, hi], widened by a few units of
    // round-off: the kernel itself decides at the ends, as on the general path.
    std::pair<std::size_t, std::size_t> within(double lo, double hi) const {
        const double slack = 1e-12 * std::max({std::abs(lo), std::abs(hi), hi - lo});
        const std::size_t begin = firstNotBelow(lo - slack);
        std::size_t end = firstNotBelow(hi + slack);
        while (end < along.size() && along[end] <= hi + slack) ++end;  // (the first above, as upper_bound)
        return {begin, end};
    }

private:
    // The first index j with along[j] >= value (std::lower_bound's): on a grid from a guess by
    // arithmetic, moved to the exact place by comparisons, so the answer is bisection's.
    std::size_t firstNotBelow(double value) const {
        if (spacing == 0) return static_cast<std::size_t>(std::lower_bound(along.begin(), along.end(), value) - along.begin());
        const double guess = std::ceil((value - first) / spacing);
        std::size_t j = !(guess > 0) ? 0 : guess >= static_cast<double>(along.size()) ? along.size() : static_cast<std::size_t>(guess);
        while (j > 0 && along[j - 1] >= value) --j;
        while (j < along.size() && along[j] < value) ++j;
        return j;
    }
};

bool CoarseGrainer::alongOneAxis() const {
    return !cylindrical_ && !setup_.coordinates.isDomainAverage() && setup_.coordinates.kernelDimension() == 1 &&
           setup_.width.isDiagonal();
}

namespace {

// The weights of one source at the sorted points along[0, n): first in a loop without branches
// (which the compiler turns into vector code), then added point by point.
//
// A particle at x: W1(q) with q = |a_k (r_k - x_k)|, times the scale; zero beyond the cut-off.
template <class Profile>
void particleWeights(const double* along, std::size_t n, double x, double ak, double scale, double* weight) {
    for (std::size_t j = 0; j < n; ++j) {
        const double q = std::abs(ak * (along[j] - x));
        weight[j] = q < Profile::cutoff ? scale * Profile::ofDistance(q) : 0.0;
    }
}

// A segment from `start` whose extent along the axis is e in widths: the line integral
// KernelProfile::lineIntegralAlongAxisOf at each point, times the scale, with the ends clipped to
// the support; the rare points whose clipped interval is short, and every point of a segment
// across the axis (e = 0), take that function's answer.
template <class Profile>
void segmentWeights(const KernelProfile& profile, const double* along, std::size_t n, double start, double ak,
                    double e, double scale, double* weight) {
    const double factor = scale * profile.normalisation() / std::abs(e);
    for (std::size_t j = 0; j < n; ++j) {
        const double u0 = ak * (along[j] - start), u1 = u0 + e;
        // (Selections by value, not std::min and std::max, so that the loop has no branches.)
        const double smaller = u1 < u0 ? u1 : u0, larger = u1 < u0 ? u0 : u1;
        const double lo = smaller < -Profile::cutoff ? -Profile::cutoff : smaller;
        const double hi = larger > Profile::cutoff ? Profile::cutoff : larger;
        const double length = hi - lo;
        // (G / c_1 is odd; beyond the support the value is not used.)
        const double gHi = std::copysign(Profile::axialIntegral(std::abs(hi)), hi);
        const double gLo = std::copysign(Profile::axialIntegral(std::abs(lo)), lo);
        weight[j] = length > 0 ? factor * (gHi - gLo) : 0.0;
    }
    // A second pass (a count in the first would stop its vector code) for the short intervals.
    // (A branch across the axis, e = 0, has the kernel's value there: that function's answer.)
    auto takeShort = [&](std::size_t j) {  // (true where the clipped interval is short or empty)
        const double u0 = ak * (along[j] - start);
        const double length = std::min(std::max(u0, u0 + e), Profile::cutoff) - std::max(std::min(u0, u0 + e), -Profile::cutoff);
        if ((length > 0 && length < 1e-3) || e == 0) weight[j] = scale * profile.lineIntegralAlongAxisOf<Profile>(u0, e);
        return length < 1e-3;
    };
    // The clipped interval slides across the support as j grows (the points are sorted): its
    // length rises, stays at min(|e|, 2 cutoff), falls (each bound rounds monotonically), so
    // where that plateau is well above 1e-3 the short intervals are the first and last points
    // up to the first long one from each end.
    if (std::abs(e) < 2e-3) {
        for (std::size_t j = 0; j < n; ++j) takeShort(j);
        return;
    }
    std::size_t front = 0;
    while (front < n && takeShort(front)) ++front;
    for (std::size_t j = n; j > front + 1 && takeShort(j - 1); --j) {}
}

// A contact's nine terms, held by value: row[t] += w terms[t] then compiles to vector code (an
// array whose address went to contactTensor might, for all the compiler knows, be the row).
struct Tensor9 {
    double t[9];
    explicit Tensor9(const double (&tensor)[9]) { std::copy(tensor, tensor + 9, t); }
    void addWeighted(double w, double* __restrict row) const {
        for (int k = 0; k < 9; ++k) row[k] += w * t[k];
    }
};

}  // namespace

template <class Profile>
TALUS_CG_VECTOR_CLONES void CoarseGrainer::scatterParticlesAlongAxis(const std::vector<Vec3>& points,
                                                                     const PointsAlongAxis& byAxis,
                                                                     std::vector<double>& sums) const {
    const std::size_t fields = static_cast<std::size_t>(layout_.count());
    const int k = setup_.coordinates.kernelAxes()[0];
    const double ak = setup_.width.a()[4 * k];
    const double weightScale = scale_ * profile_.normalisation();
    std::vector<double> weight(points.size());
    static_assert(FieldSums::speciesDensity == 11, "the terms below fill the row up to the species densities");
    for (std::size_t i = 0; i < position_.size(); ++i) {
        const Vec3& x = position_[i];
        const auto [first, last] = byAxis.within(x[k] - halfExtent_[k], x[k] + halfExtent_[k]);
        if (first == last) continue;
        particleWeights<Profile>(byAxis.along.data() + first, last - first, x[k], ak, weightScale, weight.data());
        // The particle's terms of FieldSums (m, V, m v, m v v), formed once and added at each
        // point with its weight: a point costs eleven multiply-adds and the species' one.
        const Vec3& v = velocity_[i];
        const double m = mass_[i];
        const double terms[11] = {m,
                                  volume_[i],
                                  m * v[0],
                                  m * v[1],
                                  m * v[2],
                                  m * v[0] * v[0],
                                  m * v[0] * v[1],
                                  m * v[0] * v[2],
                                  m * v[1] * v[1],
                                  m * v[1] * v[2],
                                  m * v[2] * v[2]};
        const int speciesColumn = FieldSums::speciesDensity + species_[i];
        for (std::size_t j = first; j < last; ++j) {
            const double w = weight[j - first];
            if (w == 0) continue;
            double* row = sums.data() + byAxis.order[j] * fields;
            for (int t = 0; t < 11; ++t) row[t] += w * terms[t];
            row[speciesColumn] += w * m;
        }
    }
}

// Contact segments: from start_ along segment_, the line integral of the kernel along the axis
// (KernelProfile::lineIntegralAlongAxis), compiled once per shape; the tensor is formed once per
// segment.
template <class Profile>
TALUS_CG_VECTOR_CLONES void CoarseGrainer::scatterContactsAlongAxis(const std::vector<Vec3>& points,
                                                                    const PointsAlongAxis& byAxis,
                                                                    std::vector<double>& sums) const {
    const std::size_t fields = static_cast<std::size_t>(layout_.count());
    const int k = setup_.coordinates.kernelAxes()[0];
    const double ak = setup_.width.a()[4 * k];
    const double h = halfExtent_[k];
    std::vector<double> weight(points.size());
    for (std::size_t c = 0; c < contactStart_.size(); ++c) {
        const Vec3& segment = contactSegment_[c];
        const double start = contactStart_[c][k], end = start + segment[k];
        const auto [first, last] = byAxis.within(std::min(start, end) - h, std::max(start, end) + h);
        if (first == last) continue;
        segmentWeights<Profile>(profile_, byAxis.along.data() + first, last - first, start, ak, -ak * segment[k], scale_,
                                weight.data());
        double tensor[9];
        contactTensor(c, tensor);
        const Tensor9 terms(tensor);
        for (std::size_t j = first; j < last; ++j) {
            const double w = weight[j - first];
            if (w == 0) continue;
            terms.addWeighted(w, sums.data() + byAxis.order[j] * fields + layout_.contactStressIndex());
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
