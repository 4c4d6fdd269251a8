// Triangle meshes (Walls/TriangleMesh.h): merged vertices, edges and their triangles, normals,
// rigid motions and the checks of bad triangles; and the grid that finds the triangles near a
// sphere (Walls/TriangleGrid.h), against the brute-force list.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "TestHelpers.h"
#include "Walls/TriangleGrid.h"
#include "Walls/TriangleMesh.h"

using namespace talus;
using namespace talus::test;

namespace {

// The unit cube [0, 1]^3 as 12 triangles, corners counter-clockwise seen from outside (outward
// normals), each face split along the diagonal from its first to its third corner.
std::vector<TriangleCorners> unitCube() {
    auto at = [](int v) { return Vec3(v & 1, v >> 1 & 1, v >> 2 & 1); };  // corner v = x + 2 y + 4 z
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}};
    std::vector<TriangleCorners> triangles;
    for (const auto& f : faces) {
        triangles.push_back({at(f[0]), at(f[1]), at(f[2])});
        triangles.push_back({at(f[0]), at(f[2]), at(f[3])});
    }
    return triangles;
}

// An n x n grid of unit squares at height 0, each split in two along the diagonal from (i, j) to
// (i + 1, j + 1).
std::vector<TriangleCorners> squareGrid(int n) {
    std::vector<TriangleCorners> triangles;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3 p00(i, j, 0), p10(i + 1, j, 0), p11(i + 1, j + 1, 0), p01(i, j + 1, 0);
            triangles.push_back({p00, p10, p11});
            triangles.push_back({p00, p11, p01});
        }
    return triangles;
}

}  // namespace

// An n x n grid of squares has (n + 1)^2 vertices and 2 n (n + 1) sides plus n^2 diagonals as
// edges; the 4 n sides on the border belong to one triangle, the other edges to two. Corners that
// the triangles repeat, even 1e-12 apart (below the tolerance 1e-9 x the diagonal 3 sqrt(2)), are
// one vertex.
TEST(TriangleMesh, MergesRepeatedCornersIntoSharedVertices) {
    const int n = 3;
    std::vector<TriangleCorners> triangles = squareGrid(n);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> hair(-1e-12, 1e-12);
    for (TriangleCorners& c : triangles)
        for (Vec3& x : c) x += Vec3(hair(random), hair(random), hair(random));
    const TriangleMesh mesh(triangles);
    EXPECT_EQ(mesh.triangleCount(), std::size_t(2 * n * n));
    EXPECT_EQ(mesh.vertexCount(), std::size_t((n + 1) * (n + 1)));
    ASSERT_EQ(mesh.edgeCount(), std::size_t(2 * n * (n + 1) + n * n));
    int border = 0;
    for (std::size_t e = 0; e < mesh.edgeCount(); ++e) {
        const Vec3 a = mesh.vertex(mesh.edge(e)[0]), b = mesh.vertex(mesh.edge(e)[1]);
        const bool onBorder = (std::abs(a.x() - b.x()) < 1e-9 && (std::abs(a.x()) < 1e-9 || std::abs(a.x() - n) < 1e-9)) ||
                              (std::abs(a.y() - b.y()) < 1e-9 && (std::abs(a.y()) < 1e-9 || std::abs(a.y() - n) < 1e-9));
        border += onBorder;
        EXPECT_EQ(mesh.edgeTriangles(e).size(), onBorder ? 1u : 2u) << "edge " << a.transpose() << " - " << b.transpose();
    }
    EXPECT_EQ(border, 4 * n);
    EXPECT_NEAR(mesh.tolerance(), 1e-9 * std::sqrt(2.0 * n * n), 1e-20);
}

// The cube: 8 vertices, 12 sides and 6 face diagonals = 18 edges, each shared by two triangles
// (a closed surface); every vertex in 3 to 6 triangles, 36 corners in all. An edge lists its
// lower vertex first, and edge k of a triangle joins its corners k and k + 1.
TEST(TriangleMesh, EdgesKnowTheirTrianglesAndVerticesTheirs) {
    const TriangleMesh mesh(unitCube());
    EXPECT_EQ(mesh.vertexCount(), 8u);
    ASSERT_EQ(mesh.edgeCount(), 18u);
    for (std::size_t e = 0; e < mesh.edgeCount(); ++e) {
        EXPECT_LT(mesh.edge(e)[0], mesh.edge(e)[1]);
        ASSERT_EQ(mesh.edgeTriangles(e).size(), 2u);
        for (const std::uint32_t t : mesh.edgeTriangles(e)) {
            const auto& v = mesh.triangle(t);
            EXPECT_TRUE(std::count(v.begin(), v.end(), mesh.edge(e)[0]) == 1 &&
                        std::count(v.begin(), v.end(), mesh.edge(e)[1]) == 1);
        }
    }
    std::size_t corners = 0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        corners += mesh.vertexTriangles(v).size();
        EXPECT_GE(mesh.vertexTriangles(v).size(), 3u);
        for (const std::uint32_t t : mesh.vertexTriangles(v))
            EXPECT_EQ(std::count(mesh.triangle(t).begin(), mesh.triangle(t).end(), v), 1);
    }
    EXPECT_EQ(corners, 36u);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            const auto& ends = mesh.edge(mesh.triangleEdges(t)[k]);
            const std::uint32_t a = mesh.triangle(t)[k], b = mesh.triangle(t)[(k + 1) % 3];
            EXPECT_EQ(ends[0], std::min(a, b));
            EXPECT_EQ(ends[1], std::max(a, b));
        }
}

// (b - a) x (c - a) over its length: +z for the counter-clockwise triangle of the xy plane, -z
// reversed; the triangle through the three unit points has normal (1, 1, 1) / sqrt(3). The cube's
// normals point out: at its face centres, the normal is the direction from the cube's centre.
TEST(TriangleMesh, NormalsFollowTheRightHandRule) {
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    const TriangleMesh mesh({{a, b, c}, {a + Vec3(0, 0, 1), c + Vec3(0, 0, 1), b + Vec3(0, 0, 1)},
                             {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}});
    EXPECT_EQ(mesh.normal(0), Vec3(0, 0, 1));
    EXPECT_EQ(mesh.normal(1), Vec3(0, 0, -1));
    EXPECT_NEAR((mesh.normal(2) - Vec3(1, 1, 1) / std::sqrt(3.0)).norm(), 0, 1e-15);
    const TriangleMesh cube(unitCube());
    for (std::size_t t = 0; t < cube.triangleCount(); ++t) {
        const Vec3 middle = (cube.corner(t, 0) + cube.corner(t, 1) + cube.corner(t, 2)) / 3;
        const Vec3 out = middle - Vec3(0.5, 0.5, 0.5);
        // The face's axis is the largest component of `out`.
        Vec3 axis = Vec3::Zero();
        Eigen::Index k;
        out.cwiseAbs().maxCoeff(&k);
        axis[k] = out[k] > 0 ? 1 : -1;
        EXPECT_EQ(cube.normal(t), axis) << "triangle " << t;
    }
}

// Translating the cube by (1, 2, 3) moves its box to [1, 2] x [2, 3] x [3, 4]; turning it then by
// 90 degrees about the z axis through (1, 2, 3) maps (x, y) to (1 - (y - 2), 2 + (x - 1)): the box
// becomes [0, 1] x [2, 3] x [3, 4], and each normal turns as the vectors do: (nx, ny) -> (-ny, nx).
TEST(TriangleMesh, TranslateAndRotateMoveVerticesBoxAndNormals) {
    TriangleMesh mesh(unitCube());
    EXPECT_EQ(mesh.lo(), Vec3(0, 0, 0));
    EXPECT_EQ(mesh.hi(), Vec3(1, 1, 1));
    std::vector<Vec3> normals;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) normals.push_back(mesh.normal(t));
    mesh.translate(Vec3(1, 2, 3));
    EXPECT_EQ(mesh.lo(), Vec3(1, 2, 3));
    EXPECT_EQ(mesh.hi(), Vec3(2, 3, 4));
    mesh.rotate(Vec3(1, 2, 3), Vec3(0, 0, 2), pi / 2);
    EXPECT_NEAR((mesh.lo() - Vec3(0, 2, 3)).norm(), 0, 1e-15);
    EXPECT_NEAR((mesh.hi() - Vec3(1, 3, 4)).norm(), 0, 1e-15);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3 turned(-normals[t].y(), normals[t].x(), normals[t].z());
        EXPECT_NEAR((mesh.normal(t) - turned).norm(), 0, 1e-15) << "triangle " << t;
    }
    // A turn by a matrix about a point on the cube's diagonal by 120 degrees about (1, 1, 1)
    // permutes the axes, x -> y -> z -> x: the box [0, 1] x [2, 3] x [3, 4] about the point
    // (0, 2, 3) goes to [0, 1] x [2, 3] x [3, 4] again.
    mesh.rotate(Vec3(0, 2, 3), Mat3(Eigen::AngleAxisd(2 * pi / 3, Vec3(1, 1, 1).normalized())));
    EXPECT_NEAR((mesh.lo() - Vec3(0, 2, 3)).norm(), 0, 1e-14);
    EXPECT_NEAR((mesh.hi() - Vec3(1, 3, 4)).norm(), 0, 1e-14);
    expectError([&] { mesh.rotate(Vec3::Zero(), Vec3::Zero(), 1); }, {"nonzero axis"});
}

TEST(TriangleMesh, BadTrianglesNameTheSourceAndPlace) {
    const TriangleCorners good{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    auto mesh = [&](const TriangleCorners& second) {
        return TriangleMesh({good, second}, MeshSource{"test mesh m.txt", "line", {5, 7}});
    };
    expectError([&] { mesh({Vec3(0, 0, 1), Vec3(nan, 0, 1), Vec3(0, 1, 1)}); },
                {"test mesh m.txt line 7: corner 2", "is not finite"});
    expectError([&] { mesh({Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, -inf, 1)}); },
                {"test mesh m.txt line 7: corner 3", "inf", "is not finite"});
    // On one line, and nearly: height over longest edge 1e-10 (below 1e-8); a point.
    expectError([&] { mesh({Vec3(0, 0, 1), Vec3(2, 0, 1), Vec3(1, 0, 1)}); }, {"test mesh m.txt line 7:", "zero area"});
    expectError([&] { mesh({Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0.5, 1e-10, 1)}); }, {"line 7:", "zero area"});
    expectError([&] { mesh({Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)}); }, {"line 7:", "zero area"});
    // A thin triangle of height 1e-6 over its length is no error.
    EXPECT_NO_THROW(mesh({Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0.5, 1e-6, 1)}));
    // A well-shaped triangle smaller than the tolerance (1e-9 x the diagonal sqrt(2)): one vertex.
    expectError([&] { mesh({Vec3(0, 0, 1), Vec3(1e-12, 0, 1), Vec3(0, 1e-12, 1)}); },
                {"line 7: corners 1 and 2 are closer than the mesh's tolerance"});
    // The same triangle twice (its corners in another order) would be met twice.
    expectError([&] { mesh({good[1], good[2], good[0]}); },
                {"test mesh m.txt line 7: the triangle has the same corners as the one at line 5"});
    expectError([] { TriangleMesh({}, MeshSource{"test mesh m.txt", "line", {}}); }, {"test mesh m.txt: no triangles"});
    // Without places, triangles are counted from 1.
    expectError([&] { TriangleMesh({good, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)}}); },
                {"triangle mesh triangle 2:", "zero area"});
}

namespace {

// Random triangles in [0, 10]^3 of sizes from 0.05 to 3.
TriangleMesh someTriangles(int count, unsigned seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> position(0, 10), size(0.05, 3), unit(-1, 1);
    std::vector<TriangleCorners> triangles;
    while (int(triangles.size()) < count) {
        const Vec3 a(position(random), position(random), position(random));
        const double s = size(random);
        const TriangleCorners t{a, a + s * Vec3(unit(random), unit(random), unit(random)),
                                a + s * Vec3(unit(random), unit(random), unit(random))};
        if ((t[1] - t[0]).cross(t[2] - t[0]).norm() > 0.01 * s * s) triangles.push_back(t);
    }
    return TriangleMesh(triangles);
}

// The triangles whose bounding box overlaps the sphere's, by looking at each.
std::vector<std::uint32_t> bruteForceNear(const TriangleMesh& mesh, const Vec3& centre, double radius) {
    std::vector<std::uint32_t> near;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        bool overlaps = true;
        for (int a = 0; a < 3; ++a) {
            const double lo = std::min({mesh.corner(t, 0)[a], mesh.corner(t, 1)[a], mesh.corner(t, 2)[a]});
            const double hi = std::max({mesh.corner(t, 0)[a], mesh.corner(t, 1)[a], mesh.corner(t, 2)[a]});
            overlaps = overlaps && lo <= centre[a] + radius && centre[a] - radius <= hi;
        }
        if (overlaps) near.push_back(static_cast<std::uint32_t>(t));
    }
    return near;
}

}  // namespace

// For cells smaller than, like and larger than the triangles, and spheres inside, across and
// outside the mesh's box (radius 0 included), the grid finds exactly the brute-force list. (Cells
// of 0.07: more cells than a table of all of them may have, so the occupied ones are searched.)
TEST(TriangleGrid, FindsTheTrianglesWhoseBoxesOverlapTheSpheres) {
    const TriangleMesh mesh = someTriangles(300, 11);
    std::mt19937_64 random(12);
    std::uniform_real_distribution<double> position(-3, 13), radius(0, 2);
    for (const double cellSize : {0.07, 0.3, 1.0, 4.0, 30.0}) {
        const TriangleGrid grid(mesh, cellSize);
        std::size_t found = 0;
        for (int k = 0; k < 300; ++k) {
            const Vec3 centre(position(random), position(random), position(random));
            const double r = k % 50 == 0 ? 0.0 : radius(random);
            const auto near = grid.trianglesNear(centre, r);
            ASSERT_EQ(near, bruteForceNear(mesh, centre, r)) << "cell " << cellSize << " centre " << centre.transpose();
            found += near.size();
        }
        EXPECT_GT(found, 300u);  // (the spheres do meet triangles)
    }
}

// A box that only touches a triangle's box (at x = 4 = 4.5 - 0.5, a cell boundary) counts; a sphere
// larger than the mesh finds every triangle; one far away none.
TEST(TriangleGrid, TouchingBoxesCountAndLargeOrFarSpheresWork) {
    const TriangleMesh mesh(squareGrid(4));  // [0, 4]^2 at z = 0
    const TriangleGrid grid(mesh, 0.5);
    const auto touching = grid.trianglesNear(Vec3(4.5, 0.4, 0), 0.5);
    EXPECT_EQ(touching, bruteForceNear(mesh, Vec3(4.5, 0.4, 0), 0.5));
    EXPECT_EQ(touching.size(), 2u);  // the square [3, 4] x [0, 1]
    EXPECT_EQ(grid.trianglesNear(Vec3(2, 2, 0), 100).size(), mesh.triangleCount());
    EXPECT_TRUE(grid.trianglesNear(Vec3(2, 2, 50), 1).empty());
    EXPECT_TRUE(grid.trianglesNear(Vec3(-1e300, 2, 0), 1).empty());
}

TEST(TriangleGrid, BadCellSizesAndQueriesAreErrors) {
    const TriangleMesh mesh(squareGrid(4));
    expectError([&] { TriangleGrid(mesh, 0); }, {"cell size must be positive"});
    expectError([&] { TriangleGrid(mesh, 1e-7); }, {"cell size 1e-07 is too small for triangle mesh"});
    const TriangleGrid grid(mesh, 1);
    expectError([&] { grid.trianglesNear(Vec3(std::nan(""), 0, 0), 1); }, {"finite centre"});
}
