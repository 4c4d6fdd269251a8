// Fuzz target: the restart reader of talus-cg (Talus's and MercuryDPM's restart files).
#include <cmath>

#include "FuzzEntries.h"
#include "IO/InputError.h"
#include "IO/RestartFileReader.h"

namespace talus::fuzz {

bool cgRestart(const std::uint8_t* data, std::size_t size) {
    cg::RestartInfo info;
    try {
        info = cg::readRestartFile(scratchFile("cg-restart", data, size));
    } catch (const cg::InputError&) {
        return false;
    }
    promise(std::isfinite(info.time), "a time not finite");
    for (double density : info.speciesDensity) promise(density > 0 && std::isfinite(density), "a density not positive");
    for (const cg::CylinderWall& w : info.cylinders) {
        promise(w.radius > 0 && std::isfinite(w.radius), "a cylinder radius not positive");
        for (int k = 0; k < 3; ++k)
            promise(std::isfinite(w.axisPoint[k]) && std::isfinite(w.axisDirection[k]), "a cylinder number not finite");
    }
    for (const cg::SuperquadricShape& shape : info.shapes) {
        const double volume = shape.volume();
        promise(volume > 0 && std::isfinite(volume), "a shape volume not positive");
    }
    promise(info.particles.empty() || info.particles.size() == info.fixed.size(), "particles and fixed flags differ in number");
    for (std::size_t p = 0; p < info.particles.size(); ++p) {
        const cg::RestartParticle& particle = info.particles[p];
        promise(particle.shape >= -1 && particle.shape < static_cast<int>(info.shapes.size()), "a shape index out of range");
        promise(particle.species >= 0 && particle.species < static_cast<int>(info.speciesDensity.size()), "a species out of range");
        promise(p == 0 || info.particles[p - 1].id <= particle.id, "particles not in ascending id");
    }
    return true;
}

}  // namespace talus::fuzz
