// Talus's .restart file (Documentation/FileFormats/restart.md): a line per section, starting with
// its key, and the section's item lines. The one description of its keys and of the records the
// coarse-graining tool reads by position (time, domain, species, wall, shapes and particle
// lines): the kernel writes and reads them (Kernel/IO/RestartFile.cc) in this order, talus-cg
// (Tools/CG/IO/RestartFileReader.cc) takes the fields it needs by these names, and
// UnitTests/RestartFormatTest.cc finds each field of a written file where its name says.
#pragma once

namespace talus::formats::restart {

// The first line: "Talus restart VERSION". 2: the run line ends with the reorder flag; 3: kept
// values; 4: the one-way periodic box (maser) and its pairs; 5: shapes; 6: the interior pair
// count; 7: the summation line (the order of the force sums); 8: revolved walls (a wall line ends
// with the profile, the next segment's direction and the start-joined flag); 9: the meshes whose
// triangles are walls (a section after the walls); 10: a mesh line ends with its motion index,
// merging tolerance, travel since the list build and last step, the pair-list line with the
// moving meshes' travel.
inline constexpr const char* magicWords[] = {"Talus", "restart"};
inline constexpr int version = 10;

// The section keys, in the order of the file.
namespace key {
inline constexpr const char* name = "name";
inline constexpr const char* run = "run";
inline constexpr const char* files = "files";
inline constexpr const char* summation = "summation";
inline constexpr const char* time = "time";
inline constexpr const char* gravity = "gravity";
inline constexpr const char* domain = "domain";
inline constexpr const char* oneWay = "oneway";
inline constexpr const char* species = "species";
inline constexpr const char* pairs = "pairs";
inline constexpr const char* motions = "motions";
inline constexpr const char* walls = "walls";
inline constexpr const char* meshes = "meshes";
inline constexpr const char* shapes = "shapes";
inline constexpr const char* particles = "particles";
inline constexpr const char* pairList = "pairlist";
inline constexpr const char* oneWayPairs = "onewaypairs";
inline constexpr const char* random = "random";
inline constexpr const char* output = "output";
inline constexpr const char* values = "values";
inline constexpr const char* end = "end";
}  // namespace key
// Item lines start with this indent.
inline constexpr const char* itemIndent = "  ";

// The fields of a section line count from the first after its key; those of an item line from
// the first of the line.

// `time t step`
enum TimeField : int { time, step, timeFields };

// `domain lo(3) hi(3) px py pz`
enum DomainField : int {
    domainLower,
    domainUpper = domainLower + 3,
    periodic = domainUpper + 3,
    domainFields = periodic + 3,
};

// A species item: `name density law parameters...`.
enum SpeciesField : int { speciesName, density, law, speciesFieldsAtLeast };

// A wall item: `normal(3) point(3) species motion radius profile(4) next(2) startJoined`; a
// cylinder (radius > 0) and a revolved segment (a profile of non-zero length) have their axis
// direction as the normal and a point of their axis as the point (Kernel/Walls/Wall.h). Before
// version 8 the line ended with the radius.
enum WallField : int {
    wallNormal,
    wallPoint = wallNormal + 3,
    wallSpecies = wallPoint + 3,
    wallMotion,
    wallRadius,
    wallProfile,
    wallFieldsBeforeVersion8 = wallProfile,
    wallNext = wallProfile + 4,
    wallStartJoined = wallNext + 2,
    wallFields,
};

// `shapes flag count`: flag 1 when the scene has superquadric particles.
enum ShapesField : int { shapesFlag, shapeCount, shapesFields };

// A shape item: a superquadric's semi-axes a b c and blockiness e1 e2.
enum ShapeField : int { semiAxes, blockiness = semiAxes + 3, shapeFields = blockiness + 2 };

// `particles count nextId`
enum ParticlesField : int { particleCount, nextId, particlesFields };

// A particle item (in slot order). Scenes with shapes append orientation (w x y z), lab angular
// momentum (3), principal inertia (3) and the shape index.
enum ParticleField : int {
    id,
    position,
    velocity = position + 3,
    angularVelocity = velocity + 3,
    force = angularVelocity + 3,
    torque = force + 3,
    radius = torque + 3,
    mass,
    inverseMass,
    inverseInertia,
    particleSpecies,
    fixed,
    motion,
    sphereFields,  // 23
    orientation = sphereFields,
    angularMomentum = orientation + 4,
    principalInertia = angularMomentum + 3,
    shape = principalInertia + 3,
    shapedFields,  // 34
};

}  // namespace talus::formats::restart
