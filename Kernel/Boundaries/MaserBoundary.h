// The maser inflow boundary of Theory/Maser.md (Denissen 2019, app. 3.C.5): a periodic box upstream
// of an open chute that first develops a flow of its own and then, once activated, feeds a copy of
// every particle that leaves it through its downstream face into the chute.
//
// Phase 1: the box [lo, hi] along x is the whole simulation, periodic in x (the driver sets the
// domain so); its particles are of the maser species, copies of the chute species
// (maserSpecies), so the box and the chute tell their particles apart without any change of
// physics. Phase 2 (activate): the domain extends downstream to the chute's end and is open
// along x; the box stays periodic one way (Domain::oneWay): a particle of the box that crosses
// the downstream face moves back by the box length, and a copy of it, of the chute species, is
// added at the position it had, with its velocity and spin. Particles near the upstream face feel
// those near the downstream face through their images; those near the downstream face feel the
// chute particles in front of them instead (otherwise they would feel two sets of neighbours).
// Chute particles and box particles interact normally across the face.
//
// The totals (crossings, created particles and their mass per chute species) are kept in the
// restart file; the box itself and the phase are part of the simulation's domain.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "Boundaries/Boundary.h"

namespace talus {

class Simulation;

class MaserBoundary : public Boundary {
public:
    // The box spans [lo, hi] along x (it must be longer than two particle diameters: checked at
    // activation and at every neighbour-list build). Make it in the driver's constructor,
    //   MaserBoundary& maser = scene().addBoundary<MaserBoundary>(*this, lo, hi, species);
    // its totals are kept in the restart file per chute species for the first `species`
    // species; `name` prefixes them there.
    MaserBoundary(Made made, Simulation& s, double lo, double hi, std::size_t species, const std::string& name = "maser");

    // Moves the box (before its species are added: for a geometry known only then, from flags).
    void setBox(double lo, double hi);

    // The maser copy of a chute species ("maser-NAME", behaving exactly like it): the box's
    // particles, fixed ones included, are of these species; a particle that leaves the box
    // becomes one of `chuteSpecies`. Call after the chute species' pair laws are final.
    std::size_t maserSpecies(Simulation& s, std::size_t chuteSpecies);

    // Phase 2: the domain reaches from the box's upstream face to chuteEnd along x and is no
    // longer periodic along x; the box feeds the chute from now on. Stops with a message if the
    // box holds no mobile particle, is shorter than two of its particles' diameters, or the
    // domain does not start at the box.
    // With seedChute, the first box length of the chute gets a copy of the box's mobile
    // particles (chute species, shifted by the box length): the particles at the downstream face
    // then keep the neighbours in front of them that they had in the periodic box. Into an empty
    // chute they would move on unhindered while their images push the upstream particles, which
    // sit against the base: a start-up transient with overlaps of the order of the radius.
    void activate(Simulation& s, double chuteEnd, bool seedChute = true);
    // Moves the domain's downstream end (the chute's end) of an active maser, as activate does;
    // a driver that grows its chute at a restart calls it (and moves its outlet with it).
    void setChuteEnd(Simulation& s, double chuteEnd) const;
    bool active(const Simulation& s) const;

    double lo() const { return lo_; }
    double hi() const { return hi_; }
    // Since activation: particles that left through the downstream face (each copied into the
    // chute), of them per chute species, and their mass; particles that left through the upstream
    // face (moved forward by the box length once a diameter behind the face, not copied).
    double crossings() const { return crossings_; }
    double crossings(std::size_t chuteSpecies) const { return speciesCount_.at(chuteSpecies); }
    double createdMass() const { return mass_; }
    double createdMass(std::size_t chuteSpecies) const { return speciesMass_.at(chuteSpecies); }
    double backwardCrossings() const { return backward_; }
    // The particles that seeded the chute at activation, and their mass.
    double seeded() const { return seeded_; }
    double seededMass() const { return seededMass_; }

    bool actsAfterDrift() const override { return true; }
    void afterDrift(Simulation& s) override;
    // On ranks each rank copies and moves the box particles it owns; the totals are summed over
    // the ranks every step, so every rank (and the restart file) has them whole. The box may be
    // cut by rank boundaries: the pairs across its face are listed through ghosts
    // (Parallel/DomainSplit.h).
    bool runsOnRanks() const override { return true; }

private:
    double lo_, hi_;
    double crossings_ = 0, mass_ = 0, backward_ = 0, seeded_ = 0, seededMass_ = 0;
    std::vector<double> speciesCount_, speciesMass_;
};

}  // namespace talus
