#include "Boundaries/Region.h"

#include <cmath>
#include <sstream>
#include <string>

#include "Error.h"

namespace talus {

namespace {

const char* axisName(int a) { return a == 0 ? "x" : a == 1 ? "y" : "z"; }

std::string str(const Vec3& v) {
    std::ostringstream s;
    s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return s.str();
}

// Whether [lo, hi] covers the whole period of a periodic axis of the domain: the region is then
// that period, without faces along the axis.
bool spansPeriod(const Domain& domain, int a, double lo, double hi) {
    return domain.periodic[a] && lo <= domain.lo[a] && hi >= domain.hi[a];
}

// A centre at least `margin` inside [lo, hi] along axis a (anywhere in the period if the
// interval spans it), from the draw u in [0, 1).
double within(const Domain& domain, int a, double lo, double hi, double margin, double u) {
    if (spansPeriod(domain, a, lo, hi)) lo = domain.lo[a], hi = domain.hi[a], margin = 0;
    return lo + margin + u * (hi - lo - 2 * margin);
}

// Whether a sphere of radius r at coordinate x lies in [lo, hi] along axis a.
bool withinFaces(const Domain& domain, int a, double lo, double hi, double x, double r) {
    return spansPeriod(domain, a, lo, hi) || (x >= lo + r && x <= hi - r);
}

double extent(const Domain& domain, int a, double lo, double hi) {
    return spansPeriod(domain, a, lo, hi) ? domain.length(a) : hi - lo;
}

void requireDiameterFits(const Domain& domain, int a, double lo, double hi, double radius, const std::string& what) {
    require(spansPeriod(domain, a, lo, hi) || hi - lo >= 2 * radius,
            what + " " + talus::str(hi - lo) + " wide along " + axisName(a) + ", less than the largest particle diameter " +
                talus::str(2 * radius));
}

}  // namespace

// --- box ---

Box::Box(const Vec3& lo, const Vec3& hi) : lo_(lo), hi_(hi) {
    require(isFinite(lo) && isFinite(hi) && (hi - lo).minCoeff() > 0,
            "box region: the upper corner " + str(hi) + " must lie above the lower corner " + str(lo) + " along x, y and z");
}

void Box::checkFits(double radius, const Domain& domain) const {
    for (int a = 0; a < 3; ++a) requireDiameterFits(domain, a, lo_[a], hi_[a], radius, "box region:");
}

Vec3 Box::randomPoint(double margin, const Domain& domain, std::mt19937_64& random) const {
    Vec3 x;
    for (int a = 0; a < 3; ++a) x[a] = within(domain, a, lo_[a], hi_[a], margin, uniformTop53(random));
    return x;
}

bool Box::holds(const Vec3& x, double r, const Domain& domain) const {
    for (int a = 0; a < 3; ++a)
        if (!withinFaces(domain, a, lo_[a], hi_[a], x[a], r)) return false;
    return true;
}

double Box::volume(const Domain& domain) const {
    return extent(domain, 0, lo_[0], hi_[0]) * extent(domain, 1, lo_[1], hi_[1]) * extent(domain, 2, lo_[2], hi_[2]);
}

void Box::bounds(const Domain& domain, Vec3& lo, Vec3& hi) const {
    for (int a = 0; a < 3; ++a) {
        const bool spans = spansPeriod(domain, a, lo_[a], hi_[a]);
        lo[a] = spans ? domain.lo[a] : lo_[a];
        hi[a] = spans ? domain.hi[a] : hi_[a];
    }
}

// --- cylinder ---

Cylinder::Cylinder(const Vec3& base, int axis, double length, double radius)
    : base_(base), axis_(axis), length_(length), radius_(radius) {
    require(axis >= 0 && axis <= 2, "cylinder region: axis must be 0 (x), 1 (y) or 2 (z), got " + std::to_string(axis));
    require(isFinite(base), "cylinder region: the base point " + str(base) + " is not finite");
    require(std::isfinite(length) && length > 0, "cylinder region: length must be positive, got " + talus::str(length));
    require(std::isfinite(radius) && radius > 0, "cylinder region: radius must be positive, got " + talus::str(radius));
}

void Cylinder::checkFits(double radius, const Domain& domain) const {
    require(radius_ >= radius, "cylinder region: radius " + talus::str(radius_) +
                                   " is less than the largest particle's bounding radius " + talus::str(radius));
    requireDiameterFits(domain, axis_, base_[axis_], base_[axis_] + length_, radius, "cylinder region: length");
}

Vec3 Cylinder::randomPoint(double margin, const Domain& domain, std::mt19937_64& random) const {
    // Uniform in the square of half-width radius - margin around the axis (the holds() test keeps
    // the disc), and along the axis. One draw per coordinate, z first, then y, then x: the order
    // in which the drum's filling always drew them.
    const double reach = radius_ - margin;
    Vec3 x;
    for (int a = 2; a >= 0; --a) {
        const double u = uniformRounded64(random);
        x[a] = a == axis_ ? within(domain, a, base_[a], base_[a] + length_, margin, u) : base_[a] + reach * (2 * u - 1);
    }
    return x;
}

bool Cylinder::holds(const Vec3& x, double r, const Domain& domain) const {
    return fromAxis(x) <= radius_ - r && withinFaces(domain, axis_, base_[axis_], base_[axis_] + length_, x[axis_], r);
}

double Cylinder::volume(const Domain& domain) const { return pi * radius_ * radius_ * axialLength(domain); }

void Cylinder::bounds(const Domain& domain, Vec3& lo, Vec3& hi) const {
    for (int a = 0; a < 3; ++a) {
        if (a != axis_) {
            lo[a] = base_[a] - radius_, hi[a] = base_[a] + radius_;
        } else {
            const bool spans = spansPeriod(domain, a, base_[a], base_[a] + length_);
            lo[a] = spans ? domain.lo[a] : base_[a];
            hi[a] = spans ? domain.hi[a] : base_[a] + length_;
        }
    }
}

double Cylinder::fromAxis(const Vec3& x) const {
    const int b = axis_ == 0 ? 1 : 0, c = axis_ == 2 ? 1 : 2;  // the two axes across
    return std::hypot(x[b] - base_[b], x[c] - base_[c]);
}

double Cylinder::axialLength(const Domain& domain) const {
    return extent(domain, axis_, base_[axis_], base_[axis_] + length_);
}

// --- annulus ---

Annulus::Annulus(const Vec3& base, int axis, double length, double innerRadius, double outerRadius)
    : Cylinder(base, axis, length, outerRadius), innerRadius_(innerRadius) {
    require(std::isfinite(innerRadius) && innerRadius >= 0,
            "annulus region: inner radius must not be negative, got " + talus::str(innerRadius));
    require(innerRadius < outerRadius, "annulus region: inner radius " + talus::str(innerRadius) +
                                           " must be less than the outer radius " + talus::str(outerRadius));
}

void Annulus::checkFits(double radius, const Domain& domain) const {
    require(radius_ - innerRadius_ >= 2 * radius, "annulus region: outer radius - inner radius = " +
                                                      talus::str(radius_ - innerRadius_) +
                                                      ", less than the largest particle diameter " + talus::str(2 * radius));
    Cylinder::checkFits(radius, domain);
}

bool Annulus::holds(const Vec3& x, double r, const Domain& domain) const {
    return fromAxis(x) >= innerRadius_ + r && Cylinder::holds(x, r, domain);
}

double Annulus::volume(const Domain& domain) const {
    return pi * (radius_ * radius_ - innerRadius_ * innerRadius_) * axialLength(domain);
}

}  // namespace talus
