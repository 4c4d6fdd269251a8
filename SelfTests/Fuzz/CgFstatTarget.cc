// Fuzz target: the .fstat reader of talus-cg.
#include <cmath>

#include "FuzzEntries.h"
#include "IO/FstatFileReader.h"
#include "IO/InputError.h"

namespace talus::fuzz {

bool cgFstat(const std::uint8_t* data, std::size_t size) {
    std::vector<cg::ContactFrame> frames;
    try {
        frames = cg::readAllFstatFrames(scratchFile("cg-fstat", data, size));
    } catch (const cg::InputError&) {
        return false;
    }
    for (const cg::ContactFrame& f : frames) {
        promise(std::isfinite(f.time), "a time not finite");
        for (const cg::ContactLine& c : f.contacts) {
            promise(c.i >= 0, "a negative particle index");
            for (int k = 0; k < 3; ++k)
                promise(std::isfinite(c.point[k]) && std::isfinite(c.normal[k]) && std::isfinite(c.force[k]),
                        "a contact number not finite");
            promise(std::isfinite(c.overlap), "an overlap not finite");
        }
    }
    return true;
}

}  // namespace talus::fuzz
