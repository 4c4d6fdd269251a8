#include "Fields/CylindricalCoarseGrainer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "IO/InputError.h"
#include "Kernels/AngularMoments.h"

namespace talus::cg {

CylindricalCoarseGrainer::CylindricalCoarseGrainer(const CoarseGrainingSetup& setup)
    : setup_(setup), profile_(setup.shape, setup.coordinates.kernelDimension()) {
    const Coordinates& c = setup_.coordinates;
    const std::string flag = "--coordinates " + c.name();
    if (c.axis() < 0) {
        throw InputError(flag + ": no drum axis: give --axis x|y|z and --axis-point X Y Z (or a restart file with a cylinder wall)");
    }
    axis_ = c.axis();
    if (setup_.contactStress) {
        throw InputError("--stress on: the contact stress is not available in cylindrical coordinates (" + flag + ") yet");
    }
    const int across1 = (axis_ + 1) % 3, across2 = (axis_ + 2) % 3;
    for (int k : {across1, across2}) {
        if (setup_.periodic[k]) {
            throw InputError(flag + ": the domain is periodic along " + std::string(1, axisLetter(k)) +
                             ", across the drum axis " + std::string(1, axisLetter(axis_)) +
                             ": cylindrical coordinates need a bounded cross-section (--periodic)");
        }
    }
    // The angular average needs a kernel that is isotropic across the axis: B diagonal with equal
    // widths across it (Kernels/AngularMoments.h).
    const auto& b = setup_.width.widths();
    for (int r = 0; r < 3; ++r) {
        for (int q = 0; q < 3; ++q) {
            if (r != q && b[3 * r + q] != 0) {
                throw InputError("--width-matrix: cylindrical coordinates (" + flag +
                                 ") need a kernel isotropic across the axis: give -w W or --widths with equal widths across it");
            }
        }
    }
    const double w1 = b[4 * across1], w2 = b[4 * across2];
    if (w1 != w2) {
        throw InputError("--widths: in cylindrical coordinates the widths across the axis (" + std::string(1, axisLetter(across1)) +
                         " and " + std::string(1, axisLetter(across2)) + " for --axis " + std::string(1, axisLetter(axis_)) +
                         ") must be equal, found " + str(w1) + " and " + str(w2));
    }
    crossWidth_ = w1;
    axialWidth_ = b[4 * axis_];
    if (!(crossWidth_ > 0) || !(axialWidth_ > 0)) throw InputError("--width: widths must be positive");
    if (setup_.speciesDensity.empty()) throw InputError("--density: at least one species density is needed");
    layout_.species = static_cast<int>(setup_.speciesDensity.size());
    layout_.contactStress = false;
    layout_.cylindrical = true;
}

void CylindricalCoarseGrainer::setFrame(const ParticleFrame& frame, const std::string& dataPath) {
    const Coordinates& c = setup_.coordinates;
    const bool resolvesAxial = c.resolves(2);
    scale_ = 1.0 / (crossWidth_ * crossWidth_ * (resolvesAxial ? axialWidth_ : c.averagedLength(frame.box)));
    const std::size_t n = frame.size();
    if (!setup_.excluded.empty() && setup_.excluded.size() != n) {
        throw InputError(dataPath + " line " + std::to_string(frame.headerLine) + ": the frame at t = " + str(frame.time) +
                         " has " + std::to_string(n) + " particles, but the restart file describes " +
                         std::to_string(setup_.excluded.size()) + ": its fixed particles cannot be matched (drop --fixed exclude or boundary)");
    }
    radius_.clear();
    axial_.clear();
    mass_.clear();
    volume_.clear();
    velocity_.clear();
    species_.clear();
    const double reachAcross = profile_.cutoff() * crossWidth_;
    const double reachAlong = resolvesAxial ? profile_.cutoff() * axialWidth_ : 0.0;
    const int across1 = (axis_ + 1) % 3, across2 = (axis_ + 2) % 3;  // (across1, across2, axis) right-handed
    const double length = frame.box.length(axis_);
    const bool periodicAxis = resolvesAxial && setup_.periodic[axis_] && length > 0;
    const long reach = periodicAxis ? periodicImagesEachSide(reachAlong, profile_.cutoff(), length, axis_,
                                                             dataPath + " line " + std::to_string(frame.headerLine))
                                    : 0;
    std::vector<Vec3> boxLo, boxHi;
    for (std::size_t p = 0; p < n; ++p) {
        const int s = frame.species[p];
        if (s >= layout_.species) {
            throw InputError(dataPath + " line " + std::to_string(frame.headerLine + 1 + static_cast<long>(p)) +
                             ": a particle of species " + std::to_string(s) + ", but densities are known for " +
                             std::to_string(layout_.species) + " species only (--density d0,d1,... or --restart)");
        }
        if ((!setup_.excluded.empty() && setup_.excluded[p]) || !frame.isOwned(p)) continue;
        const Vec3& x = frame.position[p];
        const Vec3& v = frame.velocity[p];
        const double d1 = x[across1] - c.axisPoint()[across1], d2 = x[across2] - c.axisPoint()[across2];
        const double ri = std::hypot(d1, d2);
        // e_r = (cos, sin) in the (across1, across2) plane; on the axis any direction (its C1 and
        // C2 vanish, so the choice does not enter the fields).
        const double cosine = ri > 0 ? d1 / ri : 1.0, sine = ri > 0 ? d2 / ri : 0.0;
        const Vec3 u{v[across1] * cosine + v[across2] * sine, -v[across1] * sine + v[across2] * cosine, v[axis_]};
        const double volume = frame.volumeOf(p);
        // Images along a periodic axis whose support overlaps the box.
        for (long image = -reach; image <= reach; ++image) {
            const double si = x[axis_] + double(image) * length;
            if (periodicAxis && !(si - reachAlong < frame.box.hi[axis_] && si + reachAlong > frame.box.lo[axis_])) continue;
            radius_.push_back(ri);
            axial_.push_back(si);
            mass_.push_back(frame.massOf(p, setup_.speciesDensity[s]));
            volume_.push_back(volume);
            velocity_.push_back(u);
            species_.push_back(s);
            boxLo.push_back({ri - reachAcross, 0.0, si - reachAlong});
            boxHi.push_back({ri + reachAcross, 0.0, si + reachAlong});
        }
    }
    const Vec3 cellSize{2 * reachAcross, 1.0, std::max(2 * reachAlong, 1e-12)};
    bins_.build(boxLo, boxHi, c.resolvesAxes(), cellSize);
}

void CylindricalCoarseGrainer::evaluate(const std::vector<Vec3>& points, std::vector<double>& sums) const {
    const int fields = layout_.count();
    sums.assign(points.size() * fields, 0.0);
    const bool resolvesAxial = setup_.coordinates.resolves(2);
    const double inverseCross = 1.0 / crossWidth_, inverseAlong = 1.0 / axialWidth_;
    const int angular = layout_.angularMomentumIndex();
    for (std::size_t p = 0; p < points.size(); ++p) {
        const double r = points[p][0], s = points[p][2];
        if (!(r >= 0)) throw InputError("--points: the distance r from the axis must be 0 or more, found " + str(r));
        double* row = sums.data() + p * fields;
        const auto range = bins_.sourcesNear(points[p]);
        for (const std::uint32_t* it = range.begin; it != range.end; ++it) {
            const std::uint32_t i = *it;
            const double dr = (r - radius_[i]) * inverseCross;
            const double ds = resolvesAxial ? (s - axial_[i]) * inverseAlong : 0.0;
            const double m2 = dr * dr + ds * ds;
            if (m2 >= profile_.cutoffSquared()) continue;
            const AngularMoments c = angularMoments(profile_, m2, r * radius_[i] * inverseCross * inverseCross);
            const double m = mass_[i] * scale_;
            const double c0 = m * c.c0, c1 = m * c.c1, c2 = m * c.c2;
            const Vec3& u = velocity_[i];
            row[FieldSums::density] += c0;
            row[FieldSums::volumeFraction] += volume_[i] * scale_ * c.c0;
            row[FieldSums::momentum + 0] += u[0] * c1;
            row[FieldSums::momentum + 1] += u[1] * c1;
            row[FieldSums::momentum + 2] += u[2] * c0;
            const double rr = u[0] * u[0], tt = u[1] * u[1];
            row[FieldSums::momentumFlux + 0] += 0.5 * (rr * (c0 + c2) + tt * (c0 - c2));
            row[FieldSums::momentumFlux + 1] += u[0] * u[1] * c2;
            row[FieldSums::momentumFlux + 2] += u[0] * u[2] * c1;
            row[FieldSums::momentumFlux + 3] += 0.5 * (rr * (c0 - c2) + tt * (c0 + c2));
            row[FieldSums::momentumFlux + 4] += u[1] * u[2] * c1;
            row[FieldSums::momentumFlux + 5] += u[2] * u[2] * c0;
            row[FieldSums::speciesDensity + species_[i]] += c0;
            row[angular] += radius_[i] * u[1] * c0;
            row[angular + 1] += radius_[i] * radius_[i] * c0;
        }
    }
}

}  // namespace talus::cg
