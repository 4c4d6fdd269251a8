// One saved step of a .data file: the particles as MercuryDPM's 3-D layout describes them
// (Documentation/FileFormats/data.md). Structure of arrays, as in the kernel (Documentation/Architecture.md "Data layout").
#pragma once

#include <array>
#include <numbers>
#include <vector>

namespace talus::cg {

using Vec3 = std::array<double, 3>;

// The nominal domain of the frame header (the periodic box in periodic directions).
struct DomainBox {
    Vec3 lo{0, 0, 0};
    Vec3 hi{0, 0, 0};
    double length(int axis) const { return hi[axis] - lo[axis]; }
};

struct ParticleFrame {
    double time = 0;
    DomainBox box;
    long headerLine = 0;  // line of the frame header in the .data file, for messages
    // One entry per particle line, in file order (Talus: ascending global id; MercuryDPM: index).
    std::vector<Vec3> position;
    std::vector<Vec3> velocity;
    std::vector<double> radius;
    std::vector<int> species;  // the info column, which both codes fill with the species index
    // Volumes, when the particles are not all spheres of their radius: superquadrics of a Talus
    // restart file (IO/ParticleShapes.h), whose .data radius is their bounding radius; empty:
    // spheres.
    std::vector<double> volume;
    // Per particle, true for a superquadric (its contact points and partners' centres are not
    // along the contact normal at r - dn/2); empty: all spheres.
    std::vector<bool> shaped;
    // Masses, when the caller knows them (a driver coarse-graining its own particles, of any
    // shape); empty for .data frames, whose masses come from the volume and the species density.
    std::vector<double> mass;
    // A run coarse-graining its own particles on MPI ranks (InRun/InRunFields.h): the last
    // `ghosts` lines are copies of particles other ranks own, there only as the partners of this
    // rank's contacts, and are left out of the particle fields. 0 for .data frames.
    std::size_t ghosts = 0;

    std::size_t size() const { return radius.size(); }
    bool isShaped(std::size_t p) const { return !shaped.empty() && shaped[p]; }
    // Particle p's volume: given, or a sphere of its radius.
    double volumeOf(std::size_t p) const { return volume.empty() ? sphereVolume(p) : volume[p]; }
    // Particle p's mass: given, or its volume times the species' density.
    double massOf(std::size_t p, double density) const { return mass.empty() ? density * volumeOf(p) : mass[p]; }
    // Whether line p is one of this frame's own particles (not a ghost).
    bool isOwned(std::size_t p) const { return p + ghosts < size(); }
    double sphereVolume(std::size_t p) const { return 4.0 / 3.0 * std::numbers::pi * radius[p] * radius[p] * radius[p]; }
    void clear() {
        position.clear();
        velocity.clear();
        radius.clear();
        species.clear();
        volume.clear();
        shaped.clear();
        mass.clear();
    }
};

}  // namespace talus::cg
