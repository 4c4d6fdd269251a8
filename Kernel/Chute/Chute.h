// talus::Chute, the base class of chute-flow drivers (Theory/Chutes.md eq. (1)): x downslope, y
// across, z normal to the base, gravity g (sin t, 0, -cos t) at inclination t, a rough base of
// fixed particles.
//
// A driver sets the geometry and the base in setupInitialConditions():
//
//     setChuteAngle(angle);                         // degrees (a driver flag, say)
//     setChuteGeometry({.length = 20, .width = 10});  // periodic in x and y
//     addBase(ChuteBase::disordered, /*diameter*/ 1, baseSpecies, /*seed*/ 1);
//
// and then adds its flowing particles (Boundaries/InsertionBoundary.h). Chute adds no state of
// its own to the simulation (the angle is the direction of gravity, the base is fixed particles
// or a wall), so a restart needs nothing more than Simulation's.
#pragma once

#include <cstdint>

#include "Simulation.h"

namespace talus {

enum class ChuteBase {
    disordered,  // fixed spheres at random, non-overlapping positions in a thin layer (from a seed)
    ordered,     // fixed spheres on a square lattice at z = 0 (a monolayer)
    flat,        // a plane wall at z = 0
};

struct ChuteGeometry {
    double length = 20;        // along x
    double width = 10;         // along y (always periodic)
    double height = 40;        // extent of the domain above the base (for output and insertion)
    bool periodicEnds = true;  // periodic in x; false: open ends (inflow and outflow boundaries)
};

class Chute : public Simulation {
public:
    // Inclination in degrees, in (-90, 90); sets gravity to (sin t, 0, -cos t) |g| (|g| = 1
    // unless setGravityMagnitude was called).
    void setChuteAngle(double degrees);
    double chuteAngle() const;  // in degrees, from the direction of gravity
    void setGravityMagnitude(double g);

    // Domain [0, length] x [0, width] x [-baseDiameter, height]; y periodic, x periodic if
    // periodicEnds. Call before addBase.
    void setChuteGeometry(const ChuteGeometry& geometry);
    const ChuteGeometry& chuteGeometry() const { return geometry_; }

    // The rough base (Theory/Chutes.md "The rough base"), of the given species. For the particle
    // bases also a flat safety floor half a diameter below the base (nothing should reach it; the
    // peers' scripts have the same). Returns the number of base particles (0 for a flat base).
    //  - disordered: centres uniform in x and y and within +-roughness diameter/2 of z = 0, placed
    //    one by one without overlap until 100 attempts per unit area in a row fail (random
    //    sequential addition, close to jammed: it covers about 0.57 of the floor), reproducible
    //    from the seed;
    //  - ordered: a square lattice of spacing as close to the diameter as the periodic lengths
    //    allow (never closer), centres at z = 0.
    std::size_t addBase(ChuteBase type, double diameter, std::size_t species, std::uint64_t seed = 1,
                        double roughness = 0.5);

    // The base continued downstream: copies of the fixed particles of species `from`, shifted along
    // x by whole multiples of `period`, whose centres fall in [xFrom, xTo), added as fixed
    // particles of species `to` (a maser's base laid along the chute it feeds). Each rank copies
    // the particles it owns. Returns the number of copies in the whole scene.
    // A start configuration: `count` spheres of the species and radius, at rest at random places
    // in the box [lo, hi] (Boundaries/InsertionBoundary.h, random numbers from scene().random()); prints
    // the insertion's report once and stops with an error naming `what` unless all were placed.
    void insertAtRest(std::size_t count, std::size_t species, double radius, const Vec3& lo, const Vec3& hi,
                      const std::string& what);

    double continueBase(std::size_t from, std::size_t to, double period, double xFrom, double xTo);

private:
    ChuteGeometry geometry_;
    double gravityMagnitude_ = 1;
    double angle_ = 0;  // degrees
    bool geometrySet_ = false;
};

}  // namespace talus
