#include "Parallel/DomainSplit.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "Contacts/ContactForces.h"
#include "Error.h"

namespace talus {

namespace {

void packParticle(const ParticleStore& p, std::size_t i, Packer& out) {
    p.forEachArray([&](const auto& array) { out.put(array[i]); });
}

void unpackParticle(ParticleStore& p, Unpacker& in) {
    p.forEachArray([&](auto& array) {
        using T = typename std::decay_t<decltype(array)>::value_type;
        array.push_back(in.template get<T>());
    });
}

// An empty store of the same kind (with the arrays of shapes if p has them).
ParticleStore emptyLike(const ParticleStore& p) {
    ParticleStore s;
    if (p.hasShapes()) s.enableShapes();
    return s;
}

// Keeps the slots for which keep(i) is true, in their order.
template <class Keep>
void keepSlots(ParticleStore& p, Keep keep) {
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (keep(i)) kept.push_back(i);
    p.forEachArray([&](auto& array) {
        for (std::size_t k = 0; k < kept.size(); ++k) array[k] = array[kept[k]];
        array.resize(kept.size());
    });
}

}  // namespace

void DomainSplit::setGrid(const std::array<int, 3>& ranksPerAxis) {
    const auto [gx, gy, gz] = ranksPerAxis;
    require(gx >= 1 && gy >= 1 && gz >= 1 && gx * gy * gz == ranks(),
            "rank grid " + std::to_string(gx) + "x" + std::to_string(gy) + "x" + std::to_string(gz) + " has " +
                std::to_string(gx * gy * gz) + " cells, but the run has " + std::to_string(ranks()) +
                " ranks (mpirun -np): --rank-grid must multiply to the number of ranks");
    grid_ = ranksPerAxis;
    for (auto& b : bounds_) b.clear();
}

// A particle's share of the work, in spheres: a superquadric's contacts cost several spheres'
// (the exact contact's Newton solve; an aspect-2 ellipsoid in a flowing drum costs 3.9 spheres,
// Documentation/Drums/RotatingDrum.md "Cost"). Whole numbers, so that the sums over the ranks
// are exact.
double DomainSplit::workOf(const ParticleStore& p, std::size_t i) {
    return p.isShaped(i) ? 4.0 : 1.0;
}

// Along each split axis: a histogram of the coordinate over the particles' extent (4096 bins;
// each particle counted by its work, workOf, summed over ranks), then each interior boundary
// where the cumulative count reaches its share, interpolated in its bin. Whole-number counts make
// the sum exact, so every rank gets the same boundaries.
void DomainSplit::balance(const ParticleStore& p, const Domain& domain, bool replicated) {
    for (int a = 0; a < 3; ++a) {
        const int n = grid_[a];
        std::vector<double>& bounds = bounds_[a];
        bounds.clear();
        if (n == 1) continue;
        double range[2] = {-INFINITY, -INFINITY};  // -(smallest coordinate), largest
        for (std::size_t i = 0; i < p.owned(); ++i) {
            range[0] = std::max(range[0], -p.position[i][a]);
            range[1] = std::max(range[1], p.position[i][a]);
        }
        if (!replicated) communicator_.allReduce(range, 2, Communicator::Reduction::max);
        double lo = -range[0], hi = range[1];
        if (domain.periodic[a]) lo = domain.lo[a], hi = domain.hi[a];
        if (!(hi > lo)) {  // no particles, or all at one coordinate: equal lengths of the domain
            lo = domain.lo[a], hi = domain.hi[a];
            for (int r = 1; r < n; ++r) bounds.push_back(lo + (hi - lo) * r / n);
            continue;
        }
        // The moving particles alone where there are any: a fixed particle (a chute's base, a drum's
        // wall) is not integrated, and its contacts are also its moving partners', so counting it
        // would give the rank with more of them less of the work (Documentation/Parallel.md, "Cells
        // by particle count"). Counts of both kinds side by side, summed over the ranks together.
        constexpr int bins = 4096;
        std::vector<double> count(2 * bins, 0.0);
        const double width = (hi - lo) / bins;
        for (std::size_t i = 0; i < p.owned(); ++i) {
            const int b = std::clamp(static_cast<int>((p.position[i][a] - lo) / width), 0, bins - 1);
            count[p.fixed[i] ? bins + b : b] += workOf(p, i);
        }
        if (!replicated) communicator_.allReduce(count.data(), 2 * bins, Communicator::Reduction::sum);
        double total = 0;
        for (int b = 0; b < bins; ++b) total += count[b];
        if (total == 0)  // (only fixed particles: count them)
            for (int b = 0; b < bins; ++b) total += count[b] = count[bins + b];
        count.resize(bins);
        double below = 0;
        int b = 0;
        for (int r = 1; r < n; ++r) {
            const double target = total * r / n;
            while (b < bins - 1 && below + count[b] < target) below += count[b++];
            const double fraction = count[b] > 0 ? std::clamp((target - below) / count[b], 0.0, 1.0) : 0.0;
            bounds.push_back(lo + (b + fraction) * width);
        }
        // The ranks must agree on the boundaries to the bit, or a particle would have two owners
        // or none: whole-number counts make the sums exact, and the maximum over ranks makes sure.
        if (!replicated) communicator_.allReduce(bounds.data(), n - 1, Communicator::Reduction::max);
    }
}

int DomainSplit::cellAlong(int axis, double x) const {
    const std::vector<double>& b = bounds_[axis];
    return static_cast<int>(std::upper_bound(b.begin(), b.end(), x) - b.begin());
}

std::array<int, 3> DomainSplit::cellOf(int rank) const {
    return {rank % grid_[0], rank / grid_[0] % grid_[1], rank / (grid_[0] * grid_[1])};
}

int DomainSplit::ownerOf(const Vec3& x) const {
    return rankAt(cellAlong(0, x.x()), cellAlong(1, x.y()), cellAlong(2, x.z()));
}

void DomainSplit::keepOwnShare(ParticleStore& p) const {
    require(p.ghostCount == 0, "keepOwnShare: the store holds ghosts");
    keepSlots(p, [&](std::size_t i) { return ownerOf(p.position[i]) == rank(); });
}

void DomainSplit::migrate(ParticleStore& p, std::vector<CarriedHistory>& carried) {
    const Stopwatch watch(seconds.rebuild);
    p.dropGhosts();
    const int me = rank();
    std::unordered_map<std::uint64_t, int> leaving;  // id -> new owner
    std::vector<std::size_t> count(ranks(), 0);
    std::vector<Bytes> particles(ranks()), histories(ranks());
    const std::array<int, 3> here = cellOf(me);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const int owner = ownerOf(p.position[i]);
        if (owner == me) continue;
        leaving.emplace(p.id[i], owner);
        ++migrated;
        const std::array<int, 3> there = cellOf(owner);
        bool far = false;
        for (int a = 0; a < 3; ++a) {
            migratedAlong[a] += there[a] != here[a];
            far = far || std::abs(there[a] - here[a]) > 1;
        }
        migratedFar += far;
        Packer to(particles[owner]);
        packParticle(p, i, to);
        ++count[owner];
    }
    // The histories that involve a leaving particle go with it (to both owners if both leave).
    std::vector<std::size_t> historyCount(ranks(), 0);
    auto sendHistory = [&](const CarriedHistory& c, int to) {
        Packer(histories[to]).put(c);
        ++historyCount[to];
    };
    if (!leaving.empty())
        for (const CarriedHistory& c : carried) {
            const auto a = leaving.find(c.a), b = leaving.find(c.b);
            const int toA = a != leaving.end() ? a->second : -1, toB = b != leaving.end() ? b->second : -1;
            if (toA >= 0) sendHistory(c, toA);
            if (toB >= 0 && toB != toA) sendHistory(c, toB);
        }
    std::vector<Bytes> outgoing(ranks());
    for (int r = 0; r < ranks(); ++r) {
        if (r == me) continue;
        Packer out(outgoing[r]);
        out.put(static_cast<std::uint64_t>(count[r]));
        outgoing[r].insert(outgoing[r].end(), particles[r].begin(), particles[r].end());
        out.put(static_cast<std::uint64_t>(historyCount[r]));
        outgoing[r].insert(outgoing[r].end(), histories[r].begin(), histories[r].end());
    }
    if (!leaving.empty()) keepSlots(p, [&](std::size_t i) { return !leaving.count(p.id[i]); });
    const std::vector<Bytes> incoming = communicator_.exchange(outgoing);
    for (int r = 0; r < ranks(); ++r) {
        if (r == me || incoming[r].empty()) continue;
        Unpacker in(incoming[r]);
        const auto n = in.get<std::uint64_t>();
        for (std::uint64_t k = 0; k < n; ++k) unpackParticle(p, in);
        const auto h = in.get<std::uint64_t>();
        for (std::uint64_t k = 0; k < h; ++k) carried.push_back(in.get<CarriedHistory>());
    }
    // A pair across ranks had its history on both: the copies are equal (same arithmetic).
    std::stable_sort(carried.begin(), carried.end());
    carried.erase(std::unique(carried.begin(), carried.end(),
                              [](const CarriedHistory& x, const CarriedHistory& y) { return x.a == y.a && x.b == y.b; }),
                  carried.end());
}

template <class F>
void DomainSplit::forEachOtherRankNear(const Vec3& x, std::uint32_t species, const Domain& domain, double width,
                                       F&& f) const {
    const int me = rank();
    const OneWayPeriodicBox& box = domain.oneWay;
    // The cells along an axis that meet [from, to], each once.
    auto addCellsMeeting = [&](int a, double from, double to, std::vector<int>& cells) {
        for (int c = cellAlong(a, from); c <= cellAlong(a, to); ++c)
            if (std::find(cells.begin(), cells.end(), c) == cells.end()) cells.push_back(c);
    };
    // The cells along an axis that meet [x - width, x + width], through the periodic images too.
    auto cellsNear = [&](int a, double x, std::vector<int>& cells) {
        const bool periodic = domain.periodic[a];
        const double L = domain.length(a), lo = domain.lo[a], hi = domain.hi[a];
        for (int image = periodic ? -1 : 0; image <= (periodic ? 1 : 0); ++image) {
            double from = x + image * L - width, to = x + image * L + width;
            if (periodic) {
                from = std::max(from, lo);
                to = std::min(to, std::nextafter(hi, lo));
                if (from > to) continue;
            }
            addCellsMeeting(a, from, to, cells);
        }
    };
    // The ranks meeting the cube [x - width, x + width]^3 (and its images) are the products of
    // the cells meeting each of its sides.
    thread_local std::array<std::vector<int>, 3> cells;  // (kept: no allocation per particle)
    for (int a = 0; a < 3; ++a) {
        cells[a].clear();
        if (grid_[a] == 1)
            cells[a].push_back(0);
        else
            cellsNear(a, x[a], cells[a]);
    }
    // A particle of an active maser box near one of its faces pairs with those near the other
    // face through the box's image (PairList::oneWayPairs): its ghosts go there too.
    if (box.active && box.isMember(species) && grid_[0] > 1) {
        if (box.hi - x.x() < width) addCellsMeeting(0, x.x() - box.length() - width, x.x() - box.length() + width, cells[0]);
        if (x.x() - box.lo < width) addCellsMeeting(0, x.x() + box.length() - width, x.x() + box.length() + width, cells[0]);
    }
    for (int cz : cells[2])
        for (int cy : cells[1])
            for (int cx : cells[0])
                if (const int r = rankAt(cx, cy, cz); r != me) f(r);
}

bool DomainSplit::nobodyElseNeeds(const Vec3& x, std::uint32_t species, const Domain& domain) const {
    bool needed = false;
    forEachOtherRankNear(x, species, domain, ghostWidth_, [&needed](int) { needed = true; });
    return !needed && ownerOf(x) == rank();
}

bool DomainSplit::isSentAsGhost(std::uint32_t slot) const {
    for (const std::vector<std::uint32_t>& slots : sendSlots_)
        if (std::find(slots.begin(), slots.end(), slot) != slots.end()) return true;
    return false;
}

void DomainSplit::makeGhosts(ParticleStore& p, const Domain& domain, double width) {
    const Stopwatch watch(seconds.rebuild);
    require(p.ghostCount == 0, "makeGhosts: the store holds ghosts already");
    const int n = ranks();
    sendSlots_.assign(n, {});
    ghostWidth_ = width;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        forEachOtherRankNear(p.position[i], p.species[i], domain, width, [&](int r) { sendSlots_[r].push_back(i); });
    std::vector<Bytes> outgoing(n);
    for (int r = 0; r < n; ++r) {
        Packer out(outgoing[r]);
        for (std::uint32_t i : sendSlots_[r]) packParticle(p, i, out);
    }
    const std::vector<Bytes> incoming = communicator_.exchange(outgoing);
    const std::size_t owned = p.size();
    sendTo_.clear();
    receiveFrom_.clear();
    receiveCount_.clear();
    std::vector<std::vector<std::uint32_t>> slots;
    for (int r = 0; r < n; ++r) {
        if (!sendSlots_[r].empty()) sendTo_.push_back(r), slots.push_back(std::move(sendSlots_[r]));
        if (incoming[r].empty()) continue;
        const std::size_t before = p.size();
        Unpacker in(incoming[r]);
        while (!in.atEnd()) unpackParticle(p, in);
        receiveFrom_.push_back(r);
        receiveCount_.push_back(p.size() - before);
    }
    sendSlots_ = std::move(slots);
    p.ghostCount = p.size() - owned;
    // (Decided by all ranks at once, so that all use the allreduce or none.)
    double allPartners = n > 1 && static_cast<int>(sendTo_.size()) == n - 1 &&
                         static_cast<int>(receiveFrom_.size()) == n - 1;
    communicator_.allReduce(&allPartners, 1, Communicator::Reduction::min);
    partnersAreAll_ = allPartners > 0;
}

namespace {

// What a ghost needs from its owner each step (the force loop's inputs that change), the last
// forces from `forces`.
template <class Store, class Forces, class F>
void forEachMovingField(Store& p, Forces& forces, F&& f) {
    f(p.position); f(p.velocity); f(p.angularVelocity); f(forces);
    if (p.hasShapes()) f(p.orientation);
}

}  // namespace

// One message per partner, field by field: the positions of all its ghosts, then their
// velocities, and so on. The ghosts from one partner sit in consecutive slots, so each field
// arrives with one copy. A slot beyond the owned ones (a particle removed since the ghosts were
// made, which forces a list build on every rank: the update is then not applied) sends zeros,
// so that every message has the size its receiver expects.
void DomainSplit::startGhostUpdate(const ParticleStore& p, const std::vector<Vec3>& lastForces, const Agreement& mine) {
    if (sendTo_.empty() && receiveFrom_.empty()) return;
    const Stopwatch watch(seconds.ghosts);
    std::size_t bytesPerParticle = 0;
    forEachMovingField(p, lastForces, [&](const auto& array) { bytesPerParticle += sizeof(array[0]); });
    outgoing_.resize(sendTo_.size());
    for (std::size_t k = 0; k < sendTo_.size(); ++k) {
        const std::vector<std::uint32_t>& slots = sendSlots_[k];
        outgoing_[k].assign(sizeof(Agreement) + slots.size() * bytesPerParticle, 0);
        char* out = outgoing_[k].data();
        std::memcpy(out, mine.data(), sizeof(Agreement));
        out += sizeof(Agreement);
        forEachMovingField(p, lastForces, [&](const auto& array) {
            constexpr std::size_t size = sizeof(array[0]);
            for (std::uint32_t i : slots) {
                if (i < p.owned()) std::memcpy(out, &array[i], size);
                out += size;
            }
        });
    }
    incoming_.resize(receiveFrom_.size());
    for (std::size_t k = 0; k < receiveFrom_.size(); ++k)
        incoming_[k].resize(sizeof(Agreement) + receiveCount_[k] * bytesPerParticle);
    communicator_.startExchangeWith(sendTo_, outgoing_, receiveFrom_, incoming_);
}

void DomainSplit::finishGhostUpdate(Agreement& agreement) {
    if (sendTo_.empty() && receiveFrom_.empty()) return;
    const Stopwatch watch(seconds.ghosts);
    communicator_.finishExchange();
    if (!partnersAreAll_) return;
    for (const Bytes& in : incoming_) {
        Agreement theirs;
        std::memcpy(theirs.data(), in.data(), sizeof(Agreement));
        for (std::size_t k = 0; k < theirs.size(); ++k) agreement[k] = std::max(agreement[k], theirs[k]);
    }
}

void DomainSplit::applyGhostUpdate(ParticleStore& p, std::vector<Vec3>& lastForces) {
    if (receiveFrom_.empty()) return;
    const Stopwatch watch(seconds.ghosts);
    require(lastForces.size() == p.size(), "applyGhostUpdate: the last forces are not one per particle");
    std::size_t slot = p.owned();
    for (std::size_t k = 0; k < receiveFrom_.size(); ++k) {
        const std::size_t n = receiveCount_[k];
        const char* in = incoming_[k].data() + sizeof(Agreement);
        forEachMovingField(p, lastForces, [&](auto& array) {
            const std::size_t bytes = n * sizeof(array[0]);
            std::memcpy(static_cast<void*>(array.data() + slot), in, bytes);
            in += bytes;
        });
        slot += n;
    }
}

std::size_t DomainSplit::ghostsSent() const {
    std::size_t n = 0;
    for (const auto& s : sendSlots_) n += s.size();
    return n;
}

ParticleStore DomainSplit::gatherParticles(const ParticleStore& p) {
    Bytes mine;
    Packer out(mine);
    for (std::size_t i = 0; i < p.owned(); ++i) packParticle(p, i, out);
    const std::vector<Bytes> all = communicator_.gatherToRoot(mine);
    ParticleStore gathered = emptyLike(p);
    for (const Bytes& bytes : all) {
        Unpacker in(bytes);
        while (!in.atEnd()) unpackParticle(gathered, in);
    }
    return gathered;
}

ContactRecordList DomainSplit::gatherRecords(const ParticleStore& p, const ContactRecordList& records,
                                             const ParticleStore& gathered) {
    Bytes mine;
    Packer out(mine);
    for (const ContactRecord& r : records) {
        out.put(r);
        out.put(p.id[r.i]);
        out.put(r.j >= 0 ? static_cast<std::int64_t>(p.id[r.j]) : r.j);
    }
    const std::vector<Bytes> all = communicator_.gatherToRoot(mine);
    ContactRecordList result;
    if (all.empty()) return result;
    std::unordered_map<std::uint64_t, std::uint32_t> slotOf;
    for (std::uint32_t i = 0; i < gathered.size(); ++i) slotOf.emplace(gathered.id[i], i);
    for (const Bytes& bytes : all) {
        Unpacker in(bytes);
        while (!in.atEnd()) {
            ContactRecord r = in.get<ContactRecord>();
            r.i = slotOf.at(in.get<std::uint64_t>());
            const auto j = in.get<std::int64_t>();
            r.j = j >= 0 ? static_cast<std::int64_t>(slotOf.at(static_cast<std::uint64_t>(j))) : j;
            result.push_back(r);
        }
    }
    return result;
}

std::vector<CarriedHistory> DomainSplit::gatherHistories(const std::vector<CarriedHistory>& mine) {
    Bytes bytes;
    Packer out(bytes);
    for (const CarriedHistory& c : mine) out.put(c);
    std::vector<CarriedHistory> all;
    for (const Bytes& b : communicator_.gatherToRoot(bytes)) {
        Unpacker in(b);
        while (!in.atEnd()) all.push_back(in.get<CarriedHistory>());
    }
    std::sort(all.begin(), all.end());
    return all;
}

}  // namespace talus
