#include "Fields/DepthAverage.h"

#include <algorithm>

namespace talus::cg {

std::vector<OutputColumn> depthAveragedColumns(const FieldSums& layout) {
    std::vector<OutputColumn> columns{{"MassPerArea", "M/L^2"},
                                      {"BulkDensity", "M/L^3"},
                                      {"Height", "L"},
                                      {"SolidHeight", "L"},
                                      {"DepthAveragedVelocityX", "L/T"},
                                      {"DepthAveragedVelocityY", "L/T"},
                                      {"DepthAveragedVelocityZ", "L/T"}};
    for (int s = 0; s < layout.species; ++s) columns.push_back({"DepthAveragedConcentration_s" + std::to_string(s), "1"});
    return columns;
}

DepthAverageCoverage depthAverage(const FieldSums& layout, const std::vector<double>& sums, long pointsPerColumn,
                                  double dz, std::optional<double> bulkDensity, std::vector<std::vector<double>>& rows) {
    DepthAverageCoverage coverage;
    const int fields = layout.count();
    const std::size_t points = sums.size() / fields;
    for (std::size_t first = 0; first + pointsPerColumn <= points; first += pointsPerColumn) {
        double mass = 0, massSquared = 0, solid = 0, momentum[3] = {0, 0, 0}, peak = 0;
        std::vector<double> speciesMass(layout.species, 0.0);
        for (long k = 0; k < pointsPerColumn; ++k) {
            const double* row = sums.data() + (first + k) * fields;
            const double rho = row[FieldSums::density];
            mass += rho * dz;
            massSquared += rho * rho * dz;
            solid += row[FieldSums::volumeFraction] * dz;
            for (int c = 0; c < 3; ++c) momentum[c] += row[FieldSums::momentum + c] * dz;
            for (int s = 0; s < layout.species; ++s) speciesMass[s] += row[layout.speciesDensityIndex(s)] * dz;
            peak = std::max(peak, rho);
        }
        const double top = sums[(first + pointsPerColumn - 1) * fields + FieldSums::density];
        if (peak > 0) coverage.topDensityRatio = std::max(coverage.topDensityRatio, top / peak);
        const double rhoBulk = bulkDensity ? *bulkDensity : (mass > 0 ? massSquared / mass : 0.0);
        std::vector<double> values{mass, rhoBulk, rhoBulk > 0 ? mass / rhoBulk : 0.0, solid};
        for (int c = 0; c < 3; ++c) values.push_back(mass > 0 ? momentum[c] / mass : 0.0);
        for (int s = 0; s < layout.species; ++s) {
            values.push_back(mass > 0 ? std::clamp(speciesMass[s] / mass, 0.0, 1.0) : 0.0);
        }
        rows.push_back(std::move(values));
    }
    return coverage;
}

}  // namespace talus::cg
