// The simulation box: its extent along x, y, z, and which axes are periodic
// (Theory/Chutes.md eq. (1) uses x and y). Along a periodic axis positions are kept in [lo, hi) and
// pair separations use the nearest image; along the other axes the extent only frames the output.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "Math/Vector.h"

namespace talus {

// A box along x that is periodic one way inside a domain that is open along x: the activated
// maser of Theory/Maser.md (Boundaries/MaserBoundary.h). Mobile particles of its species near the
// upstream face (lo) feel the particles of its species near the downstream face (hi) through
// their images shifted by -(hi - lo); those near the downstream face do not feel the upstream
// ones. Listed as PairList::oneWayPairs.
struct OneWayPeriodicBox {
    bool active = false;
    double lo = 0, hi = 0;
    // Per species: the species a particle of the box becomes when it leaves through the
    // downstream face, or -1 for species that are not the box's. Set before activation too
    // (MaserBoundary::maserSpecies), so that the restart file keeps it in both phases.
    std::vector<std::int32_t> outflowSpecies;

    // Past this overlap (a fraction of the smaller radius) a pair across the face stops being
    // purely one way: the downstream particle feels the part of the normal force that the
    // overlap beyond it makes (continuous, zero at the threshold). Normal overlaps are a few
    // thousandths of a radius; the valve only keeps a slow flow from pressing a downstream
    // particle through an upstream one that sits against the base (ContactForceLoop::oneWayPairs).
    static constexpr double reactionOverlap = 0.1;

    double length() const { return hi - lo; }
    bool isMember(std::uint32_t species) const {
        return species < outflowSpecies.size() && outflowSpecies[species] >= 0;
    }
};

struct Domain {
    Vec3 lo = Vec3::Zero();
    Vec3 hi = Vec3::Ones();
    std::array<bool, 3> periodic{false, false, false};
    OneWayPeriodicBox oneWay;

    double length(int axis) const { return hi[axis] - lo[axis]; }
    bool anyPeriodic() const { return periodic[0] || periodic[1] || periodic[2]; }

    // What a position must lie in, per axis, to need no wrap: [lo, hi) along the periodic axes,
    // everything along the others (so that lanes can compare every axis alike).
    struct WrapBounds {
        double low[3], high[3];
    };
    WrapBounds wrapBounds() const {
        const double inf = std::numeric_limits<double>::infinity();
        WrapBounds b;
        for (int a = 0; a < 3; ++a) b.low[a] = periodic[a] ? lo[a] : -inf, b.high[a] = periodic[a] ? hi[a] : inf;
        return b;
    }
    // Moves x into [lo, hi) along the periodic axes.
    void wrap(Vec3& x) const {
        for (int a = 0; a < 3; ++a)
            if (periodic[a]) wrapCoordinate(x[a], lo[a], hi[a], length(a));
    }
    // The same for the first n of an array of positions (in the lanes of the form in use:
    // Particles/VelocityVerletLanes.h wrapPositions, Math/LaneForm.h).
    void wrap(Vec3* x, std::size_t n) const;
    static void wrapCoordinate(double& c, double lo, double hi, double L) {
        if (c >= hi) {
            c -= L;
            if (c >= hi) c = lo + std::fmod(c - lo, L);  // moved more than a box length
        } else if (c < lo) {
            c += L;
            if (c < lo) c = hi - std::fmod(hi - c, L);
            if (c >= hi) c = lo;
        }
    }

    // Nearest periodic image of a separation d = xi - xj of two wrapped positions (PeriodicImage,
    // which loops that call it many times keep).
    Vec3 nearestImage(const Vec3& d) const;
};

// The nearest image of separations along the periodic axes of a domain, with the box lengths
// read once (for the force loop and the neighbour search, which need it for every pair).
class PeriodicImage {
public:
    explicit PeriodicImage(const Domain& domain) {
        for (int a = 0; a < 3; ++a) {
            length_[a] = domain.periodic[a] ? domain.length(a) : INFINITY;
            half_[a] = 0.5 * length_[a];
        }
    }
    Vec3 nearest(Vec3 d) const {
        for (int a = 0; a < 3; ++a) {
            if (d[a] > half_[a]) d[a] -= length_[a];
            else if (d[a] < -half_[a]) d[a] += length_[a];
        }
        return d;
    }
    double length(int axis) const { return length_[axis]; }  // infinite along a closed axis
    double halfLength(int axis) const { return half_[axis]; }

private:
    double length_[3], half_[3];
};

inline Vec3 Domain::nearestImage(const Vec3& d) const { return PeriodicImage(*this).nearest(d); }

}  // namespace talus
