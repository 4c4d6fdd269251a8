// Several steps per pass over the particles (time skewing; Documentation/TimeSkewing.md): which
// particles advance when, and which listed pairs each advance computes, so that stretches of the
// bed are advanced several steps while their data is in the caches, instead of every particle
// and pair being read from memory once a step (Documentation/CacheCliff.md).
//
// A step moves a particle using only its listed partners' states at the step before: the force
// of a pair at step t needs both particles at step t, and a particle may go on to t + 1 once all
// its pairs of step t are computed. So a region may advance from t to t + 1 while every partner is
// at t (the pair is computed now) or at t + 1 (it was computed when the partner advanced). The
// schedule below keeps that: the box (periodic along x and y) is cut into cells at least the
// longest listed separation wide, so that every pair joins neighbouring cells; the columns (along
// y) are grouped into strips; within a strip a wave runs along x, advancing row u at level t in the
// order of u + t, so that the few rows the wave touches stay cached while they take their steps.
// Cells within t cells of a strip's edge along y sit out level t in their strip's wave and advance
// in the next strip's, a row behind its front; rows within t cells of the periodic seam along x
// sit out level t and advance afterwards in a second pass, as the trapezoid tilings of stencil
// codes do (Frigo and Strumpen 2005; Wonnacott 2000 for time skewing). The design was tried
// first in a model of the step (Drivers/Benchmarks/StripWave.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "Boundaries/Domain.h"
#include "Contacts/HGrid.h"
#include "Contacts/PairList.h"

namespace talus {

// The cells of the waves and the particle order they need: by strip, row (along x), column
// (along y), then height.
class WaveCells {
public:
    // The cells for waves of `levels` steps (1-255) among pairs at most `longestSeparation`
    // apart, in strips of about `stripColumns` columns; none (and why) unless x and y are
    // periodic and the box holds at least 2 levels cells along each, and strips that wide.
    static std::optional<WaveCells> fit(const Domain& domain, double longestSeparation, int levels, int stripColumns,
                                        std::string* why = nullptr);

    int rows() const { return rows_; }
    int columns() const { return columns_; }
    int strips() const { return static_cast<int>(stripStart_.size()) - 1; }
    int levels() const { return levels_; }
    int stripStart(int strip) const { return stripStart_[static_cast<std::size_t>(strip)]; }
    // The strip holding a column (0 to columns() - 1).
    int strip(int column) const {
        return static_cast<int>(std::upper_bound(stripStart_.begin(), stripStart_.end(), column) - stripStart_.begin()) - 1;
    }
    std::size_t cellCount() const { return static_cast<std::size_t>(rows_) * static_cast<std::size_t>(columns_); }

    int row(const Vec3& x) const { return bin(x[0] - lo_[0], width_[0], rows_); }
    int column(const Vec3& x) const { return bin(x[1] - lo_[1], width_[1], columns_); }
    // The place of cell (row, column) in the wave order.
    std::size_t cell(int row, int column) const;
    std::size_t cellOf(const Vec3& x) const { return cell(row(x), column(x)); }

    // The permutation that puts the particles in the wave order, cell by cell and, within a
    // cell, by bands of height one cell wide (keeping their order within a band): new slot k
    // holds old slot order[k], as spaceFillingCurveOrder gives it.
    std::vector<std::size_t> order(const std::vector<Vec3>& positions) const;

    // Calls visit(row, first column, columns, level) for every region of a wave in turn: a row of
    // cells along y (columns wrapping around the box), advanced from step `level` of the wave to
    // the next. Every cell is in exactly one region per level.
    // Two passes, the rows away from the seam along x, then those within t cells of it at level t;
    // each strip in turn, a wave along x. The seam between strip q - 1 and q (its 2t + 2 columns
    // at level t) goes along with strip q's wave, seamLag rows behind it, and the seam between
    // the last strip and the first (one strip: its own edges) along with the last strip's: so
    // that a seam's cells are advanced while strip q's side of them is still cached, instead of
    // in a wave of their own after all strips, which read them from memory again (slower by
    // 6% at 10^5 particles: Documentation/TimeSkewing.md, "The wave").
    template <class Visit>
    void forEachRegion(Visit visit) const {
        constexpr int seamLag = 1;  // (a seam region needs strip q's rows beside it at its level)
        const int last = strips() - 1;
        for (int xPass = 0; xPass < 2; ++xPass) {
            const bool xSeam = xPass == 1;
            const auto inPass = [&](int u, int t) {  // row u (unwrapped across the seam along x) at level t
                return xSeam ? u >= rows_ - 1 - t && u <= rows_ + t : u >= t + 1 && u <= rows_ - 2 - t;
            };
            for (int q = 0; q <= last; ++q) {
                const int begin = stripStart(q), end = stripStart(q + 1);
                for (int wave = 0; wave < 2 * rows_ + 2 * levels_ + seamLag; ++wave) {
                    for (int t = 0; t < levels_; ++t) {
                        const int u = wave - t, across = end - begin - 2 - 2 * t;
                        if (inPass(u, t) && across > 0) visit(u % rows_, (begin + t + 1) % columns_, across, t);
                    }
                    for (int seam = q - 1; seam <= q; ++seam) {  // the seams at the end of strip `seam`
                        if (seam < 0 || (seam == q && q != last)) continue;
                        const int seamEnd = stripStart(seam + 1);
                        for (int t = 0; t < levels_; ++t) {
                            const int u = wave - seamLag - t;
                            if (inPass(u, t)) visit(u % rows_, (seamEnd - 1 - t) % columns_, 2 * t + 2, t);
                        }
                    }
                }
            }
        }
    }

private:
    static int bin(double offset, double width, int count) {
        const int k = static_cast<int>(offset / width);
        return k < 0 ? 0 : k >= count ? count - 1 : k;
    }
    Vec3 lo_ = Vec3::Zero();
    double width_[2] = {1, 1};
    int rows_ = 0, columns_ = 0, levels_ = 1;
    std::vector<int> stripStart_;  // first column of each strip, and columns_ at the end
};

// A run of places in the pair list, [begin, end).
struct PlaceRun {
    std::uint32_t begin = 0, end = 0;
};

// One advance of a region: its particles (up to two runs of slots) from step `level` of the wave
// to the next, after the listed pairs it computes at that step, the places of the runs
// placeRuns()[runs, end): those before interiorEnd hold interior pairs (PairList::interiorPairs),
// the rest pairs that need the periodic image; and its particles' wall candidates,
// wallIndex()[wallsBegin, wallsEnd).
// A region of the first level first starts the wave's first step (the half kick and the drift)
// of the particles in the runs of slots driftRuns()[driftBegin, driftEnd), those of its own rows
// and the next that no region before it started: the wave's first step goes along with its first
// level, as its later steps do with the levels before them, instead of a pass over all particles
// ahead of the wave (which at 10^6 particles reads them all from memory once more a wave).
struct WaveRegion {
    std::uint32_t runs = 0, interiorEnd = 0, end = 0;
    std::uint32_t wallsBegin = 0, wallsEnd = 0;
    std::uint32_t driftBegin = 0, driftEnd = 0;
    std::uint32_t runBegin[2] = {0, 0}, runEnd[2] = {0, 0};
    int level = 0;
};

class WaveSchedule {
public:
    // The regions of a wave over the listed pairs (the first interiorPairs of them interior) of
    // particles in slots [0, particles), listed at `positions`; false (and why) if the particles
    // are not in the cells' order or a pair does not join neighbouring cells. It notes which
    // region advances each particle at each step of the wave and fails if a particle does not
    // advance once from every step in turn, or a region advances a particle whose partner is not
    // at the same step or the next, or a particle's first step does not start once, before the
    // first region that computes one of its pairs or advances it.
    // pairOrder: if given, the order of the pairs that makes each region's pairs a few runs of
    // places (new place k holds the pair at place pairOrder[k]; the interior pairs stay first),
    // which the caller must give the list (PairList::reorderPairs) before the schedule is used:
    // its runs are of the new places. Without it, the runs are of the places as they are.
    bool make(const WaveCells& cells, const std::vector<ParticlePair>& pairs, std::size_t interiorPairs,
              const std::vector<Vec3>& positions, std::size_t particles, std::string* why = nullptr,
              const std::vector<WallCandidate>& walls = {}, std::vector<std::uint32_t>* pairOrder = nullptr);

    const std::vector<WaveRegion>& regions() const { return regions_; }
    const std::vector<PlaceRun>& placeRuns() const { return placeRuns_; }
    const std::vector<std::uint32_t>& wallIndex() const { return wallIndex_; }
    const std::vector<PlaceRun>& driftRuns() const { return driftRuns_; }  // (runs of slots)
    int levels() const { return levels_; }
    std::size_t bytes() const {
        return regions_.capacity() * sizeof(WaveRegion) + placeRuns_.capacity() * sizeof(PlaceRun) +
               wallIndex_.capacity() * sizeof(std::uint32_t) + driftRuns_.capacity() * sizeof(PlaceRun);
    }

private:
    std::vector<WaveRegion> regions_;
    std::vector<PlaceRun> placeRuns_;
    std::vector<std::uint32_t> wallIndex_;
    std::vector<PlaceRun> driftRuns_;
    int levels_ = 0;
};

}  // namespace talus
