#include "Fields/CoarseGrainer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <unordered_map>

#include "Fields/ContactBranches.h"
#include "IO/InputError.h"
#include "Kernels/RadialShapes.h"

namespace talus::cg {

namespace {

std::string lineOf(const std::string& path, long line) { return path + " line " + std::to_string(line); }

// u = A d: a distance d in units of the (anisotropic) widths, A the inverse width matrix in rows.
template <class Matrix>
void inWidths(const Matrix& a, const double d[3], double u[3]) {
    for (int r = 0; r < 3; ++r) u[r] = a[3 * r] * d[0] + a[3 * r + 1] * d[1] + a[3 * r + 2] * d[2];
}

Vec3 shifted(Vec3 v, const Vec3& shift) {
    for (int k = 0; k < 3; ++k) v[k] += shift[k];
    return v;
}

}  // namespace

CoarseGrainer::CoarseGrainer(CoarseGrainingSetup setup)
    // (The domain average O has no kernel; its profile, of dimension 1, is never evaluated.)
    : setup_(std::move(setup)), profile_(setup_.shape, std::max(1, setup_.coordinates.kernelDimension())) {
    if (setup_.coordinates.isCylindrical()) {
        cylindrical_ = std::make_unique<CylindricalCoarseGrainer>(setup_);
        layout_ = cylindrical_->layout();
        return;
    }
    if (!setup_.coordinates.isDomainAverage()) setup_.width.restrictTo(setup_.coordinates);
    if (setup_.speciesDensity.empty()) throw InputError("--density: at least one species density is needed");
    for (double rho : setup_.speciesDensity) {
        if (!(rho > 0) || !std::isfinite(rho)) throw InputError("--density: densities must be positive, found " + str(rho));
    }
    layout_.species = static_cast<int>(setup_.speciesDensity.size());
    layout_.contactStress = setup_.contactStress;
    for (int k = 0; k < 3; ++k) {
        halfExtent_[k] = setup_.coordinates.resolves(k) ? setup_.width.supportHalfExtent(k, profile_.cutoff()) : 0.0;
    }
    restrictTo({});
}

void CoarseGrainer::restrictTo(const std::vector<Vec3>& points) {
    const double infinity = std::numeric_limits<double>::infinity();
    regionLo_ = pointsLo_ = {-infinity, -infinity, -infinity};
    regionHi_ = pointsHi_ = {infinity, infinity, infinity};
    if (points.empty() || cylindrical_ || setup_.coordinates.isDomainAverage()) return;
    for (int k = 0; k < 3; ++k) {
        if (!setup_.coordinates.resolves(k)) continue;  // (sources reach every point along an averaged axis)
        const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                                  [k](const Vec3& a, const Vec3& b) { return a[k] < b[k]; });
        pointsLo_[k] = (*lo)[k];
        pointsHi_[k] = (*hi)[k];
        // (Widened by far more than the round-off of a support's ends: a source kept in vain
        // costs a little time, one left out in error would change a sum.)
        const double slack = 1e-9 * std::max({std::abs(pointsLo_[k]), std::abs(pointsHi_[k]), halfExtent_[k], 1.0});
        regionLo_[k] = pointsLo_[k] - slack;
        regionHi_[k] = pointsHi_[k] + slack;
    }
}

long periodicImagesEachSide(double reach, double cutoff, double length, int axis, const std::string& where) {
    if (!(reach <= maxReachInPeriodicLengths * length)) {
        const std::string letter(1, axisLetter(axis));
        throw InputError(where + ": along the periodic " + letter + " axis the kernel reaches " + str(reach) +
                         " from a particle (cut off at " + str(cutoff) + " times the width), " + str(reach / length) +
                         " times the periodic length " + str(length) + " of the domain; at most " +
                         str(maxReachInPeriodicLengths) +
                         " periodic lengths are supported (every one adds two images of each particle): average over " +
                         letter + " (--coordinates), narrow the kernel (--width) or check the domain in the file");
    }
    return static_cast<long>(std::ceil(reach / length)) + 1;
}

void CoarseGrainer::imageShifts(const Vec3& lo, const Vec3& hi, const DomainBox& box,
                                std::vector<Vec3>& shifts) const {
    shifts.assign(1, Vec3{0, 0, 0});
    for (int k = 0; k < 3; ++k) {
        if (imagesEachSide_[k] == 0) continue;
        // Every image whose support overlaps the periodic box (a kernel wider than the box
        // needs several).
        const double length = box.length(k);
        const long reach = imagesEachSide_[k];
        std::vector<Vec3> next;
        for (const Vec3& shift : shifts) {
            for (long n = -reach; n <= reach; ++n) {
                const double s = double(n) * length;
                if (lo[k] + s < box.hi[k] && hi[k] + s > box.lo[k]) {
                    Vec3 image = shift;
                    image[k] = s;
                    next.push_back(image);
                }
            }
        }
        if (!next.empty()) shifts = std::move(next);
    }
}

void CoarseGrainer::setExcluded(std::vector<bool> excluded) {
    if (cylindrical_) cylindrical_->setExcluded(excluded);
    setup_.excluded = std::move(excluded);
}

void CoarseGrainer::setFrame(const ParticleFrame& frame, const ContactFrame* contacts,
                             const std::string& dataPath, const std::string& fstatPath) {
    if (!frame.mass.empty() && frame.mass.size() != frame.size())
        throw InputError("the frame at t = " + str(frame.time) + " has " + std::to_string(frame.size()) +
                         " particles but " + std::to_string(frame.mass.size()) + " masses");
    if (cylindrical_) {
        cylindrical_->setFrame(frame, contacts, dataPath, fstatPath);
        return;
    }
    const std::size_t n = frame.size();
    scale_ = (setup_.coordinates.isDomainAverage() ? 1.0 : setup_.width.determinant()) / setup_.coordinates.averagedLength(frame.box);
    if (!setup_.excluded.empty() && setup_.excluded.size() != n) {
        throw InputError(lineOf(dataPath, frame.headerLine) + ": the frame at t = " + str(frame.time) + " has " +
                         std::to_string(n) + " particles, but the restart file describes " +
                         std::to_string(setup_.excluded.size()) +
                         ": its fixed particles cannot be matched (drop --fixed exclude or boundary)");
    }
    for (int k = 0; k < 3; ++k) {
        const double length = frame.box.length(k);
        const bool images = setup_.periodic[k] && setup_.coordinates.resolves(k) && length > 0;
        imagesEachSide_[k] = images ? periodicImagesEachSide(halfExtent_[k], profile_.cutoff(), length, k,
                                                             lineOf(dataPath, frame.headerLine))
                                    : 0;
    }
    position_.clear();
    velocity_.clear();
    mass_.clear();
    volume_.clear();
    species_.clear();
    // The support boxes go to scratch vectors kept from frame to frame (fresh memory costs page
    // faults at every frame).
    std::vector<Vec3>& boxLo = boxLo_;
    std::vector<Vec3>& boxHi = boxHi_;
    boxLo.clear();
    boxHi.clear();
    position_.reserve(n);
    velocity_.reserve(n);
    mass_.reserve(n);
    volume_.reserve(n);
    species_.reserve(n);
    boxLo.reserve(n);
    boxHi.reserve(n);
    std::vector<Vec3> shifts;
    for (std::size_t p = 0; p < n; ++p) {
        const int s = frame.species[p];
        if (s >= layout_.species) {
            throw InputError(lineOf(dataPath, frame.headerLine + 1 + static_cast<long>(p)) + ": a particle of species " +
                             std::to_string(s) + ", but densities are known for " + std::to_string(layout_.species) +
                             " species only (--density d0,d1,... or --restart)");
        }
        if ((!setup_.excluded.empty() && setup_.excluded[p]) || !frame.isOwned(p)) continue;
        const double volume = frame.volumeOf(p);
        Vec3 lo, hi;
        for (int k = 0; k < 3; ++k) {
            lo[k] = frame.position[p][k] - halfExtent_[k];
            hi[k] = frame.position[p][k] + halfExtent_[k];
        }
        imageShifts(lo, hi, frame.box, shifts);
        for (const Vec3& shift : shifts) {
            Vec3 x = frame.position[p];
            for (int k = 0; k < 3; ++k) {
                x[k] += shift[k];
                lo[k] = x[k] - halfExtent_[k];
                hi[k] = x[k] + halfExtent_[k];
            }
            if (!meetsRegion(lo, hi)) continue;
            position_.push_back(x);
            velocity_.push_back(frame.velocity[p]);
            mass_.push_back(frame.massOf(p, setup_.speciesDensity[s]));
            volume_.push_back(volume);
            species_.push_back(s);
            boxLo.push_back(lo);
            boxHi.push_back(hi);
        }
    }
    Vec3 cellSize;
    for (int k = 0; k < 3; ++k) cellSize[k] = std::max(2 * halfExtent_[k], 1e-12);
    const bool binned = !alongOneAxis();
    if (binned) particleBins_.build(boxLo, boxHi, setup_.coordinates.resolvesAxes(), cellSize);

    contactStart_.clear();
    contactSegment_.clear();
    contactForce_.clear();
    boundaryPoint_.clear();
    boundaryForce_.clear();
    if (setup_.contactStress && contacts != nullptr) {
        addContacts(frame, *contacts, dataPath, fstatPath, cellSize);
    } else if (binned) {
        contactBins_.build({}, {}, setup_.coordinates.resolvesAxes(), cellSize);
        boundaryBins_.build({}, {}, setup_.coordinates.resolvesAxes(), cellSize);
    }
}

void CoarseGrainer::addContacts(const ParticleFrame& frame, const ContactFrame& contacts, const std::string& dataPath,
                                const std::string& fstatPath, const Vec3& cellSize) {
    // Mostly one source per line (more only for images across periodic faces).
    contactStart_.reserve(contacts.contacts.size());
    contactSegment_.reserve(contacts.contacts.size());
    contactForce_.reserve(contacts.contacts.size());
    std::vector<Vec3>& segmentLo = boxLo_;
    std::vector<Vec3>& segmentHi = boxHi_;
    segmentLo.clear();
    segmentHi.clear();
    std::vector<Vec3> pointLo, pointHi, shifts;
    // A branch's ends lie within a (bounding) radius and an overlap of its contact point, so
    // within 2R of it (R the largest radius); along an axis without images a line whose point is
    // farther than 2R + the support's half-extent from the region of restrictTo has no source
    // there: it is skipped unformed.
    double largestRadius = 0;
    for (double r : frame.radius) largestRadius = std::max(largestRadius, r);
    Vec3 wantedLo, wantedHi;
    bool restricted = false;
    for (int k = 0; k < 3; ++k) {
        const bool bounded = imagesEachSide_[k] == 0 && std::isfinite(regionLo_[k]);
        const double reach = 2 * largestRadius + halfExtent_[k];
        wantedLo[k] = bounded ? regionLo_[k] - reach : -std::numeric_limits<double>::infinity();
        wantedHi[k] = bounded ? regionHi_[k] + reach : std::numeric_limits<double>::infinity();
        restricted = restricted || bounded;
    }
    const auto nearRegion = [&](const Vec3& c) {
        for (int k = 0; k < 3; ++k) {
            if (c[k] < wantedLo[k] || c[k] > wantedHi[k]) return false;
        }
        return true;
    };
    forEachContactBranch(frame, contacts, setup_, dataPath, fstatPath, [&](const ContactBranch& branch) {
        const Vec3& xm = branch.centre;
        const Vec3& b = branch.branch;
        Vec3 lo, hi;
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(xm[k], xm[k] - b[k]) - halfExtent_[k];
            hi[k] = std::max(xm[k], xm[k] - b[k]) + halfExtent_[k];
        }
        imageShifts(lo, hi, frame.box, shifts);
        for (const Vec3& shift : shifts) {
            if (!meetsRegion(shifted(lo, shift), shifted(hi, shift))) continue;
            contactStart_.push_back(shifted(xm, shift));
            contactSegment_.push_back({-b[0], -b[1], -b[2]});
            contactForce_.push_back(branch.force);
            segmentLo.push_back(shifted(lo, shift));
            segmentHi.push_back(shifted(hi, shift));
        }
        if (!branch.boundary) return;
        // The boundary's force on the flowing particle, spread from the contact point x_m - b
        // (the image of c next to x_m).
        const Vec3 point{xm[0] - b[0], xm[1] - b[1], xm[2] - b[2]};
        for (int k = 0; k < 3; ++k) {
            lo[k] = point[k] - halfExtent_[k];
            hi[k] = point[k] + halfExtent_[k];
        }
        imageShifts(lo, hi, frame.box, shifts);
        for (const Vec3& shift : shifts) {
            if (!meetsRegion(shifted(lo, shift), shifted(hi, shift))) continue;
            boundaryPoint_.push_back(shifted(point, shift));
            boundaryForce_.push_back(branch.force);
            pointLo.push_back(shifted(lo, shift));
            pointHi.push_back(shifted(hi, shift));
        }
    }, restricted ? std::function<bool(const Vec3&)>(nearRegion) : nullptr);
    if (alongOneAxis()) return;
    contactBins_.build(segmentLo, segmentHi, setup_.coordinates.resolvesAxes(), cellSize);
    boundaryBins_.build(pointLo, pointHi, setup_.coordinates.resolvesAxes(), cellSize);
}

template <class Profile, bool Diagonal>
void CoarseGrainer::evaluateParticles(const std::vector<Vec3>& points, std::vector<double>& sums) const {
    const Profile shape;
    const int fields = layout_.count();
    const auto& a = setup_.width.a();
    const double weightScale = scale_ * profile_.normalisation();
    for (std::size_t p = 0; p < points.size(); ++p) {
        double* row = sums.data() + p * fields;
        const Vec3& r = points[p];
        double rho = 0, nu = 0, m[3] = {0, 0, 0}, k[6] = {0, 0, 0, 0, 0, 0};
        const auto range = particleBins_.sourcesNear(r);
        for (const std::uint32_t* it = range.begin; it != range.end; ++it) {
            const std::uint32_t i = *it;
            const double d0 = r[0] - position_[i][0], d1 = r[1] - position_[i][1], d2 = r[2] - position_[i][2];
            double q2;
            if constexpr (Diagonal) {
                // A = diag(1/w): three products, not a matrix-vector product.
                const double u0 = a[0] * d0, u1 = a[4] * d1, u2 = a[8] * d2;
                q2 = u0 * u0 + u1 * u1 + u2 * u2;
            } else {
                const double d[3] = {d0, d1, d2};
                double u[3];
                inWidths(a, d, u);
                q2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
            }
            if (q2 >= Profile::cutoffSquared) continue;
            const double w = weightScale * shape(q2);
            const double mw = mass_[i] * w;
            const Vec3& v = velocity_[i];
            rho += mw;
            nu += volume_[i] * w;
            m[0] += mw * v[0];
            m[1] += mw * v[1];
            m[2] += mw * v[2];
            k[0] += mw * v[0] * v[0];
            k[1] += mw * v[0] * v[1];
            k[2] += mw * v[0] * v[2];
            k[3] += mw * v[1] * v[1];
            k[4] += mw * v[1] * v[2];
            k[5] += mw * v[2] * v[2];
            row[FieldSums::speciesDensity + species_[i]] += mw;
        }
        row[FieldSums::density] = rho;
        row[FieldSums::volumeFraction] = nu;
        for (int c = 0; c < 3; ++c) row[FieldSums::momentum + c] = m[c];
        for (int c = 0; c < 6; ++c) row[FieldSums::momentumFlux + c] = k[c];
    }
}

void CoarseGrainer::evaluateContacts(const std::vector<Vec3>& points, std::vector<double>& sums) const {
    const int fields = layout_.count();
    const int first = layout_.contactStressIndex();
    const auto& a = setup_.width.a();
    for (std::size_t p = 0; p < points.size(); ++p) {
        double* row = sums.data() + p * fields + first;
        const auto range = contactBins_.sourcesNear(points[p]);
        for (const std::uint32_t* it = range.begin; it != range.end; ++it) {
            const std::uint32_t c = *it;
            // u(s) = A (r - x_i - s segment) = u0 + s e
            const double d[3] = {points[p][0] - contactStart_[c][0], points[p][1] - contactStart_[c][1],
                                 points[p][2] - contactStart_[c][2]};
            const double g[3] = {-contactSegment_[c][0], -contactSegment_[c][1], -contactSegment_[c][2]};
            double u0[3], e[3];
            inWidths(a, d, u0);
            inWidths(a, g, e);
            const double line = profile_.lineIntegral(u0, e);
            if (line == 0) continue;
            const double w = scale_ * line;
            addContactTensor(c, w, row);
        }
    }
}

void CoarseGrainer::contactTensor(std::size_t c, double (&tensor)[9]) const {
    // The tensor f (x) b of the branch, b = -segment.
    const Vec3& f = contactForce_[c];
    const Vec3& segment = contactSegment_[c];
    for (int r = 0; r < 3; ++r) {
        for (int col = 0; col < 3; ++col) tensor[3 * r + col] = f[r] * -segment[col];
    }
}

void CoarseGrainer::addContactTensor(std::size_t c, double weight, double* row) const {
    double tensor[9];
    contactTensor(c, tensor);
    for (int t = 0; t < 9; ++t) row[t] += weight * tensor[t];
}

void CoarseGrainer::evaluateBoundaryForces(const std::vector<Vec3>& points, std::vector<double>& sums) const {
    const int fields = layout_.count();
    const int first = layout_.interactionForceIndex();
    const auto& a = setup_.width.a();
    for (std::size_t p = 0; p < points.size(); ++p) {
        double* row = sums.data() + p * fields + first;
        const auto range = boundaryBins_.sourcesNear(points[p]);
        for (const std::uint32_t* it = range.begin; it != range.end; ++it) {
            const std::uint32_t c = *it;
            const double d[3] = {points[p][0] - boundaryPoint_[c][0], points[p][1] - boundaryPoint_[c][1],
                                 points[p][2] - boundaryPoint_[c][2]};
            double u[3];
            inWidths(a, d, u);
            const double q2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
            const double w = scale_ * profile_.value(q2);
            for (int k = 0; k < 3; ++k) row[k] += w * boundaryForce_[c][k];
        }
    }
}

void CoarseGrainer::evaluateDomainAverage(double* row) const {
    // Every source with the weight 1/V (scale_): the sums of eq. (5)-(10) with W replaced by the
    // indicator of the box over its volume and the line integral by 1 (whole branches).
    for (std::size_t i = 0; i < mass_.size(); ++i) {
        FieldSums::addParticle(row, mass_[i] * scale_, volume_[i] * scale_, velocity_[i], species_[i]);
    }
    if (!setup_.contactStress) return;
    for (std::size_t c = 0; c < contactForce_.size(); ++c) addContactTensor(c, scale_, row + layout_.contactStressIndex());
    for (const Vec3& f : boundaryForce_) {
        for (int k = 0; k < 3; ++k) row[layout_.interactionForceIndex() + k] += scale_ * f[k];
    }
}

void CoarseGrainer::evaluate(const std::vector<Vec3>& points, std::vector<double>& sums) const {
    if (cylindrical_) {
        cylindrical_->evaluate(points, sums);
        return;
    }
    for (const Vec3& r : points) {
        for (int k = 0; k < 3; ++k) {
            if (r[k] < pointsLo_[k] || r[k] > pointsHi_[k]) {
                throw InputError("the point (" + str(r[0]) + ", " + str(r[1]) + ", " + str(r[2]) +
                                 ") lies outside the points this coarse graining was restricted to (restrictTo)");
            }
        }
    }
    sums.assign(points.size() * layout_.count(), 0.0);
    if (setup_.coordinates.isDomainAverage()) {
        // One value for the whole box, the same at every point asked for.
        const std::size_t fields = static_cast<std::size_t>(layout_.count());
        if (points.empty()) return;
        evaluateDomainAverage(sums.data());
        for (std::size_t p = 1; p < points.size(); ++p) std::copy_n(sums.data(), fields, sums.data() + p * fields);
        return;
    }
    if (alongOneAxis()) {
        evaluateAlongOneAxis(points, sums);
        return;
    }
    const bool diagonal = setup_.width.isDiagonal();
    switch (setup_.shape) {
        case KernelShape::Lucy:
            diagonal ? evaluateParticles<LucyShape, true>(points, sums) : evaluateParticles<LucyShape, false>(points, sums);
            break;
        case KernelShape::Gauss:
            diagonal ? evaluateParticles<GaussShape, true>(points, sums) : evaluateParticles<GaussShape, false>(points, sums);
            break;
        case KernelShape::Heaviside:
            diagonal ? evaluateParticles<HeavisideShape, true>(points, sums)
                     : evaluateParticles<HeavisideShape, false>(points, sums);
            break;
    }
    if (setup_.contactStress) {
        evaluateContacts(points, sums);
        evaluateBoundaryForces(points, sums);
    }
}

}  // namespace talus::cg
