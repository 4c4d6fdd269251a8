// Fuzz target: Talus's .restart reader.
#include "Error.h"
#include "FuzzEntries.h"
#include "IO/RestartFile.h"

namespace talus::fuzz {

bool talusRestart(const std::uint8_t* data, std::size_t size) {
    SimulationState s;
    try {
        readRestartFile(scratchFile("restart", data, size), s);
    } catch (const Error&) {
        return false;
    }
    // Indices into the state's lists must be in range: the run would use them unchecked.
    const ParticleStore& p = s.particles;
    const std::size_t n = p.size();
    promise(p.radius.size() == n && p.species.size() == n && p.motion.size() == n, "arrays of different lengths");
    for (std::size_t i = 0; i < n; ++i) {
        promise(p.species[i] < s.species.size(), "a particle species out of range");
        promise(p.motion[i] >= -1 && p.motion[i] < static_cast<std::int32_t>(s.motions.size()), "a motion out of range");
        promise(p.radius[i] > 0 && p.mass[i] > 0, "a radius or mass that is not positive");
        promise(p.position[i].allFinite() && p.velocity[i].allFinite(), "a number not finite");
    }
    for (const Wall& w : s.walls) promise(w.species < s.species.size(), "a wall species out of range");
    for (const auto& pair : s.pairList.pairs) promise(pair.i < n && pair.j < n, "a pair of a missing particle");
    for (const auto& pair : s.pairList.wallPairs)
        promise(pair.particle < n && pair.wall < s.walls.size(), "a wall pair of a missing particle or wall");
    promise(s.pairList.history.size() == s.pairList.pairs.size(), "pairs and histories of different lengths");
    promise(((s.domain.hi - s.domain.lo).array() > 0).all(), "an empty or inverted domain");
    return true;
}

}  // namespace talus::fuzz
