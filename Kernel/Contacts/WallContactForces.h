// The members of the force loop (ContactForceLoopInLanes, Contacts/ContactForceLoop.h) for the
// contacts that are not listed pairs of two particles: a particle and a wall candidate, and the
// pairs across the downstream face of a one-way periodic box (a maser). Included at the end of
// ContactForceLoop.h.
#pragma once

#include "Contacts/ContactForceLoop.h"
#include "Walls/MeshWalls.h"

namespace talus::TALUS_LANES {

// The pairs across the downstream face of the one-way periodic box (Domain::oneWay, Theory/Maser.md eq. (3)):
// the scalar path with j's image, and the force on i alone. They are few (one layer of the
// face), so they never enter a batch; they write no .fstat records (a force without its
// reaction would break the stress of coarse graining).
template <class Law>
void ContactForceLoopInLanes<Law>::oneWayPairs(PairList& list, const Domain& domain) {
    if (list.oneWayPairs.empty()) return;
    const PeriodicImage image(domain);
    const double shift = domain.oneWay.length();
    oneWay_ = true;
    for (std::size_t k = 0; k < list.oneWayPairs.size(); ++k) {
        const std::uint32_t i = list.oneWayPairs[k].i, j = list.oneWayPairs[k].j;
        Vec3 d = p_.position[i] - p_.position[j];
        d.x() += shift;
        d = image.nearest(d);
        const double sumR = p_.radius[i] + p_.radius[j], distance = d.norm();
        const Vec3 n = d / distance;
        ContactHistory history = list.oneWayHistory.get(k);
        Arms arms;
        ContactKinematics c = contactKinematics(n, sumR - distance, p_.radius[i], p_.radius[j],
                                                p_.velocity[i] - p_.velocity[j], p_.angularVelocity[i],
                                                p_.angularVelocity[j], arms);
        c.inverseDistance = 1 / distance;
        c.inverseReducedMass = p_.invMass[i] + p_.invMass[j];
        c.otherAcceleration = previousForce_[i].dot(n) * p_.invMass[i] - previousForce_[j].dot(n) * p_.invMass[j] -
                              history.lastNormalForce * c.inverseReducedMass;
        if constexpr (Law::usesEffectiveRadius) c.effectiveRadius = p_.radius[i] * p_.radius[j] / sumR;
        if constexpr (Law::rollingResistance)
            setRolling(c, p_.angularVelocity[i] - p_.angularVelocity[j], p_.radius[i] * p_.radius[j] / sumR);
        const Law& law = laws_(p_.species[i], p_.species[j]);
        const double smallerRadius = std::min(p_.radius[i], p_.radius[j]);
        if (distance < sumR) {
            touch(i, j, c, arms, history, law, smallerRadius);
            // Beyond a tenth of the radius j feels the share of the normal force that the
            // excess overlap makes: in a slow flow, j may be pushed on from behind while i,
            // in front of j's image, sits against the base, and the overlap would grow
            // without bound (OneWayPeriodicBox::reactionOverlap).
            const double excess = c.overlap - OneWayPeriodicBox::reactionOverlap * smallerRadius;
            if (excess > 0 && history.lastNormalForce > 0) {
                p_.force[j] -= (history.lastNormalForce * excess / c.overlap) * n;
                ++summary_.oneWayReactions;
            }
        } else {
            history = apart(i, j, c, arms, history, law);
        }
        list.oneWayHistory.set(k, history);
    }
    oneWay_ = false;
}

template <class Law>
void ContactForceLoopInLanes<Law>::wallPair(PairList& list, std::size_t k, const std::vector<Wall>& walls,
                                           const std::vector<PrescribedMotion>& motions) {
    const std::uint32_t i = list.wallPairs[k].particle;
    const Wall& wall = walls[list.wallPairs[k].wall];
    if (shapes_ && p_.isShaped(i)) [[unlikely]] {
        // (A shaped particle lies within its bounding sphere, p_.radius: a sphere clear of the wall
        // by more than rounding leaves a pair that was apart apart, with nothing to solve.)
        const double distance = wall.signedDistance(p_.position[i]);
        if (!(list.wallHistory.state(k) == ContactHistory::apart && distance - p_.radius[i] > 1e-9 * p_.radius[i]))
            shapedWall(list, k, i, wall, motions);
        return;
    }
    // A triangle apart and clear of the particle by more than the closing distance stays apart
    // below: tried first against the sphere about it that holds it (no nearest point sought),
    // then with its nearest point but without asking its neighbours whether it counts.
    // A moving mesh closes in by its own step too (its last one, as the next's: MeshWalls::lastStep).
    const bool apartBefore = list.wallHistory.state(k) == ContactHistory::apart;
    const double closing = wall.isTriangle() ? closing_ + wall.mesh->lastStep : closing_;
    if (wall.isTriangle() && apartBefore) [[unlikely]] {
        const MeshWalls& mesh = *wall.mesh;
        const double clear = mesh.reach[wall.triangle] + p_.radius[i] + closing;
        if ((p_.position[i] - mesh.centre[wall.triangle]).squaredNorm() >= clear * clear) return;
    }
    // (Asked within a hair more than r + closing, so that a point not asked passes the test of
    // distance - r against closing below whatever the rounding.)
    const double askWithin =
        apartBefore ? (p_.radius[i] + closing) * (1 + 1e-12) : std::numeric_limits<double>::infinity();
    const Wall::Gap gap = wall.isTriangle() ? wall.triangleGap(p_.position[i], askWithin) : wall.gapTo(p_.position[i]);
    const double distance = gap.distance;
    const bool touching = distance < p_.radius[i];
    // (A moving wall may close in faster than the particles: no shortcut for it, unless it slides
    // in place or is a triangle, whose mesh's step `closing` holds.)
    if (!touching && apartBefore && (wall.motion < 0 || wall.slidesInPlace || wall.isTriangle()) &&
        distance - p_.radius[i] >= closing)
        return;
    if (!gap.counts) [[unlikely]] {
        // A revolved segment's joint that the next segment counts (Walls/Wall.h): no contact here.
        if (list.wallHistory.state(k) != ContactHistory::apart) list.wallHistory.set(k, ContactHistory{});
        return;
    }
    ContactHistory history = list.wallHistory.get(k);
    const double overlap = p_.radius[i] - distance;
    const Vec3& normal = gap.normal;
    const Vec3 contactPoint = p_.position[i] - (p_.radius[i] - 0.5 * overlap) * normal;
    const Vec3 wallVelocity =
        wall.motion >= 0 ? motions[wall.motion].pointVelocity(contactPoint) : Vec3::Zero();
    Arms arms;
    ContactKinematics c = contactKinematics(normal, overlap, p_.radius[i], 0, p_.velocity[i] - wallVelocity,
                                            p_.angularVelocity[i], Vec3::Zero(), arms);
    c.inverseDistance = 0;  // a wall: the spring is projected, not rotated (ContactKinematics.h)
    c.inverseReducedMass = p_.invMass[i];
    c.otherAcceleration = (previousForce_[i].dot(c.normal) - history.lastNormalForce) * p_.invMass[i];
    // Hertz: a plane leaves the sphere's radius; a wall curved along one direction (the inside of
    // a drum, a cone) the mean curvature of the gap, 1/r - kappa/2 (Theory/ContactLaws.md eq. (6b)).
    c.effectiveRadius = wall.isCylinder()   ? 1 / (1 / p_.radius[i] - 0.5 / wall.radius)
                        : gap.curvature != 0 ? 1 / (1 / p_.radius[i] - 0.5 * gap.curvature)
                                             : p_.radius[i];
    if constexpr (Law::rollingResistance)
        setRolling(c, p_.angularVelocity[i] - (wall.motion >= 0 ? motions[wall.motion].angularVelocity : Vec3::Zero()),
                   p_.radius[i]);
    const Law& law = laws_(p_.species[i], wall.species);
    const std::int64_t wallIndex = -static_cast<std::int64_t>(list.wallPairs[k].wall) - 1;
    if (touching)
        touch(i, wallIndex, c, arms, history, law, p_.radius[i]);
    else
        history = apart(i, wallIndex, c, arms, history, law);
    list.wallHistory.set(k, history);
}

}  // namespace talus::TALUS_LANES
