// The rotating drum of Theory/RotatingDrum.md: what the driver does, in the order it happens (the methods are
// summarised in RotatingDrum.h and Documentation/Drums/RotatingDrum.md).
#include "RotatingDrum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include "Chute/Chute.h"
#include "DrumAnalysis.h"

namespace talus {

namespace {
// Loose packing fraction of the settled bed, to turn --fill into a particle count.
constexpr double bedPackingFraction = 0.6;
constexpr double particleVolume = pi / 6;  // d = 1 spheres and the ellipsoids of Theory/RotatingDrum.md eq. (1)
}  // namespace

RotatingDrum::RotatingDrum() {
    addFlag("radius", "drum radius r (the thesis: 15)", radius);
    addFlag("length", "periodic length of the drum along its axis y", length);
    addFlag("aspect", "aspect ratio R of the ellipsoids (a = R^(2/3)/2, b = c = R^(-1/3)/2)", aspect);
    addFlag("fill", "fraction of the drum's cross-section the bed fills, in (0, 1)", fill);
    addFlag("particles", "number of particles, half spheres, half ellipsoids (0: from --fill)", particleCount);
    addFlag("froude", "Froude number F = w^2 r / g of the rotation", froude);
    addTextFlag("wall", "particles (a wrapped rough layer of d = 0.5) or smooth (the cylinder wall)", wallType);
    addFlag("seed", "seed of the wall layer and of the insertion", seed);
    addFlag("sample-interval", "time between the samples written to NAME.series", sampleInterval);
    addFlag("settled-energy", "kinetic energy per particle below which the bed counts as at rest", settledEnergy);
    addFlag("insertion-rounds", "rounds of insertion (each after the bed settled) before giving up", insertionRounds);
    addFlag("cg-width", "width of the Lucy kernel of the mixing index", cgWidth);
    keepInRestart("drum.targetCount", targetCount_);
    keepInRestart("drum.insertedSpheres", insertedSpheres_);
    keepInRestart("drum.insertedEllipsoids", insertedEllipsoids_);
    keepInRestart("drum.rounds", rounds_);
    keepInRestart("drum.lastInsertion", lastInsertion_);
    keepInRestart("drum.rotationStart", rotationStart_);
    keepInRestart("drum.innerRadius", innerRadius_);
    keepInRestart("drum.angleSum", angleSum_);
    keepInRestart("drum.angleSamples", angleSamples_);
}

double RotatingDrum::angularSpeed() const { return std::sqrt(froude * gravity().norm() / radius); }

double RotatingDrum::rotations() const {
    return rotating() ? angularSpeed() * (time() - rotationStart_) / (2 * pi) : 0.0;
}

void RotatingDrum::checkFlags() const {
    require(std::isfinite(aspect) && aspect >= 1, "--aspect must be at least 1 (prolate ellipsoids), got " + str(aspect));
    require(fill > 0 && fill < 1, "--fill must lie in (0, 1), got " + str(fill));
    require(wallType == "particles" || wallType == "smooth", "--wall must be particles or smooth, got '" + wallType + "'");
    require(particleCount >= 0, "--particles must not be negative, got " + std::to_string(particleCount));
    require(std::isfinite(froude) && froude > 0 && froude < 1,
            "--froude must lie in (0, 1) (F >= 1 centrifuges the bed), got " + str(froude));
    require(sampleInterval > 0, "--sample-interval must be positive, got " + str(sampleInterval));
    require(cgWidth > 0, "--cg-width must be positive, got " + str(cgWidth));
    // The longest particle is 2a = R^(2/3); the bed needs a few of them across the drum.
    const double longest = std::cbrt(aspect * aspect);
    const double smallest = 2 * longest + wallDiameter;
    require(radius >= smallest, "--radius " + str(radius) + " is too small for particles of length " + str(longest) +
                                    ": the drum's diameter must hold 4 of them besides the wall, --radius " +
                                    str(smallest) + " or more");
    require(length >= 2 * longest, "--length " + str(length) + " is shorter than two particle lengths (" +
                                       str(2 * longest) + ")");
}

void RotatingDrum::setupInitialConditions() {
    checkFlags();
    random().seed(static_cast<std::uint64_t>(seed));
    setGravity(Vec3(0, 0, -1));
    setDomain(Vec3(-radius - 1, 0, -radius - 1), Vec3(radius + 1, length, radius + 1));
    setPeriodic(false, true, false);
    // Theory/RotatingDrum.md eq. (1): equal volumes pi/6, equal density, mass 1; tc and e for two particles (m_ij = 1/2).
    const double density = 1 / particleVolume;
    const auto law = LinearSpringDashpot::fromCollision(collisionTime, restitution, 0.5).withFriction(friction);
    addSpecies("spheres", density, law);
    addSpecies("ellipsoids", density, law);
    const std::size_t wallSpecies = addSpecies("wall", density, law);
    if (aspect > 1)
        shape_ = addShape(Superquadric::ellipsoid(std::cbrt(aspect * aspect) / 2, 0.5 / std::cbrt(aspect),
                                              0.5 / std::cbrt(aspect)));

    // The drum turns later (startRotation); its motion exists from the start, at rest.
    const int motion = static_cast<int>(addMotion(PrescribedMotion{}));
    if (wallType == "smooth") {
        addCylinderWall(Vec3::Zero(), Vec3::UnitY(), radius, wallSpecies, motion);
        innerRadius_ = radius;
    } else {
        addParticleWall(wallSpecies, motion);
    }

    const double crossSection = pi * innerRadius_ * innerRadius_;
    targetCount_ = particleCount > 0 ? particleCount
                                     : 2 * static_cast<int>(std::lround(fill * crossSection * length *
                                                                        bedPackingFraction / particleVolume / 2));
    const double bedVolume = targetCount_ * particleVolume / bedPackingFraction;
    require(bedVolume < 0.9 * crossSection * length,
            std::to_string(targetCount_) + " particles (--particles, --fill) do not fit into the drum (their bed would fill " +
                str(bedVolume / (crossSection * length)) + " of it); use fewer, a larger --radius or --length");
    std::printf("%s: drum r = %g, inner radius %.4g, length %g, %d particles (fill %.3g), aspect %g\n", name().c_str(),
                radius, innerRadius_, length, targetCount_, bedVolume / (crossSection * length), aspect);
    insertRemaining();
}

// Theory/RotatingDrum.md eq. (2): a flat rough base of length 2 pi r and width L (the chute's disordered layer of
// d = 0.5, made in a scratch simulation) wrapped onto the cylinder.
void RotatingDrum::addParticleWall(std::size_t wallSpecies, int motion) {
    Chute flat;
    flat.setChuteGeometry({.length = 2 * pi * radius, .width = length, .height = 1, .periodicEnds = true});
    flat.addSpecies("wall", 1, LinearSpringDashpot::fromCollision(collisionTime, restitution, 0.5));
    flat.addBase(ChuteBase::disordered, wallDiameter, 0, static_cast<std::uint64_t>(seed));
    innerRadius_ = radius;
    for (std::size_t i = 0; i < flat.particles().size(); ++i) {
        if (!flat.particles().fixed[i]) continue;
        const Vec3& x = flat.particles().position[i];
        const double angle = x.x() / radius, r = radius + x.z();
        addFixedParticle(Vec3(r * std::cos(angle), x.y(), r * std::sin(angle)), wallDiameter / 2, wallSpecies, motion);
        innerRadius_ = std::min(innerRadius_, r - wallDiameter / 2);
    }
}

// Theory/RotatingDrum.md "Filling": random places where the particle's bounding sphere overlaps no other
// (nearest periodic image along y) and lies inside the drum; 1000 failures in a row end the round.
int RotatingDrum::insertRemaining() {
    const ParticleStore& p = particles();
    const double boundingRadius = aspect > 1 ? shapes()[shape_].boundingRadius() : 0.5;
    const double reach = innerRadius_ - boundingRadius;
    // Anywhere in the drum: a particle falls at most 2 r before it lands, at v = sqrt(4 r) <= 7.8
    // for r <= 15, and the contact (e = 0.1) stops it within about half of v sqrt(m_ij/kn),
    // kn = m_ij (pi^2 + ln(e)^2)/tc^2, i.e. 0.05: 16% of the short semi-axis at R = 4.
    std::uniform_real_distribution<double> unit(0, 1);
    std::normal_distribution<double> gauss;
    const int before = particlesInserted();
    while (particlesInserted() < targetCount_) {
        const bool sphere = insertedSpheres_ < targetCount_ / 2 + targetCount_ % 2 && insertedSpheres_ <= insertedEllipsoids_;
        const double ownRadius = sphere ? 0.5 : boundingRadius;
        bool placed = false;
        for (int attempt = 0; attempt < 1000 && !placed; ++attempt) {
            const Vec3 x(reach * (2 * unit(random()) - 1), length * unit(random()),
                         reach * (2 * unit(random()) - 1));
            if (std::hypot(x.x(), x.z()) > innerRadius_ - ownRadius) continue;
            bool free = true;
            for (std::size_t i = 0; i < p.size() && free; ++i) {
                Vec3 d = x - p.position[i];
                d.y() -= length * std::round(d.y() / length);
                free = d.norm() >= ownRadius + p.radius[i];
            }
            if (!free) continue;
            placed = true;
            if (sphere) {
                addParticle(x, 0.5, 0);
                ++insertedSpheres_;
            } else if (aspect == 1) {  // R = 1: the "ellipsoids" are spheres (and talus-cg reads the run)
                addParticle(x, 0.5, 1);
                ++insertedEllipsoids_;
            } else {
                const Quat q = Quat(gauss(random()), gauss(random()), gauss(random()), gauss(random())).normalized();
                addSuperquadric(x, shape_, 1, q);
                ++insertedEllipsoids_;
            }
        }
        if (!placed) break;
    }
    ++rounds_;
    lastInsertion_ = time();
    std::printf("%s: insertion round %d at t = %g: placed %d, %d of %d in (%d spheres, %d ellipsoids)\n",
                name().c_str(), rounds_, time(), particlesInserted() - before, particlesInserted(), targetCount_,
                insertedSpheres_, insertedEllipsoids_);
    return particlesInserted() - before;
}

void RotatingDrum::startRotation() {
    const double w = angularSpeed();
    // Theory/RotatingDrum.md eq. (3)-(4): velocity (-w r sin th, 0, w r cos th) at angle th = atan2(Z, X) is the rotation
    // w x X with w = (0, -w, 0): the angle grows, the bottom moves towards +x.
    motions()[0].angularVelocity = Vec3(0, -w, 0);
    // The wall moves from now on (the time loop sets these velocities from the next step).
    ParticleStore& p = particles();
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.motion[i] == 0) {
            p.velocity[i] = motions()[0].pointVelocity(p.position[i]);
            p.angularVelocity[i] = motions()[0].angularVelocity;
        }
    rotationStart_ = time();
    const int missing = targetCount_ - particlesInserted();
    std::printf("%s: bed at rest at t = %g (kinetic energy per particle %.3g); rotating at w = %.6g (F = %g, one turn "
                "in %.4g)%s\n", name().c_str(), time(), (energies().kinetic + energies().rotational) / particlesInserted(),
                w, froude, 2 * pi / w,
                missing == 0 ? "" : (", " + std::to_string(missing) + " particles could not be inserted: " +
                                     std::to_string(targetCount_ / 2 + targetCount_ % 2 - insertedSpheres_) + " spheres, " +
                                     std::to_string(targetCount_ / 2 - insertedEllipsoids_) + " ellipsoids").c_str());
}

// Mass conservation: every inserted particle is still there and inside the drum (none escaped
// through the wall; y is periodic, so none leaves along the axis).
void RotatingDrum::checkBed() const {
    std::size_t mobile = 0;
    for (std::size_t i = 0; i < particles().size(); ++i) {
        if (particles().fixed[i]) continue;
        ++mobile;
        const Vec3& x = particles().position[i];
        require(std::hypot(x.x(), x.z()) < radius + wallDiameter,
                "particle id " + std::to_string(particles().id[i]) + " left the drum at t = " + str(time()));
    }
    require(mobile == static_cast<std::size_t>(particlesInserted()),
            "the drum holds " + std::to_string(mobile) + " particles, " + std::to_string(particlesInserted()) +
                " were inserted (t = " + str(time()) + ")");
}

void RotatingDrum::actionsAfterTimeStep() {
    // At the multiples of the sample interval (so also after a restart).
    if (std::abs(time() - sampleInterval * std::round(time() / sampleInterval)) > 0.5 * timeStep()) return;
    checkBed();
    writeSample();
    if (rotating()) return;
    // Filling: wait for the bed to settle (at least the fall time from the insertion region,
    // 2 sqrt(4 r) from the top of the drum), then insert the rest or start turning.
    const double kineticPerParticle = (energies().kinetic + energies().rotational) / std::max(1, particlesInserted());
    if (time() - lastInsertion_ < 2 * std::sqrt(4 * radius) || kineticPerParticle > settledEnergy) return;
    if (particlesInserted() < targetCount_ && rounds_ < insertionRounds)
        insertRemaining();
    else
        startRotation();
}

void RotatingDrum::writeSample() {
    const drum::MixingIndices mixing = drum::mixingIndices(particles(), sphereSpecies(), radius,
                                                          static_cast<int>(std::ceil(8 * radius)), cgWidth);
    const double angle = rotating() ? drum::surfaceAngle(particles()) : NAN;
    if (rotating() && rotations() >= 1 && std::isfinite(angle)) angleSum_ += angle, ++angleSamples_;
    if (!settings().writeData) return;  // --files off
    std::ostringstream line;
    line.precision(10);
    line << time() << ' ' << rotations() << ' ' << energies().kinetic + energies().rotational << ' '
         << mixing.mixing << ' ' << mixing.segregation << ' ' << angle << '\n';
    series_.append(line.str());
}

void RotatingDrum::actionsAfterSolve() {
    const drum::MixingIndices mixing = drum::mixingIndices(particles(), sphereSpecies(), radius,
                                                          static_cast<int>(std::ceil(8 * radius)), cgWidth);
    std::printf("%s: at t = %g after %.3g rotations: M = %.8f, S = %.8f (spheres at the %s); mean angle of repose "
                "after the first turn %.2f degrees (%d samples); %d of %d particles in the drum\n",
                name().c_str(), time(), rotations(), mixing.mixing, mixing.segregation,
                mixing.spheresAtCore ? "core" : "periphery", angleSamples_ > 0 ? angleSum_ / angleSamples_ : NAN,
                angleSamples_, particlesInserted(), targetCount_);
}

}  // namespace talus
