// Shared scenes for the contact-physics tests (ContactCollisionTest.cc, ObliqueImpactTest.cc,
// RollingTest.cc, SettlingEnergyTest.cc, ContactReportTest.cc): real simulations driven through the
// public driver API (talus::Simulation), so that the tests check what a driver gets, time loop
// included.
#pragma once

#include <cmath>
#include <functional>
#include <utility>

#include "TestHelpers.h"

namespace talus::test {

// Density that gives a sphere of diameter 1 unit mass (Theory/Chutes.md "Units and axes": m = 1 for
// d = 1).
inline constexpr double unitMassDensity = 6 / pi;

inline double sphereMass(double radius, double density = unitMassDensity) {
    return density * 4.0 / 3.0 * pi * radius * radius * radius;
}

using TestScene = SceneSimulation;

// A square box of side `side` open at the top: a floor at z = 0 and four side walls, all of
// `species` (SettlingEnergyTest.cc, ContactReportTest.cc).
inline void addOpenBox(Simulation& s, double side, std::size_t species) {
    s.scene().addOpenBox(Vec3::Zero(), Vec3(side, side, 0), species);
}

// What a head-on collision measured.
struct HeadOnResult {
    double restitution;          // (normal relative speed after) / (normal relative speed before)
    double contactDuration;      // exit time - entry time of the free-flight lines (see run())
    double kineticEnergyBefore;  // translational + rotational, of the mobile particles
    double kineticEnergyAfter;
};

// A central collision along x without gravity: a sphere of radius `radius` at speed `speed`
// hits either a second sphere (radius `partnerRadius`, moving towards it at `partnerSpeed`) or,
// when partnerRadius <= 0, a wall at rest. Both partners use one species with `law`.
struct HeadOnCollision {
    ContactLaw law;
    double radius = 0.5;
    double partnerRadius = 0.4;  // <= 0: a wall
    double speed = 1;
    double partnerSpeed = 0.5;
    double timeStep = 0;
    double longestDuration = 0;  // an upper bound of the contact duration, to size the run
    // The contact starts (stepsBeforeContact + entryPhase) steps after t = 0: a phase in (0, 1)
    // puts the first touch between two steps, as in a real simulation.
    int stepsBeforeContact = 5;
    double entryPhase = 0.37;

    bool withWall() const { return partnerRadius <= 0; }
    double approachSpeed() const { return speed + (withWall() ? 0 : partnerSpeed); }
    double reducedMass() const {
        const double m = sphereMass(radius);
        if (withWall()) return m;
        const double mp = sphereMass(partnerRadius);
        return m * mp / (m + mp);
    }

    // The spheres move at constant speed before and after the contact, so the overlap is a
    // straight line in time outside it: dn(t) = vin (t - tin) before (tin is set by the initial
    // gap) and dn(t) = -vout (t - tout) after, where tout follows from any state after the
    // contact. tout - tin is the contact duration of the discrete trajectory, without the
    // one-step uncertainty of counting steps in contact.
    HeadOnResult run() const {
        const double entryTime = (stepsBeforeContact + entryPhase) * timeStep;
        const double gap = approachSpeed() * entryTime;
        const double partnerX = radius + (withWall() ? 0 : partnerRadius) + gap;
        TestScene scene;
        scene.setup = [&](TestScene& s) {
            s.scene().setGravity(Vec3::Zero());
            s.scene().setDomain(Vec3(-1, -1, -1), Vec3(partnerX + 1, 1, 1));
            const auto species = s.scene().addSpecies("solid", unitMassDensity, law);
            s.scene().addParticle(Vec3::Zero(), radius, species, Vec3(speed, 0, 0));
            if (withWall())
                s.scene().addWall(-Vec3::UnitX(), Vec3(partnerX, 0, 0), species);
            else
                s.scene().addParticle(Vec3(partnerX, 0, 0), partnerRadius, species, Vec3(-partnerSpeed, 0, 0));
        };
        double kineticBefore = 0;
        scene.afterStep = [&](TestScene& s) {
            if (s.step() == 1) kineticBefore = kineticEnergy(s);  // still in free flight
        };
        scene.runFor(timeStep, entryTime + 1.5 * longestDuration + 5 * timeStep);

        const ParticleStore& p = scene.scene().particles();
        // Separation along x (x of the partner minus x of the sphere) and its rate.
        const double partnerPosition = withWall() ? partnerX : p.position[1].x();
        const double partnerVelocity = withWall() ? 0 : p.velocity[1].x();
        const double overlap = radius + (withWall() ? 0 : partnerRadius) - (partnerPosition - p.position[0].x());
        const double separationSpeed = partnerVelocity - p.velocity[0].x();
        require(overlap < 0 && separationSpeed > 0, "HeadOnCollision: the run ended before the contact did");
        const double exitTime = scene.time() + overlap / separationSpeed;
        return {separationSpeed / approachSpeed(), exitTime - entryTime, kineticBefore, kineticEnergy(scene)};
    }

    static double kineticEnergy(const Simulation& s) {
        const Energies e = s.energies();
        return e.kinetic + e.rotational;
    }
};

}  // namespace talus::test
