// Filling a drum: random sequential addition of particles of several kinds (a species with a
// sphere's radius or a superquadric shape) into a cylinder about the y axis (x = z = 0), the
// domain's periodic axis of length `length`. Each particle gets up to maxAttempts random centres,
// uniform in the square [-reach, reach]^2 of (x, z) (reach: the inner radius less the largest
// bounding radius) and along y; the first whose bounding sphere lies inside the inner radius and
// overlaps no particle's bounding sphere (nearest periodic image along y) is taken. Superquadrics
// get a uniformly random orientation (a normalised quaternion of four Gaussian numbers). The kind
// of the next particle is the one with the fewest inserted among those below their target (the
// first on ties), so that the kinds fill alike. A round ends when every target is met or a
// particle fails every attempt. Under mpirun every rank draws the same places against the whole
// scene (Sampling/ParticleSums.h gatherParticles) and each particle is added once
// (Sampling/AddedOnce.h): call it on every rank.
#pragma once

#include <cstddef>
#include <vector>

namespace talus {

class Simulation;

struct FillingKind {
    std::size_t species = 0;
    double radius = 0.5;  // of a sphere
    int shape = -1;       // a superquadric shape (Simulation::addShape), or -1 for a sphere
    int target = 0;       // particles of this kind wanted in all
};

class CylinderFilling {
public:
    CylinderFilling(double innerRadius, double length, std::vector<FillingKind> kinds, int maxAttempts = 1000);
    // One round; `inserted` holds the particles of each kind inserted so far (the caller keeps it,
    // in its restart values) and grows with those placed. Returns how many it placed.
    int fillRound(Simulation& simulation, std::vector<int>& inserted) const;

private:
    double innerRadius_, length_;
    std::vector<FillingKind> kinds_;
    int maxAttempts_;
};

}  // namespace talus
