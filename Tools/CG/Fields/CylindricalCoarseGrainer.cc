#include "Fields/CylindricalCoarseGrainer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "Fields/ContactBranches.h"
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
    layout_.contactStress = setup_.contactStress;
    layout_.cylindrical = true;
}

namespace {

// 5-point Gauss-Legendre rule on [-1, 1].
constexpr double legendreNode[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
constexpr double legendreWeight[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                      0.2369268850561891};

}  // namespace

CylindricalCoarseGrainer::LocalFrame CylindricalCoarseGrainer::localFrame(const Vec3& x) const {
    const Vec3& centre = setup_.coordinates.axisPoint();
    const int across1 = (axis_ + 1) % 3, across2 = (axis_ + 2) % 3;
    const double d1 = x[across1] - centre[across1], d2 = x[across2] - centre[across2];
    LocalFrame local;
    local.radius = std::hypot(d1, d2);
    local.axial = x[axis_];
    // e_r = (cos, sin) in the (across1, across2) plane; on the axis any direction (its C1 and C2
    // vanish, so the choice does not enter the fields).
    const double cosine = local.radius > 0 ? d1 / local.radius : 1.0, sine = local.radius > 0 ? d2 / local.radius : 0.0;
    local.basis[0] = Vec3{0, 0, 0};
    local.basis[1] = Vec3{0, 0, 0};
    local.basis[2] = Vec3{0, 0, 0};
    local.basis[0][across1] = cosine;
    local.basis[0][across2] = sine;
    local.basis[1][across1] = -sine;
    local.basis[1][across2] = cosine;
    local.basis[2][axis_] = 1;
    return local;
}

void CylindricalCoarseGrainer::setContacts(const ParticleFrame& frame, const ContactFrame& contacts, double reachAcross,
                                           double reachAlong, const std::function<void(double, const std::function<void(double)>&)>& images,
                                           const std::string& dataPath, const std::string& fstatPath) {
    std::vector<Vec3> contactLo, contactHi, boundaryLo, boundaryHi;
    const int across1 = (axis_ + 1) % 3, across2 = (axis_ + 2) % 3;
    forEachContactBranch(frame, contacts, setup_, dataPath, fstatPath, [&](const ContactBranch& branch) {
        const Vec3& b = branch.branch;
        // Theory/CoarseGraining.md eq. (10) in cylindrical components: the line integral along
        // the branch by composite Gauss-Legendre quadrature, panels at most a quarter of a width
        // long, each node a source of the tensor in the local basis of its own position.
        const double across = std::hypot(b[across1], b[across2]) / crossWidth_, along = b[axis_] / axialWidth_;
        const int panels = std::max(1, static_cast<int>(std::ceil(std::hypot(across, along) / maxPanelInWidths)));
        for (int panel = 0; panel < panels; ++panel) {
            for (int k = 0; k < 5; ++k) {
                const double t = (panel + 0.5 * (legendreNode[k] + 1)) / panels, weight = 0.5 * legendreWeight[k] / panels;
                const LocalFrame local = localFrame({branch.centre[0] - t * b[0], branch.centre[1] - t * b[1], branch.centre[2] - t * b[2]});
                std::array<double, 9> tensor{};
                for (int r = 0; r < 3; ++r) {
                    for (int q = 0; q < 3; ++q) {
                        double value = 0;
                        for (int i = 0; i < 3; ++i) {
                            for (int j = 0; j < 3; ++j) value += local.basis[r][i] * branch.force[i] * b[j] * local.basis[q][j];
                        }
                        tensor[3 * r + q] = weight * value;
                    }
                }
                images(local.axial, [&](double s) {
                    contactRadius_.push_back(local.radius);
                    contactAxial_.push_back(s);
                    contactTensor_.push_back(tensor);
                    contactLo.push_back({local.radius - reachAcross, 0.0, s - reachAlong});
                    contactHi.push_back({local.radius + reachAcross, 0.0, s + reachAlong});
                });
            }
        }
        if (!branch.boundary) return;
        // The boundary's force, from the contact point centre - b, in its local components.
        const LocalFrame local = localFrame({branch.centre[0] - b[0], branch.centre[1] - b[1], branch.centre[2] - b[2]});
        Vec3 force;
        for (int r = 0; r < 3; ++r) {
            force[r] = local.basis[r][0] * branch.force[0] + local.basis[r][1] * branch.force[1] + local.basis[r][2] * branch.force[2];
        }
        images(local.axial, [&](double s) {
            boundaryRadius_.push_back(local.radius);
            boundaryAxial_.push_back(s);
            boundaryForce_.push_back(force);
            boundaryLo.push_back({local.radius - reachAcross, 0.0, s - reachAlong});
            boundaryHi.push_back({local.radius + reachAcross, 0.0, s + reachAlong});
        });
    });
    const Vec3 cellSize{2 * reachAcross, 1.0, std::max(2 * reachAlong, 1e-12)};
    contactBins_.build(contactLo, contactHi, setup_.coordinates.resolvesAxes(), cellSize);
    boundaryBins_.build(boundaryLo, boundaryHi, setup_.coordinates.resolvesAxes(), cellSize);
}

void CylindricalCoarseGrainer::setFrame(const ParticleFrame& frame, const ContactFrame* contacts, const std::string& dataPath,
                                        const std::string& fstatPath) {
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
    const double length = frame.box.length(axis_);
    const bool periodicAxis = resolvesAxial && setup_.periodic[axis_] && length > 0;
    const long reach = periodicAxis ? periodicImagesEachSide(reachAlong, profile_.cutoff(), length, axis_,
                                                             dataPath + " line " + std::to_string(frame.headerLine))
                                    : 0;
    // Calls add(s) for the axial coordinate si and its images along a periodic axis whose support
    // overlaps the box.
    const auto images = [&](double si, const std::function<void(double)>& add) {
        for (long image = -reach; image <= reach; ++image) {
            const double s = si + double(image) * length;
            if (periodicAxis && !(s - reachAlong < frame.box.hi[axis_] && s + reachAlong > frame.box.lo[axis_])) continue;
            add(s);
        }
    };
    std::vector<Vec3> boxLo, boxHi;
    for (std::size_t p = 0; p < n; ++p) {
        const int s = frame.species[p];
        if (s >= layout_.species) {
            throw InputError(dataPath + " line " + std::to_string(frame.headerLine + 1 + static_cast<long>(p)) +
                             ": a particle of species " + std::to_string(s) + ", but densities are known for " +
                             std::to_string(layout_.species) + " species only (--density d0,d1,... or --restart)");
        }
        if ((!setup_.excluded.empty() && setup_.excluded[p]) || !frame.isOwned(p)) continue;
        const Vec3& v = frame.velocity[p];
        const LocalFrame local = localFrame(frame.position[p]);
        const double ri = local.radius;
        Vec3 u;
        for (int r = 0; r < 3; ++r) u[r] = local.basis[r][0] * v[0] + local.basis[r][1] * v[1] + local.basis[r][2] * v[2];
        const double volume = frame.volumeOf(p);
        images(local.axial, [&](double si) {
            radius_.push_back(ri);
            axial_.push_back(si);
            mass_.push_back(frame.massOf(p, setup_.speciesDensity[s]));
            volume_.push_back(volume);
            velocity_.push_back(u);
            species_.push_back(s);
            boxLo.push_back({ri - reachAcross, 0.0, si - reachAlong});
            boxHi.push_back({ri + reachAcross, 0.0, si + reachAlong});
        });
    }
    const Vec3 cellSize{2 * reachAcross, 1.0, std::max(2 * reachAlong, 1e-12)};
    bins_.build(boxLo, boxHi, c.resolvesAxes(), cellSize);
    contactRadius_.clear();
    contactAxial_.clear();
    contactTensor_.clear();
    boundaryRadius_.clear();
    boundaryAxial_.clear();
    boundaryForce_.clear();
    if (setup_.contactStress && contacts != nullptr) {
        setContacts(frame, *contacts, reachAcross, reachAlong, images, dataPath, fstatPath);
    } else {
        contactBins_.build({}, {}, c.resolvesAxes(), cellSize);
        boundaryBins_.build({}, {}, c.resolvesAxes(), cellSize);
    }
}

void CylindricalCoarseGrainer::evaluate(const std::vector<Vec3>& points, std::vector<double>& sums) const {
    const int fields = layout_.count();
    sums.assign(points.size() * fields, 0.0);
    const int angular = layout_.angularMomentumIndex();
    for (std::size_t p = 0; p < points.size(); ++p) {
        const double r = points[p][0], s = points[p][2];
        if (!(r >= 0)) throw InputError("--points: the distance r from the axis must be 0 or more, found " + str(r));
        double* row = sums.data() + p * fields;
        const auto range = bins_.sourcesNear(points[p]);
        for (const std::uint32_t* it = range.begin; it != range.end; ++it) {
            const std::uint32_t i = *it;
            const AngularMoments c = momentsAt(r, s, radius_[i], axial_[i]);
            if (c.c0 == 0 && c.c1 == 0 && c.c2 == 0) continue;
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
        if (!layout_.contactStress) continue;
        // A tensor T (local components at its source) averaged over the circle: with e_r(theta) =
        // cos(phi) e_r' + sin(phi) e_theta', the cos^2 and sin^2 means are (C0 +- C2)/2, cos and
        // sin means C1 and 0 (Documentation/CoarseGraining.md "Cylindrical coordinates").
        double* stress = row + layout_.contactStressIndex();
        const auto contacts = contactBins_.sourcesNear(points[p]);
        for (const std::uint32_t* it = contacts.begin; it != contacts.end; ++it) {
            const AngularMoments c = momentsAt(r, s, contactRadius_[*it], contactAxial_[*it]);
            if (c.c0 == 0 && c.c1 == 0 && c.c2 == 0) continue;
            const double plus = 0.5 * scale_ * (c.c0 + c.c2), minus = 0.5 * scale_ * (c.c0 - c.c2);
            const double c0 = scale_ * c.c0, c1 = scale_ * c.c1;
            const auto& t = contactTensor_[*it];  // rr rt rs tr tt ts sr st ss
            stress[0] += t[0] * plus + t[4] * minus;
            stress[1] += t[1] * plus - t[3] * minus;
            stress[2] += t[2] * c1;
            stress[3] += t[3] * plus - t[1] * minus;
            stress[4] += t[0] * minus + t[4] * plus;
            stress[5] += t[5] * c1;
            stress[6] += t[6] * c1;
            stress[7] += t[7] * c1;
            stress[8] += t[8] * c0;
        }
        double* force = row + layout_.interactionForceIndex();
        const auto boundary = boundaryBins_.sourcesNear(points[p]);
        for (const std::uint32_t* it = boundary.begin; it != boundary.end; ++it) {
            const AngularMoments c = momentsAt(r, s, boundaryRadius_[*it], boundaryAxial_[*it]);
            force[0] += boundaryForce_[*it][0] * scale_ * c.c1;
            force[1] += boundaryForce_[*it][1] * scale_ * c.c1;
            force[2] += boundaryForce_[*it][2] * scale_ * c.c0;
        }
    }
}

AngularMoments CylindricalCoarseGrainer::momentsAt(double r, double s, double ri, double si) const {
    const double inverseCross = 1.0 / crossWidth_, inverseAlong = 1.0 / axialWidth_;
    const double dr = (r - ri) * inverseCross;
    const double ds = setup_.coordinates.resolves(2) ? (s - si) * inverseAlong : 0.0;
    const double m2 = dr * dr + ds * ds;
    if (m2 >= profile_.cutoffSquared()) return {};
    return angularMoments(profile_, m2, r * ri * inverseCross * inverseCross);
}

}  // namespace talus::cg
