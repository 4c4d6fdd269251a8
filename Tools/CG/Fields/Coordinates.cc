#include "Fields/Coordinates.h"

#include <cctype>

#include "IO/InputError.h"

namespace talus::cg {

char axisLetter(int axis) { return "xyz"[axis]; }

Coordinates Coordinates::fromName(const std::string& name) {
    Coordinates c;
    c.resolved_ = {false, false, false};
    for (char letter : name) {
        const char l = static_cast<char>(std::tolower(static_cast<unsigned char>(letter)));
        const int axis = l == 'x' ? 0 : l == 'y' ? 1 : l == 'z' ? 2 : -1;
        if (axis < 0 || c.resolved_[axis]) {
            throw InputError("--coordinates: '" + name + "' is not one of XYZ, XY, XZ, YZ, X, Y, Z");
        }
        c.resolved_[axis] = true;
    }
    if (c.dimension() == 0) throw InputError("--coordinates: empty");
    return c;
}

std::string Coordinates::name() const {
    std::string n;
    for (int k = 0; k < 3; ++k) {
        if (resolved_[k]) n += static_cast<char>('X' + k);
    }
    return n;
}

int Coordinates::dimension() const { return int(resolved_[0]) + int(resolved_[1]) + int(resolved_[2]); }

std::vector<int> Coordinates::kernelAxes() const {
    std::vector<int> axes;
    for (int k = 0; k < 3; ++k) {
        if (resolved_[k]) axes.push_back(k);
    }
    return axes;
}

double Coordinates::averagedLength(const DomainBox& box) const {
    double length = 1;
    for (int k = 0; k < 3; ++k) {
        if (!resolved_[k]) {
            const double l = box.length(k);
            if (!(l > 0)) {
                throw InputError("--coordinates " + name() + " averages over " +
                                 std::string(1, axisLetter(k)) +
                                 ", but the domain box has no positive length along it (" + str(l) + ")");
            }
            length *= l;
        }
    }
    return length;
}

}  // namespace talus::cg
