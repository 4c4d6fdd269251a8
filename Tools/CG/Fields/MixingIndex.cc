#include "Fields/MixingIndex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "Fields/CoarseGrainer.h"
#include "Fields/EvaluationPoints.h"
#include "IO/InputError.h"

namespace talus::cg {

MixingIndices mixingIndices(const FieldSums& layout, const std::vector<Vec3>& points, const std::vector<double>& sums,
                            const Coordinates& coordinates, int species) {
    if (species < 0 || species >= layout.species) {
        throw InputError("--mixing: species " + std::to_string(species) + " is not one of the " +
                         std::to_string(layout.species) + " species (0 to " + std::to_string(layout.species - 1) + ")");
    }
    const int fields = layout.count();
    double mass = 0, speciesMass = 0, entropy = 0;
    Vec3 moment{0, 0, 0};
    for (std::size_t p = 0; p < points.size(); ++p) {
        const double* row = sums.data() + p * fields;
        const double rho = row[FieldSums::density];
        if (!(rho > 0)) continue;
        const double phi = std::clamp(row[layout.speciesDensityIndex(species)] / rho, 0.0, 1.0);
        // Theory/CoarseGraining.md eq. (13)-(16): m = phi ln phi + (1 - phi) ln(1 - phi), with 0 ln
        // 0 = 0.
        double m = 0;
        if (phi > 0) m += phi * std::log(phi);
        if (phi < 1) m += (1 - phi) * std::log1p(-phi);
        entropy += rho * m;
        mass += rho;
        speciesMass += row[layout.speciesDensityIndex(species)];
        for (int k = 0; k < 3; ++k) moment[k] += rho * points[p][k];
    }
    if (!(mass > 0)) throw InputError("--mixing: no mass at the evaluation points, the mixing index is undefined");
    MixingIndices result;
    result.mixing = entropy < 0 ? -entropy / (std::numbers::ln2 * mass) : 0.0;  // (m <= 0; not -0 for one kind)
    for (int k = 0; k < 3; ++k) result.centre[k] = coordinates.resolves(k) ? moment[k] / mass : 0.0;
    double speciesDistance = 0, materialDistance = 0;
    for (std::size_t p = 0; p < points.size(); ++p) {
        const double* row = sums.data() + p * fields;
        double d2 = 0;
        for (int k = 0; k < 3; ++k) {
            if (coordinates.resolves(k)) d2 += (points[p][k] - result.centre[k]) * (points[p][k] - result.centre[k]);
        }
        const double d = std::sqrt(d2);
        materialDistance += std::max(row[FieldSums::density], 0.0) * d;
        speciesDistance += std::max(row[layout.speciesDensityIndex(species)], 0.0) * d;
    }
    result.materialDistance = materialDistance / mass;
    result.speciesDistance = speciesMass > 0 ? speciesDistance / speciesMass : 0.0;
    result.speciesAtCore = speciesMass > 0 && result.speciesDistance < result.materialDistance;
    result.segregation = result.speciesAtCore ? result.mixing - 1 : 1 - result.mixing;
    // One kind alone (the species has no mass at the points, or all of it): M = 0, but there is
    // no mixture whose kinds could be at the core or the periphery.
    if (!(speciesMass > 0) || speciesMass == mass) result.segregation = std::numeric_limits<double>::quiet_NaN();
    return result;
}

MixingIndices frameMixingIndices(const ParticleFrame& frame, const CoarseGrainingSetup& setup,
                                 const std::array<long, 3>& count, const Vec3& lo, const Vec3& hi, int species) {
    CoarseGrainer grainer(setup);
    grainer.setFrame(frame, nullptr);
    const std::vector<Vec3> points = gridPoints(setup.coordinates, count, lo, hi);
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    return mixingIndices(grainer.layout(), points, sums, setup.coordinates, species);
}

}  // namespace talus::cg
