// Where and how deep a non-spherical particle touches another particle or a plane wall: the
// geometry the force loop needs (Contacts/ContactForces.h), from the exact stage of
// Theory/Superquadrics.md eq. (5)-(8).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "Contacts/ContactHistory.h"
#include "Contacts/SuperquadricContact.h"
#include "Particles/ParticleStore.h"
#include "Walls/Wall.h"

namespace talus {

struct ShapedContactGeometry {
    bool converged = false;
    bool touching = false;
    Vec3 normal = Vec3::Zero();        // from j (or the wall) to i
    double overlap = 0;
    Vec3 contactPoint = Vec3::Zero();  // middle of the overlap
    double effectiveRadius = 0;        // from the mean curvatures, for laws that use it (Hertzian)
    SuperquadricContactPoint solution; // the next step's warm start (pairs)
    double gapBound = 0;               // pairs apart: the gap is at least this
};

// The radius of curvature 1/|K| of a body's surface at x, from the mean curvature
// K = (g^T H g - |g|^2 tr H) / (2 |g|^3) of its shape function (Theory/Superquadrics.md eq. (12)),
// capped at ten bounding radii so that a flat face does not make a Hertzian contact infinitely
// stiff.
inline double curvatureRadius(const PlacedSuperquadric& body, const Vec3& x) {
    const ShapeValue v = body.at(x);
    const double g = v.gradient.norm();
    const double K = std::abs(v.gradient.dot(v.hessian * v.gradient) - g * g * v.hessian.trace()) / (2 * g * g * g);
    return std::min(1 / K, 10 * body.shape->boundingRadius());
}

inline double seriesRadius(double a, double b) { return a * b / (a + b); }

// The lab frames of the shaped particles (frames[i] for particle i), placed once per force
// evaluation so that all the contacts of a particle share its rotation and quadric; and every
// particle's spin |w_i| (spin[i]), for the gap bounds of pairs apart.
inline void placeShapedParticles(const ParticleStore& p, const std::vector<Superquadric>& shapes,
                                 std::vector<PlacedSuperquadric>& frames, std::vector<double>& spin) {
    frames.resize(p.size());
    spin.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.isShaped(i))
            frames[i] = {&shapes[static_cast<std::size_t>(p.shape[i])], p.position[i], p.orientation[i].toRotationMatrix()};
        // (In the order of the fused multiply-adds the pair's own |w| had when it was made there.)
        const Vec3& w = p.angularVelocity[i];
        spin[i] = std::sqrt(std::fma(w.x(), w.x(), std::fma(w.z(), w.z(), w.y() * w.y())));
    }
}

// A particle as a placed superquadric at `centre` (its own position or a periodic image): its
// frame itself if it is there, else a copy moved there (`moved`); a sphere partner becomes a
// sphere-shaped superquadric (kept in `sphere`). The result refers to frames, moved or sphere.
inline const PlacedSuperquadric& placed(const ParticleStore& p, const std::vector<PlacedSuperquadric>& frames,
                                        std::size_t i, const Vec3& centre, std::optional<PlacedSuperquadric>& moved,
                                        std::optional<Superquadric>& sphere) {
    if (p.shape[i] >= 0) {
        if (frames[i].centre == centre) return frames[i];
        moved = frames[i];
        moved->centre = centre;
        return *moved;
    }
    sphere = Superquadric::sphere(p.radius[i]);
    moved.emplace(&*sphere, centre, Mat3::Identity());
    return *moved;
}

// Particles i and j, j at xj (its periodic image next to i); `history` holds the warm start.
// The curvatures are evaluated only if the law needs the effective radius (`withRadius`).
inline ShapedContactGeometry shapedPairGeometry(const ParticleStore& p, const std::vector<PlacedSuperquadric>& frames,
                                                std::size_t i, std::size_t j, const Vec3& xj,
                                                const ContactHistory& history, bool withRadius,
                                                const SuperquadricContactSettings& settings = {}) {
    std::optional<Superquadric> sphereI, sphereJ;
    std::optional<PlacedSuperquadric> movedI, movedJ;
    const PlacedSuperquadric& a = placed(p, frames, i, p.position[i], movedI, sphereI);
    const PlacedSuperquadric& b = placed(p, frames, j, xj, movedJ, sphereJ);
    SuperquadricContactPoint start{p.position[i] + history.warmPoint, history.warmMultiplier};
    const SuperquadricContact c = findSuperquadricContact(a, b, history.warmMultiplier > 0 ? &start : nullptr, settings);
    ShapedContactGeometry g;
    g.converged = c.converged;
    g.touching = c.touching;
    g.normal = c.normal;
    g.overlap = c.overlap;
    g.contactPoint = c.contactPoint;
    g.solution = {c.solution.point - p.position[i], c.solution.multiplier};
    g.gapBound = c.gapBound;
    if (c.touching && withRadius) {
        // Each body's curvature on its own surface, at the ends of the overlap along the normal.
        const Vec3 halfOverlap = 0.5 * c.overlap * c.normal;
        g.effectiveRadius = seriesRadius(curvatureRadius(a, c.contactPoint - halfOverlap),
                                         curvatureRadius(b, c.contactPoint + halfOverlap));
    }
    return g;
}

// Particle i against a wall: its point deepest into the wall (or the drum's tangent plane) is the
// one furthest along the wall's outward direction -N (Superquadric::furthestPointAlong, in the body
// frame).
inline ShapedContactGeometry shapedWallGeometry(const ParticleStore& p, const std::vector<PlacedSuperquadric>& frames,
                                                std::size_t i, const Wall& wall, bool withRadius) {
    const PlacedSuperquadric& body = frames[i];
    const Mat3& R = body.rotation;
    // (A drum wall: its tangent plane nearest to the particle's centre, Walls/Wall.h.)
    const Vec3 normal = wall.normalAt(p.position[i]);
    const Vec3 deepest = p.position[i] + R * body.shape->furthestPointAlong(R.transpose() * -normal);
    ShapedContactGeometry g;
    g.converged = true;
    g.overlap = -wall.tangentPlaneDistance(deepest, p.position[i]);
    g.touching = g.overlap > 0;
    g.normal = normal;
    g.contactPoint = deepest + 0.5 * g.overlap * normal;
    if (g.touching && withRadius) g.effectiveRadius = curvatureRadius(body, deepest);
    return g;
}

}  // namespace talus
