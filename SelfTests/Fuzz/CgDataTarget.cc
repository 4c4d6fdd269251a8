// Fuzz target: the .data reader of talus-cg.
#include <cmath>

#include "FuzzEntries.h"
#include "IO/DataFileReader.h"
#include "IO/InputError.h"

namespace talus::fuzz {

bool cgData(const std::uint8_t* data, std::size_t size) {
    std::vector<cg::ParticleFrame> frames;
    try {
        frames = cg::readAllDataFrames(scratchFile("cg-data", data, size));
    } catch (const cg::InputError&) {
        return false;
    }
    for (const cg::ParticleFrame& f : frames) {
        promise(std::isfinite(f.time), "a time not finite");
        for (int k = 0; k < 3; ++k)
            promise(std::isfinite(f.box.lo[k]) && std::isfinite(f.box.hi[k]) && f.box.hi[k] >= f.box.lo[k],
                    "a box not finite or inverted");
        for (std::size_t i = 0; i < f.size(); ++i) {
            promise(f.radius[i] > 0 && std::isfinite(f.radius[i]) && f.species[i] >= 0, "a bad radius or species");
            for (int k = 0; k < 3; ++k)
                promise(std::isfinite(f.position[i][k]) && std::isfinite(f.velocity[i][k]), "a number not finite");
        }
    }
    return true;
}

}  // namespace talus::fuzz
