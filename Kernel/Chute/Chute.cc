#include "Chute/Chute.h"

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "Boundaries/Domain.h"
#include "Boundaries/InsertionBoundary.h"
#include "Error.h"
#include "Sampling/Messages.h"
#include "Sampling/ParticleSums.h"

namespace talus {

namespace {

// Random sequential addition of equal spheres in a periodic slab, with a cell grid of one
// diameter so that each attempt looks at 27 cells only.
std::vector<Vec3> disorderedLayer(const Domain& domain, double diameter, double thickness, std::uint64_t seed) {
    const double length = domain.length(0), width = domain.length(1);
    const int nx = std::max(1, static_cast<int>(length / diameter)), ny = std::max(1, static_cast<int>(width / diameter));
    const double cellX = length / nx, cellY = width / ny;  // >= diameter
    std::vector<std::vector<std::size_t>> cells(static_cast<std::size_t>(nx) * ny);
    const PeriodicImage image(domain);
    std::vector<Vec3> centres;
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const auto cellOf = [&](double x, double y) {
        const int ix = std::min(nx - 1, static_cast<int>((x - domain.lo.x()) / cellX));
        const int iy = std::min(ny - 1, static_cast<int>((y - domain.lo.y()) / cellY));
        return std::pair{ix, iy};
    };
    const auto overlaps = [&](const Vec3& x) {
        const auto [ix, iy] = cellOf(x.x(), x.y());
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy) {
                const std::size_t cell = static_cast<std::size_t>((ix + dx + nx) % nx) * ny + (iy + dy + ny) % ny;
                for (std::size_t k : cells[cell])
                    if (image.nearest(x - centres[k]).squaredNorm() < diameter * diameter) return true;
            }
        return false;
    };
    // Random sequential addition approaches its jamming limit slowly; 100 failed attempts in a row
    // per unit area (in diameters squared) get within a few percent of it (coverage 0.565 of the
    // floor on 20 x 10, against 0.526 after 1000 and 0.593 after 10^6 failures in a row).
    const long attemptsInARow = std::max(1000L, std::lround(100 * length * width / (diameter * diameter)));
    for (long failures = 0; failures < attemptsInARow;) {
        const Vec3 x(domain.lo.x() + length * unit(random), domain.lo.y() + width * unit(random),
                     thickness * (unit(random) - 0.5));
        if (overlaps(x)) {
            ++failures;
            continue;
        }
        failures = 0;
        const auto [ix, iy] = cellOf(x.x(), x.y());
        cells[static_cast<std::size_t>(ix) * ny + iy].push_back(centres.size());
        centres.push_back(x);
    }
    return centres;
}

}  // namespace

void Chute::setChuteAngle(double degreesAngle) {
    require(std::isfinite(degreesAngle) && degreesAngle > -90 && degreesAngle < 90,
            "chute angle (--angle) must lie in (-90, 90) degrees, got " + str(degreesAngle));
    angle_ = degreesAngle;
    scene().setGravity(gravityMagnitude_ * Vec3(std::sin(degrees(angle_)), 0, -std::cos(degrees(angle_))));
}

double Chute::chuteAngle() const {
    const Vec3& g = scene().gravity();
    return std::atan2(g.x(), -g.z()) * 180 / pi;
}

void Chute::setGravityMagnitude(double g) {
    require(std::isfinite(g) && g > 0, "gravity magnitude must be positive, got " + str(g));
    gravityMagnitude_ = g;
    setChuteAngle(angle_);
}

void Chute::setChuteGeometry(const ChuteGeometry& geometry) {
    require(geometry.length > 0 && geometry.width > 0 && geometry.height > 0,
            "chute length, width and height must be positive, got " + str(geometry.length) + ", " +
                str(geometry.width) + ", " + str(geometry.height));
    geometry_ = geometry;
    geometrySet_ = true;
    scene().setDomain(Vec3(0, 0, -1), Vec3(geometry.length, geometry.width, geometry.height));
    scene().setPeriodic(geometry.periodicEnds, true, false);
}

std::size_t Chute::addBase(ChuteBase type, double diameter, std::size_t species, std::uint64_t seed,
                           double roughness) {
    require(geometrySet_, "chute base: call setChuteGeometry before addBase");
    require(std::isfinite(diameter) && diameter > 0, "chute base diameter must be positive, got " + str(diameter));
    require(roughness >= 0 && roughness <= 1, "chute base roughness must lie in [0, 1] diameters, got " + str(roughness));
    require(diameter <= geometry_.length && diameter <= geometry_.width,
            "chute base diameter " + str(diameter) + " is larger than the chute");
    // The domain reaches one diameter below the base, for output.
    scene().setDomain(Vec3(0, 0, -diameter), Vec3(geometry_.length, geometry_.width, geometry_.height));
    if (type == ChuteBase::flat) {
        scene().addWall(Vec3::UnitZ(), Vec3::Zero(), species);
        return 0;
    }
    std::vector<Vec3> centres;
    if (type == ChuteBase::ordered) {
        const int nx = static_cast<int>(geometry_.length / diameter), ny = static_cast<int>(geometry_.width / diameter);
        const double dx = geometry_.length / nx, dy = geometry_.width / ny;
        for (int ix = 0; ix < nx; ++ix)
            for (int iy = 0; iy < ny; ++iy) centres.emplace_back((ix + 0.5) * dx, (iy + 0.5) * dy, 0);
    } else {
        centres = disorderedLayer(scene().domain(), diameter, roughness * diameter, seed);
    }
    for (const Vec3& x : centres) scene().addFixedParticle(x, diameter / 2, species);
    // The safety floor: below every base particle.
    scene().addWall(Vec3::UnitZ(), Vec3(0, 0, -0.5 * (1 + roughness) * diameter), species);
    return centres.size();
}

double Chute::continueBase(std::size_t from, std::size_t to, double period, double xFrom, double xTo) {
    require(period > 0, "continueBase: the period must be positive");
    double added = 0;
    forEachSelected(*this, ofSpecies(from), [&](std::size_t i) {
        if (!scene().particles().fixed[i]) return;
        const Vec3 x = scene().particles().position[i];
        const double r = scene().particles().radius[i];
        for (int k = 1; x.x() + k * period < xTo; ++k)
            if (x.x() + k * period >= xFrom) scene().addFixedParticle(x + Vec3(k * period, 0, 0), r, to), ++added;
    });
    return ranks().sum(added);
}

void Chute::insertAtRest(std::size_t count, std::size_t species, double radius, const Vec3& lo, const Vec3& hi,
                         const std::string& what) {
    InsertionBoundary box(lo, hi, SizeDistribution::byNumber().add(species, radius));
    const InsertionReport report = box.insertCount(*this, count);
    say(*this, "%s\n", report.describe().c_str());
    require(report.complete, "could not place " + what + ": " + report.describe());
}

}  // namespace talus
