// The members of the force loop (ContactForceLoopInLanes, Contacts/ContactForceLoop.h) that
// finish a batch of lasting contacts (Contacts/ContactBatch.h): the batch computed in lanes, then
// its forces, torques and histories applied in the order the contacts came. Included at the end
// of ContactForceLoop.h.
#pragma once

#include "Contacts/ContactForceLoop.h"

namespace talus::TALUS_LANES {

// The batch's contacts computed (all lanes at once, vectorised), then applied to their
// particles and histories in the order they came, with the summary and output records.
template <class Law>
void ContactForceLoopInLanes<Law>::flush(PairList& list) {
    ContactBatch& b = batch_;
    if (b.count == 0) return;
    const bool extras = perPair_ || records_ || list.history.hasWarmStarts();
    const bool frictionless = !extras && b.template frictionless<Law>();
    if (frictionless) {
        b.template gather<true>(p_, previousForce_, list.history);
        b.template compute<Law, true>(dt_);
    } else {
        b.gather(p_, previousForce_, list.history);
        b.template compute<Law>(dt_);
    }
    if (changed_)  // (interiorPairs)
        for (int l = 0; l < b.count; ++l) changed_->save(list.history, b.k[l]);
    if (extras) [[unlikely]]
        applyBatchWithExtras(list);
    else if (frictionless)
        applyBatch<true>(list);
    else
        applyBatch<false>(list);
    summary_.contacts += static_cast<std::size_t>(b.count);
    b.count = 0;
}

// The common case of flush: forces and torques added, histories set, the largest overlap
// noted, nothing else. Through plain pointers that the compiler knows apart (they do not
// alias: separate arrays), so that a lane costs its loads, additions and stores: with the
// vectors' own accessors, and the rare cases' branches in the loop, it took 88 instructions
// a contact in a profile of the settled bed, a fifth of the settled step's.
template <class Law>
template <bool frictionless>
void ContactForceLoopInLanes<Law>::applyBatch(PairList& list) {
    const ContactBatch& b = batch_;
    double* __restrict force = p_.force[0].data();
    double* __restrict torque = p_.torque[0].data();
    double* __restrict lasting = list.history.lastingRecords();
    ContactHistory::State* __restrict state = list.history.mutableStates();
    double largestFraction = summary_.maxOverlapFraction;
    for (int l = 0; l < b.count; ++l) {
        const std::size_t i = 3 * std::size_t{b.i[l]}, j = 3 * std::size_t{b.j[l]}, k = b.k[l];
        force[i] += b.fx[l], force[i + 1] += b.fy[l], force[i + 2] += b.fz[l];
        force[j] -= b.fx[l], force[j + 1] -= b.fy[l], force[j + 2] -= b.fz[l];
        if constexpr (!frictionless) {  // (no torques: ContactBatch::frictionless)
            torque[i] += b.tix[l], torque[i + 1] += b.tiy[l], torque[i + 2] += b.tiz[l];
            torque[j] += b.tjx[l], torque[j + 1] += b.tjy[l], torque[j + 2] += b.tjz[l];
        }
        double* record = lasting + 4 * k;
        record[0] = b.sx[l], record[1] = b.sy[l], record[2] = b.sz[l], record[3] = b.fn[l];
        state[k] = ContactHistory::touching;
        const double size = std::min(b.ri[l], b.rj[l]);
        if (b.overlap[l] > largestFraction * size) [[unlikely]] {
            noteOverlap(b.i[l], b.j[l], b.overlap[l], size);
            largestFraction = summary_.maxOverlapFraction;
        }
    }
}

// flush with pair forces kept for sums in id order, output records or warm starts.
template <class Law>
void ContactForceLoopInLanes<Law>::applyBatchWithExtras(PairList& list) {
    ContactBatch& b = batch_;
    for (int l = 0; l < b.count; ++l) {
        const std::uint32_t i = b.i[l], j = b.j[l];
        const Vec3 force(b.fx[l], b.fy[l], b.fz[l]);
        if (perPair_) [[unlikely]] {
            perPair_[b.k[l]] = {force, Vec3(b.tix[l], b.tiy[l], b.tiz[l]), Vec3(b.tjx[l], b.tjy[l], b.tjz[l])};
        } else {
            p_.force[i] += force;
            p_.force[j] -= force;
            p_.torque[i] += Vec3(b.tix[l], b.tiy[l], b.tiz[l]);
            p_.torque[j] += Vec3(b.tjx[l], b.tjy[l], b.tjz[l]);
        }
        const Vec3 spring(b.sx[l], b.sy[l], b.sz[l]);
        list.history.set(b.k[l], {spring, b.fn[l], ContactHistory::touching});
        noteOverlap(i, j, b.overlap[l], std::min(b.ri[l], b.rj[l]));
        if (records_) [[unlikely]] {
            const Vec3 n = Vec3(b.dx[l], b.dy[l], b.dz[l]).normalized();
            ContactKinematics c{};
            c.overlap = b.overlap[l];
            c.effectiveRadius = b.ri[l] * b.rj[l] / (b.ri[l] + b.rj[l]);
            const Vec3 tangential = force - b.fn[l] * n;
            records_->add({i, j, p_.position[i] - (b.ri[l] - 0.5 * b.overlap[l]) * n, b.overlap[l],
                           spring.norm(), b.fn[l], n, tangential, laws_(p_.species[i], p_.species[j]).elasticEnergy(c, spring)});
        }
    }
}

}  // namespace talus::TALUS_LANES
