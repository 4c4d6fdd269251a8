// The rotating drum (methods: RotatingDrum.h, Documentation/Drums/RotatingDrum.md).
#include "RotatingDrum.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "Boundaries/Filling.h"
#include "Chute/Chute.h"
#include "DrumAnalysis.h"
#include "Sampling/Messages.h"
#include "Sampling/ParticleSums.h"

namespace talus {

RotatingDrum::RotatingDrum() {
    run().addFlag("radius", "drum radius r (the thesis: 15)", radius);
    run().addFlag("length", "periodic length of the drum along its axis y", length);
    run().addFlag("aspect", "aspect ratio R of the ellipsoids (a = R^(2/3)/2, b = c = R^(-1/3)/2)", aspect);
    run().addFlag("fill", "fraction of the drum's cross-section the bed fills, in (0, 1)", fill);
    run().addFlag("particles", "number of particles (0: from --fill)", particleCount);
    run().addFlag("sphere-fraction", "the fraction of the particles that are spheres, the rest ellipsoids", sphereFraction);
    run().addFlag("froude", "Froude number F = w^2 r / g of the rotation", froude);
    run().addTextFlag("wall", "particles (a wrapped rough layer of d = 0.5) or smooth (the cylinder wall)", wallType);
    run().addFlag("seed", "seed of the wall layer and of the insertion", seed);
    run().addFlag("sample-interval", "time between the samples written to NAME.series", sampleInterval);
    run().addFlag("settled-energy", "kinetic energy per particle below which the bed counts as at rest", settledEnergy);
    run().addFlag("insertion-rounds", "rounds of insertion (each after the bed settled) before giving up", insertionRounds);
    run().addFlag("cg-width", "width of the Lucy kernel of the mixing index", cgWidth);
    run().addFlag("rotations", "end the run at the first sample after this many turns (0: at --end-time)", turnsToRun);
    for (auto [key, value] : {std::pair{"targetCount", &targetCount_}, {"insertedSpheres", &insertedSpheres_},
                              {"insertedEllipsoids", &insertedEllipsoids_}, {"rounds", &rounds_}, {"angleSamples", &angleSamples_}})
        run().keepInRestart(std::string("drum.") + key, *value);
    for (auto [key, value] : {std::pair{"lastInsertion", &lastInsertion_}, {"rotationStart", &rotationStart_},
                              {"innerRadius", &innerRadius_}, {"angleSum", &angleSum_}})
        run().keepInRestart(std::string("drum.") + key, *value);
    series_.setPrecision(10);
}

void RotatingDrum::checkFlags() const {
    require(std::isfinite(aspect) && aspect >= 1, "--aspect must be at least 1 (prolate ellipsoids), got " + str(aspect));
    require(fill > 0 && fill < 1, "--fill must lie in (0, 1), got " + str(fill));
    require(wallType == "particles" || wallType == "smooth", "--wall must be particles or smooth, got '" + wallType + "'");
    require(particleCount >= 0, "--particles must not be negative, got " + std::to_string(particleCount));
    require(sphereFraction >= 0 && sphereFraction <= 1, "--sphere-fraction must lie in [0, 1], got " + str(sphereFraction));
    require(std::isfinite(froude) && froude > 0 && froude < 1,
            "--froude must lie in (0, 1) (F >= 1 centrifuges the bed), got " + str(froude));
    require(sampleInterval > 0, "--sample-interval must be positive, got " + str(sampleInterval));
    require(cgWidth > 0, "--cg-width must be positive, got " + str(cgWidth));
    require(turnsToRun >= 0, "--rotations must not be negative, got " + str(turnsToRun));
    // The longest particle is 2a = R^(2/3); the bed needs a few of them across the drum.
    const double longest = std::cbrt(aspect * aspect), smallest = 2 * longest + wallDiameter;
    require(radius >= smallest, "--radius " + str(radius) + " is too small for particles of length " + str(longest) +
                                    ": the drum's diameter must hold 4 of them besides the wall, --radius " + str(smallest) + " or more");
    require(length >= 2 * longest, "--length " + str(length) + " is shorter than two particle lengths (" + str(2 * longest) + ")");
}

void RotatingDrum::setupInitialConditions() {
    checkFlags();
    scene().random().seed(static_cast<std::uint64_t>(seed));
    scene().setGravity(Vec3(0, 0, -1));
    scene().setDomain(Vec3(-radius - 1, 0, -radius - 1), Vec3(radius + 1, length, radius + 1));
    scene().setPeriodic(false, true, false);
    // Theory/RotatingDrum.md eq. (1): volumes pi/6, one density, mass 1; tc, e for m_ij = 1/2.
    const double density = 1 / particleVolume;
    const auto law = LinearSpringDashpot::fromCollision(collisionTime, restitution, 0.5).withFriction(friction);
    scene().addSpecies("spheres", density, law);
    scene().addSpecies("ellipsoids", density, law);
    const std::size_t wallSpecies = scene().addSpecies("wall", density, law);
    if (aspect > 1)
        shape_ = scene().addShape(Superquadric::ellipsoid(std::cbrt(aspect * aspect) / 2, 0.5 / std::cbrt(aspect), 0.5 / std::cbrt(aspect)));
    // The drum turns later (startRotation); its motion exists from the start, at rest.
    const int motion = static_cast<int>(scene().addMotion(PrescribedMotion{}));
    innerRadius_ = radius;  // (a wall of particles narrows it: addParticleWall)
    if (wallType == "smooth")
        scene().addCylinderWall(Vec3::Zero(), Vec3::UnitY(), radius, wallSpecies, motion);
    else
        addParticleWall(wallSpecies, motion);

    const double crossSection = pi * innerRadius_ * innerRadius_;
    targetCount_ = particleCount > 0 ? particleCount
                                     : 2 * static_cast<int>(std::lround(fill * crossSection * length *
                                                                        bedPackingFraction / particleVolume / 2));
    const double bedVolume = targetCount_ * particleVolume / bedPackingFraction;
    require(bedVolume < 0.9 * crossSection * length,
            std::to_string(targetCount_) + " particles (--particles, --fill) do not fit into the drum (their bed would fill " +
                str(bedVolume / (crossSection * length)) + " of it); use fewer, a larger --radius or --length");
    say(*this, "%s: drum r = %g, inner radius %.4g, length %g, %d particles (fill %.3g), aspect %g\n", settings().name.c_str(),
        radius, innerRadius_, length, targetCount_, bedVolume / (crossSection * length), aspect);
    insertRemaining();
}

// Theory/RotatingDrum.md eq. (2): a flat rough base of length 2 pi r and width L (the chute's
// disordered layer of d = 0.5, made in a scratch simulation) wrapped onto the cylinder.
void RotatingDrum::addParticleWall(std::size_t wallSpecies, int motion) {
    Chute flat;
    flat.setChuteGeometry({.length = 2 * pi * radius, .width = length, .height = 1, .periodicEnds = true});
    flat.scene().addSpecies("wall", 1, LinearSpringDashpot::fromCollision(collisionTime, restitution, 0.5));
    flat.addBase(ChuteBase::disordered, wallDiameter, 0, static_cast<std::uint64_t>(seed));
    for (std::size_t i = 0; i < flat.scene().particles().size(); ++i) {
        const Vec3& x = flat.scene().particles().position[i];  // (all fixed: the base alone)
        const double angle = x.x() / radius, r = radius + x.z();
        scene().addFixedParticle(Vec3(r * std::cos(angle), x.y(), r * std::sin(angle)), wallDiameter / 2, wallSpecies, motion);
        innerRadius_ = std::min(innerRadius_, r - wallDiameter / 2);
    }
}

// Theory/RotatingDrum.md "Filling" (Boundaries/Filling.h), spheres and ellipsoids in turn,
// anywhere in the drum: a particle falls at most 2 r, to v = sqrt(4 r) <= 7.8 for r <= 15, and the
// contact (e = 0.1) stops it within about half of v sqrt(m_ij/kn), kn = m_ij (pi^2 + ln(e)^2)/tc^2,
// i.e. 0.05: 16% of the short semi-axis at R = 4. (R = 1: the "ellipsoids" are spheres.)
int RotatingDrum::insertRemaining() {
    const Filling drum(Cylinder(Vec3::Zero(), /*axis y*/ 1, length, innerRadius_), 1000, Filling::CandidateMargin::largestRadius);
    const int ellipsoidShape = aspect > 1 ? static_cast<int>(shape_) : -1;
    std::vector<int> inserted = {insertedSpheres_, insertedEllipsoids_};
    const int placed = static_cast<int>(drum.fillInTurn(*this, {{.species = 0, .target = targetSpheres()},
        {.species = 1, .shape = ellipsoidShape, .target = targetCount_ - targetSpheres()}}, inserted).inserted);
    insertedSpheres_ = inserted[0], insertedEllipsoids_ = inserted[1], lastInsertion_ = time();
    say(*this, "%s: insertion round %d at t = %g: placed %d, %d of %d in (%d spheres, %d ellipsoids)\n", settings().name.c_str(),
        ++rounds_, time(), placed, particlesInserted(), targetCount_, insertedSpheres_, insertedEllipsoids_);
    return placed;
}

void RotatingDrum::startRotation() {
    const double w = angularSpeed();
    // Theory/RotatingDrum.md eq. (3)-(4): (-w r sin th, 0, w r cos th) at th = atan2(Z, X) is w x X
    // for w = (0, -w, 0): the angle grows, the bottom moves towards +x.
    scene().motions()[0].angularVelocity = Vec3(0, -w, 0);
    // The wall moves from now on (the time loop sets these velocities from the next step).
    ParticleStore& p = scene().particles();
    forEachSelected(*this, [](const ParticleStore& q, std::size_t i) { return q.motion[i] == 0; }, [&](std::size_t i) {
        p.velocity[i] = scene().motions()[0].pointVelocity(p.position[i]);
        p.angularVelocity[i] = scene().motions()[0].angularVelocity;
    });
    rotationStart_ = time();
    const int missing = targetCount_ - particlesInserted();
    const std::string missed = ", " + std::to_string(missing) + " particles could not be inserted: " +
        std::to_string(targetSpheres() - insertedSpheres_) + " spheres, " +
        std::to_string(targetCount_ - targetSpheres() - insertedEllipsoids_) + " ellipsoids";
    say(*this, "%s: bed at rest at t = %g (kinetic energy per particle %.3g); rotating at w = %.6g (F = %g, one turn in "
        "%.4g)%s\n", settings().name.c_str(), time(), bedEnergy() / particlesInserted(), w, froude, 2 * pi / w, missing ? missed.c_str() : "");
}

// Mass conservation: every inserted particle is still there and inside the drum (none escaped
// through the wall; y is periodic, so none leaves along the axis).
void RotatingDrum::checkBed() const {
    const double farthest = maxOver(*this, mobileParticles(), [](const ParticleStore& p, std::size_t i) {
        return std::hypot(p.position[i].x(), p.position[i].z());
    });
    requireOnAllRanks(*this, !(farthest >= radius + wallDiameter), "a particle left the drum (distance " + str(farthest) +
                                                                      " from the axis) at t = " + str(time()));
    // Every particle has mass 1 (Theory/RotatingDrum.md eq. (1)): the bed's mass is its count.
    const Totals bed = totalsOver(*this);
    requireOnAllRanks(*this, bed.count == particlesInserted() && std::abs(bed.mass - bed.count) <= 1e-12 * bed.count,
                      "the drum holds " + str(bed.count) + " particles of mass " + str(bed.mass) + ", " +
                          std::to_string(particlesInserted()) + " were inserted (t = " + str(time()) + ")");
}

void RotatingDrum::actionsAfterTimeStep() {
    if (!clock_.every(sampleInterval)) return;
    checkBed();
    writeSample();
    finishAfterTurns();
    if (rotating()) return;
    // Filling: wait for the bed to settle (at least the fall time from the insertion region,
    // 2 sqrt(4 r) from the top of the drum), then insert the rest or start turning.
    const double kineticPerParticle = bedEnergy() / std::max(1, particlesInserted());
    if (time() - lastInsertion_ < 2 * std::sqrt(4 * radius) || kineticPerParticle > settledEnergy) return;
    if (particlesInserted() < targetCount_ && rounds_ < insertionRounds)
        insertRemaining();
    else
        startRotation();
}

void RotatingDrum::writeSample() {
    const ParticleStore bed = gatherParticles(*this);  // (the whole bed, whatever the rank count)
    const drum::MixingIndices mixing = mixingOf(bed);
    const double angle = rotating() ? drum::surfaceAngle(bed) : NAN;
    if (rotating() && rotations() >= 1 && std::isfinite(angle)) angleSum_ += angle, ++angleSamples_;
    if (!settings().writeData) return;  // --files off
    series_.write({time(), rotations(), bedEnergy(), mixing.mixing, mixing.segregation, angle});
}

void RotatingDrum::actionsAfterSolve() {
    const drum::MixingIndices mixing = mixingOf(gatherParticles(*this));
    say(*this, "%s: at t = %g after %.3g rotations: M = %.8f, S = %.8f (%s); mean angle of repose "
        "after the first turn %.2f degrees (%d samples); %d of %d particles in the drum\n", settings().name.c_str(), time(),
        rotations(), mixing.mixing, mixing.segregation, drum::whereTheSpheresAre(mixing),
        angleSamples_ > 0 ? angleSum_ / angleSamples_ : NAN, angleSamples_, particlesInserted(), targetCount_);
}

// Translational + rotational energy of the bed (Simulation::energies would count a rank's ghosts).
double RotatingDrum::bedEnergy() const { return totalsOver(*this).kineticEnergy(); }

// The mixing and segregation indices of the bed on a grid of 8 cells per unit of the radius.
drum::MixingIndices RotatingDrum::mixingOf(const ParticleStore& bed) const {
    return drum::mixingIndices(bed, sphereSpecies(), radius, static_cast<int>(std::ceil(8 * radius)), cgWidth);
}

}  // namespace talus
