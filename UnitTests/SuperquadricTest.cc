// The superquadric shape (Kernel/Shapes/Superquadric.h) against closed forms (spheres,
// ellipsoids), independent numerical integration (blocky shapes), finite differences and
// samples of the parametric surface.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "Error.h"
#include "Shapes/Superquadric.h"

using namespace talus;

namespace {

// Tanh-sinh (double-exponential) quadrature of g over [0, L]: exact to round-off for the
// power-law endpoint singularities of a superquadric's profile (x^e near its edge), where
// Gauss rules converge slowly. Step h = 1/64 over |t| <= 4.
double tanhSinh(const std::function<double(double)>& g, double L) {
    const double h = 1.0 / 64;
    double sum = 0;
    for (int k = -256; k <= 256; ++k) {
        const double t = k * h, u = 0.5 * pi * std::sinh(t);
        const double x = 0.5 * L * (1 + std::tanh(u));
        const double weight = 0.5 * L * 0.5 * pi * std::cosh(t) / (std::cosh(u) * std::cosh(u));
        if (x <= 0 || x >= L || weight == 0) continue;
        sum += weight * g(x);
    }
    return h * sum;
}

// Volume and second moments of the solid by integration over its octant: z from 0 to
// zTop(x, y) = c (1 - nu^(e2/e1))^(e1/2), y from 0 to b (1 - (x/a)^(2/e2))^(e2/2).
struct Moments {
    double volume, xx, yy, zz;  // integrals of 1, x^2, y^2, z^2 over the solid
};
Moments integrate(double a, double b, double c, double e1, double e2) {
    Moments m{};
    auto over = [&](auto weight) {
        return 8 * tanhSinh([&](double x) {
                   const double yTop = b * std::pow(1 - std::pow(x / a, 2 / e2), e2 / 2);
                   return tanhSinh([&](double y) {
                       const double nu = std::pow(x / a, 2 / e2) + std::pow(y / b, 2 / e2);
                       const double zTop = c * std::pow(std::max(0.0, 1 - std::pow(nu, e2 / e1)), e1 / 2);
                       return weight(x, y, zTop);
                   }, yTop);
               }, a);
    };
    m.volume = over([](double, double, double z) { return z; });
    m.xx = over([](double x, double, double z) { return x * x * z; });
    m.yy = over([](double, double y, double z) { return y * y * z; });
    m.zz = over([](double, double, double z) { return z * z * z / 3; });
    return m;
}

double signedPower(double v, double e) { return (v < 0 ? -1 : 1) * std::pow(std::abs(v), e); }

// A point of the parametric surface at latitude eta and longitude omega.
Vec3 surfacePoint(const Superquadric& s, double eta, double omega) {
    const double ce = signedPower(std::cos(eta), s.e1());
    return Vec3(s.a() * ce * signedPower(std::cos(omega), s.e2()), s.b() * ce * signedPower(std::sin(omega), s.e2()),
                s.c() * signedPower(std::sin(eta), s.e1()));
}

const Superquadric shapes[] = {{1, 1, 1, 1, 1},      {0.5, 1, 2, 1, 1},     {1, 0.7, 0.4, 0.3, 0.3},
                               {0.6, 1.2, 0.9, 0.5, 0.8}, {1, 1, 3, 0.1, 1},   {2, 0.3, 0.5, 1, 0.1},
                               {1, 2, 0.5, 0.8, 0.4}};

}  // namespace

TEST(Superquadric, SphereAndEllipsoidVolumeAndInertiaAreTheClosedForms) {
    const double density = 6 / pi;
    const Superquadric sphere = Superquadric::sphere(0.5);
    EXPECT_NEAR(sphere.volume(), pi / 6, 1e-12 * pi / 6);
    const double m = density * pi / 6;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sphere.principalInertia(density)[k], 0.4 * m * 0.25, 1e-12 * m);
    const double a = 0.5, b = 1, c = 2;
    const Superquadric ellipsoid = Superquadric::ellipsoid(a, b, c);
    const double volume = 4 * pi / 3 * a * b * c, mass = density * volume;
    EXPECT_NEAR(ellipsoid.volume(), volume, 1e-12 * volume);
    const Vec3 I = ellipsoid.principalInertia(density), expected = mass / 5 * Vec3(b * b + c * c, a * a + c * c, a * a + b * b);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(I[k], expected[k], 1e-12 * expected[k]);
}

TEST(Superquadric, BlockyVolumeAndInertiaMatchNumericalIntegration) {
    for (const Superquadric& s : shapes) {
        const Moments m = integrate(s.a(), s.b(), s.c(), s.e1(), s.e2());
        EXPECT_NEAR(s.volume(), m.volume, 1e-10 * m.volume) << s.a() << ' ' << s.e1() << ' ' << s.e2();
        const double density = 1.3;
        const Vec3 I = s.principalInertia(density), expected = density * Vec3(m.yy + m.zz, m.xx + m.zz, m.xx + m.yy);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(I[k], expected[k], 1e-10 * expected[k]) << "axis " << k;
    }
}

TEST(Superquadric, BoundingRadiusBoundsEverySurfacePointAndIsReached) {
    for (const Superquadric& s : shapes) {
        double largest = 0;
        const int n = 400;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                const Vec3 x = surfacePoint(s, 0.5 * pi * i / n, 0.5 * pi * j / n);
                EXPECT_NEAR(s.shapeFunction(x), 0, 1e-9);
                largest = std::max(largest, x.norm());
            }
        EXPECT_LE(largest, s.boundingRadius() * (1 + 1e-14));
        EXPECT_GE(largest, 0.99 * s.boundingRadius());
        if (s.isEllipsoid()) {
            EXPECT_DOUBLE_EQ(s.boundingRadius(), s.semiAxes().maxCoeff());
        }
        EXPECT_LE(s.boundingRadius(), s.semiAxes().norm());  // the loose bound of Theory/Superquadrics.md "Volume, inertia, bounding radius"
    }
}

TEST(Superquadric, GradientAndHessianMatchFiniteDifferences) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    for (const Superquadric& s : shapes) {
        for (int trial = 0; trial < 200; ++trial) {
            const Vec3 x(coordinate(random) * s.a(), coordinate(random) * s.b(), coordinate(random) * s.c());
            const ShapeValue v = s.evaluate(x);
            EXPECT_NEAR(v.value, s.shapeFunction(x), 1e-12 * (1 + std::abs(v.value)));
            for (int k = 0; k < 3; ++k) {
                // Central differences with a step scaled to the point: error O(h^2) f''' .
                const double h = 1e-5 * s.semiAxes()[k];
                Vec3 up = x, down = x;
                up[k] += h, down[k] -= h;
                const double slope = (s.shapeFunction(up) - s.shapeFunction(down)) / (2 * h);
                EXPECT_NEAR(v.gradient[k], slope, 1e-5 * (1 + std::abs(slope)));
                const Vec3 curvature = (s.gradient(up) - s.gradient(down)) / (2 * h);
                for (int l = 0; l < 3; ++l)
                    EXPECT_NEAR(v.hessian(l, k), curvature[l], 1e-4 * (1 + curvature.cwiseAbs().maxCoeff()));
            }
        }
    }
}

TEST(Superquadric, EllipsoidDerivativesAreTheClosedForms) {
    const Superquadric e = Superquadric::ellipsoid(0.5, 1, 2);
    const Vec3 x(0.3, -0.2, 1.1);
    const ShapeValue v = e.evaluate(x);
    EXPECT_NEAR(v.value, 0.36 + 0.04 + 0.3025 - 1, 1e-15);
    EXPECT_TRUE(v.gradient.isApprox(Vec3(2 * 0.3 / 0.25, 2 * -0.2, 2 * 1.1 / 4), 1e-15));
    EXPECT_TRUE(v.hessian.isApprox(Vec3(8, 2, 0.5).asDiagonal().toDenseMatrix(), 1e-15));
}

TEST(Superquadric, FurthestPointLiesOnTheSurfaceWithItsNormalAlongTheDirection) {
    std::mt19937_64 random(11);
    std::normal_distribution<double> gauss;
    for (const Superquadric& s : shapes) {
        std::vector<Vec3> directions = {Vec3::UnitX(), -Vec3::UnitY(), Vec3::UnitZ(), Vec3(1, 1, 0).normalized(),
                                        Vec3(0, 1, 1e-9).normalized(), Vec3(1e-12, 0, -1).normalized()};
        for (int k = 0; k < 300; ++k) directions.push_back(Vec3(gauss(random), gauss(random), gauss(random)).normalized());
        for (const Vec3& n : directions) {
            const Vec3 x = s.furthestPointAlong(n);
            EXPECT_NEAR(s.shapeFunction(x), 0, 1e-12);
            const Vec3 normal = s.gradient(x);
            // Parallel to n where the surface is smooth (on its edges, e < 1 with x or z = 0,
            // the normal cone is wider and any n in it is valid).
            if (normal.norm() > 0 && x.cwiseAbs().minCoeff() > 1e-6) {
                EXPECT_LT(normal.normalized().cross(n).norm(), 1e-9) << n.transpose();
            }
            // No surface sample lies further along n.
            double furthest = -INFINITY;
            for (int i = 0; i <= 60; ++i)
                for (int j = 0; j <= 120; ++j)
                    furthest = std::max(furthest, n.dot(surfacePoint(s, pi * (i / 60.0 - 0.5), 2 * pi * j / 120.0)));
            EXPECT_GE(n.dot(x), furthest - 1e-12);
        }
    }
}

TEST(Superquadric, BadParametersAreNamed) {
    auto message = [](auto make) {
        try {
            make();
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message([] { Superquadric(0, 1, 1, 1, 1); }).find("semi-axis a"), std::string::npos);
    EXPECT_NE(message([] { Superquadric(1, -2, 1, 1, 1); }).find("semi-axis b"), std::string::npos);
    EXPECT_NE(message([] { Superquadric(1, 1, NAN, 1, 1); }).find("semi-axis c"), std::string::npos);
    EXPECT_NE(message([] { Superquadric(1, 1, 1, 0, 1); }).find("e1"), std::string::npos);
    EXPECT_NE(message([] { Superquadric(1, 1, 1, 1, 1.5); }).find("e2"), std::string::npos);
    EXPECT_NE(message([] { Superquadric(1, 1, 1, 1, NAN); }).find("e2"), std::string::npos);
}
