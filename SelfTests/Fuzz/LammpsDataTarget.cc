// Fuzz target: the LAMMPS data reader (atom style sphere).
#include <cmath>

#include "Error.h"
#include "FuzzEntries.h"
#include "IO/LammpsDataFile.h"

namespace talus::fuzz {

bool lammpsData(const std::uint8_t* data, std::size_t size) {
    LammpsData d;
    try {
        d = readLammpsData(scratchFile("lammps", data, size));
    } catch (const Error&) {
        return false;
    }
    // What the reader promises of the data it returns.
    promise(d.types >= 1, "no atom types");
    promise(((d.hi - d.lo).array() > 0).all() && d.lo.allFinite() && d.hi.allFinite(), "an empty or infinite box");
    for (const LammpsAtom& a : d.atoms) {
        promise(a.id >= 1, "atom id 0");
        promise(a.type >= 1 && a.type <= d.types, "atom type out of range");
        promise(std::isfinite(a.diameter) && a.diameter > 0 && std::isfinite(a.density) && a.density > 0,
                "a diameter or density that is not a positive number");
        promise(a.position.allFinite() && a.velocity.allFinite() && a.angularVelocity.allFinite(), "a number not finite");
    }
    return true;
}

}  // namespace talus::fuzz
