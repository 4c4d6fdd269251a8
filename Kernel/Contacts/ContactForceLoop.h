// The force loop: contact forces and torques of every listed pair and wall candidate, compiled
// once per contact law (no dispatch, search or allocation per contact) and once per lane form
// (Math/LaneKernels.h; the entry point is Contacts/ContactForces.h).
// Geometry and kinematics follow Theory/ContactLaws.md eq. (1)-(3): n from j to i, dn = ri + rj - rij, branch vectors
// bij = -(ri - dn/2) n and bji = (rj - dn/2) n to the middle of the overlap.
#pragma once

#include <algorithm>
#include <bit>
#include <sstream>
#include <cmath>
#include <cstdint>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/ContactBatch.h"
#include "Contacts/ContactForces.h"
#include "Contacts/ContactReport.h"
#include "Contacts/EllipsoidContactBatch.h"
#include "Contacts/IdOrderedForceSums.h"
#include "Contacts/PairList.h"
#include "Contacts/PairSweepLanes.h"
#include "Contacts/ShapedContactGeometry.h"
#include "Contacts/WaveSchedule.h"
#include "Error.h"
#include "Math/LaneNamespace.h"
#include "Particles/ParticleStore.h"
#include "Species/SpeciesTable.h"
#include "Walls/Wall.h"
#include "Walls/PrescribedMotion.h"

namespace talus::TALUS_LANES {

// Kinematics of particle i against a partner at distance rij along the unit normal n (Theory/ContactLaws.md eq. (1)-(3));
// overlap = ri + rj - rij may be negative for a pair that just separated. The branch vectors are
// bij = -armI n and bji = armJ n with arms ri - dn/2 and rj - dn/2 (rj = 0 for walls), so the
// spin part of the tangential velocity, wi x bij - wj x bji, is -(armI wi + armJ wj) x n.
struct Arms {
    double i, j;
};
inline ContactKinematics contactKinematics(const Vec3& n, double overlap, double radiusI, double radiusJ,
                                           const Vec3& relativeVelocity, const Vec3& spinI, const Vec3& spinJ,
                                           Arms& arms) {
    arms = {radiusI - 0.5 * overlap, radiusJ - 0.5 * overlap};
    ContactKinematics c;
    c.normal = n;
    c.overlap = overlap;
    c.relativeVelocity = relativeVelocity;
    c.normalVelocity = relativeVelocity.dot(n);
    c.tangentialVelocity = relativeVelocity - c.normalVelocity * n - (arms.i * spinI + arms.j * spinJ).cross(n);
    return c;
}

// The force loop over the listed pairs and wall candidates of one step, for one contact law.
// Its parts are member functions so that the compiler inlines the common case (a pair inside a
// contact) whole and keeps the rare ones (the ends of a contact, output records) out of the way.
template <class Law>
class ContactForceLoopInLanes final : public ContactForceLoopOfForm<Law> {
public:
    explicit ContactForceLoopInLanes(const ContactForceLoopArguments<Law>& a)
        : p_(a.p), laws_(a.laws), dt_(a.dt), closing_(2 * a.maxSpeed * a.dt), previousForce_(a.previousForce),
          summary_(a.summary), records_(a.records), shapes_(a.p.hasShapes() ? a.shapes : nullptr),
          perPair_(a.perPair), shapeSettings_(a.shapeSettings), prefetchPartners_(a.p.size() >= prefetchFromParticles) {
        if constexpr (Law::rollingResistance)
            require(!shapes_, std::string("the contact law ") + Law::name +
                                  " (rolling resistance) is for spheres; this scene has superquadric particles");
    }

    // nearPairs: the near list may be swept (not with particles on prescribed motions, whose
    // positions the step sets apart from their velocities).
    // Two passes per chunk of the list: a branch-free sweep over the listed pairs
    // (Contacts/PairSweep.h) picks those that need work (touching, about to touch within the
    // next step, or just separated), then the contacts are computed for those alone.
    // The sweep sees each particle's radius grown by how far it moves within the step relative
    // to a frame moving with a velocity u common to all, |v - u| dt (PairSweep.h): a pair
    // closes its gap by at most |vi - vj| dt <= (|vi - u| + |vj - u|) dt, so a pair whose grown
    // spheres are apart cannot touch within the step (the test of pairContact below). The
    // margins (a millionth of the reach, 1e-12 of the radius) keep rounding from dropping a
    // pair that the test would take. Against one margin for all, 2 vmax dt, this leaves out
    // most of the near pairs of a fast dilute flow, where a few fast spheres set vmax.
    void particlePairs(PairList& list, const Domain& domain, bool nearPairs) override {
        restPairs(list, domain, nearPairs);
    }

    // The first part of particlePairs where a rank's ghosts are still on their way
    // (Parallel/RankContext.h): the sweep's points of the owned particles, then the interior pairs
    // (both particles owned and away from the periodic faces: PairList::interiorPairs), which come
    // first in the list and read no ghost. Their batched contacts may wait in the batch for restPairs, so that every particle's
    // forces are summed in the order particlePairs sums them. Each history it changes is saved in
    // `changed` first. Spheres only, without records or pair forces kept (RankContext checks).
    // Without periodic faces every pair counts as interior (PairList::interiorPairs), ghosts' too:
    // then it leaves all pairs to restPairs.
    void interiorPairs(PairList& list, const Domain& domain, bool nearPairs, ContactHistoryLog& changed) override {
        makeSweepPoints(list, p_.owned());
        if (!domain.anyPeriodic()) return;
        if (sweepForm() == SweepForm::undecided && list.pairs.size() >= 4 * SweptPairs::capacity) [[unlikely]]
            return;  // (restPairs times the sweep's forms on the whole list first)
        const PeriodicImage image(domain);
        const SweepPoint* points = list.sweepPointScratch.data();
        SweptPairs swept;
        changed_ = &changed;
        // The near list if it holds the interior pairs this step picks by the owned particles'
        // growths (PairSweep.h nearPairsHoldInterior), else all of them: the same picks.
        if (nearPairs && nearPairsHoldInterior(list, growth_))
            sweptContacts<false>(list, 0, list.near.interior, points, image, swept, &list.near);
        else
            sweptContacts<false>(list, 0, std::min(list.interiorPairs, list.pairs.size()), points, image, swept);
        changed_ = nullptr;
        interiorDone_ = true;
    }

    // particlePairs, or what interiorPairs left of it: the pairs with a ghost or across a
    // periodic face, then the batches applied.
    void restPairs(PairList& list, const Domain& domain, bool nearPairs) override {
        makeSweepPoints(list, p_.size());
        const PeriodicImage image(domain);
        const SweepPoint* points = list.sweepPointScratch.data();
        SweptPairs swept;
        if (sweepForm() == SweepForm::undecided && list.pairs.size() >= 4 * SweptPairs::capacity) [[unlikely]]
            chooseSweepForm(list.pairs.data(), list.pairs.size(), points, p_.size(), list.history.states(), image,
                            swept);
        // The near list where it holds every pair the sweep can pick (PairSweep.h), else all pairs.
        // On ranks each keeps its own: a ghost moved by the drift of its owner with the velocity
        // that came with it, which its growth holds, and any other move of a ghost rebuilds.
        if (nearPairs && useNearPairs(list, growth_)) {
            if (!list.near.made)
                TALUS_LANES::makeNearPairs(list, p_.position.data(), p_.size(), p_.radius.data(),
                                           list.nearSkinFraction * list.skin, image, list.nearPointScratch, swept);
            const NearPairs& near = list.near;
            if (!interiorDone_) sweptContacts<false>(list, 0, near.interior, points, image, swept, &near);
            sweptContacts<true>(list, near.interior, near.pairs.size(), points, image, swept, &near);
        } else {
            list.near.made = false;  // (its bound of the displacements does not follow this step)
            const std::size_t interior = std::min(list.interiorPairs, list.pairs.size());
            if (!interiorDone_) sweptContacts<false>(list, 0, interior, points, image, swept);
            sweptContacts<true>(list, interior, list.pairs.size(), points, image, swept);
        }
        interiorDone_ = pointsStarted_ = false;  // (a next call makes the points of its step anew)
        pointsMade_ = 0;
        if constexpr (Law::batched) flush(list);
        if (shapes_) flushEllipsoids(list);
    }

    // The sweep's points of the slots up to `last` not made yet this step, and the largest growth
    // among all made (made with the drift if the drift pass made them).
    void makeSweepPoints(PairList& list, std::size_t last) {
        if (!pointsStarted_) {
            pointsStarted_ = true;
            const std::optional<PairList::PointsByDrift>& drifted = list.sweepPointsByDrift;
            if (drifted && list.sweepPointScratch.size() == p_.size() && drifted->slots <= p_.size())
                growth_ = drifted->growth, pointsMade_ = drifted->slots, frame_ = drifted->frame;
            else
                frame_ = list.sweepInFlowFrame ? sweepFrameVelocity(p_) : Vec3::Zero();
            list.sweepPointsByDrift.reset();
        }
        if (last <= pointsMade_) return;
        growth_ = largerGrowth(growth_, sweepPointsForStep(p_, pointsMade_, last, dt_, frame_, list.sweepPointScratch));
        pointsMade_ = last;
    }

    // The listed pairs [from, to) (or those of a near list), a chunk at a time: the sweep, then
    // the contacts it picked.
    // In a scene of spheres without pair forces kept for sums in id order (plain), the contact
    // pass is compiled without the branches for those (3% of the settled bed's step at 3000,
    // Documentation/Performance.md, table of changes).
    template <bool nearestImage>
    void sweptContacts(PairList& list, std::size_t from, std::size_t to, const SweepPoint* points,
                       const PeriodicImage& image, SweptPairs& swept, const NearPairs* near = nullptr,
                       const std::uint32_t* index = nullptr) {
        if (!shapes_ && !perPair_)
            sweptContactsOf<nearestImage, true>(list, from, to, points, image, swept, near, index);
        else
            sweptContactsOf<nearestImage, false>(list, from, to, points, image, swept, near, index);
    }
    template <bool nearestImage, bool plain>
    void sweptContactsOf(PairList& list, std::size_t from, std::size_t to, const SweepPoint* points,
                         const PeriodicImage& image, SweptPairs& swept, const NearPairs* near,
                         const std::uint32_t* index) {
        for (std::size_t begin = from; begin < to; begin += SweptPairs::capacity) {
            const std::size_t end = std::min(to, begin + SweptPairs::capacity);
            if (near)
                sweepNearPairs<nearestImage>(*near, begin, end, points, list.history.states(), image, swept);
            else if (index)
                sweepIndexedPairs<nearestImage>(list.pairs.data(), index, begin, end, points, list.history.states(),
                                                image, swept);
            else
                sweepPairs<nearestImage>(list.pairs.data(), begin, end, points, p_.size(), list.history.states(), image,
                                         swept);
            for (std::size_t a = 0; a < swept.count; ++a) {
                if (prefetchPartners_ && a + prefetchAhead < swept.count) {
                    prefetchPartner(swept.particles[a + prefetchAhead].j);
                    list.history.prefetch(swept.pair[a + prefetchAhead]);
                }
                if constexpr (!plain) {
                    // A scene with shapes: most picked pairs are superquadric pairs, whose gap
                    // bound (in the history's record) and warm start are read at once.
                    if (shapes_ && a + prefetchAhead < swept.count) {
                        list.history.prefetch(swept.pair[a + prefetchAhead]);
                        list.history.prefetchWarmStart(swept.pair[a + prefetchAhead]);
                    }
                }
                pairContact<plain>(list, swept.pair[a], swept.particles[a], swept.separation(a));
            }
        }
    }

    // The partner's data that the contact pass reads, and the pair's history, asked for a few
    // picked pairs ahead: the partners' slots jump about, and the picked pairs are a sparse subset
    // of the list whose histories no hardware prefetcher foresees, so once the arrays outgrow the
    // caches those loads miss (the history's was the hottest instruction of the force loop at
    // 108000). Only in large scenes: measured on the benchmark chute (Documentation/Performance.md),
    // the partner's 7-10% faster at 108000 particles, no gain at 27000 and 1.5-2% slower at 3000
    // and 12000; the history's another 6-8% at 108000, from the settled bed and the flow.
    static constexpr std::size_t prefetchAhead = 8, prefetchFromParticles = 65536;
    void prefetchPartner(std::uint32_t j) const {
        __builtin_prefetch(p_.velocity.data() + j);
        __builtin_prefetch(p_.angularVelocity.data() + j);
        __builtin_prefetch(previousForce_.data() + j);
    }

    // Pair k of the list, of particles ij, whose separation xi - xj (nearest image) is d.
    // plain: no shapes and no pair forces kept (sweptContacts).
    template <bool plain>
    [[gnu::always_inline]] void pairContact(PairList& list, std::size_t k, ParticlePair ij, const Vec3& d) {
        const std::uint32_t i = ij.i, j = ij.j;
        if constexpr (!plain) {
            if (perPair_) [[unlikely]]
                currentPair_ = k;
            if (shapes_ && (p_.isShaped(i) || p_.isShaped(j))) [[unlikely]] {
                if (!shapedPairStaysApart(list, k, i, j)) shapedPair(list, k, i, j, d.x(), d.y(), d.z());
                return;
            }
        }
        const double radiusI = p_.radius[i], radiusJ = p_.radius[j], sumR = radiusI + radiusJ;
        const double r2 = d.squaredNorm();
        const bool touching = r2 < sumR * sumR;
        if constexpr (Law::batched) {
            // Inside a lasting contact: into the batch (see ContactBatch).
            if (touching && list.history.state(k) == ContactHistory::touching) {
                const Law& law = laws_(p_.species[i], p_.species[j]);
                if (law.lastsInLanes()) {
                    batch_.add(k, i, j, d, radiusI, radiusJ, laws_.lane(p_.species[i], p_.species[j]));
                    if (batch_.full()) flush(list);
                    return;
                }
            }
        }
        const Vec3 relativeVelocity = p_.velocity[i] - p_.velocity[j];
        const bool apartBefore = !touching && list.history.state(k) == ContactHistory::apart;
        // Apart with nothing pending and moving apart (v.d >= 0, so v.n >= 0: decided before
        // any square root; in a fast flow most picked pairs are such): no force, and no work
        // beyond noting that the pair applied no force this step.
        if (apartBefore && !(relativeVelocity.dot(d) < 0)) {
            noteChange(list, k);
            list.history.clearLastNormalForce(k);
            return;
        }
        const double distance = std::sqrt(r2), inverseDistance = 1 / distance;
        const Vec3 n = d * inverseDistance;
        // Apart and approaching, but not closing the gap within the next step at the present
        // speed: likewise (approachForce would push nothing).
        if (apartBefore) {
            const double u = relativeVelocity.dot(n);
            if (!(u < 0 && distance - sumR < -u * dt_)) {
                noteChange(list, k);
                list.history.clearLastNormalForce(k);
                return;
            }
        }
        ContactHistory history = list.history.get(k);
        Arms arms;
        ContactKinematics c = contactKinematics(n, sumR - distance, p_.radius[i], p_.radius[j], relativeVelocity,
                                                p_.angularVelocity[i], p_.angularVelocity[j], arms);
        c.inverseDistance = inverseDistance;
        const double inverseMassSum = p_.invMass[i] + p_.invMass[j];
        c.inverseReducedMass = inverseMassSum;
        // The last step's forces on i and j, less this pair's own (ContactKinematics.h).
        c.otherAcceleration = previousForce_[i].dot(c.normal) * p_.invMass[i] -
                              previousForce_[j].dot(c.normal) * p_.invMass[j] -
                              history.lastNormalForce * inverseMassSum;
        if constexpr (Law::usesEffectiveRadius) c.effectiveRadius = p_.radius[i] * p_.radius[j] / sumR;
        if constexpr (Law::rollingResistance)
            setRolling(c, p_.angularVelocity[i] - p_.angularVelocity[j], p_.radius[i] * p_.radius[j] / sumR);
        const Law& law = laws_(p_.species[i], p_.species[j]);
        if (touching)
            touch(i, j, c, arms, history, law, std::min(p_.radius[i], p_.radius[j]));
        else
            history = apart(i, j, c, arms, history, law);
        noteChange(list, k);
        list.history.set(k, history);
    }

    // A pair's history is about to change: in interiorPairs, saved first.
    [[gnu::always_inline]] void noteChange(const PairList& list, std::size_t k) {
        if (changed_) changed_->save(list.history, k);
    }

    // The pairs across the downstream face of the one-way periodic box (Domain::oneWay): the force
    // on i alone (Contacts/WallContactForces.h).
    void oneWayPairs(PairList& list, const Domain& domain) override;
    void wallPairs(PairList& list, const std::vector<Wall>& walls, const std::vector<PrescribedMotion>& motions) override {
        for (std::size_t k = 0; k < list.wallPairs.size(); ++k) wallPair(list, k, walls, motions);
    }

    // The pairs and wall candidates one region of a wave computes (Contacts/WaveSchedule.h): its
    // interior pairs, those near a face, its particles' walls, then the batches applied, so that
    // the region's particles have all their forces of the step before they advance. The pairs are
    // runs of places in the list, swept as a single step sweeps the list.
    // nearRuns: if given, the places in the near list (list.near) of each run's near pairs
    // (Simulation::nearPairsForWave): those alone are swept, as a single step sweeps the near list.
    void regionPairs(PairList& list, const Domain& domain, const WaveSchedule& schedule, const WaveRegion& region,
                     const std::vector<Wall>& walls, const PlaceRun* nearRuns) override {
        const PeriodicImage image(domain);
        const SweepPoint* points = list.sweepPointScratch.data();
        const PlaceRun* runs = nearRuns ? nearRuns : schedule.placeRuns().data();
        const NearPairs* near = nearRuns ? &list.near : nullptr;
        SweptPairs swept;
        for (std::uint32_t u = region.runs; u < region.interiorEnd; ++u)
            sweptContacts<false>(list, runs[u].begin, runs[u].end, points, image, swept, near);
        for (std::uint32_t u = region.interiorEnd; u < region.end; ++u)
            sweptContacts<true>(list, runs[u].begin, runs[u].end, points, image, swept, near);
        static const std::vector<PrescribedMotion> noMotions;
        for (std::uint32_t e = region.wallsBegin; e < region.wallsEnd; ++e)
            wallPair(list, schedule.wallIndex()[e], walls, noMotions);
        if constexpr (Law::batched) flush(list);
    }
    // Raises the largest speed the skipping of far walls assumes (to one measured since).
    void allowSpeed(double maxSpeed) override { closing_ = std::max(closing_, 2 * maxSpeed * dt_); }

private:
    // One wall candidate (Contacts/WallContactForces.h).
    void wallPair(PairList& list, std::size_t k, const std::vector<Wall>& walls,
                  const std::vector<PrescribedMotion>& motions);

    // --- non-spherical particles (Theory/Superquadrics.md): defined, with their comments, in
    // Contacts/ShapedContactForces.h ---
    [[gnu::noinline]] void shapedPair(PairList& list, std::size_t k, std::uint32_t i, std::uint32_t j, double dx,
                                      double dy, double dz);
    [[gnu::always_inline]] bool shapedPairStaysApart(PairList& list, std::size_t k, std::uint32_t i, std::uint32_t j);
    bool isEllipsoidOrSphere(std::uint32_t i) const;
    bool isRound(std::uint32_t i) const;
    [[gnu::always_inline]] EllipsoidContactBatch::Body batchBody(const std::vector<PlacedSuperquadric>& frames,
                                                                 std::uint32_t i, const Vec3& centre, Mat3& sphere) const;
    void flushEllipsoids(PairList& list);
    [[gnu::always_inline]] void laneContact(PairList& list, int l);
    void shapedPairWith(PairList& list, std::size_t k, std::uint32_t i, std::uint32_t j, const Vec3& xj,
                        ContactHistory history, const ShapedContactGeometry& g);
    [[gnu::noinline]] void shapedWall(PairList& list, std::size_t k, std::uint32_t i, const Wall& wall,
                                      const std::vector<PrescribedMotion>& motions);
    void shapedContact(ContactHistory& history, const ShapedContactGeometry& g, std::uint32_t i, std::int64_t j,
                       const Vec3& xj, const Vec3& vj, const Vec3& wj, double invMassJ, const Law& law, double size);

    // The largest overlap of the step, as a fraction of the smaller size (j < 0: wall -j - 1).
    [[gnu::always_inline]] void noteOverlap(std::uint32_t i, std::int64_t j, double overlap, double size) {
        if (overlap > summary_.maxOverlapFraction * size) [[unlikely]] {
            summary_.maxOverlapFraction = overlap / size;
            summary_.worstA = p_.id[i];
            summary_.worstB = j >= 0 ? p_.id[static_cast<std::size_t>(j)] : static_cast<std::uint64_t>(-j - 1);
            summary_.worstIsWall = j < 0;
        }
    }

    // The smallest semi-axis (spheres: the radius): what overlaps are measured against.
    double sizeOf(std::uint32_t i) const {
        return p_.isShaped(i) ? (*shapes_)[static_cast<std::size_t>(p_.shape[i])].semiAxes().minCoeff() : p_.radius[i];
    }

    [[noreturn]] void detectionFailed(std::uint32_t i, std::uint32_t j) const {
        std::ostringstream m;
        m << "superquadric contact detection failed between particle id " << p_.id[i] << " at ("
          << p_.position[i].transpose() << ") and particle id " << p_.id[j] << " at (" << p_.position[j].transpose()
          << "): Newton's method and its fallback (morphing from the bounding spheres) did not converge";
        throw Error(m.str());
    }

    // Force and torque on i (and j, unless it is a wall, j < 0) of one contact, or of the
    // separation impulse of a pair that stopped touching during the last step. The torques are
    // bij x f = -armI n x f and -bji x f = -armJ n x f.
    [[gnu::always_inline]] void apply(std::uint32_t i, std::int64_t j, const ContactForce& f, const Vec3& n,
                                      const Arms& arms) {
        const Vec3 force = f.normalForce * n + f.tangentialForce;
        const Vec3 turn = n.cross(f.tangentialForce);  // n x force
        if (perPair_ && j >= 0 && !oneWay_) [[unlikely]] {  // kept for the sums in id order
            PairContribution& c = perPair_[currentPair_];
            c.force += force;
            c.torqueI -= arms.i * turn;
            c.torqueJ -= arms.j * turn;
            return;
        }
        p_.force[i] += force;
        p_.torque[i] -= arms.i * turn;
        if (j >= 0 && !oneWay_) {
            p_.force[j] -= force;
            p_.torque[j] -= arms.j * turn;
        }
    }

    // Laws with rolling resistance: a torque on i and its opposite on j (Species/ContactLaws.h),
    // and what their rolling velocity needs (ContactKinematics::relativeSpin).
    void applyTorque(std::uint32_t i, std::int64_t j, const Vec3& torque) {
        if (perPair_ && j >= 0 && !oneWay_) [[unlikely]] {
            perPair_[currentPair_].torqueI += torque;
            perPair_[currentPair_].torqueJ -= torque;
            return;
        }
        p_.torque[i] += torque;
        if (j >= 0 && !oneWay_) p_.torque[j] -= torque;
    }
    static void setRolling(ContactKinematics& c, const Vec3& relativeSpin, double rollingRadius) {
        c.relativeSpin = relativeSpin;
        c.rollingRadius = rollingRadius;
    }

    [[gnu::always_inline]] void touch(std::uint32_t i, std::int64_t j, const ContactKinematics& c, const Arms& arms,
                                      ContactHistory& history, const Law& law, double smallerRadius) {
        const ContactForce f = law.force(c, history, dt_);
        history.state = ContactHistory::touching;
        history.lastNormalForce = f.normalForce;
        apply(i, j, f, c.normal, arms);
        if constexpr (Law::rollingResistance) applyTorque(i, j, law.rollingTorque(c, history, f.normalForce, dt_));
        ++summary_.contacts;
        noteOverlap(i, j, c.overlap, smallerRadius);
        if (records_ && !oneWay_) [[unlikely]]
            record(i, j, c, arms, history, law, f);
    }

    [[gnu::noinline]] void record(std::uint32_t i, std::int64_t j, ContactKinematics c, Arms arms,
                                  ContactHistory history, const Law& law, ContactForce f) {
        records_->add({i, j, p_.position[i] - arms.i * c.normal, c.overlap, history.spring.norm(), f.normalForce,
                       c.normal, f.tangentialForce, law.elasticEnergy(c, history.spring)});
    }

    // Apart now: a pair that stopped touching during the last step gets its separation impulse,
    // one that will touch within the next step its push ahead (LinearSpringDashpot.h).
    // (Everything by value, so that the caller's copies stay in registers; returns the new history.)
    [[gnu::noinline]] ContactHistory apart(std::uint32_t i, std::int64_t j, ContactKinematics c, Arms arms,
                                           ContactHistory history, const Law& law) {
        double normalForce = 0;
        if (history.isTouching()) {
            const ContactForce f = law.separationForce(c, history, dt_);
            apply(i, j, f, c.normal, arms);
            normalForce = f.normalForce;
            history = ContactHistory{};  // Theory/ContactLaws.md eq. (13): the spring lives from the first time of contact
        }
        const double push = law.approachForce(c, history, dt_);
        if (push != 0) apply(i, j, {push, Vec3::Zero()}, c.normal, arms);
        history.lastNormalForce = normalForce + push;
        if (history.state == ContactHistory::apart && history.lastNormalForce != 0) history.state = ContactHistory::separated;
        return history;
    }

    // The batch's contacts computed, then applied in the order they came (Contacts/BatchedContactForces.h):
    // flush, its common case applyBatch, and applyBatchWithExtras for pair forces kept, records or
    // warm starts.
    void flush(PairList& list);
    template <bool frictionless>
    void applyBatch(PairList& list);
    [[gnu::noinline]] void applyBatchWithExtras(PairList& list);

    ContactBatch batch_;
    bool oneWay_ = false;  // in oneWayPairs: no reaction on j, no records
    // The sweep's points of the step (makeSweepPoints): slots [0, pointsMade_) made, with the
    // frame's velocity and the largest growth among them; the interior pairs done (interiorPairs)
    // and where the histories they change are saved meanwhile.
    bool pointsStarted_ = false, interiorDone_ = false;
    std::size_t pointsMade_ = 0;
    Vec3 frame_ = Vec3::Zero();
    double growth_ = 0;
    ContactHistoryLog* changed_ = nullptr;
    ParticleStore& p_;
    const PairTable<Law>& laws_;
    const double dt_;
    double closing_;
    const std::vector<Vec3>& previousForce_;
    ContactSummary& summary_;
    ContactRecords* records_;
    const std::vector<Superquadric>* shapes_;  // null in scenes of spheres only
    PairContribution* perPair_;  // non-null: pair forces kept for sums in id order (IdOrderedForceSums.h)
    const SuperquadricContactSettings shapeSettings_;  // the Newton solve of superquadric pairs (--shape-tolerance)
    const bool prefetchPartners_;  // a large scene: the contact pass asks for its partners' data ahead
    std::size_t currentPair_ = 0;
    EllipsoidContactBatch ellipsoids_;  // (scenes with shapes only)
};

// ContactForces.h addContactForces in this form.
template <class Law>
void addContactForces(const ContactForceLoopArguments<Law>& arguments, PairList& list, const std::vector<Wall>& walls,
                      const std::vector<PrescribedMotion>& motions, const Domain& domain) {
    if (arguments.shapes && arguments.p.hasShapes())
        placeShapedParticles(arguments.p, *arguments.shapes, list.shapedFrameScratch, list.spinScratch);
    ContactForceLoopInLanes<Law> loop(arguments);
    loop.particlePairs(list, domain, motions.empty());
    loop.oneWayPairs(list, domain);
    loop.wallPairs(list, walls, motions);
}

}  // namespace talus::TALUS_LANES

#include "Contacts/BatchedContactForces.h"
#include "Contacts/ShapedContactForces.h"
#include "Contacts/WallContactForces.h"
