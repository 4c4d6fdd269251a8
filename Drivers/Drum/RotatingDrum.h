// The rotating drum of Theory/RotatingDrum.md (Denissen 2019, sec. 5.2): spheres and prolate
// ellipsoids of equal volume mixing or segregating in a drum turning about its horizontal axis y.
//
// Methods. Half of N particles (--sphere-fraction) are spheres of diameter 1, the rest prolate
// ellipsoids of semi-axes a = R^(2/3)/2, b = c = R^(-1/3)/2 (aspect ratio R, --aspect; the same
// volume pi/6), all of density 6/pi (mass 1). Contacts are linear spring-dashpots with tc = 0.05
// and e = 0.1 for two particles (reduced mass 1/2), kt = 2/7 kn, gt = gn and sliding friction 0.5;
// dt = tc/50. The drum (radius r, --radius) is periodic along its axis y (length L, --length). Its
// wall is one layer of fixed spheres of diameter 0.5, a disordered flat rough base of length 2 pi
// r (the chute's, Chute::addBase) wrapped onto the cylinder: angle x/r, X = (r + z) cos(x/r), Z =
// (r + z) sin(x/r) (Theory/RotatingDrum.md eq. (2); the thesis drops the /r); or, with --wall
// smooth, the plain cylinder wall of radius r. N follows from --fill, the fraction of the drum's
// cross-section the bed fills (taken at packing fraction 0.6), unless --particles is given.
// Filling (Theory/RotatingDrum.md "Filling"): the particles are placed one by one at random places
// in the drum where their bounding spheres overlap nothing; after 1000 failed tries in a row the
// bed settles and the rest are tried again, up to --insertion-rounds rounds. When all are in (or
// the rounds are used up: the run says how many of each kind are missing) and the bed is at rest,
// the drum starts turning at Froude number F = w^2 r / g (--froude): the wall moves as a
// prescribed rotation about y, every wall particle along its circle with velocity (-w r sin th, 0,
// w r cos th) and angular velocity w. Every --sample-interval the run appends to NAME.series:
// time, rotations, kinetic energy, the mixing and segregation indices M and S of the sphere
// fraction (DrumAnalysis.h) and the dynamic angle of repose. With --rotations N the run ends at
// the first sample after N turns (the filling's length is not known beforehand), else at
// --end-time.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "DrumAnalysis.h"
#include "IO/SeriesFile.h"
#include "Sampling/SamplingClock.h"
#include "Simulation.h"

namespace talus {

class RotatingDrum : public Simulation {
public:
    // Flags (the thesis's full scale is --radius 15, Theory/RotatingDrum.md; the defaults are a
    // scaled-down drum).
    double radius = 6, length = 6, aspect = 2, fill = 0.4, froude = 0.01;
    double sampleInterval = 1, settledEnergy = 1e-4, cgWidth = 1, turnsToRun = 0, sphereFraction = 0.5;
    int particleCount = 0, seed = 1, insertionRounds = 20;
    std::string wallType = "particles";

    static constexpr double collisionTime = 0.05, restitution = 0.1, friction = 0.5;
    static constexpr double wallDiameter = 0.5;
    static constexpr double particleVolume = pi / 6;  // d = 1 spheres and the ellipsoids of Theory/RotatingDrum.md eq. (1)
    static constexpr double bedPackingFraction = 0.6;  // of the settled bed, to turn --fill into a count

    RotatingDrum();

    // Angular speed of the drum from the Froude number, w = sqrt(F g / r).
    double angularSpeed() const { return std::sqrt(froude * scene().gravity().norm() / radius); }
    bool rotating() const { return rotationStart_ >= 0; }
    double rotationStartTime() const { return rotationStart_; }
    // Drum turns since the rotation started.
    double rotations() const { return rotating() ? angularSpeed() * (time() - rotationStart_) / (2 * pi) : 0.0; }
    // --rotations N: the run ends a step after its first sample after N turns, and its end time is
    // brought forward to a sample past that, so that the progress lines count to the end.
    void finishAfterTurns() {
        if (!rotating() || turnsToRun <= 0) return;
        const double lastTurn = rotationStart_ + turnsToRun * 2 * pi / angularSpeed();
        settings().endTime = std::min(settings().endTime, lastTurn + 2 * sampleInterval);
        if (rotations() >= turnsToRun) run().finishAfterNextStep();
    }
    int particlesToInsert() const { return targetCount_; }
    int particlesInserted() const { return insertedSpheres_ + insertedEllipsoids_; }
    // Of the particles to insert, the spheres (half of an odd count rounded up).
    int targetSpheres() const { return static_cast<int>(std::lround(targetCount_ * sphereFraction)); }
    // Distance from the axis within which the bed's bounding spheres must lie.
    double innerRadius() const { return innerRadius_; }
    std::size_t sphereSpecies() const { return 0; }

protected:
    void setupInitialConditions() override;
    void actionsAfterTimeStep() override;
    void actionsAfterSolve() override;

private:
    void checkFlags() const;
    void addParticleWall(std::size_t wallSpecies, int motion);
    // One round of random insertion; returns how many particles it placed.
    int insertRemaining();
    void startRotation();
    void checkBed() const;
    void writeSample();
    drum::MixingIndices mixingOf(const ParticleStore& bed) const;
    double bedEnergy() const;

    std::size_t shape_ = 0;
    // The run's progress, kept in the restart file.
    int targetCount_ = 0, insertedSpheres_ = 0, insertedEllipsoids_ = 0, rounds_ = 0;
    double lastInsertion_ = 0, rotationStart_ = -1, innerRadius_ = 0, angleSum_ = 0;
    int angleSamples_ = 0;
    SamplingClock clock_{*this, "samples"};
    SeriesFile series_{*this, "series",
                       {"t", "rotations", "kineticEnergy", "mixingIndex", "segregationIndex", "reposeAngleDegrees"},
                       "(energy: translational + rotational of the bed; angle nan while filling)"};
};

}  // namespace talus
