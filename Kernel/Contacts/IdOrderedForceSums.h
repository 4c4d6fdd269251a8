// Contact forces summed in an order fixed by particle ids (Simulation's --id-ordered-sums,
// Documentation/Parallel.md): the same result to the bit on any number of ranks.
//
// Floating-point addition is not associative, so a particle's total force depends on the order
// in which its contacts are added, and that order follows the pair list, which depends on the
// particles' slots and on the rank count. In this mode the force loop stores each pair's force
// and torques (PairContribution) instead of adding them, every pair is listed with the smaller id
// first (so its arithmetic is the same wherever it is computed), and each particle then adds its
// pairs' contributions in the order of its partners' ids. It costs a second pass over the pairs.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "Contacts/PairList.h"
#include "Particles/ParticleStore.h"

namespace talus {

struct PairContribution {
    Vec3 force = Vec3::Zero();    // on the pair's first particle (the second gets -force)
    Vec3 torqueI = Vec3::Zero();  // on the first particle
    Vec3 torqueJ = Vec3::Zero();  // on the second
};

class IdOrderedForceSums {
public:
    // After a list build: each owned particle's pairs, ordered by the partner's id.
    void rebuild(const PairList& list, const ParticleStore& p) {
        const std::size_t owned = p.owned();
        start_.assign(owned + 1, 0);
        for (const ParticlePair& pair : list.pairs) {
            if (pair.i < owned) ++start_[pair.i + 1];
            if (pair.j < owned) ++start_[pair.j + 1];
        }
        for (std::size_t i = 0; i < owned; ++i) start_[i + 1] += start_[i];
        entries_.resize(start_[owned]);
        std::vector<std::size_t> at(start_.begin(), start_.end() - 1);
        for (std::uint32_t k = 0; k < list.pairs.size(); ++k) {
            const ParticlePair pair = list.pairs[k];
            if (pair.i < owned) entries_[at[pair.i]++] = {p.id[pair.j], k, true};
            if (pair.j < owned) entries_[at[pair.j]++] = {p.id[pair.i], k, false};
        }
        for (std::size_t i = 0; i < owned; ++i)
            std::sort(entries_.begin() + static_cast<std::ptrdiff_t>(start_[i]),
                      entries_.begin() + static_cast<std::ptrdiff_t>(start_[i + 1]),
                      [](const Entry& a, const Entry& b) { return a.partner < b.partner; });
    }

    // Zeroed contributions for the force loop to fill (one per listed pair).
    std::vector<PairContribution>& contributions(std::size_t pairs) {
        contributions_.assign(pairs, PairContribution{});
        return contributions_;
    }

    // Adds every owned particle's contributions to its force and torque, by partner id.
    void addTo(ParticleStore& p) const {
        for (std::size_t i = 0; i + 1 < start_.size(); ++i)
            for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
                const Entry& entry = entries_[e];
                const PairContribution& c = contributions_[entry.pair];
                if (entry.first) {
                    p.force[i] += c.force;
                    p.torque[i] += c.torqueI;
                } else {
                    p.force[i] -= c.force;
                    p.torque[i] += c.torqueJ;
                }
            }
    }

private:
    struct Entry {
        std::uint64_t partner;
        std::uint32_t pair;
        bool first;  // the particle is the pair's first
    };
    std::vector<std::size_t> start_;
    std::vector<Entry> entries_;
    std::vector<PairContribution> contributions_;
};

}  // namespace talus
