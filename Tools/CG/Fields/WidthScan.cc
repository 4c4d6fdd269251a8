#include "Fields/WidthScan.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "Fields/DerivedFields.h"
#include "IO/InputError.h"

namespace talus::cg {

namespace {

constexpr double notANumber = std::numeric_limits<double>::quiet_NaN();

// Particle centres of a frame inside the support |A (x - r)| < R of a diagonal kernel with
// widths w (zero on averaged axes), periodic images included (Theory/CoarseGraining.md: the same
// sources as CoarseGrainer::setFrame).
long particlesInSupport(const ParticleFrame& frame, const std::vector<bool>& excluded, const Vec3& point, const Vec3& w,
                        double cutoff, const std::array<bool, 3>& periodic) {
    std::array<std::vector<double>, 3> shifts;
    for (int k = 0; k < 3; ++k) {
        shifts[k] = {0.0};
        const double length = frame.box.length(k);
        if (w[k] > 0 && periodic[k] && length > 0) {
            const long reach = periodicImagesEachSide(cutoff * w[k], cutoff, length, k, "width scan");
            for (long n = 1; n <= reach; ++n) {
                shifts[k].push_back(double(n) * length);
                shifts[k].push_back(-double(n) * length);
            }
        }
    }
    const double cutoff2 = cutoff * cutoff;
    long count = 0;
    std::array<std::vector<double>, 3> q2;  // (u_k)^2 of the images within the cut-off, per axis
    for (std::size_t p = 0; p < frame.size(); ++p) {
        if (!excluded.empty() && excluded[p]) continue;
        bool any = true;
        for (int k = 0; k < 3 && any; ++k) {
            q2[k].clear();
            for (double s : shifts[k]) {
                const double u = w[k] > 0 ? (frame.position[p][k] + s - point[k]) / w[k] : 0.0;
                if (u * u < cutoff2) q2[k].push_back(u * u);
            }
            any = !q2[k].empty();
        }
        if (!any) continue;
        for (double a : q2[0])
            for (double b : q2[1])
                for (double c : q2[2]) count += a + b + c < cutoff2 ? 1 : 0;
    }
    return count;
}

}  // namespace

std::vector<double> logSpacedWidths(double min, double max, long count) {
    if (!(min > 0) || !(max > min) || count < 2) {
        throw InputError("width scan: a range needs 0 < MIN < MAX and COUNT >= 2, found " + str(min) + " " + str(max) + " " +
                         std::to_string(count));
    }
    std::vector<double> widths;
    const double a = std::log10(min), b = std::log10(max);
    for (long i = 0; i < count; ++i) widths.push_back(std::pow(10.0, a + (b - a) * double(i) / double(count - 1)));
    widths.back() = max;
    widths.front() = min;
    return widths;
}

void markSensitivity(const std::array<std::vector<double>, 2>& widths, double tolerance, bool fractionField, PointScan& scan) {
    const long na = static_cast<long>(widths[0].size()), nb = static_cast<long>(widths[1].size());
    scan.scale = 1;
    if (!fractionField) {
        double largest = 0;
        for (long c = 0; c < na * nb; ++c) {
            if (scan.trusted[c]) largest = std::max(largest, std::abs(scan.value[c]));
        }
        if (largest > 0) scan.scale = largest;
    }
    scan.sensitivity.assign(na * nb, notANumber);
    scan.insensitive.assign(na * nb, false);
    for (long i = 0; i < na; ++i) {
        for (long j = 0; j < nb; ++j) {
            const long c = i * nb + j;
            if (!scan.trusted[c]) continue;
            double s = -1;
            auto neighbour = [&](long ni, long nj) {
                if (ni < 0 || nj < 0 || ni >= na || nj >= nb || !scan.trusted[ni * nb + nj]) return;
                const double decades = ni != i ? std::abs(std::log10(widths[0][ni] / widths[0][i]))
                                               : std::abs(std::log10(widths[1][nj] / widths[1][j]));
                s = std::max(s, std::abs(scan.value[ni * nb + nj] - scan.value[c]) / decades / scan.scale);
            };
            neighbour(i - 1, j);
            neighbour(i + 1, j);
            neighbour(i, j - 1);
            neighbour(i, j + 1);
            scan.sensitivity[c] = s < 0 ? std::numeric_limits<double>::infinity() : s;
            scan.insensitive[c] = scan.sensitivity[c] <= tolerance;
        }
    }
}

WidthPlateau largestCommonPlateau(const std::array<std::vector<double>, 2>& widths, const std::vector<PointScan>& points) {
    const long na = static_cast<long>(widths[0].size()), nb = static_cast<long>(widths[1].size());
    // Largest rectangle of common insensitive pairs: per row i of the first direction, the
    // height h[j] of the run of such pairs ending at i, then the largest rectangle under that
    // histogram with a stack (O(na nb)).
    std::vector<long> height(nb, 0);
    WidthPlateau best;
    for (long i = 0; i < na; ++i) {
        for (long j = 0; j < nb; ++j) {
            bool common = true;
            for (const PointScan& p : points) common = common && p.insensitive[i * nb + j];
            height[j] = common ? height[j] + 1 : 0;
        }
        std::vector<long> stack;
        for (long j = 0; j <= nb; ++j) {
            const long h = j < nb ? height[j] : 0;
            while (!stack.empty() && height[stack.back()] >= h) {
                const long top = stack.back();
                stack.pop_back();
                const long left = stack.empty() ? 0 : stack.back() + 1;
                const long area = height[top] * (j - left);
                if (area > best.pairs) {
                    best.found = true;
                    best.pairs = area;
                    best.first[0] = i - height[top] + 1;
                    best.first[1] = i;
                    best.second[0] = left;
                    best.second[1] = j - 1;
                }
            }
            stack.push_back(j);
        }
    }
    if (best.found) {
        best.chosen[0] = std::sqrt(widths[0][best.first[0]] * widths[0][best.first[1]]);
        best.chosen[1] = std::sqrt(widths[1][best.second[0]] * widths[1][best.second[1]]);
    }
    return best;
}

WidthScanResult scanWidths(const WidthScanRequest& request, const std::vector<ParticleFrame>& frames,
                           const std::vector<ContactFrame>& contacts, const std::function<void(long, long)>& progress) {
    if (frames.empty()) throw InputError("width scan: no frame to scan");
    const long na = static_cast<long>(request.widths[0].size()), nb = static_cast<long>(request.widths[1].size());
    const std::size_t np = request.points.size();
    WidthScanResult result;
    result.points.resize(np);
    for (PointScan& p : result.points) {
        p.value.assign(na * nb, notANumber);
        p.particles.assign(na * nb, 0.0);
        p.trusted.assign(na * nb, false);
    }
    CoarseGrainingSetup setup = request.setup;
    std::vector<double> sums, average, values;

    // The field at the points for diagonal widths w (sums averaged over the frames).
    auto evaluate = [&](const Vec3& w, std::vector<double>& field, std::vector<double>* count) {
        setup.width = WidthMatrix::diagonal(w[0], w[1], w[2]);
        CoarseGrainer grainer(setup);
        const FieldSums& layout = grainer.layout();
        average.assign(np * layout.count(), 0.0);
        if (count) count->assign(np, 0.0);
        Vec3 resolved{0, 0, 0};
        for (int k = 0; k < 3; ++k) resolved[k] = setup.coordinates.resolves(k) ? w[k] : 0.0;
        for (std::size_t f = 0; f < frames.size(); ++f) {
            grainer.setFrame(frames[f], contacts.empty() ? nullptr : &contacts[f]);
            grainer.evaluate(request.points, sums);
            for (std::size_t k = 0; k < sums.size(); ++k) average[k] += sums[k] / double(frames.size());
            if (count) {
                for (std::size_t p = 0; p < np; ++p) {
                    (*count)[p] += double(particlesInSupport(frames[f], setup.excluded, request.points[p], resolved,
                                                             grainer.profile().cutoff(), setup.periodic)) /
                                   double(frames.size());
                }
            }
        }
        field.assign(np, notANumber);
        for (std::size_t p = 0; p < np; ++p) {
            values.clear();
            const double* row = average.data() + p * layout.count();
            appendDerivedFields(layout, row, values);
            if (request.field < 0 || request.field >= static_cast<int>(values.size())) {
                throw InputError("width scan: field index " + std::to_string(request.field) + " beyond the " +
                                 std::to_string(values.size()) + " fields");
            }
            if (row[FieldSums::density] > 0) field[p] = values[request.field];
        }
    };

    std::vector<double> field, count;
    // Widest first along the first direction: wide kernels have the most periodic images and
    // cost the most, so a progress estimate from the pairs done errs on the safe side.
    long done = 0;
    for (long i = na - 1; i >= 0; --i) {
        for (long j = 0; j < nb; ++j) {
            Vec3 w = request.baseWidths;
            w[request.axes[0]] = request.widths[0][i];
            w[request.axes[1]] = request.widths[1][j];
            evaluate(w, field, &count);
            for (std::size_t p = 0; p < np; ++p) {
                PointScan& scan = result.points[p];
                scan.value[i * nb + j] = field[p];
                scan.particles[i * nb + j] = count[p];
                scan.trusted[i * nb + j] = !std::isnan(field[p]) && count[p] >= double(request.minParticles) &&
                                           request.widths[0][i] >= request.minWidth && request.widths[1][j] >= request.minWidth;
            }
            if (progress) progress(++done, na * nb);
        }
    }
    for (PointScan& scan : result.points) markSensitivity(request.widths, request.tolerance, request.fractionField, scan);
    result.plateau = largestCommonPlateau(request.widths, result.points);
    if (result.plateau.found) {
        Vec3 w = request.baseWidths;
        w[request.axes[0]] = result.plateau.chosen[0];
        w[request.axes[1]] = result.plateau.chosen[1];
        evaluate(w, result.chosenValue, nullptr);
    }
    return result;
}

}  // namespace talus::cg
