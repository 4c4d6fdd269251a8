// Particle order along a space-filling curve, for cache locality (Documentation/Architecture.md
// "Data layout").
//
// The force loop reads the data of both particles of every listed pair. If the particles that are
// near in space are near in memory, those reads hit the cache; a granular flow stirs its particles,
// so the order is renewed at neighbour-list rebuilds (Simulation, RunSettings::reorderParticles).
// The curve is the Morton (Z-order) curve over cells of a given size: the key interleaves the bits
// of the cell coordinates, so particles in one cell, then in each block of 2 x 2 x 2 cells, and so
// on, are contiguous.
#pragma once

#include <cstdint>
#include <vector>

#include "Math/Vector.h"

namespace talus {

// Interleaves the lowest 21 bits of x, y and z (x in bit 0, y in bit 1, z in bit 2, ...).
std::uint64_t mortonKey(std::uint32_t x, std::uint32_t y, std::uint32_t z);

// The permutation that sorts the positions along the Morton curve of cells of side cellSize
// with a corner at lo: new slot k holds old slot order[k]. Positions below lo or more than
// 2^21 cells beyond it are clamped to the edge cells. Particles in one cell keep their order, so
// the result is deterministic and ordering twice changes nothing. With ids, particles in one cell
// come in the order of their ids instead: the result then depends only on positions and ids,
// not on the order the particles had (what an MPI split needs, Parallel/DomainSplit.h).
std::vector<std::size_t> spaceFillingCurveOrder(const std::vector<Vec3>& positions, const Vec3& lo, double cellSize,
                                                const std::vector<std::uint64_t>* ids = nullptr);

}  // namespace talus
