#include "IO/ParticleShapes.h"

#include <cmath>

#include "IO/InputError.h"
#include "IO/RestartFileReader.h"

namespace talus::cg {

// V = 2 a b c e1 e2 B(e1/2 + 1, e1) B(e2/2, e2/2)   (Theory/Superquadrics.md eq. (3); Jaklic,
// Leonardis and Solina 2000, eq. (2.60)), B the beta function. Derivation, in one octant
// (x, y, z >= 0; 8 alike): with nu = (x/a)^(2/e2) + (y/b)^(2/e2) the body is nu^(e2/e1) +
// (z/c)^(2/e1) <= 1, so above (x, y) it reaches z = c (1 - nu^(e2/e1))^(e1/2). The quadrant
// {nu <= s} is the superellipse of exponent 2/e2 scaled by s^(e2/2) along both axes: area A(s) =
// a b s^e2 Gamma(1 + e2/2)^2 / Gamma(1 + e2) = a b s^e2 (e2/4) B(e2/2, e2/2). Summing the columns
// over the rings dA = A'(s) ds, and substituting t = s^(e2/e1) (s^(e2 - 1) ds = (e1/e2)
// t^(e1 - 1) dt):
//   V/8 = int_0^1 c (1 - s^(e2/e1))^(e1/2) A'(s) ds = a b c (e1 e2/4) B(e2/2, e2/2) int_0^1
//         (1 - t)^(e1/2) t^(e1 - 1) dt = a b c (e1 e2/4) B(e2/2, e2/2) B(e1, e1/2 + 1).
// A sphere (e1 = e2 = 1, B(3/2, 1) = 2/3, B(1/2, 1/2) = pi) gives 4/3 pi r^3. The kernel computes
// the same expression in the same order (Kernel/Shapes/Superquadric.cc), so masses agree to the bit.
double SuperquadricShape::volume() const {
    return 2 * semiAxes[0] * semiAxes[1] * semiAxes[2] * e1 * e2 * std::beta(e1 / 2 + 1, e1) * std::beta(e2 / 2, e2 / 2);
}

void applyRestartShapes(const RestartInfo& restart, ParticleFrame& frame, const std::string& dataPath) {
    if (restart.shapes.empty() || restart.particles.empty()) return;
    const std::size_t n = frame.size();
    const std::string header = dataPath + " line " + std::to_string(frame.headerLine);
    if (restart.particles.size() != n) {
        throw InputError(header + ": the frame at t = " + str(frame.time) + " has " + std::to_string(n) +
                         " particles, but the restart file describes " + std::to_string(restart.particles.size()) +
                         ": their shapes cannot be matched (a frame before the last insertion? --time-min)");
    }
    frame.volume.resize(n);
    frame.shaped.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
        const RestartParticle& particle = restart.particles[p];
        const std::string line = dataPath + " line " + std::to_string(frame.headerLine + 1 + static_cast<long>(p));
        // The .data radius has 10 significant digits (Formats/DataFormat.h).
        if (std::abs(frame.radius[p] - particle.radius) > 1e-9 * particle.radius || frame.species[p] != particle.species) {
            throw InputError(line + ": radius " + str(frame.radius[p]) + " and species " + std::to_string(frame.species[p]) +
                             ", but the restart file's particle " + std::to_string(p) + " (id " + std::to_string(particle.id) +
                             ") has radius " + str(particle.radius) + " and species " + std::to_string(particle.species) +
                             ": the files describe different particles");
        }
        frame.volume[p] = particle.shape < 0 ? frame.sphereVolume(p) : restart.shapes[particle.shape].volume();
        frame.shaped[p] = particle.shape >= 0;
    }
}

std::string shapesSummary(const RestartInfo& restart) {
    std::size_t shaped = 0;
    for (const RestartParticle& particle : restart.particles) shaped += particle.shape >= 0;
    if (shaped == 0) return {};
    return ", " + std::to_string(shaped) + " superquadrics of " + std::to_string(restart.shapes.size()) +
           (restart.shapes.size() == 1 ? " shape" : " shapes") + " (mass and volume from the shape)";
}

}  // namespace talus::cg
