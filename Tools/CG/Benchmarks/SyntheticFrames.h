// Particle frames made up for the coarse-graining benchmark (cgBenchmark.cc): no .data file, so
// the timings measure the library alone, and the accuracy study has a profile known exactly.
#pragma once

#include "IO/ParticleFrame.h"

namespace talus::cg::benchmark {

// `count` spheres of radius 0.5 at uniformly random centres in the cube [0, side]^3 (overlaps
// allowed: only the cost is measured), species i % speciesCount, a fixed seed so that every
// run times the same frame.
ParticleFrame uniformRandomFrame(long count, double side, int speciesCount, unsigned seed = 5);

// A simple cubic lattice of touching spheres (spacing 1, radius 0.5) filling the slab
// [0, side]^2 x [0, height] (side and height whole numbers): centres at half-integers. With
// density 6/pi each sphere has mass 1, so the bulk density is 1.
ParticleFrame latticeSlabFrame(int side, int height);

}  // namespace talus::cg::benchmark
