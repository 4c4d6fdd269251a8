#include "Contacts/WaveSchedule.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "Error.h"

namespace talus {

namespace {

bool fail(std::string* why, const std::string& reason) {
    if (why) *why = reason;
    return false;
}

// Cells a and b of `count` along a periodic axis are the same or next to each other.
bool neighbouring(int a, int b, int count) {
    const int d = std::abs(a - b);
    return d <= 1 || d == count - 1;
}

}  // namespace

std::optional<WaveCells> WaveCells::fit(const Domain& domain, double longestSeparation, int levels, int stripColumns,
                                        std::string* why) {
    const auto none = [&](const std::string& reason) -> std::optional<WaveCells> {
        fail(why, reason);
        return std::nullopt;
    };
    if (levels < 1 || levels > 255) return none("waves of 1 to 255 steps, got " + std::to_string(levels));
    if (!domain.periodic[0] || !domain.periodic[1]) return none("waves need a box periodic along x and y");
    if (!(longestSeparation > 0) || !std::isfinite(longestSeparation))
        return none("the longest listed separation is not a positive number");
    WaveCells c;
    c.levels_ = levels;
    c.lo_ = domain.lo;
    const int least = std::max(3, 2 * levels);
    int count[2];
    for (int a = 0; a < 2; ++a) {
        const double cells = std::floor(domain.length(a) / longestSeparation);
        if (cells < least)
            return none(std::string("the box holds ") + std::to_string(static_cast<long>(cells)) + " cells along " +
                        (a == 0 ? "x" : "y") + " of the longest listed separation " + str(longestSeparation) +
                        "; waves of " + std::to_string(levels) + " steps need " + std::to_string(least));
        count[a] = static_cast<int>(std::min(cells, 1e6));
        c.width_[a] = domain.length(a) / count[a];
    }
    c.rows_ = count[0], c.columns_ = count[1];
    const int strips = std::max(1, c.columns_ / std::max(stripColumns, least));
    for (int q = 0; q <= strips; ++q) c.stripStart_.push_back(static_cast<int>(static_cast<long>(q) * c.columns_ / strips));
    return c;
}

std::size_t WaveCells::cell(int row, int column) const {
    const auto q = static_cast<std::size_t>(strip(column));
    const int begin = stripStart_[q], width = stripStart_[q + 1] - begin;
    return static_cast<std::size_t>(begin) * static_cast<std::size_t>(rows_) +
           static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column - begin);
}

std::vector<std::size_t> WaveCells::order(const std::vector<Vec3>& positions) const {
    const std::size_t n = positions.size();
    double bottom = 0;
    for (std::size_t k = 0; k < n; ++k) bottom = k == 0 ? positions[k][2] : std::min(bottom, positions[k][2]);
    const double band = std::max(width_[0], width_[1]);
    std::vector<std::uint64_t> key(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double h = (positions[k][2] - bottom) / band;
        const std::uint64_t height = h < 1048575.0 ? static_cast<std::uint64_t>(h) : 1048575;  // (NaN: the top)
        key[k] = (static_cast<std::uint64_t>(cellOf(positions[k])) << 20) | height;
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
    return order;
}

bool WaveSchedule::make(const WaveCells& cells, const std::vector<ParticlePair>& pairs, std::size_t interiorPairs,
                        const std::vector<Vec3>& positions, std::size_t particles, std::string* why,
                        const std::vector<WallCandidate>& walls, std::vector<std::uint32_t>* pairOrder) {
    regions_.clear();
    placeRuns_.clear();
    wallIndex_.clear();
    driftRuns_.clear();
    levels_ = cells.levels();
    if (positions.size() < particles) return fail(why, "fewer positions than particles");
    if (particles > 0xfffffffeu) return fail(why, "too many particles for a wave schedule");
    if (pairs.size() * static_cast<std::size_t>(levels_) > 0xffffffffu || walls.size() * static_cast<std::size_t>(levels_) > 0xffffffffu)
        return fail(why, "too many listed pairs for a wave schedule of " + std::to_string(levels_) + " steps");
    // The particles' cells, in the wave order, and where each cell's slots begin.
    std::vector<std::uint32_t> cellStart(cells.cellCount() + 1, 0);
    std::size_t previous = 0;
    std::vector<int> row(particles), column(particles);
    for (std::size_t k = 0; k < particles; ++k) {
        row[k] = cells.row(positions[k]), column[k] = cells.column(positions[k]);
        const std::size_t c = cells.cell(row[k], column[k]);
        if (c < previous)
            return fail(why, "the particles are not in the order of the wave's cells (slot " + std::to_string(k) +
                                 "; list builds put them so unless --reorder is off)");
        previous = c;
        ++cellStart[c + 1];
    }
    std::partial_sum(cellStart.begin(), cellStart.end(), cellStart.begin());
    // Every listed pair joins neighbouring cells.
    for (const ParticlePair& p : pairs) {
        if (p.i >= particles || p.j >= particles) return fail(why, "a listed pair names a slot beyond the particles");
        if (!neighbouring(row[p.i], row[p.j], cells.rows()) || !neighbouring(column[p.i], column[p.j], cells.columns()))
            return fail(why, "listed pair (" + std::to_string(p.i) + ", " + std::to_string(p.j) +
                                 ") joins cells that are not neighbours");
    }
    // Each particle's wall candidates.
    std::vector<std::uint32_t> firstWall(particles + 1, 0), wallOf(walls.size());
    for (const WallCandidate& w : walls) {
        if (w.particle >= particles) return fail(why, "a wall candidate names a slot beyond the particles");
        ++firstWall[w.particle + 1];
    }
    std::partial_sum(firstWall.begin(), firstWall.end(), firstWall.begin());
    std::vector<std::uint32_t> wallFill(firstWall.begin(), firstWall.end() - 1);
    for (std::uint32_t k = 0; k < walls.size(); ++k) wallOf[wallFill[walls[k].particle]++] = k;
    // The regions in the wave's order, and the one advancing each particle at each level
    // (regionAt[i * levels + t]), each particle checked to advance from every step once, in turn.
    const auto levels = static_cast<std::size_t>(levels_);
    std::vector<std::uint32_t> regionAt(particles * levels);
    std::vector<std::uint16_t> step(particles, 0);
    // The first step's start (the drift), a strip's row at a time (its cells take consecutive
    // slots): each level-0 region starts those of its rows and the rows beside it, in the
    // columns of its own and the next, that no region before it started (driftedBy[i]: the region).
    std::vector<unsigned char> rowStarted(static_cast<std::size_t>(cells.strips()) * static_cast<std::size_t>(cells.rows()), 0);
    constexpr std::uint32_t notYet = 0xffffffffu;
    std::vector<std::uint32_t> driftedBy(particles, notYet);
    std::uint32_t lastRunOf = notYet;  // (the region of the last run, which the next may extend)
    const auto startRow = [&](int q, int r, std::uint32_t id) {
        unsigned char& started = rowStarted[static_cast<std::size_t>(q) * static_cast<std::size_t>(cells.rows()) +
                                            static_cast<std::size_t>(r)];
        if (started) return;
        started = 1;
        const std::uint32_t begin = cellStart[cells.cell(r, cells.stripStart(q))];
        const std::uint32_t end = cellStart[cells.cell(r, cells.stripStart(q + 1) - 1) + 1];
        if (begin == end) return;
        for (std::uint32_t i = begin; i < end; ++i) driftedBy[i] = id;
        if (lastRunOf == id && driftRuns_.back().end == begin)
            driftRuns_.back().end = end;
        else
            driftRuns_.push_back({begin, end});
        lastRunOf = id;
    };
    bool ok = true;
    cells.forEachRegion([&](int u, int firstColumn, int across, int t) {
        if (!ok) return;
        WaveRegion region;
        region.level = t;
        int runs = 0;
        for (int k = 0; k < across; ++k) {
            const std::size_t c = cells.cell(u, (firstColumn + k) % cells.columns());
            if (runs > 0 && region.runEnd[runs - 1] == cellStart[c]) {
                region.runEnd[runs - 1] = cellStart[c + 1];
            } else if (runs < 2) {
                region.runBegin[runs] = cellStart[c], region.runEnd[runs] = cellStart[c + 1], ++runs;
            } else {
                ok = fail(why, "a region of more than two runs of slots (strips narrower than a seam)");
                return;
            }
        }
        if (regions_.size() >= 0xffffffffu) {
            ok = fail(why, "too many regions for a wave schedule");
            return;
        }
        const auto id = static_cast<std::uint32_t>(regions_.size());
        for (int r = 0; r < runs; ++r)
            for (std::uint32_t i = region.runBegin[r]; i < region.runEnd[r]; ++i) {
                if (step[i] != t) {
                    ok = fail(why, "particle " + std::to_string(i) + " at step " + std::to_string(step[i]) +
                                       " of the wave when its region advances from step " + std::to_string(t));
                    return;
                }
                step[i] = static_cast<std::uint16_t>(t + 1);
                regionAt[i * levels + static_cast<std::size_t>(t)] = id;
            }
        region.wallsBegin = static_cast<std::uint32_t>(wallIndex_.size());
        for (int r = 0; r < runs; ++r)
            wallIndex_.insert(wallIndex_.end(), wallOf.begin() + firstWall[region.runBegin[r]],
                              wallOf.begin() + firstWall[region.runEnd[r]]);
        region.wallsEnd = static_cast<std::uint32_t>(wallIndex_.size());
        if (runs == 0) return;  // (a region without particles has no pairs)
        region.driftBegin = static_cast<std::uint32_t>(driftRuns_.size());
        if (t == 0)
            for (int r = u - 1; r <= u + 1; ++r)
                for (int k = -1; k <= across; ++k) {
                    const int column = ((firstColumn + k) % cells.columns() + cells.columns()) % cells.columns();
                    startRow(cells.strip(column), (r + cells.rows()) % cells.rows(), id);
                }
        region.driftEnd = static_cast<std::uint32_t>(driftRuns_.size());
        regions_.push_back(region);
    });
    if (!ok) return false;
    for (std::size_t k = 0; k < particles; ++k) {
        if (step[k] != levels_) return fail(why, "particle " + std::to_string(k) + " was not advanced by every step of the wave");
        if (driftedBy[k] > regionAt[k * levels])
            return fail(why, "particle " + std::to_string(k) + " advanced before its first step started");
    }
    // A pair is computed at level t by the first of its particles' regions to advance then (the
    // other particle is still at step t; when its own region advances, the first is at t + 1). So
    // the one advancing second must still be at step t when the first advances (its region of
    // level t - 1 came before), and the one advancing first not yet at t + 2 when the second
    // does (its region of level t + 1 comes after): else the partners are two steps apart.
    // The pairs' order, if asked for (pairOrder): interior pairs first, then by the regions that
    // compute the pair at the wave's steps in turn, the first step's first, so that the pairs of a
    // region that went through the same regions before it take one run of places. Sorted by the
    // first step's region (a counting sort), then by a key of hashes of the later steps' regions,
    // 9 bits each for waves of 8 (those of longer waves share the 64 bits: a pair's region at a
    // step has only a few others to be told from, those of the pairs that shared its regions so
    // far), ties in the list's order. The keys are made in the pass that checks the pairs.
    const bool ordering = pairOrder != nullptr;
    const std::size_t bits = levels > 1 ? std::max<std::size_t>(1, 64 / (levels - 1)) : 64;
    std::vector<std::uint32_t> firstRegion(ordering ? pairs.size() : 0);
    std::vector<std::uint64_t> later(ordering ? pairs.size() : 0);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const std::uint32_t* a = &regionAt[pairs[k].i * levels];
        const std::uint32_t* b = &regionAt[pairs[k].j * levels];
        if (std::max(driftedBy[pairs[k].i], driftedBy[pairs[k].j]) > std::min(a[0], b[0]))
            return fail(why, "listed pair (" + std::to_string(pairs[k].i) + ", " + std::to_string(pairs[k].j) +
                                 ") computed before the first step of both its particles started");
        std::uint64_t key = 0;
        for (std::size_t t = 0; t < levels; ++t) {
            const bool iFirst = a[t] <= b[t];
            const std::uint32_t* first = iFirst ? a : b;
            const std::uint32_t* second = iFirst ? b : a;
            if ((t > 0 && second[t - 1] > first[t]) || (t + 1 < levels && first[t + 1] < second[t])) {
                const std::uint32_t late = iFirst ? pairs[k].j : pairs[k].i, early = iFirst ? pairs[k].i : pairs[k].j;
                return fail(why, "particles " + std::to_string(early) + " and " + std::to_string(late) +
                                     " are two steps of the wave apart when one of them advances from step " + std::to_string(t));
            }
            if (ordering && t > 0 && t * bits <= 64)
                key |= ((first[t] * 0x9e3779b97f4a7c15ull) >> (64 - bits)) << (64 - t * bits);
        }
        if (ordering) firstRegion[k] = std::min(a[0], b[0]), later[k] = key;
    }
    std::vector<std::uint32_t> order(pairs.size());
    std::iota(order.begin(), order.end(), 0u);
    if (ordering) {
        std::vector<std::uint32_t> start(regions_.size() + 1, 0);
        for (std::uint32_t r : firstRegion) ++start[r + 1];
        std::partial_sum(start.begin(), start.end(), start.begin());
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::uint32_t k = 0; k < pairs.size(); ++k) order[fill[firstRegion[k]]++] = k;  // (ascending within)
        std::vector<std::pair<std::uint64_t, std::uint32_t>> bucket;  // (a region's pairs, sorted in the cache)
        for (std::size_t r = 0; r < regions_.size(); ++r) {
            bucket.clear();
            for (std::uint32_t e = start[r]; e < start[r + 1]; ++e) bucket.emplace_back(later[order[e]], order[e]);
            std::sort(bucket.begin(), bucket.end());
            for (std::uint32_t e = start[r]; e < start[r + 1]; ++e) order[e] = bucket[e - start[r]].second;
        }
        std::vector<std::uint32_t> sorted(pairs.size());
        std::size_t placedInterior = 0, placedFace = interiorPairs;
        for (std::uint32_t k : order) sorted[k < interiorPairs ? placedInterior++ : placedFace++] = k;
        order.swap(sorted);
        *pairOrder = order;
        std::vector<std::uint64_t>().swap(later);  // (the memory back before the runs are found)
        std::vector<std::uint32_t>().swap(firstRegion);
    }
    // Each region's runs of places (new places, in the order above), ascending, broken where the
    // interior pairs end: found in one pass over the pairs (a region's open run grows while its
    // pairs follow each other), then laid out region after region.
    struct OpenRun {
        std::uint32_t region, begin, end;
    };
    std::vector<OpenRun> found;
    constexpr std::uint32_t none = 0xffffffffu;
    std::vector<std::uint32_t> open(regions_.size(), none), openEnd(regions_.size(), none), perRegion(regions_.size() + 1, 0);
    for (std::uint32_t k = 0; k < order.size(); ++k) {
        const ParticlePair& p = pairs[order[k]];
        for (std::size_t t = 0; t < levels; ++t) {
            const std::uint32_t r = std::min(regionAt[p.i * levels + t], regionAt[p.j * levels + t]);
            if (openEnd[r] != k || k == interiorPairs) {
                if (open[r] != none) found[open[r]].end = openEnd[r];
                open[r] = static_cast<std::uint32_t>(found.size());
                found.push_back({r, k, k + 1});
                ++perRegion[r + 1];
            }
            openEnd[r] = k + 1;
        }
    }
    for (std::size_t r = 0; r < regions_.size(); ++r)
        if (open[r] != none) found[open[r]].end = openEnd[r];
    std::partial_sum(perRegion.begin(), perRegion.end(), perRegion.begin());
    placeRuns_.resize(found.size());
    for (std::size_t r = 0; r < regions_.size(); ++r) {
        regions_[r].runs = regions_[r].interiorEnd = perRegion[r];
        regions_[r].end = perRegion[r + 1];
    }
    for (const OpenRun& run : found) {
        WaveRegion& region = regions_[run.region];
        placeRuns_[region.interiorEnd++] = {run.begin, run.end};  // (interiorEnd: the next place for now)
    }
    for (WaveRegion& region : regions_) {  // (its runs ascending: the interior ones first)
        region.interiorEnd = region.runs;
        while (region.interiorEnd < region.end && placeRuns_[region.interiorEnd].begin < interiorPairs) ++region.interiorEnd;
    }
    return true;
}

}  // namespace talus
