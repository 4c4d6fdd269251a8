#include "Fields/EvaluationPoints.h"

#include "IO/InputError.h"
#include "IO/TextFile.h"

namespace talus::cg {

std::vector<Vec3> gridPoints(const Coordinates& coordinates, const std::array<long, 3>& count,
                             const Vec3& lo, const Vec3& hi) {
    std::array<long, 3> n{1, 1, 1};
    for (int k = 0; k < 3; ++k) {
        if (!coordinates.resolves(k)) continue;
        if (count[k] < 1) throw InputError("-n: the number of points along " + std::string(1, axisLetter(k)) + " must be at least 1");
        if (!(hi[k] > lo[k])) {
            throw InputError("-" + std::string(1, axisLetter(k)) + ": the range must have max > min, found " + str(lo[k]) + " " + str(hi[k]));
        }
        n[k] = count[k];
    }
    auto coordinate = [&](int k, long i) {
        return coordinates.resolves(k) ? lo[k] + (double(i) + 0.5) * (hi[k] - lo[k]) / double(n[k]) : 0.0;
    };
    std::vector<Vec3> points;
    points.reserve(n[0] * n[1] * n[2]);
    for (long i = 0; i < n[0]; ++i) {
        for (long j = 0; j < n[1]; ++j) {
            for (long k = 0; k < n[2]; ++k) points.push_back({coordinate(0, i), coordinate(1, j), coordinate(2, k)});
        }
    }
    return points;
}

std::vector<Vec3> readPointList(const std::string& path, const Coordinates& coordinates) {
    TextFile file(path);
    const auto axes = coordinates.kernelAxes();
    std::vector<Vec3> points;
    std::string line;
    std::vector<std::string_view> fields;
    while (file.nextLine(line)) {
        splitFields(line, fields);
        if (fields.empty() || fields[0].front() == '#') continue;
        Vec3 point{0, 0, 0};
        if (fields.size() == 3 && !coordinates.isCylindrical()) {
            for (int k = 0; k < 3; ++k) {
                point[k] = coordinates.resolves(k) ? parseReal(fields[k], file, std::string("coordinate ") + axisLetter(k)) : 0.0;
            }
        } else if (fields.size() == axes.size()) {
            for (std::size_t c = 0; c < axes.size(); ++c) {
                point[axes[c]] = parseReal(fields[c], file, "coordinate " + coordinates.coordinateName(axes[c]));
            }
        } else {
            file.fail((coordinates.isCylindrical() ? std::string("expected ") : "expected 3 coordinates (x y z) or ") +
                      std::to_string(axes.size()) + " (" + coordinates.name() + "), found " + std::to_string(fields.size()) +
                      " columns");
        }
        points.push_back(point);
    }
    if (points.empty()) throw InputError(path + ": no points in the point list");
    return points;
}

}  // namespace talus::cg
