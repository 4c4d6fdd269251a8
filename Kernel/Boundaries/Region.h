// Regions a filling puts particles into (Boundaries/Filling.h, Documentation/UserGuide/Insertion.md):
// a box, a cylinder about a coordinate axis, and an annulus (a cylinder with a coaxial core taken
// out). A region answers three questions: a random candidate centre, whether a particle's
// bounding sphere lies inside, and its volume (for a packing fraction). Along an axis where the
// domain is periodic and the region covers the whole period, the region is that period and has no
// faces: a particle may lie across the period's ends, and a candidate is drawn anywhere in it.
// A new region is a class here with the six functions below (Documentation/Architecture.md
// "Adding a part").
#pragma once

#include <algorithm>
#include <memory>
#include <random>

#include "Boundaries/Domain.h"
#include "Math/Vector.h"

namespace talus {

class Region {
public:
    virtual ~Region() = default;
    virtual std::unique_ptr<Region> clone() const = 0;

    // Throws, naming the parameter, unless a particle of bounding radius `radius` fits inside.
    virtual void checkFits(double radius, const Domain& domain) const = 0;
    // A candidate centre, uniform over a set that holds every point lying at least `margin`
    // inside the region (the box: exactly those; the cylinder and the annulus: the box around
    // their cross-section, so that holds() must sift the candidates).
    virtual Vec3 randomPoint(double margin, const Domain& domain, std::mt19937_64& random) const = 0;
    // Whether a sphere of radius r centred at x lies wholly inside (r = 0: whether x does).
    virtual bool holds(const Vec3& x, double r, const Domain& domain) const = 0;
    virtual double volume(const Domain& domain) const = 0;
    // A box that holds the region (for the overlap grid of the filling).
    virtual void bounds(const Domain& domain, Vec3& lo, Vec3& hi) const = 0;
};

// The box [lo, hi].
class Box : public Region {
public:
    Box(const Vec3& lo, const Vec3& hi);
    std::unique_ptr<Region> clone() const override { return std::make_unique<Box>(*this); }
    void checkFits(double radius, const Domain& domain) const override;
    Vec3 randomPoint(double margin, const Domain& domain, std::mt19937_64& random) const override;
    bool holds(const Vec3& x, double r, const Domain& domain) const override;
    double volume(const Domain& domain) const override;
    void bounds(const Domain& domain, Vec3& lo, Vec3& hi) const override;

private:
    Vec3 lo_, hi_;
};

// The cylinder of the given radius about the coordinate axis `axis` (0: x, 1: y, 2: z) through
// `base`, from base along the axis for `length`.
class Cylinder : public Region {
public:
    Cylinder(const Vec3& base, int axis, double length, double radius);
    std::unique_ptr<Region> clone() const override { return std::make_unique<Cylinder>(*this); }
    void checkFits(double radius, const Domain& domain) const override;
    Vec3 randomPoint(double margin, const Domain& domain, std::mt19937_64& random) const override;
    bool holds(const Vec3& x, double r, const Domain& domain) const override;
    double volume(const Domain& domain) const override;
    void bounds(const Domain& domain, Vec3& lo, Vec3& hi) const override;

protected:
    // Distance of x from the axis.
    double fromAxis(const Vec3& x) const;
    // Length along the axis: the period if the cylinder spans it.
    double axialLength(const Domain& domain) const;

    Vec3 base_;
    int axis_;
    double length_, radius_;
};

// The part of the cylinder of radius outerRadius outside the coaxial one of innerRadius.
class Annulus : public Cylinder {
public:
    Annulus(const Vec3& base, int axis, double length, double innerRadius, double outerRadius);
    std::unique_ptr<Region> clone() const override { return std::make_unique<Annulus>(*this); }
    void checkFits(double radius, const Domain& domain) const override;
    bool holds(const Vec3& x, double r, const Domain& domain) const override;
    double volume(const Domain& domain) const override;

private:
    double innerRadius_;
};

// A number uniform in [0, 1) from the top 53 bits of one draw (the box's draws, and the size
// distribution's). std::uniform_real_distribution would do, but the standard leaves its algorithm
// open; this way a seed gives the same particles with every standard library.
inline double uniformTop53(std::mt19937_64& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }
// A number uniform in [0, 1) from all 64 bits of one draw, rounded to the nearest double and kept
// below 1: what std::uniform_real_distribution<double>(0, 1) gives with libstdc++, written out so
// that it is the same with every standard library. The cylinder's draws, the drum's since its
// first filling: changing them would change its particles.
inline double uniformRounded64(std::mt19937_64& random) {
    return std::min(static_cast<double>(random()) * 0x1.0p-64, 1 - 0x1.0p-53);
}

}  // namespace talus
