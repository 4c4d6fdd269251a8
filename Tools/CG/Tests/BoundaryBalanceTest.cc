// Fixed particles and walls as a boundary (Fields/CoarseGrainer.h "Boundaries"; Weinhart,
// Thornton, Luding and Bokhove 2012, Granular Matter 14) on a synthetic packing in exact static
// equilibrium under tilted gravity: a jittered simple-cubic lattice of flowing spheres on a layer
// of fixed spheres (two sites of the base replaced by a flat wall), periodic in x and y.
//
// The contact forces are built from the top down so that every flowing particle balances
// exactly: the load of particle i, L_i = m_i g + (forces from the partners above it), is carried
// by its partners below (flowing, fixed or the wall) in random shares. Fixed particles also touch
// each other, with arbitrary forces: the boundary must ignore those. Pairs are written once from
// a random side or from both sides, contacts with the base sometimes from the fixed side only.
//
// For such a packing the depth profile (Z coordinates, Lucy kernel) must satisfy at every height,
// base included (the particles are at rest: no kinetic stress, d(rho V)/dt = 0):
//   -d(sigma_xz)/dz + rho g_x + F_x = 0,   -d(sigma_zz)/dz + rho g_z + F_z = 0
// with F the InteractionForce density. Reason: d(sigma_az)/dz of the contact stress is exactly
// sum_contacts f_a [W(z - end) - W(z - start)], which with F moves every force to the centre of
// the flowing particle it acts on, where it cancels that particle's weight.
// The derivative is a central difference with step h = 1e-4: its error is at most
// h^2/6 max|sigma'''| with |sigma'''| <= sum |f| |W''| / area, |W''| <= 12 c_1 / w^3 = 15 / w^3
// (Lucy in 1-D), about 1e-7 of rho |g| here; round-off adds eps |sigma| / h ~ 1e-11. Tolerance
// 1e-6 of the largest rho |g|.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

constexpr double spacing = 0.9;         // lattice spacing (neighbours overlap, diagonals do not)
constexpr int sites = 4;                 // per periodic direction
constexpr int layers = 5;                // of flowing particles
constexpr double density = 2.0;
constexpr double gravity = 9.81;
const double angle = 24 * std::numbers::pi / 180;
const Vec3 g{gravity * std::sin(angle), 0, -gravity * std::cos(angle)};

struct Packing {
    ParticleFrame frame;
    ContactFrame contacts;
    std::vector<bool> fixed;
    double baseTop = 0;  // highest top (centre + radius) of a fixed particle
    double boundaryContactTop = 0;  // highest contact point with the fixed particles or the wall
};

double length() { return sites * spacing; }

Vec3 minimumImage(Vec3 d) {
    for (int k = 0; k < 2; ++k) d[k] -= length() * std::round(d[k] / length());
    return d;
}

ContactLine line(const Packing& p, long i, long j, const Vec3& forceOnI) {
    const Vec3 d = minimumImage({p.frame.position[i][0] - p.frame.position[j][0], p.frame.position[i][1] - p.frame.position[j][1],
                                 p.frame.position[i][2] - p.frame.position[j][2]});
    const double distance = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    ContactLine c;
    c.i = i;
    c.j = j;
    c.overlap = p.frame.radius[i] + p.frame.radius[j] - distance;
    for (int k = 0; k < 3; ++k) {
        c.normal[k] = d[k] / distance;
        c.point[k] = p.frame.position[i][k] - (p.frame.radius[i] - 0.5 * c.overlap) * c.normal[k];
    }
    c.force = forceOnI;
    return c;
}

Packing makePacking(unsigned seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> jitter(-0.02, 0.02), uniform(0, 1), radius(0.5, 0.52);
    Packing p;
    p.frame.box = DomainBox{{0, 0, -1}, {length(), length(), layers + 1.0}};
    const std::vector<std::pair<int, int>> wallSites{{1, 2}, {3, 0}};
    auto isWallSite = [&](int a, int b) { return std::find(wallSites.begin(), wallSites.end(), std::make_pair(a, b)) != wallSites.end(); };
    for (int layer = 0; layer <= layers; ++layer) {
        for (int a = 0; a < sites; ++a) {
            for (int b = 0; b < sites; ++b) {
                if (layer == 0 && isWallSite(a, b)) continue;
                p.frame.position.push_back({(a + 0.5) * spacing + jitter(random), (b + 0.5) * spacing + jitter(random),
                                            layer * spacing + jitter(random)});
                p.frame.radius.push_back(radius(random));
                p.fixed.push_back(layer == 0);
                if (layer == 0) p.baseTop = std::max(p.baseTop, p.frame.position.back()[2] + p.frame.radius.back());
            }
        }
    }
    const long n = static_cast<long>(p.frame.radius.size());
    p.frame.velocity.assign(n, Vec3{0, 0, 0});
    p.frame.species.assign(n, 0);

    // Contacts: every pair closer than the sum of radii.
    std::vector<std::vector<long>> partners(n);
    for (long i = 0; i < n; ++i) {
        for (long j = i + 1; j < n; ++j) {
            const Vec3 d = minimumImage({p.frame.position[i][0] - p.frame.position[j][0],
                                         p.frame.position[i][1] - p.frame.position[j][1],
                                         p.frame.position[i][2] - p.frame.position[j][2]});
            if (std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) < p.frame.radius[i] + p.frame.radius[j]) {
                partners[i].push_back(j);
                partners[j].push_back(i);
            }
        }
    }
    // Forces from the top down: force[{i, j}] is the force on i from j.
    std::vector<long> order;
    for (long i = 0; i < n; ++i) {
        if (!p.fixed[i]) order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](long a, long b) { return p.frame.position[a][2] > p.frame.position[b][2]; });
    std::vector<Vec3> load(n, Vec3{0, 0, 0});
    for (long i : order) {
        const double m = density * sphereVolume(p.frame.radius[i]);
        for (int k = 0; k < 3; ++k) load[i][k] += m * g[k];
        std::vector<long> below;
        for (long j : partners[i]) {
            if (p.frame.position[j][2] < p.frame.position[i][2]) below.push_back(j);
        }
        // The first layer over a wall site has no fixed particle straight below: the wall holds it.
        const bool baseBelow = std::any_of(below.begin(), below.end(), [&](long j) {
            return p.fixed[j] && std::abs(p.frame.position[j][0] - p.frame.position[i][0]) < 0.2 &&
                   std::abs(p.frame.position[j][1] - p.frame.position[i][1]) < 0.2;
        });
        const bool onWall = p.frame.position[i][2] < 1.5 * spacing && !baseBelow;
        std::vector<double> share(below.size() + (onWall ? 1 : 0));
        double total = 0;
        for (double& s : share) total += (s = 0.2 + uniform(random));
        for (std::size_t k = 0; k < below.size(); ++k) {
            const long j = below[k];
            Vec3 f;  // on i from j
            for (int a = 0; a < 3; ++a) f[a] = -share[k] / total * load[i][a];
            // j carries -f.
            for (int a = 0; a < 3; ++a) load[j][a] -= f[a];
            // Written from i only, from j only (force -f on j), or from both sides (contacts with
            // the base from the fixed side only in about a third of the cases).
            const double side = uniform(random), fromI = p.fixed[j] ? 0.4 : 0.5, fromJ = p.fixed[j] ? 0.7 : 0.8;
            if (side < fromI || side >= fromJ) p.contacts.contacts.push_back(line(p, i, j, f));
            if (side >= fromI) p.contacts.contacts.push_back(line(p, j, i, {-f[0], -f[1], -f[2]}));
            if (p.fixed[j]) p.boundaryContactTop = std::max(p.boundaryContactTop, p.contacts.contacts.back().point[2]);
        }
        if (onWall) {
            // A flat wall below i: contact point straight down at r - dn/2, normal into the wall.
            ContactLine c;
            c.i = i;
            c.j = -1;
            c.overlap = 0.01;
            c.normal = {0, 0, -1};
            c.point = p.frame.position[i];
            c.point[2] -= p.frame.radius[i] - 0.5 * c.overlap;
            for (int a = 0; a < 3; ++a) c.force[a] = -share.back() / total * load[i][a];
            p.contacts.contacts.push_back(c);
            p.boundaryContactTop = std::max(p.boundaryContactTop, c.point[2]);
        }
    }
    // The base particles press on each other with arbitrary forces (the base is held in place).
    for (long i = 0; i < n; ++i) {
        if (!p.fixed[i]) continue;
        for (long j : partners[i]) {
            if (j > i && p.fixed[j]) {
                p.contacts.contacts.push_back(line(p, i, j, {50 * uniform(random), 50 * uniform(random), 50 * uniform(random)}));
            }
        }
    }
    return p;
}

CoarseGrainingSetup depthSetup(const Packing& p, bool boundary) {
    CoarseGrainingSetup setup;
    setup.shape = KernelShape::Lucy;
    setup.coordinates = Coordinates::fromName("Z");
    setup.width = WidthMatrix::isotropic(1.0);
    setup.periodic = {true, true, false};
    setup.speciesDensity = {density};
    setup.contactStress = true;
    setup.excluded = p.fixed;
    setup.excludedAreBoundary = boundary;
    return setup;
}

std::vector<Vec3> heights(double lo, double hi, double step, double shift = 0) {
    std::vector<Vec3> points;
    for (double z = lo; z <= hi + 1e-12; z += step) points.push_back({0, 0, z + shift});
    return points;
}

}  // namespace

TEST(BoundaryBalance, PackingHasBoundaryContactsOfEveryKind) {
    const Packing p = makePacking(7);
    int wall = 0, fromFlowing = 0, fromFixed = 0, fixedPairs = 0;
    for (const ContactLine& c : p.contacts.contacts) {
        if (c.isWall()) ++wall;
        else if (p.fixed[c.i] && p.fixed[c.j]) ++fixedPairs;
        else if (p.fixed[c.j]) ++fromFlowing;
        else if (p.fixed[c.i]) ++fromFixed;
    }
    EXPECT_EQ(wall, 2);
    EXPECT_GT(fromFlowing, 5);
    EXPECT_GT(fromFixed, 5);
    EXPECT_GT(fixedPairs, 10);
}

TEST(BoundaryBalance, MomentumBalanceHoldsAtEveryHeightBaseIncluded) {
    for (unsigned seed : {7u, 8u}) {
        const Packing p = makePacking(seed);
        CoarseGrainer grainer(depthSetup(p, true));
        grainer.setFrame(p.frame, &p.contacts);
        const FieldSums& layout = grainer.layout();
        const int fields = layout.count();
        const double h = 1e-4;
        const std::vector<Vec3> points = heights(-2, layers + 1.5, 0.01);
        std::vector<double> at, above, below;
        grainer.evaluate(points, at);
        grainer.evaluate(heights(-2, layers + 1.5, 0.01, h), above);
        grainer.evaluate(heights(-2, layers + 1.5, 0.01, -h), below);
        double scale = 0;
        for (std::size_t q = 0; q < points.size(); ++q) scale = std::max(scale, at[q * fields + FieldSums::density] * gravity);
        double worst = 0, largestForce = 0;
        for (std::size_t q = 0; q < points.size(); ++q) {
            const double rho = at[q * fields + FieldSums::density];
            for (int a : {0, 1, 2}) {
                const int stress = layout.contactStressIndex() + 3 * a + 2;  // sigma_az
                const double divergence = (above[q * fields + stress] - below[q * fields + stress]) / (2 * h);
                const double force = at[q * fields + layout.interactionForceIndex() + a];
                largestForce = std::max(largestForce, std::abs(force));
                const double residual = -divergence + rho * g[a] + force;
                worst = std::max(worst, std::abs(residual) / scale);
            }
        }
        EXPECT_LT(worst, 1e-6) << "seed " << seed;
        // The boundary force is of the order of the weight density there, not a rounding error.
        EXPECT_GT(largestForce, 0.5 * scale) << "seed " << seed;
    }
}

TEST(BoundaryBalance, BasalFrictionIsTanTheta) {
    const Packing p = makePacking(9);
    CoarseGrainer grainer(depthSetup(p, true));
    grainer.setFrame(p.frame, &p.contacts);
    const FieldSums& layout = grainer.layout();
    const int fields = layout.count();
    // The traction of the base, t = integral of F dz: the kernel integrates to 1 over z, so with
    // Gauss-Legendre panels split at every kink of the Lucy profile (each contact point and its
    // support's ends) the integral is exact to round-off, and equals the base's total force per
    // area, which carries the weight: t = -(sum m) g / area (the packing is in equilibrium).
    std::vector<double> breaks;
    double weight = 0;
    for (const ContactLine& c : p.contacts.contacts) {
        for (double s : {-1.0, 0.0, 1.0}) breaks.push_back(c.point[2] + s);
    }
    for (std::size_t i = 0; i < p.fixed.size(); ++i) {
        if (!p.fixed[i]) weight += density * sphereVolume(p.frame.radius[i]);
    }
    // 8 nodes: a panel's map to u in [0, 1] (CGTestHelpers.h) turns the quartic into a polynomial
    // of degree 14, which 8 nodes integrate exactly.
    const GaussLegendre gl(8);
    std::vector<double> z, w;
    gl.panels(-2, 3, breaks, z, w);
    std::vector<Vec3> points;
    for (double x : z) points.push_back({0, 0, x});
    std::vector<double> sums;
    grainer.evaluate(points, sums);
    Vec3 traction{0, 0, 0};
    for (std::size_t q = 0; q < points.size(); ++q) {
        for (int a = 0; a < 3; ++a) traction[a] += w[q] * sums[q * fields + layout.interactionForceIndex() + a];
    }
    const double area = length() * length();
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(traction[a], -weight * g[a] / area, 1e-10 * weight * gravity / area) << a;
    EXPECT_NEAR(-traction[0] / traction[2], std::tan(angle), 1e-12);
    // Above the boundary layer (the kernel no longer reaches a boundary contact point) the stress
    // carries the weight above: sigma_az = -g_a (mass above per area), so -sigma_xz / sigma_zz
    // is tan(theta) at every height with load.
    const double lo = p.boundaryContactTop + 1.0;
    std::vector<double> profile;
    const std::vector<Vec3> column = heights(lo, lo + 2, 0.25);
    grainer.evaluate(column, profile);
    for (std::size_t q = 0; q < column.size(); ++q) {
        const double xz = profile[q * fields + layout.contactStressIndex() + 2];
        const double zz = profile[q * fields + layout.contactStressIndex() + 8];
        ASSERT_GT(zz, 0) << "z = " << column[q][2];
        EXPECT_NEAR(-xz / zz, std::tan(angle), 1e-10) << "z = " << column[q][2];
    }
}

TEST(BoundaryBalance, BoundaryAndExcludeAgreeBeyondTheKernelsReachOfTheBase) {
    const Packing p = makePacking(10);
    CoarseGrainer boundary(depthSetup(p, true)), exclude(depthSetup(p, false));
    boundary.setFrame(p.frame, &p.contacts);
    exclude.setFrame(p.frame, &p.contacts);
    const int fields = boundary.layout().count();
    ASSERT_EQ(fields, exclude.layout().count());
    // Where the two differ: segments from the contact points into the fixed centres, and the
    // forces of fixed particles, all below the top of the base; the kernel reaches 1 beyond.
    const double reach = p.baseTop + 1.0;
    const std::vector<Vec3> points = heights(-2, layers + 1.5, 0.05);
    std::vector<double> a, b;
    boundary.evaluate(points, a);
    exclude.evaluate(points, b);
    double largest = 0;
    for (double v : a) largest = std::max(largest, std::abs(v));
    bool differBelow = false;
    for (std::size_t q = 0; q < points.size(); ++q) {
        for (int f = 0; f < fields; ++f) {
            const double difference = std::abs(a[q * fields + f] - b[q * fields + f]);
            if (points[q][2] > reach) {
                EXPECT_LE(difference, 1e-12 * largest) << "z = " << points[q][2] << ", field " << f;
            } else if (difference > 1e-3 * largest) {
                differBelow = true;
            }
        }
    }
    EXPECT_TRUE(differBelow) << "the two treatments should differ near the base";
}
