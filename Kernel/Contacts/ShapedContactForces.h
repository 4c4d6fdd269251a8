// The members of the force loop (ContactForceLoopInLanes, Contacts/ContactForceLoop.h) for pairs and wall
// contacts with superquadric particles (Theory/Superquadrics.md), which only scenes with shapes reach: kept
// apart from the sphere path. Included at the end of ContactForceLoop.h.
#pragma once

#include "Contacts/ContactForceLoop.h"

namespace talus::TALUS_LANES {

// A pair with a superquadric: the exact contact (warm-started), then the law on the
// kinematics of the contact point, with the branch vectors from the centres to it. The ends
// of a contact are not treated (the law's plain step), and the tangential spring is turned
// into the new tangent plane with its length kept (Denissen 2019, app. 5.A.3).
// (The separation comes as three numbers, in registers: a Vec3 would go through memory.)
template <class Law>
void ContactForceLoopInLanes<Law>::shapedPair(PairList& list, std::size_t k, std::uint32_t i, std::uint32_t j, double dx,
                                       double dy, double dz) {
    const Vec3 xj = p_.position[i] - Vec3(dx, dy, dz);  // j's image next to i
    ContactHistory history = list.history.get(k);
    // A warm-started pair (a lasting contact, or one apart since its last solve) of an ellipsoid
    // with an ellipsoid or a sphere: into the batch (EllipsoidContactBatch.h; laws without the
    // effective radius, which would need the curvatures). A sphere is the ellipsoid Q = I / r^2
    // there, as the scalar path's sphere-shaped partner (ShapedContactGeometry.h, placed) is; two
    // round bodies have the closed form. Bounding spheres apart need no solve (the scalar path).
    if constexpr (!Law::usesEffectiveRadius) {
        if (history.warmMultiplier > 0 && isEllipsoidOrSphere(i) && isEllipsoidOrSphere(j) && !(isRound(i) && isRound(j))) {
            const std::vector<PlacedSuperquadric>& frames = list.shapedFrameScratch;
            Mat3 sphereI, sphereJ;
            const EllipsoidContactBatch::Body bodyI = batchBody(frames, i, p_.position[i], sphereI),
                                              bodyJ = batchBody(frames, j, xj, sphereJ);
            const double reach = bodyI.boundingRadius + bodyJ.boundingRadius;
            if ((xj - p_.position[i]).squaredNorm() < reach * reach) {  // (as findSuperquadricContact tests it)
                ellipsoids_.add(k, i, j, bodyI, bodyJ, {p_.position[i] + history.warmPoint, history.warmMultiplier});
                if (ellipsoids_.full()) flushEllipsoids(list);
                return;
            }
        }
    }
    shapedPairWith(list, k, i, j, xj, history,
                   shapedPairGeometry(p_, list.shapedFrameScratch, i, j, xj, history, Law::usesEffectiveRadius,
                                      shapeSettings_));
}

// A pair apart keeps a lower bound of its gap (ShapedContactGeometry::gapBound) and lowers it
// each step by how far the two bodies can have closed in (relative speed of the centres plus
// each spin times its bounding radius, with a margin of half for the change of speed within
// the step); while it stays positive the pair cannot touch and is not solved. Such a pair is
// marked "approaching", so that the force loop's sweep visits it every step, also while its
// bounding spheres are apart: the bound is then never stale. Most visits of a settled packing end
// here, so this check is inlined into the sweep and only the pairs it cannot skip pay the call.
// (The bound is lowered in place: a skipped pair reads and writes nothing else. The spins |w|
// are each particle's, taken once per force evaluation with its frame; the closing speed
// |vi - vj| + |wi| ri + |wj| rj in fused multiply-adds.)
template <class Law>
inline bool ContactForceLoopInLanes<Law>::shapedPairStaysApart(PairList& list, std::size_t k, std::uint32_t i,
                                                               std::uint32_t j) {
    if (list.history.state(k) != ContactHistory::approaching || !(list.history.gapBoundOf(k) > 0)) return false;
    const std::vector<double>& spin = list.spinScratch;
    const double closing =
        std::fma(spin[j], p_.radius[j], std::fma(spin[i], p_.radius[i], (p_.velocity[i] - p_.velocity[j]).norm()));
    double& gapBound = list.history.gapBoundOf(k);
    gapBound -= 1.5 * closing * dt_;
    list.history.clearLastNormalForce(k);
    return gapBound > 0;
}

// A plain sphere (no shape) or an ellipsoid; a plain sphere or a sphere-shaped one.
template <class Law>
bool ContactForceLoopInLanes<Law>::isEllipsoidOrSphere(std::uint32_t i) const {
    return p_.shape[i] < 0 || (*shapes_)[static_cast<std::size_t>(p_.shape[i])].isEllipsoid();
}
template <class Law>
bool ContactForceLoopInLanes<Law>::isRound(std::uint32_t i) const {
    return p_.shape[i] < 0 || (*shapes_)[static_cast<std::size_t>(p_.shape[i])].isSphere();
}

// Particle i (at `centre`: its own position or j's image) for the batch: an ellipsoid's placed
// frame, or a plain sphere's quadric (kept in `sphere`) with its bounding radius and semi-axes r.
template <class Law>
inline EllipsoidContactBatch::Body ContactForceLoopInLanes<Law>::batchBody(const std::vector<PlacedSuperquadric>& frames,
                                                                    std::uint32_t i, const Vec3& centre, Mat3& sphere) const {
    if (p_.shape[i] >= 0) {
        const Superquadric& shape = *frames[i].shape;
        return {centre, frames[i].quadric, shape.boundingRadius(), shape.semiAxes().minCoeff()};
    }
    sphere = EllipsoidContactBatch::sphereQuadric(p_.radius[i]);
    return {centre, sphere, p_.radius[i], p_.radius[i]};
}

// The batched warm-started ellipsoid pairs: a lane the batch could not finish goes to the
// scalar path, from the same warm start; a lane found apart keeps its solution and gap bound.
// With the linear law the finished lanes' contact step is batched too, except on output steps,
// where the scalar path records each contact.
template <class Law>
void ContactForceLoopInLanes<Law>::flushEllipsoids(PairList& list) {
    EllipsoidContactBatch& b = ellipsoids_;
    if (b.count == 0) return;
    b.compute(shapeSettings_.tolerance);
    bool forcesInLanes = false;
    if constexpr (Law::batched && !Law::usesEffectiveRadius) {  // (the ellipsoid batch's laws: above)
        forcesInLanes = !records_;
        if (forcesInLanes) {
            for (int l = 0; l < b.count; ++l) {
                const std::uint32_t i = b.i[l], j = b.j[l];
                b.setMotion(l, p_.velocity[i], p_.angularVelocity[i], p_.velocity[j], p_.angularVelocity[j],
                            list.history.springOf(b.k[l]), list.history.state(b.k[l]) == ContactHistory::touching,
                            laws_(p_.species[i], p_.species[j]));
            }
            b.forceLanes(dt_);
        }
    }
    for (int l = 0; l < b.count; ++l) {
        const std::uint32_t i = b.i[l], j = b.j[l];
        const Vec3 xj(b.cjx[l], b.cjy[l], b.cjz[l]);
        if (b.done[l] == 0) {
            const ContactHistory history = list.history.get(b.k[l]);
            shapedPairWith(list, b.k[l], i, j, xj, history,
                           shapedPairGeometry(p_, list.shapedFrameScratch, i, j, xj, history, false, shapeSettings_));
        } else if (b.apart[l] != 0) {  // (the lane's force, if computed, is not used)
            ShapedContactGeometry g;
            g.converged = true;
            g.solution = {Vec3(b.px[l], b.py[l], b.pz[l]) - p_.position[i], b.mu[l]};
            g.gapBound = b.gapBound[l];
            shapedPairWith(list, b.k[l], i, j, xj, list.history.get(b.k[l]), g);
        } else if (forcesInLanes) {
            laneContact(list, l);
        } else {
            ShapedContactGeometry g;
            g.converged = g.touching = true;
            g.normal = Vec3(b.nx[l], b.ny[l], b.nz[l]);
            g.overlap = b.overlap[l];
            g.contactPoint = Vec3(b.mx[l], b.my[l], b.mz[l]);
            g.solution = {Vec3(b.px[l], b.py[l], b.pz[l]) - p_.position[i], b.mu[l]};
            shapedPairWith(list, b.k[l], i, j, xj, list.history.get(b.k[l]), g);
        }
    }
    b.count = 0;
}

// Lane l's contact, computed in the lanes, applied (as shapedPairWith and shapedContact would).
template <class Law>
inline void ContactForceLoopInLanes<Law>::laneContact(PairList& list, int l) {
    const EllipsoidContactBatch& b = ellipsoids_;
    const std::uint32_t i = b.i[l], j = b.j[l];
    list.history.setTouching(b.k[l], Vec3(b.sx[l], b.sy[l], b.sz[l]), b.fn[l],
                             Vec3(b.px[l], b.py[l], b.pz[l]) - p_.position[i], b.mu[l]);
    const Vec3 force(b.fx[l], b.fy[l], b.fz[l]);
    const Vec3 torqueI(b.tix[l], b.tiy[l], b.tiz[l]), torqueJ(b.tjx[l], b.tjy[l], b.tjz[l]);
    if (perPair_) [[unlikely]] {  // kept for the sums in id order (IdOrderedForceSums.h)
        perPair_[b.k[l]] = {force, torqueI, torqueJ};
    } else {
        p_.force[i] += force;
        p_.torque[i] += torqueI;
        p_.force[j] -= force;
        p_.torque[j] += torqueJ;
    }
    ++summary_.contacts, ++summary_.contactsInLanes;
    noteOverlap(i, j, b.overlap[l], std::min(sizeOf(i), sizeOf(j)));
}

// Pair k with its exact geometry g: the warm start kept, the contact's force (or none), the
// gap bound of a pair apart.
template <class Law>
void ContactForceLoopInLanes<Law>::shapedPairWith(PairList& list, std::size_t k, std::uint32_t i, std::uint32_t j,
                                           const Vec3& xj, ContactHistory history, const ShapedContactGeometry& g) {
    if (!g.converged) detectionFailed(i, j);
    history.warmPoint = g.solution.point;
    history.warmMultiplier = g.solution.multiplier;
    const Law& law = laws_(p_.species[i], p_.species[j]);
    currentPair_ = k;  // (for the forces kept for sums in id order; the batch comes here out of turn)
    shapedContact(history, g, i, j, xj, p_.velocity[j], p_.angularVelocity[j], p_.invMass[j], law,
                  std::min(sizeOf(i), sizeOf(j)));
    if (!g.touching && g.gapBound > 0) {
        history.state = ContactHistory::approaching;
        history.gapBound() = g.gapBound;
    }
    list.history.set(k, history);
}

template <class Law>
void ContactForceLoopInLanes<Law>::shapedWall(PairList& list, std::size_t k, std::uint32_t i, const Wall& wall,
                                       const std::vector<PrescribedMotion>& motions) {
    ContactHistory history = list.wallHistory.get(k);
    const ShapedContactGeometry g = shapedWallGeometry(p_, list.shapedFrameScratch, i, wall, Law::usesEffectiveRadius);
    const Vec3 wallVelocity = wall.motion >= 0 ? motions[wall.motion].pointVelocity(g.contactPoint) : Vec3::Zero();
    const Vec3 wallSpin = wall.motion >= 0 ? motions[wall.motion].angularVelocity : Vec3::Zero();
    // A wall as a partner of infinite mass whose "centre" is the contact point itself.
    const Law& law = laws_(p_.species[i], wall.species);
    shapedContact(history, g, i, -static_cast<std::int64_t>(list.wallPairs[k].wall) - 1, g.contactPoint,
                  wallVelocity, wallSpin, 0, law, sizeOf(i));
    list.wallHistory.set(k, history);
}

template <class Law>
void ContactForceLoopInLanes<Law>::shapedContact(ContactHistory& history, const ShapedContactGeometry& g, std::uint32_t i,
                                          std::int64_t j, const Vec3& xj, const Vec3& vj, const Vec3& wj,
                                          double invMassJ, const Law& law, double size) {
    if (!g.touching) {
        history.spring.setZero();
        history.lastNormalForce = 0;
        history.state = ContactHistory::apart;
        return;
    }
    const Vec3& n = g.normal;
    const Vec3 bi = g.contactPoint - p_.position[i], bj = g.contactPoint - xj;
    ContactKinematics c;
    c.normal = n;
    c.overlap = g.overlap;
    c.relativeVelocity = p_.velocity[i] + p_.angularVelocity[i].cross(bi) - vj - wj.cross(bj);
    c.normalVelocity = c.relativeVelocity.dot(n);
    c.tangentialVelocity = c.relativeVelocity - c.normalVelocity * n;
    c.inverseReducedMass = p_.invMass[i] + invMassJ;
    c.otherAcceleration = 0;  // (only the treatment of contact ends uses it)
    c.effectiveRadius = g.effectiveRadius;
    c.inverseDistance = 0;  // the spring is projected (below), not rotated as for spheres
    if (history.isTouching())
        turnSpringIntoTangentPlane(history.spring.x(), history.spring.y(), history.spring.z(), n.x(), n.y(), n.z());
    else
        history.spring.setZero();
    // The law's plain step: the ends of the contact are not treated (see above).
    ContactForce f;
    if constexpr (requires { law.plainForce(c, history, dt_); })
        f = law.plainForce(c, history, dt_);
    else
        f = law.force(c, history, dt_);
    history.state = ContactHistory::touching;
    history.lastNormalForce = f.normalForce;
    const Vec3 force = f.normalForce * n + f.tangentialForce;
    if (perPair_ && j >= 0) [[unlikely]] {  // kept for the sums in id order (IdOrderedForceSums.h)
        perPair_[currentPair_] = {force, bi.cross(force), -bj.cross(force)};
    } else {
        p_.force[i] += force;
        p_.torque[i] += bi.cross(force);
        if (j >= 0) {
            p_.force[j] -= force;
            p_.torque[j] -= bj.cross(force);
        }
    }
    ++summary_.contacts;
    noteOverlap(i, j, g.overlap, size);
    if (records_) [[unlikely]]
        records_->add({i, j, g.contactPoint, g.overlap, history.spring.norm(), f.normalForce, n,
                       f.tangentialForce, law.elasticEnergy(c, history.spring)});
}

}  // namespace talus::TALUS_LANES
