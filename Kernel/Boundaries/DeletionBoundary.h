// Deletion: removes the mobile particles whose centre has passed a plane, and records what left
// (the outflow end of an open chute, Theory/Chutes.md "The long chute and the chapter-4 variant").
// The plane and the totals are kept in the restart file, so a restarted run goes on counting
// (Run::keepInRestart).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "Boundaries/Boundary.h"
#include "Math/Vector.h"

namespace talus {

class Simulation;

class DeletionBoundary : public Boundary {
public:
    // Deletes particles with (x - point) . normal > 0 at the end of every step (of every wave).
    // Make it in the driver's constructor,
    //   DeletionBoundary& outlet = scene().addBoundary<DeletionBoundary>(*this, normal, point, species, "outlet");
    // `name` prefixes its totals in the restart file and must be unique among the driver's
    // boundaries; totals are kept per species for the first `species` species.
    DeletionBoundary(Made made, Simulation& s, const Vec3& normal, const Vec3& point, std::size_t species,
                     const std::string& name = "deletion");

    // Moves the plane (before the run, for a geometry known only then).
    void setPlane(const Vec3& normal, const Vec3& point);

    // Removes every mobile particle past the plane; returns how many. The simulation calls it at
    // the end of every step (of a wave's last step: a particle past the plane of an open end
    // touches nothing that matters). On ranks every rank calls it at the same step: each removes
    // the particles it owns (and returns their number), the totals are summed.
    std::size_t apply(Simulation& s);
    void afterStep(Simulation& s) override { apply(s); }
    bool runsOnRanks() const override { return true; }

    const Vec3& normal() const { return normal_; }
    const Vec3& point() const { return point_; }
    double count() const { return count_; }
    double mass() const { return mass_; }
    double volume() const { return volume_; }
    double mass(std::size_t species) const { return speciesMass_.at(species); }
    double volume(std::size_t species) const { return speciesVolume_.at(species); }

private:
    Vec3 normal_, point_;
    double count_ = 0, mass_ = 0, volume_ = 0;
    std::vector<double> speciesMass_, speciesVolume_;
};

}  // namespace talus
