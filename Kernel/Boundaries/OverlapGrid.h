// The overlap test of a filling (Boundaries/Filling.h): bounding spheres in a grid of cells.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "Boundaries/Domain.h"
#include "Math/Vector.h"

namespace talus {

// A uniform grid of cells no smaller than the largest contact distance 2 rmax, so that a
// candidate can touch only particles in its own and the adjacent cells: the overlap test costs
// 27 cells whatever the number of particles. Along a periodic axis of the domain the grid covers
// the whole period and wraps (a particle across the face is a neighbour); along the other axes
// it covers the region widened by one contact distance each side, as particles further out
// cannot touch a particle inside the region.
class OverlapGrid {
public:
    OverlapGrid(const Domain& domain, const Vec3& lo, const Vec3& hi, double contactDistance) : image_(domain) {
        // A dense array of cells: cap its size (16 MB of cell heads) for a huge region of small
        // particles by making the cells larger, which keeps the test exact, only slower.
        const double maxCells = 1 << 22;
        double cell = contactDistance;
        for (;;) {
            double cells = 1;
            for (int a = 0; a < 3; ++a) {
                wraps_[a] = domain.periodic[a];
                origin_[a] = wraps_[a] ? domain.lo[a] : lo[a] - contactDistance;
                const double extent = wraps_[a] ? domain.length(a) : hi[a] - lo[a] + 2 * contactDistance;
                count_[a] = std::max(1, static_cast<int>(std::min(extent / cell, maxCells)));
                size_[a] = extent / count_[a];
                cells *= count_[a];
            }
            if (cells <= maxCells) break;
            cell *= 1.26;  // about 2^(1/3): halves the number of cells
        }
        head_.assign(static_cast<std::size_t>(count_[0]) * count_[1] * count_[2], -1);
    }

    // Whether a particle at x (wrapped into the domain) can touch a candidate in the region.
    bool covers(const Vec3& x) const {
        for (int a = 0; a < 3; ++a)
            if (!wraps_[a] && (x[a] < origin_[a] || x[a] >= origin_[a] + count_[a] * size_[a])) return false;
        return true;
    }

    void add(const Vec3& x, double r) {
        int k[3];
        for (int a = 0; a < 3; ++a) k[a] = cellOf(a, x[a]);
        int& head = head_[index(k[0], k[1], k[2])];
        next_.push_back(head);
        head = static_cast<int>(position_.size());
        position_.push_back(x);
        radius_.push_back(r);
    }

    // True when a sphere of radius r at x overlaps no sphere in the grid (touching is allowed).
    bool isFree(const Vec3& x, double r) const {
        int cells[3][3], n[3];
        for (int a = 0; a < 3; ++a) n[a] = neighbourCells(a, cellOf(a, x[a]), cells[a]);
        for (int i = 0; i < n[0]; ++i)
            for (int j = 0; j < n[1]; ++j)
                for (int k = 0; k < n[2]; ++k)
                    for (int q = head_[index(cells[0][i], cells[1][j], cells[2][k])]; q >= 0; q = next_[q]) {
                        const double reach = r + radius_[q];
                        if (image_.nearest(x - position_[q]).squaredNorm() < reach * reach) return false;
                    }
        return true;
    }

private:
    int cellOf(int a, double x) const {
        const int k = static_cast<int>(std::floor((x - origin_[a]) / size_[a]));
        if (wraps_[a]) return ((k % count_[a]) + count_[a]) % count_[a];
        return std::clamp(k, 0, count_[a] - 1);
    }

    // The cells along axis a within one cell of k (each once, also when the period has fewer
    // than three cells); returns how many.
    int neighbourCells(int a, int k, int* cells) const {
        if (wraps_[a] && count_[a] < 3) {
            for (int c = 0; c < count_[a]; ++c) cells[c] = c;
            return count_[a];
        }
        int n = 0;
        for (int c = k - 1; c <= k + 1; ++c) {
            if (wraps_[a]) cells[n++] = (c + count_[a]) % count_[a];
            else if (c >= 0 && c < count_[a]) cells[n++] = c;
        }
        return n;
    }

    std::size_t index(int i, int j, int k) const {
        return (static_cast<std::size_t>(k) * count_[1] + j) * count_[0] + i;
    }

    PeriodicImage image_;
    bool wraps_[3];
    double origin_[3], size_[3];
    int count_[3];
    std::vector<int> head_;  // first sphere of each cell, -1 if none; next_ links the rest
    std::vector<int> next_;
    std::vector<Vec3> position_;
    std::vector<double> radius_;
};

}  // namespace talus
