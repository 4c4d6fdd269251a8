// Automatic choice of anisotropic widths (Theory/CoarseGraining.md eq. (1), Denissen
// 2019, sec. 4.2.2, the thesis's figure 4.5): a field is evaluated at a few points for every pair
// (wa, wb) of diagonal widths of two directions on a log grid; where it does not change with the
// widths it is a property of the flow, not of the kernel. The rule (Documentation/CoarseGraining.md
// "Choosing the widths"):
//
//  1. A width pair is *trusted* at a point when the density there is positive, the kernel's
//     support holds at least `minParticles` particle centres, and both scanned widths are at
//     least `minWidth` (default in talus-cg: the mean particle diameter). A kernel narrower
//     than the particles resolves single particles or single layers, whose values can be flat
//     without being continuum values: phi = 1 inside one small particle, or phi = 0 along one
//     layer of large particles, however wide the kernel is along the layer.
//  2. Its *sensitivity* s is the largest change of the field towards a trusted neighbour of the
//     scan grid (the 4 neighbours in log wa and log wb), per decade of width, divided by a scale
//     F: s = max_n |f_n - f| / |log10 w_n - log10 w| / F. F = 1 for concentrations and the volume
//     fraction (fractions), else the largest |f| of the point's trusted pairs (relative change).
//     The largest one-sided difference, not a central difference, so that noise that alternates
//     from one width to the next counts. No trusted neighbour: s = infinity.
//  3. *Insensitive*: trusted and s <= tolerance. The *plateau* is the largest axis-aligned
//     rectangle of the scan grid (most width pairs; the first found on ties) in which every pair
//     is insensitive at every point: a region common to all points, as the thesis's red rectangles.
//  4. The chosen widths are its centre in log coordinates: w = sqrt(w_lo w_hi) per direction.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "Fields/CoarseGrainer.h"

namespace talus::cg {

// `count` widths from `min` to `max`, equally spaced in log10 w.
std::vector<double> logSpacedWidths(double min, double max, long count);

struct WidthScanRequest {
    CoarseGrainingSetup setup;      // kernel, coordinates, densities, periodic, excluded; widths replaced
    Vec3 baseWidths{1, 1, 1};       // the widths of the direction not scanned
    std::array<int, 2> axes{0, 2};  // the two scanned directions (0 = x, 1 = y, 2 = z)
    std::array<std::vector<double>, 2> widths;  // the widths of each scanned direction
    std::vector<Vec3> points;
    int field = 0;                  // index into derivedColumns(layout)
    bool fractionField = true;      // concentration or volume fraction: scale F = 1
    double tolerance = 0.05;
    long minParticles = 10;
    double minWidth = 0;            // scanned widths below it are not trusted
};

// The scan of one point: index i * nb + j for widths[0][i], widths[1][j].
struct PointScan {
    std::vector<double> value;        // the field (NaN where the density is 0)
    std::vector<double> particles;    // particle centres in the support (mean over frames)
    std::vector<bool> trusted;
    std::vector<double> sensitivity;  // NaN where not trusted
    std::vector<bool> insensitive;
    double scale = 1;                 // F
};

struct WidthPlateau {
    bool found = false;
    long first[2] = {0, 0};   // index range [first[0], first[1]] along widths[0]
    long second[2] = {0, 0};  // along widths[1]
    double chosen[2] = {0, 0};
    long pairs = 0;           // width pairs in the rectangle
};

struct WidthScanResult {
    std::vector<PointScan> points;
    WidthPlateau plateau;
    std::vector<double> chosenValue;  // the field at the chosen widths per point (when found)
};

// Evaluates the scan over the frames (the sums averaged over them, as --time-average) and
// applies the rule above. `contacts` may be empty (no contact stress) or hold one frame per
// particle frame. `progress(done, total)` is called after each width pair.
WidthScanResult scanWidths(const WidthScanRequest& request, const std::vector<ParticleFrame>& frames,
                           const std::vector<ContactFrame>& contacts,
                           const std::function<void(long, long)>& progress = {});

// Steps 2 to 4 alone, on values already computed (for tests of the rule).
void markSensitivity(const std::array<std::vector<double>, 2>& widths, double tolerance, bool fractionField, PointScan& scan);
WidthPlateau largestCommonPlateau(const std::array<std::vector<double>, 2>& widths, const std::vector<PointScan>& points);

}  // namespace talus::cg
