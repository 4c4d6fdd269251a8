// Where fields are evaluated: a regular grid or a list of points from a file. Both become the
// same std::vector<Vec3>, evaluated by the same code (Theory/CoarseGraining.md "Fields": evaluation
// needs no grid).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "Fields/Coordinates.h"
#include "IO/ParticleFrame.h"

namespace talus::cg {

// A regular grid over [lo, hi] on the resolved axes with `count` points per axis at the cell
// centres, lo + (i + 1/2) (hi - lo) / n: each point stands for a cell of equal size, so a sum
// of values times the cell size is the midpoint rule. Averaged axes get coordinate 0 (they do
// not enter the kernel). The first resolved axis varies slowest.
std::vector<Vec3> gridPoints(const Coordinates& coordinates, const std::array<long, 3>& count,
                             const Vec3& lo, const Vec3& hi);

// Points from a text file, one per line: either x y z (averaged coordinates are ignored) or
// only the resolved coordinates (e.g. one z per line for --coordinates Z). Blank lines and
// lines starting with '#' are skipped. Cylindrical coordinates take only the resolved ones
// (r and the coordinate along the axis for RZ, r for R). Errors name file and line.
std::vector<Vec3> readPointList(const std::string& path, const Coordinates& coordinates);

}  // namespace talus::cg
