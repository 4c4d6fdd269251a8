// Particles of any shape in the coarse-graining tool: the superquadrics of a Talus restart file
// (Documentation/FileFormats/restart.md, `shapes` and the shaped particle lines), their volume,
// and the masses and volumes they give the particles of the .data frames (whose radius column
// holds a superquadric's bounding radius, Documentation/FileFormats/data.md).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "IO/ParticleFrame.h"

namespace talus::cg {

struct RestartInfo;

// A convex superquadric in its body frame (Theory/Superquadrics.md eq. (1)): semi-axes a, b, c
// and blockiness e1, e2 in (0, 1] (e1 = e2 = 1: an ellipsoid).
struct SuperquadricShape {
    std::array<double, 3> semiAxes{1, 1, 1};
    double e1 = 1, e2 = 1;

    double volume() const;
};

// One particle line of a Talus restart file, as far as the fields need it.
struct RestartParticle {
    long id = 0;
    int species = 0;
    int shape = -1;      // index into RestartInfo::shapes; -1: a sphere of `radius`
    double radius = 0;   // a superquadric's bounding radius
    double mass = 0;
    std::array<double, 4> orientation{1, 0, 0, 0};  // w x y z (body to lab); 1 0 0 0 for spheres
};

// Gives every particle of a .data frame its volume from its shape when the restart file has
// superquadric particles (nothing otherwise: spheres of the .data radius): the superquadric's
// volume (SuperquadricShape::volume), or 4/3 pi r^3 for a sphere of the .data radius r. Its mass
// is then rho_s V, rho_s its species' density (ParticleFrame::massOf).
// The frame's line p is the restart's particle p in ascending id (both files sort by id,
// data.md), so the frame must hold as many particles as the restart file; its radius (the
// bounding radius, printed with 10 digits) and species must be the restart particle's. Otherwise
// InputError naming the .data line (`dataPath`).
void applyRestartShapes(const RestartInfo& restart, ParticleFrame& frame, const std::string& dataPath);

// For the log line of the restart file: ", N superquadrics of S shapes (mass and volume from the
// shape)", or nothing when every particle is a sphere.
std::string shapesSummary(const RestartInfo& restart);

}  // namespace talus::cg
