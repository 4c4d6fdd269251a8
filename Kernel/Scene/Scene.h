// The scene of a run (Documentation/Architecture.md "The driver contract"): gravity, the box,
// species, particles (spheres and superquadrics), walls, prescribed motions and boundaries, as a
// driver builds them in setupInitialConditions() and edits them during a run, each call checking
// its input; validate() checks the whole before the run starts. A driver reaches it through
// Simulation::scene(); it works on the simulation's state and asks the rank context (Parallel/RankContext.h)
// what splitting the scene over ranks changes.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "Boundaries/Boundary.h"
#include "SimulationState.h"

namespace talus {

class RankContext;

class Scene {
public:
    Scene(SimulationState& state, RankContext& ranks) : state_(state), ranks_(ranks) {}

    // --- gravity and the box ---
    void setGravity(const Vec3& g);
    const Vec3& gravity() const { return state_.gravity; }
    void setDomain(const Vec3& lo, const Vec3& hi);
    void setPeriodic(bool x, bool y, bool z);
    const Domain& domain() const { return state_.domain; }
    // The maser's one-way periodic box (Boundaries/MaserBoundary.h).
    OneWayPeriodicBox& oneWayBox() { return state_.domain.oneWay; }

    // --- species ---
    std::size_t addSpecies(const std::string& name, double density, const ContactLaw& law);
    SpeciesTable& species() { return state_.species; }
    const SpeciesTable& species() const { return state_.species; }

    // --- particles ---
    // Adds a sphere; returns its slot. Radius must be positive and the species must exist.
    std::size_t addParticle(const Vec3& position, double radius, std::size_t species,
                            const Vec3& velocity = Vec3::Zero(), const Vec3& angularVelocity = Vec3::Zero());
    // A fixed particle: never integrated, still collides; follows motion if motion >= 0.
    std::size_t addFixedParticle(const Vec3& position, double radius, std::size_t species, int motion = -1);
    // Superquadric particles (Theory/Superquadrics.md): a shape added once, then particles of it. The particle's
    // radius is the shape's bounding radius, its mass density x volume; it turns as a rigid body
    // (Particles/RigidBodyRotation.h). Returns the shape's index / the particle's slot. A shape that is a sphere
    // (Superquadric::isSphere) makes a sphere (addParticle): the same body on the sphere path, several times
    // cheaper, with the contact's ends treated as a sphere's are (Documentation/SpeedVsError.md).
    std::size_t addShape(const Superquadric& shape);
    std::size_t addSuperquadric(const Vec3& position, std::size_t shape, std::size_t species,
                                const Quat& orientation = Quat::Identity(), const Vec3& velocity = Vec3::Zero(),
                                const Vec3& angularVelocity = Vec3::Zero());
    // A fixed superquadric: never integrated, still collides; follows motion if motion >= 0 (its
    // orientation turns with the motion).
    std::size_t addFixedSuperquadric(const Vec3& position, std::size_t shape, std::size_t species,
                                     const Quat& orientation = Quat::Identity(), int motion = -1);
    const std::vector<Superquadric>& shapes() const { return state_.shapes; }
    // The store's arrays of superquadrics, which addSuperquadric makes at its first particle. On
    // ranks each rank's store needs them once any rank has a superquadric: the ranks exchange
    // particles in one layout (Sampling/AddedOnce.h calls it on the ranks that do not add).
    void enableShapes();
    void removeParticle(std::size_t slot);
    // Moves a particle by a jump (a boundary's wrap, like the maser's): the neighbour list then
    // relists its pairs rather than being built anew.
    void moveParticleBy(std::size_t slot, const Vec3& jump);
    // Under MPI (Parallel/DomainSplit.h, Documentation/Parallel.md) the store holds this rank's
    // particles (slots below particles().owned()) and then ghosts: whole-scene numbers come from
    // Kernel/Sampling. Without MPI owned() == size().
    ParticleStore& particles() { return state_.particles; }
    const ParticleStore& particles() const { return state_.particles; }
    // The current slot of the particle with global id `id` (ids count from 0 in the order of
    // addParticle/addFixedParticle), of an owned one or (ghosts) of a ghost too. A linear search:
    // for drivers and tests, not inner loops.
    std::size_t slotOf(std::uint64_t id, bool ghosts = false) const;

    // --- walls, motions, boundaries ---
    std::size_t addWall(const Vec3& normal, const Vec3& point, std::size_t species, int motion = -1);
    // A box open at the top: a floor at lo.z() and side walls at lo and hi along x and y (in
    // that order: floor, x = lo, x = hi, y = lo, y = hi), all pointing inwards. Returns the
    // floor's index; the sides follow it.
    std::size_t addOpenBox(const Vec3& lo, const Vec3& hi, std::size_t species);
    // The inside of a cylinder (a drum's mantle, Walls/Wall.h) of the given radius about the axis
    // through axisPoint along axisDirection; a drum turns with a motion whose centre is on the
    // axis and whose angular velocity is along it (addMotion).
    std::size_t addCylinderWall(const Vec3& axisPoint, const Vec3& axisDirection, double radius, std::size_t species,
                                int motion = -1);
    // A surface of revolution (Walls/Wall.h, Theory/ContactLaws.md "Surfaces of revolution"): the
    // profile, points (rho, z) of distance from the axis and height along it from axisPoint,
    // turned about the axis through axisPoint along axisDirection, as one wall per segment, joined
    // at the inner points; the first and last points are open rims, unless they are the same
    // point (a closed profile). Both sides of it are walls. A silo of radius R with a cone to an
    // orifice of radius r0 at z = 0, open at the top at height H:
    //   scene().addRevolvedWall(Vec3::Zero(), Vec3::UnitZ(), {{r0, 0}, {R, h}, {R, H}}, steel);
    // Returns the first segment's wall index; the others follow it. It may turn about its axis
    // with a motion (addMotion) whose centre is on the axis and whose angular velocity is along it.
    std::size_t addRevolvedWall(const Vec3& axisPoint, const Vec3& axisDirection,
                                const std::vector<std::array<double, 2>>& profile, std::size_t species,
                                int motion = -1);
    // A triangle mesh (Walls/TriangleMesh.h, IO/StlReader.h) as walls, one per triangle (Walls/
    // MeshWalls.h, Theory/ContactLaws.md "Triangle meshes"): both sides of it are walls; a sphere
    // meets each face, edge and vertex once however many triangles share it. It rests, or follows
    // a motion (addMotion: translation and rotation, the vertices moved each step), and meets
    // spheres only. Returns the first triangle's wall index; the others follow it in the mesh's
    // order. A drum of triangles turning about the y axis:
    //   const int turning = static_cast<int>(scene().addMotion({.angularVelocity = Vec3(0, -2, 0)}));
    //   scene().addMeshWall(readStl("drum.stl"), steel, turning);
    std::size_t addMeshWall(TriangleMesh mesh, std::size_t species, int motion = -1);
    // Removes wall `index` (a silo's lid opened); the walls after it move down one index. Its
    // contacts end, the others keep their histories. A mesh's triangles are not removed one by one.
    void removeWall(std::size_t index);
    const std::vector<Wall>& walls() const { return state_.walls; }
    std::size_t addMotion(const PrescribedMotion& motion);
    // A motion's velocities may change during a run (a drum spun up); the moving walls and fixed
    // particles follow from the next step.
    std::vector<PrescribedMotion>& motions() { return state_.motions; }
    const std::vector<PrescribedMotion>& motions() const { return state_.motions; }
    // A boundary (Boundaries/Boundary.h) of type B, made from B's constructor arguments after the
    // first, and owned by the scene: keep the reference, e.g.
    //   DeletionBoundary& outlet = scene().addBoundary<DeletionBoundary>(*this, normal, point, 2, "outlet");
    template <class B, class... Arguments>
    B& addBoundary(Arguments&&... arguments) {
        auto made = std::make_unique<B>(Boundary::Made{}, std::forward<Arguments>(arguments)...);
        B& boundary = *made;
        boundaries_.push_back(std::move(made));
        return boundary;
    }
    const std::vector<std::unique_ptr<Boundary>>& boundaries() const { return boundaries_; }

    // The run's random generator (kept by the restart file): for insertion and the like.
    std::mt19937_64& random() { return state_.random; }

    // --- checks ---
    // The shortest collision time over the species pairs present (Theory/ContactLaws.md eq. (9)-(10)), and what it is:
    // the lightest and smallest particles of each pair of species, against each other and against walls and fixed
    // particles. A Hertzian law's time is that of an impact at impactSpeed (0: at the law's own characteristic velocity).
    double shortestCollisionTime(std::string* which = nullptr, double impactSpeed = 0) const;
    // The time step of --dt auto (Theory/Integration.md "Choosing the time step"): the shortest collision time over
    // stepsPerCollision, and in `reason` (if given) how it was found.
    double automaticTimeStep(double stepsPerCollision, double impactSpeed = 0, std::string* reason = nullptr) const;
    // The whole scene, before a run starts: the species, the walls' species, and a time step
    // of at most largestStepFraction (RunSettings, --largest-step-fraction) of the shortest
    // collision time (Theory/Integration.md eq. (12)), Hertzian contacts timed at impactSpeed as
    // for --dt auto (--impact-speed; 0: at each law's characteristic velocity).
    void validate(double timeStep, double largestStepFraction, double impactSpeed = 0) const;

private:
    void requireMotion(int motion, const std::string& what) const;
    std::size_t fixParticle(std::size_t slot, int motion);

    SimulationState& state_;
    RankContext& ranks_;
    std::vector<std::unique_ptr<Boundary>> boundaries_;
};

}  // namespace talus
