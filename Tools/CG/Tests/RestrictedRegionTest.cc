// CoarseGrainer::restrictTo: the sources that reach none of an object's points are left out of
// its frames, and its sums are bitwise those of the whole frame, on every path (along one axis,
// cell lists with periodic images, contacts between particles and with a wall as a boundary).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/EvaluationPoints.h"
#include "IO/InputError.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

const DomainBox box{{0, 0, -0.5}, {6, 4, 6}};

// Spheres dropped at random into the box (periodic in x and y) above a wall z = 0, and a contact
// line for each overlapping pair (nearest images) and each sphere that reaches the wall, with the
// geometry of the .fstat format and random forces.
void randomBedWithContacts(ParticleFrame& frame, ContactFrame& contacts) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> x(0, 6), y(0, 4), z(0.3, 5.5), unit(-1, 1);
    std::vector<Vec3> position, velocity;
    std::vector<double> radius;
    for (int i = 0; i < 400; ++i) {
        position.push_back({x(random), y(random), z(random)});
        velocity.push_back({unit(random), unit(random), unit(random)});
        radius.push_back(i % 2 ? 0.5 : 0.4);
    }
    frame = makeFrame(position, radius, box, velocity, std::vector<int>(position.size(), 0));
    contacts.contacts.clear();
    contacts.eachContactOnce = true;
    const double length[2] = {6, 4};
    for (std::size_t i = 0; i < position.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            Vec3 d;  // from j to i, nearest image
            for (int k = 0; k < 3; ++k) {
                d[k] = position[i][k] - position[j][k];
                if (k < 2) d[k] -= length[k] * std::round(d[k] / length[k]);
            }
            const double distance = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            const double overlap = radius[i] + radius[j] - distance;
            if (overlap <= 0 || overlap > 0.2) continue;  // (deep overlaps of random spheres left out)
            const Vec3 n{d[0] / distance, d[1] / distance, d[2] / distance};
            const double toPoint = radius[i] - 0.5 * overlap;
            const Vec3 point{position[i][0] - toPoint * n[0], position[i][1] - toPoint * n[1],
                             position[i][2] - toPoint * n[2]};
            contacts.contacts.push_back(contactLine(static_cast<long>(i), static_cast<long>(j), point, n, overlap,
                                                    {unit(random), unit(random), 1 + unit(random)}));
        }
        const double overlap = radius[i] - position[i][2];
        if (overlap > 0) {
            const Vec3 point{position[i][0], position[i][1], -0.5 * overlap};
            contacts.contacts.push_back(contactLine(static_cast<long>(i), -1, point, {0, 0, -1}, overlap,
                                                    {unit(random), unit(random), 2}));
        }
    }
}

CoarseGrainer grainerOf(const std::string& coordinates) {
    CoarseGrainingSetup setup;
    setup.shape = KernelShape::Lucy;
    setup.coordinates = Coordinates::fromName(coordinates);
    setup.width = WidthMatrix::isotropic(0.6);
    setup.speciesDensity = {1.9};
    setup.periodic = {true, true, false};
    setup.contactStress = true;
    return CoarseGrainer(setup);
}

}  // namespace

TEST(RestrictedRegion, SumsAreBitwiseThoseOfTheWholeFrameFromFewerSources) {
    ParticleFrame frame;
    ContactFrame contacts;
    randomBedWithContacts(frame, contacts);
    ASSERT_GT(contacts.contacts.size(), 200u);
    struct Case {
        std::string coordinates;
        std::vector<Vec3> points;
    };
    // One point at the base, a short profile within the bed, a patch of an XZ field reaching
    // across the periodic faces (x near 0 and 6).
    const std::vector<Case> cases{
        {"Z", {{0, 0, 0.5}}},
        {"Z", gridPoints(Coordinates::fromName("Z"), {1, 1, 9}, {0, 0, 1.5}, {0, 0, 2.5})},
        {"XZ", gridPoints(Coordinates::fromName("XZ"), {7, 1, 4}, {0, 0, 0.2}, {6, 0, 1.1})},
        {"XZ", gridPoints(Coordinates::fromName("XZ"), {3, 1, 3}, {0.1, 0, 3}, {0.9, 0, 3.6})},
    };
    for (const Case& c : cases) {
        CoarseGrainer whole = grainerOf(c.coordinates), restricted = grainerOf(c.coordinates);
        restricted.restrictTo(c.points);
        whole.setFrame(frame, &contacts);
        restricted.setFrame(frame, &contacts);
        std::vector<double> expected, sums;
        whole.evaluate(c.points, expected);
        restricted.evaluate(c.points, sums);
        ASSERT_EQ(sums.size(), expected.size());
        for (std::size_t k = 0; k < sums.size(); ++k) {
            EXPECT_EQ(sums[k], expected[k]) << c.coordinates << " sum " << k;  // (bitwise)
        }
        // The stress is there (the test is not of empty sums), and fewer sources made it.
        double largest = 0;
        for (double s : sums) largest = std::max(largest, std::abs(s));
        EXPECT_GT(largest, 0.1) << c.coordinates;
        EXPECT_LT(restricted.particleSourceCount(), whole.particleSourceCount() / 2) << c.coordinates;
        EXPECT_LT(restricted.contactSourceCount(), whole.contactSourceCount() / 2) << c.coordinates;
    }
}

TEST(RestrictedRegion, PointsOutsideTheRegionAreRefused) {
    ParticleFrame frame;
    ContactFrame contacts;
    randomBedWithContacts(frame, contacts);
    CoarseGrainer grainer = grainerOf("Z");
    grainer.restrictTo({{0, 0, 1}, {0, 0, 2}});
    grainer.setFrame(frame, &contacts);
    std::vector<double> sums;
    EXPECT_NO_THROW(grainer.evaluate({{0, 0, 1.5}}, sums));
    const std::string message = errorOf([&] { grainer.evaluate({{0, 0, 2.5}}, sums); });
    EXPECT_NE(message.find("outside the points"), std::string::npos) << message;
    // Restricted to no points: the whole frame again.
    grainer.restrictTo({});
    grainer.setFrame(frame, &contacts);
    EXPECT_NO_THROW(grainer.evaluate({{0, 0, 4}}, sums));
}
