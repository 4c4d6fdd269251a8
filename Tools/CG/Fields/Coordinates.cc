#include "Fields/Coordinates.h"

#include <cctype>

#include "IO/InputError.h"

namespace talus::cg {

char axisLetter(int axis) { return "xyz"[axis]; }

Coordinates Coordinates::fromName(const std::string& name) {
    Coordinates c;
    std::string upper;
    for (char letter : name) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(letter)));
    if (upper == "RZ" || upper == "R") {
        c.cylindrical_ = true;
        c.resolved_ = {true, false, upper == "RZ"};
        return c;
    }
    c.resolved_ = {false, false, false};
    if (upper == "O") return c;  // the domain average: nothing resolved
    for (char l : upper) {
        const int axis = l == 'X' ? 0 : l == 'Y' ? 1 : l == 'Z' ? 2 : -1;
        if (axis < 0 || c.resolved_[axis]) {
            throw InputError("--coordinates: '" + name + "' is not one of XYZ, XY, XZ, YZ, X, Y, Z, RZ, R, O");
        }
        c.resolved_[axis] = true;
    }
    if (c.dimension() == 0) throw InputError("--coordinates: empty");
    return c;
}

std::string Coordinates::name() const {
    if (cylindrical_) return resolved_[2] ? "RZ" : "R";
    std::string n;
    for (int k = 0; k < 3; ++k) {
        if (resolved_[k]) n += static_cast<char>('X' + k);
    }
    return n.empty() ? "O" : n;
}

int Coordinates::dimension() const { return int(resolved_[0]) + int(resolved_[1]) + int(resolved_[2]); }

int Coordinates::kernelDimension() const {
    if (cylindrical_) return resolved_[2] ? 3 : 2;
    return dimension();
}

std::vector<int> Coordinates::kernelAxes() const {
    std::vector<int> axes;
    for (int k = 0; k < 3; ++k) {
        if (resolved_[k]) axes.push_back(k);
    }
    return axes;
}

std::string Coordinates::coordinateName(int slot) const {
    if (!cylindrical_) return std::string(1, axisLetter(slot));
    if (slot == 0) return "r";
    return axis_ >= 0 ? std::string(1, axisLetter(axis_)) : std::string("s");
}

void Coordinates::setAxis(int axis, const Vec3& point) {
    axis_ = axis;
    axisPoint_ = point;
}

double Coordinates::averagedLength(const DomainBox& box) const {
    if (cylindrical_) {
        if (resolved_[2]) return 1;
        const double l = axis_ >= 0 ? box.length(axis_) : 0.0;
        if (!(l > 0)) {
            throw InputError("--coordinates R averages along the axis, but the domain box has no positive length along it (" +
                             str(l) + "); use RZ");
        }
        return l;
    }
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
