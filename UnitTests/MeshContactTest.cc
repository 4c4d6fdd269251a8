// Contacts of spheres with triangle meshes (Walls/MeshContact.h): the point of a triangle nearest
// to a point against dense sampling, and the contacts of spheres with flat floors, convex edges
// and corners, and concave corners, whose points, normals and overlaps follow from elementary
// geometry. Candidates come from the triangle grid (Walls/TriangleGrid.h), as they will in the
// force loop.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <set>

#include "IO/StlReader.h"
#include "TestHelpers.h"
#include "Walls/MeshContact.h"
#include "Walls/TriangleGrid.h"

using namespace talus;
using namespace talus::test;

namespace {

// The rectangle corner + s u + t v (s, t in [0, 1]) as m x m cells of two triangles each, normals
// along u x v; cell (i, j) is split along its diagonal from (i, j) to (i + 1, j + 1) when
// rising(i, j), else along the other one.
void addRectangle(std::vector<TriangleCorners>& triangles, const Vec3& corner, const Vec3& u, const Vec3& v, int m,
                  const std::function<bool(int, int)>& rising = [](int, int) { return true; }) {
    // ((i u) / m: exact for whole-numbered corners when i u / m is whole.)
    auto at = [&](int i, int j) { return Vec3(corner + (double(i) * u + double(j) * v) / double(m)); };
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            const Vec3 p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
            if (rising(i, j)) {
                triangles.push_back({p00, p10, p11});
                triangles.push_back({p00, p11, p01});
            } else {
                triangles.push_back({p00, p10, p01});
                triangles.push_back({p10, p11, p01});
            }
        }
}

// The unit cube [0, 1]^3 with outward normals, each face m x m cells.
std::vector<TriangleCorners> cube(int m) {
    std::vector<TriangleCorners> t;
    const Vec3 o = Vec3::Zero(), x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
    addRectangle(t, o, y, x, m);  // z = 0, normal y x x = -z
    addRectangle(t, z, x, y, m);  // z = 1, +z
    addRectangle(t, o, z, y, m);  // x = 0, -x
    addRectangle(t, x, y, z, m);  // x = 1, +x
    addRectangle(t, o, x, z, m);  // y = 0, -y
    addRectangle(t, y, z, x, m);  // y = 1, +y
    return t;
}

// A mesh with the grid that gives the candidates, as the force loop will hold them.
struct MeshWithGrid {
    TriangleMesh mesh;
    TriangleGrid grid;
    explicit MeshWithGrid(const std::vector<TriangleCorners>& triangles, double cellSize = 1)
        : mesh(triangles), grid(mesh, cellSize) {}
    explicit MeshWithGrid(TriangleMesh m, double cellSize = 1) : mesh(std::move(m)), grid(mesh, cellSize) {}
    std::vector<MeshContact> contacts(const Vec3& centre, double radius) const {
        return sphereMeshContacts(mesh, centre, radius, grid.trianglesNear(centre, radius));
    }
};

// Expects exactly one contact with these values (the feature too, when given); returns it.
MeshContact expectOneContact(const MeshWithGrid& m, const Vec3& centre, double radius, const Vec3& normal,
                             const Vec3& point, double overlap, std::optional<MeshFeature> feature,
                             const std::string& where) {
    const std::vector<MeshContact> contacts = m.contacts(centre, radius);
    const std::string at = where + ", centre " + str(centre.x()) + " " + str(centre.y()) + " " + str(centre.z());
    EXPECT_EQ(contacts.size(), 1u) << at;
    if (contacts.size() != 1) return {};
    const MeshContact& c = contacts[0];
    EXPECT_NEAR((c.normal - normal).norm(), 0, 1e-12) << at;
    EXPECT_NEAR((c.point - point).norm(), 0, 1e-12) << at;
    EXPECT_NEAR(c.overlap, overlap, 1e-12) << at;
    if (feature) {
        EXPECT_EQ(int(c.feature), int(*feature)) << at;
    }
    return c;
}

const Vec3 up = Vec3::UnitZ();

}  // namespace

// The nearest point of a triangle lies on it, no sample of a dense grid of points on it (spacing
// longest edge / 60) is nearer, and one is nearer than it plus that spacing; on the face, x minus
// the point is along the normal; on an edge, perpendicular to the edge; at a corner, it is the
// corner.
TEST(MeshContact, ClosestPointAgreesWithDenseSampling) {
    std::mt19937_64 random(31);
    std::uniform_real_distribution<double> unit(-1, 1);
    auto someVector = [&] { return Vec3(unit(random), unit(random), unit(random)); };
    const int n = 60;
    int seen[3] = {0, 0, 0};
    for (int k = 0; k < 40; ++k) {
        const TriangleCorners c{someVector(), someVector(), someVector()};
        const Vec3 normal = (c[1] - c[0]).cross(c[2] - c[0]);
        if (normal.norm() < 0.05) continue;
        const double longest = std::max({(c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[0] - c[2]).norm()});
        Eigen::Matrix<double, 3, 2> edges;
        edges << c[1] - c[0], c[2] - c[0];
        for (int q = 0; q < 20; ++q) {
            const Vec3 x = 2 * someVector();
            const TrianglePoint p = closestPointOnTriangle(x, c);
            ++seen[int(p.feature)];
            double sampled = std::numeric_limits<double>::infinity();
            for (int i = 0; i <= n; ++i)
                for (int j = 0; i + j <= n; ++j)
                    sampled = std::min(sampled, (x - (c[0] + (double(i) / n) * edges.col(0) + (double(j) / n) * edges.col(1))).norm());
            const double distance = (x - p.point).norm();
            EXPECT_LE(distance, sampled + 1e-12);
            EXPECT_GE(distance, sampled - longest / n);
            // Barycentric weights of the point: (1 - b - g, b, g).
            const Eigen::Vector2d bg = edges.colPivHouseholderQr().solve(p.point - c[0]);
            const Vec3 w(1 - bg.sum(), bg.x(), bg.y());
            EXPECT_NEAR((edges * bg - (p.point - c[0])).norm(), 0, 1e-12);  // in the plane
            EXPECT_GE(w.minCoeff(), -1e-12);
            switch (p.feature) {
                case MeshFeature::face:
                    EXPECT_GT(w.minCoeff(), 0);
                    EXPECT_NEAR((x - p.point).cross(normal.normalized()).norm(), 0, 1e-12);
                    break;
                case MeshFeature::edge:
                    EXPECT_NEAR(w[(p.which + 2) % 3], 0, 1e-12);
                    EXPECT_NEAR((x - p.point).dot((c[(p.which + 1) % 3] - c[p.which]).normalized()), 0, 1e-12);
                    break;
                case MeshFeature::vertex:
                    EXPECT_EQ(p.point, c[p.which]);
                    break;
            }
        }
    }
    EXPECT_GT(seen[0], 20);
    EXPECT_GT(seen[1], 20);
    EXPECT_GT(seen[2], 20);
}

// The nearest point from the geometry a mesh keeps (closestPointOnMeshTriangle: stored normals,
// inward edge normals, edge directions) is closestPointOnTriangle's from the corners: the same
// feature and corner or edge, and the same point to rounding, for points all around the triangles
// of a cube turned off the axes (points within the tolerance of edges and corners included), on
// the mesh as made and after it has turned. The triangles that share an edge find the very same
// point on it, to the bit, and classify it alike.
TEST(MeshContact, TheMeshsNearestPointIsTheCornersOne) {
    TriangleMesh mesh(cube(3));
    std::mt19937_64 random(41);
    std::uniform_real_distribution<double> unit(-1, 1);
    auto someVector = [&] { return Vec3(unit(random), unit(random), unit(random)); };
    int seen[3] = {0, 0, 0}, sharedEdges = 0;
    for (int turn = 0; turn < 2; ++turn) {
        if (turn == 1) mesh.rotate(Vec3(0.3, 0.2, 0.1), Vec3(1, 2, 3).normalized(), 0.7);
        for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
            const TriangleCorners c{mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2)};
            for (int q = 0; q < 40; ++q) {
                // Around the triangle, or a hair (below the tolerance) off one of its corners or
                // edges' midpoints.
                const Vec3 x = q < 30 ? Vec3(c[q % 3] + 0.5 * someVector())
                                      : Vec3((q % 2 ? c[q % 3] : 0.5 * (c[q % 3] + c[(q + 1) % 3])) +
                                             0.3 * mesh.tolerance() * someVector() + 0.2 * mesh.normal(t));
                const TrianglePoint fromCorners = closestPointOnTriangle(x, c, mesh.tolerance());
                const TrianglePoint fromMesh = closestPointOnMeshTriangle(x, mesh, t);
                ++seen[int(fromMesh.feature)];
                ASSERT_EQ(int(fromMesh.feature), int(fromCorners.feature)) << "triangle " << t << " x " << x.transpose();
                ASSERT_EQ(fromMesh.which, fromCorners.which) << "triangle " << t << " x " << x.transpose();
                EXPECT_LT((fromMesh.point - fromCorners.point).norm(), 1e-14);
                if (fromMesh.feature != MeshFeature::edge) continue;
                const std::uint32_t e = mesh.triangleEdges(t)[fromMesh.which];
                for (const std::uint32_t other : mesh.edgeTriangles(e)) {
                    if (other == t) continue;
                    const TrianglePoint there = closestPointOnMeshTriangle(x, mesh, other);
                    if (there.feature != MeshFeature::edge || mesh.triangleEdges(other)[there.which] != e) continue;
                    EXPECT_EQ(there.point, fromMesh.point);
                    ++sharedEdges;
                }
            }
        }
    }
    EXPECT_GT(seen[0], 200);
    EXPECT_GT(seen[1], 200);
    EXPECT_GT(seen[2], 200);
    EXPECT_GT(sharedEdges, 100);
}

// The triangle (0,0,0) (1,0,0) (0,1,0): over its inside the face, beside each edge the edge (edge
// 1, from (1,0,0) to (0,1,0), nearest to (2, 2) at (0.5, 0.5)), beyond each corner the corner.
// Within the tolerance of an edge a point is on the edge, within it of a corner at the corner.
TEST(MeshContact, ClosestPointRegionsOfATriangle) {
    const TriangleCorners c{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    struct Case {
        Vec3 x, point;
        MeshFeature feature;
        int which;
        double tolerance;
    };
    const Case cases[] = {
        {Vec3(0.2, 0.2, 5), Vec3(0.2, 0.2, 0), MeshFeature::face, 0, 0},
        {Vec3(0.5, -1, 0), Vec3(0.5, 0, 0), MeshFeature::edge, 0, 0},
        {Vec3(2, 2, 1), Vec3(0.5, 0.5, 0), MeshFeature::edge, 1, 0},
        {Vec3(-1, 0.5, -2), Vec3(0, 0.5, 0), MeshFeature::edge, 2, 0},
        {Vec3(-1, -1, 3), Vec3(0, 0, 0), MeshFeature::vertex, 0, 0},
        {Vec3(3, -1, 0), Vec3(1, 0, 0), MeshFeature::vertex, 1, 0},
        {Vec3(-0.5, 3, 0), Vec3(0, 1, 0), MeshFeature::vertex, 2, 0},
        {Vec3(0.5, 1e-3, 1), Vec3(0.5, 1e-3, 0), MeshFeature::face, 0, 0},
        {Vec3(0.5, 1e-3, 1), Vec3(0.5, 0, 0), MeshFeature::edge, 0, 1e-2},
        {Vec3(1e-3, 2e-3, 1), Vec3(0, 0, 0), MeshFeature::vertex, 0, 1e-2},
    };
    for (const Case& k : cases) {
        const TrianglePoint p = closestPointOnTriangle(k.x, c, k.tolerance);
        EXPECT_NEAR((p.point - k.point).norm(), 0, 1e-15) << k.x.transpose();
        EXPECT_EQ(int(p.feature), int(k.feature)) << k.x.transpose();
        EXPECT_EQ(p.which, k.which) << k.x.transpose();
    }
}

// A floor z = 0 of 10 x 10 unit squares, split along diagonals all alike (6 triangles meet at an
// inner vertex), alternating (8 or 4) or at random. A sphere of radius r with its centre at height
// h < r above or below any point (x, y) of the floor touches it at (x, y, 0) only: one contact,
// normal (0, 0, +-1), overlap r - h; over a face inside a face contact, over a shared side or
// diagonal an edge contact, over a vertex a vertex contact; and over 1000 points at random of the
// floor with diagonals at random. With r = 1.5 and h = 1 the sphere reaches sqrt(1.25) ~ 1.1
// around, over many triangles whose nearest points lie on their edges (a rule that counts an edge
// unless a triangle sharing it has a face contact finds 3 contacts over the middle of a side).
TEST(MeshContact, SphereOnAFlatFloorMeetsItOnce) {
    std::mt19937_64 random(21);
    std::bernoulli_distribution coin;
    std::vector<bool> randomRising(100);
    for (std::size_t k = 0; k < randomRising.size(); ++k) randomRising[k] = coin(random);
    const std::vector<std::pair<std::string, std::function<bool(int, int)>>> patterns = {
        {"diagonals alike", [](int, int) { return true; }},
        {"diagonals alternating", [](int i, int j) { return (i + j) % 2 == 0; }},
        {"diagonals at random", [&](int i, int j) { return bool(randomRising[10 * i + j]); }}};
    std::uniform_real_distribution<double> across(0, 10);
    std::set<std::size_t> valences;
    struct Sphere {
        double r, h, side;
    };
    const Sphere spheres[] = {{0.5, 0.3, 1}, {0.5, 0.3, -1}, {1.5, 1.0, 1}};
    for (const auto& [name, rising] : patterns) {
        std::vector<TriangleCorners> triangles;
        addRectangle(triangles, Vec3::Zero(), Vec3(10, 0, 0), Vec3(0, 10, 0), 10, rising);
        const MeshWithGrid floor(triangles);
        auto expectAt = [&](const Sphere& s, double x, double y, std::optional<MeshFeature> feature) {
            return expectOneContact(floor, Vec3(x, y, s.side * s.h), s.r, s.side * up, Vec3(x, y, 0), s.r - s.h,
                                    feature, name);
        };
        for (const Sphere& s : spheres) {
            for (int i = 0; i < 10; ++i)
                for (int j = 0; j < 10; ++j) {
                    expectAt(s, i + 0.3, j + 0.6, MeshFeature::face);  // (off both diagonals)
                    expectAt(s, i + 0.5, j, MeshFeature::edge);
                    expectAt(s, i, j + 0.25, MeshFeature::edge);
                    expectAt(s, i + 0.5, j + 0.5, MeshFeature::edge);  // (on either diagonal)
                }
            for (int i = 0; i <= 10; ++i)
                for (int j = 0; j <= 10; ++j) {
                    const MeshContact c = expectAt(s, i, j, MeshFeature::vertex);
                    if (c.feature == MeshFeature::vertex) valences.insert(floor.mesh.vertexTriangles(c.index).size());
                }
        }
        if (name == "diagonals at random")
            for (int k = 0; k < 1000; ++k) expectAt(spheres[k % 3], across(random), across(random), std::nullopt);
    }
    EXPECT_TRUE(valences.count(6) && valences.count(8) && valences.count(4)) << "inner vertices of 6, 8 and 4 triangles";
}

// The floor with diagonals at random written by the STL writer and read back, ASCII and binary:
// its corners are whole numbers (exact in 32-bit floats), so every contact is the same to the bit.
TEST(MeshContact, FloorReadBackFromStlGivesTheSameContacts) {
    std::mt19937_64 random(22);
    std::bernoulli_distribution coin;
    std::vector<TriangleCorners> triangles;
    addRectangle(triangles, Vec3::Zero(), Vec3(10, 0, 0), Vec3(0, 10, 0), 10, [&](int, int) { return coin(random); });
    const MeshWithGrid original(triangles);
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("talus-mesh-contact-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    for (const StlEncoding encoding : {StlEncoding::ascii, StlEncoding::binary}) {
        const std::string path = (folder / "floor.stl").string();
        writeStl(path, original.mesh, encoding);
        const MeshWithGrid readBack(readStl(path));
        std::uniform_real_distribution<double> across(0, 10), height(-1, 1);
        for (int k = 0; k < 300; ++k) {
            const Vec3 centre(across(random), across(random), height(random));
            const auto a = original.contacts(centre, 1.2), b = readBack.contacts(centre, 1.2);
            ASSERT_EQ(a.size(), b.size());
            EXPECT_EQ(a.size(), 1u);
            for (std::size_t q = 0; q < a.size(); ++q) {
                EXPECT_TRUE(sameBits(a[q].normal, b[q].normal) && sameBits(a[q].point, b[q].point) &&
                            sameBits(a[q].overlap, b[q].overlap));
                EXPECT_EQ(a[q].feature, b[q].feature);
                EXPECT_EQ(a[q].index, b[q].index);
            }
        }
    }
    std::filesystem::remove_all(folder);
}

// A block's top (z = 0, x < 0) and its side (x = 0, z < 0) meet at a right angle along the y axis.
// A centre at distance d from the edge, at angle theta from +x towards +z (0 to 90 degrees), is
// nearest to the edge point (0, y, 0): one edge contact, normal (cos theta, 0, sin theta), overlap
// r - d; at y = 0, where the triangles along the edge meet, a vertex contact with the same values.
// Over the top (theta = 120 degrees) the top's face point (d cos theta, y, 0) is nearer, at
// distance d sin theta: one face contact with normal +z.
TEST(MeshContact, ConvexEdgeGivesOneEdgeContact) {
    std::vector<TriangleCorners> triangles;
    addRectangle(triangles, Vec3(-2, -2, 0), Vec3(2, 0, 0), Vec3(0, 4, 0), 2);   // the top, +z
    addRectangle(triangles, Vec3(0, -2, 0), Vec3(0, 0, -2), Vec3(0, 4, 0), 2);  // the side, +x
    const MeshWithGrid block(triangles);
    const double r = 0.5, d = 0.3;
    for (const double y : {-1.3, 0.0, 0.5, 1.7})
        for (const double degreesFromX : {0.0, 20.0, 45.0, 70.0, 90.0}) {
            const double theta = degrees(degreesFromX);
            const Vec3 normal(std::cos(theta), 0, std::sin(theta));
            expectOneContact(block, Vec3(0, y, 0) + d * normal, r, normal, Vec3(0, y, 0), r - d,
                             y == 0 ? MeshFeature::vertex : MeshFeature::edge, "edge");
        }
    const double theta = degrees(120);
    expectOneContact(block, Vec3(d * std::cos(theta), 0.5, d * std::sin(theta)), r, up,
                     Vec3(d * std::cos(theta), 0.5, 0), r - d * std::sin(theta), MeshFeature::face, "top");
}

// The unit cube, faces of 1 and of 2 x 2 cells. Beyond a corner c, at c + d u with u pointing out of
// every face there (each component's sign that of c's away from the cube's middle): one vertex
// contact at c with normal u. Beside an edge, at distance d from its point p in a direction n
// between its two faces' normals: one edge contact at p with normal n. Overlap r - d.
TEST(MeshContact, CubeCornersAndEdgesGiveOneContactEach) {
    const double r = 0.5, d = 0.3;
    for (const int m : {1, 2}) {
        const MeshWithGrid box(cube(m), 0.5);
        for (int k = 0; k < 8; ++k) {
            const Vec3 c(k & 1, k >> 1 & 1, k >> 2 & 1);
            const Vec3 sign = 2 * c - Vec3::Ones();
            const Vec3 u = Vec3(sign.x() * 1, sign.y() * 2, sign.z() * 3).normalized();
            const MeshContact contact = expectOneContact(box, c + d * u, r, u, c, r - d, MeshFeature::vertex, "corner");
            if (contact.feature == MeshFeature::vertex) {
                EXPECT_EQ(box.mesh.vertex(contact.index), c);
            }
        }
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < 4; ++k) {
                const int b = (a + 1) % 3, c = (a + 2) % 3;
                Vec3 p = Vec3::Zero(), n = Vec3::Zero();
                p[a] = 0.3;  // (not at a vertex: those lie at 0, 0.5 and 1 along an edge)
                p[b] = k & 1;
                p[c] = k >> 1;
                for (const double theta : {degrees(10), degrees(45), degrees(80)}) {
                    n[b] = (2 * p[b] - 1) * std::cos(theta);
                    n[c] = (2 * p[c] - 1) * std::sin(theta);
                    expectOneContact(box, p + d * n, r, n, p, r - d, MeshFeature::edge, "cube edge");
                }
            }
    }
}

// The inside of a box: floor z = 0 (normal +z), wall x = 0 (normal +x), back wall y = -1 (normal
// +y). A sphere of radius 0.6 at (0.3, 0.2, 0.4) touches the floor at (0.3, 0.2, 0) (overlap 0.6 -
// 0.4) and the wall at (0, 0.2, 0.4) (overlap 0.6 - 0.3): two face contacts; moved to y = -0.5 it
// touches the back wall too, at (0.3, -1, 0.4) (overlap 0.6 - 0.5): three.
TEST(MeshContact, ConcaveCornerGivesAFaceContactPerFace) {
    std::vector<TriangleCorners> triangles;
    addRectangle(triangles, Vec3(0, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), 2);  // floor
    addRectangle(triangles, Vec3(0, -1, 0), Vec3(0, 2, 0), Vec3(0, 0, 2), 2);  // wall
    addRectangle(triangles, Vec3(0, -1, 0), Vec3(0, 0, 2), Vec3(2, 0, 0), 2);  // back wall
    const MeshWithGrid corner(triangles);
    struct Expected {
        Vec3 normal, point;
        double overlap;
    };
    auto expectContacts = [&](const Vec3& centre, const std::vector<Expected>& expected) {
        const auto contacts = corner.contacts(centre, 0.6);
        ASSERT_EQ(contacts.size(), expected.size());
        for (const Expected& e : expected) {
            const auto it = std::find_if(contacts.begin(), contacts.end(),
                                         [&](const MeshContact& c) { return (c.normal - e.normal).norm() < 1e-12; });
            ASSERT_NE(it, contacts.end()) << "no contact with normal " << e.normal.transpose();
            EXPECT_EQ(int(it->feature), int(MeshFeature::face));
            EXPECT_NEAR((it->point - e.point).norm(), 0, 1e-12);
            EXPECT_NEAR(it->overlap, e.overlap, 1e-12);
        }
    };
    expectContacts(Vec3(0.3, 0.2, 0.4), {{up, Vec3(0.3, 0.2, 0), 0.2}, {Vec3::UnitX(), Vec3(0, 0.2, 0.4), 0.3}});
    expectContacts(Vec3(0.3, -0.5, 0.4), {{up, Vec3(0.3, -0.5, 0), 0.2},
                                          {Vec3::UnitX(), Vec3(0, -0.5, 0.4), 0.3},
                                          {Vec3::UnitY(), Vec3(0.3, -1, 0.4), 0.1}});
}

// A centre on the floor (distance 0) has no direction to the contact point: it takes the normal of
// the triangle, +z, whether it lies in a face, on an edge or at a vertex; the overlap is r.
TEST(MeshContact, CentreOnTheMeshTakesTheFaceNormal) {
    std::vector<TriangleCorners> triangles;
    addRectangle(triangles, Vec3::Zero(), Vec3(10, 0, 0), Vec3(0, 10, 0), 10);
    const MeshWithGrid floor(triangles);
    expectOneContact(floor, Vec3(2.3, 4.6, 0), 0.5, up, Vec3(2.3, 4.6, 0), 0.5, MeshFeature::face, "in a face");
    expectOneContact(floor, Vec3(2.5, 4, 0), 0.5, up, Vec3(2.5, 4, 0), 0.5, MeshFeature::edge, "on an edge");
    expectOneContact(floor, Vec3(3, 3, 0), 0.5, up, Vec3(3, 3, 0), 0.5, MeshFeature::vertex, "at a vertex");
}

// A sphere whose distance equals its radius does not touch (the overlap must be positive); a hair
// nearer it does. No candidates, no contacts; a candidate listed twice counts once; and an edge
// decides right when only one of its triangles is a candidate (the other one is asked anyway).
TEST(MeshContact, ReachAndCandidates) {
    std::vector<TriangleCorners> triangles;
    addRectangle(triangles, Vec3::Zero(), Vec3(4, 0, 0), Vec3(0, 4, 0), 4);
    const MeshWithGrid floor(triangles);
    EXPECT_TRUE(floor.contacts(Vec3(2.3, 1.6, 0.5), 0.5).empty());
    expectOneContact(floor, Vec3(2.3, 1.6, 0.5 - 1e-9), 0.5, up, Vec3(2.3, 1.6, 0), 1e-9, MeshFeature::face, "a hair");
    const Vec3 centre(2.5, 2, 0.3);  // over the side between squares (2, 1) and (2, 2)
    EXPECT_TRUE(sphereMeshContacts(floor.mesh, centre, 0.5, {}).empty());
    std::vector<std::uint32_t> twice = floor.grid.trianglesNear(centre, 0.5);
    twice.insert(twice.end(), twice.begin(), twice.end());
    EXPECT_EQ(sphereMeshContacts(floor.mesh, centre, 0.5, twice).size(), 1u);
    // Alone, only the two triangles with that side report it.
    int reporting = 0;
    for (std::uint32_t t = 0; t < floor.mesh.triangleCount(); ++t) {
        const std::vector<std::uint32_t> one{t};
        const auto contacts = sphereMeshContacts(floor.mesh, centre, 0.5, one);
        ASSERT_LE(contacts.size(), 1u);
        if (contacts.empty()) continue;
        ++reporting;
        EXPECT_EQ(int(contacts[0].feature), int(MeshFeature::edge));
        EXPECT_NEAR((contacts[0].normal - up).norm(), 0, 1e-15);
        EXPECT_NEAR(contacts[0].overlap, 0.2, 1e-15);
    }
    EXPECT_EQ(reporting, 2);
}
