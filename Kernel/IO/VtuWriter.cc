#include "IO/VtuWriter.h"

#include <filesystem>
#include <ostream>

#include "IO/DurableFile.h"

namespace talus {

namespace {

template <class Get>
void dataArray(std::ostream& out, const char* type, const char* name, int components, std::size_t count, Get get) {
    out << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
        << "\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < count; ++k) get(out, k);
    out << "</DataArray>\n";
}

void writeFrame(std::ostream& out, const ParticleStore& p, const std::vector<std::uint32_t>& order,
                const std::vector<Superquadric>& shapes) {
    out.precision(10);
    const std::size_t n = order.size();
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n<Points>\n";
    auto vec = [&](const std::vector<Vec3>& v) {
        return [&, vp = &v](std::ostream& o, std::size_t k) {
            const Vec3& x = (*vp)[order[k]];
            o << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
        };
    };
    dataArray(out, "Float64", "Position", 3, n, vec(p.position));
    out << "</Points>\n<PointData Scalars=\"Radius\" Vectors=\"Velocity\">\n";
    dataArray(out, "Float64", "Radius", 1, n, [&](std::ostream& o, std::size_t k) { o << p.radius[order[k]] << '\n'; });
    dataArray(out, "Float64", "Velocity", 3, n, vec(p.velocity));
    dataArray(out, "Float64", "AngularVelocity", 3, n, vec(p.angularVelocity));
    dataArray(out, "Int32", "Species", 1, n, [&](std::ostream& o, std::size_t k) { o << p.species[order[k]] << '\n'; });
    dataArray(out, "UInt64", "Id", 1, n, [&](std::ostream& o, std::size_t k) { o << p.id[order[k]] << '\n'; });
    dataArray(out, "UInt8", "Fixed", 1, n, [&](std::ostream& o, std::size_t k) { o << int(p.fixed[order[k]]) << '\n'; });
    if (p.hasShapes()) {
        // Non-spherical particles: orientation (w x y z) and, for ParaView's Tensor Glyph filter
        // (sphere source, "Extract eigenvalues" on), the tensor R diag(a, b, c) R^T whose
        // eigenvectors and eigenvalues are the body axes and semi-axes; spheres: r I.
        dataArray(out, "Float64", "Orientation", 4, n, [&](std::ostream& o, std::size_t k) {
            const Quat& q = p.orientation[order[k]];
            o << q.w() << ' ' << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
        });
        dataArray(out, "Float64", "ShapeTensor", 9, n, [&](std::ostream& o, std::size_t k) {
            const std::size_t i = order[k];
            Mat3 t = p.radius[i] * Mat3::Identity();
            if (p.isShaped(i)) {
                const Mat3 R = p.orientation[i].toRotationMatrix();
                t = R * shapes[static_cast<std::size_t>(p.shape[i])].semiAxes().asDiagonal() * R.transpose();
            }
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) o << t(a, b) << (a == 2 && b == 2 ? '\n' : ' ');
        });
    }
    // One VTK_VERTEX cell (type 1) per particle, point k in cell k: filters that work on cells
    // (Threshold, Extract Cells, Clip) then keep or drop each particle on its own, which one
    // poly-vertex cell holding every point would not allow.
    out << "</PointData>\n<Cells>\n";
    dataArray(out, "Int64", "connectivity", 1, n, [](std::ostream& o, std::size_t k) { o << k << '\n'; });
    dataArray(out, "Int64", "offsets", 1, n, [](std::ostream& o, std::size_t k) { o << k + 1 << '\n'; });
    dataArray(out, "UInt8", "types", 1, n, [](std::ostream& o, std::size_t) { o << "1\n"; });
    out << "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

void writeVtu(const std::string& path, const ParticleStore& p, const std::vector<std::uint32_t>& order,
              const std::vector<Superquadric>& shapes) {
    // (The folder is synced once per frame, by the restart file written after the frame.)
    replaceFile(path, [&](std::ostream& out) { writeFrame(out, p, order, shapes); }, /*syncFolder*/ false);
}

void writeMeshVtu(const std::string& path, const std::vector<std::shared_ptr<MeshWalls>>& meshes) {
    // The vertices of all meshes in one list, and per triangle its mesh, index and first vertex.
    struct Triangle {
        std::size_t mesh, index, firstVertex;
    };
    std::vector<const Vec3*> vertices;
    std::vector<Triangle> triangles;
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        const TriangleMesh& m = meshes[k]->mesh;
        const std::size_t first = vertices.size();
        for (std::size_t v = 0; v < m.vertexCount(); ++v) vertices.push_back(&m.vertex(v));
        for (std::size_t t = 0; t < m.triangleCount(); ++t) triangles.push_back({k, t, first});
    }
    const std::size_t n = vertices.size(), cells = triangles.size();
    replaceFile(path, [&](std::ostream& out) {
        out.precision(17);  // (the walls' own numbers, to the bit)
        out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << cells << "\">\n<Points>\n";
        dataArray(out, "Float64", "Position", 3, n, [&](std::ostream& o, std::size_t v) {
            o << vertices[v]->x() << ' ' << vertices[v]->y() << ' ' << vertices[v]->z() << '\n';
        });
        // One VTK_TRIANGLE cell (type 5) per triangle, its corners in the mesh's order; per cell
        // its wall's index, its mesh and its species.
        out << "</Points>\n<CellData Scalars=\"Wall\">\n";
        dataArray(out, "Int64", "Wall", 1, cells, [&](std::ostream& o, std::size_t c) {
            o << meshes[triangles[c].mesh]->firstWall + triangles[c].index << '\n';
        });
        dataArray(out, "Int64", "Mesh", 1, cells, [&](std::ostream& o, std::size_t c) { o << triangles[c].mesh << '\n'; });
        dataArray(out, "Int64", "Species", 1, cells,
                  [&](std::ostream& o, std::size_t c) { o << meshes[triangles[c].mesh]->species << '\n'; });
        out << "</CellData>\n<Cells>\n";
        dataArray(out, "Int64", "connectivity", 1, cells, [&](std::ostream& o, std::size_t c) {
            const Triangle& t = triangles[c];
            const auto& v = meshes[t.mesh]->mesh.triangle(t.index);
            o << t.firstVertex + v[0] << ' ' << t.firstVertex + v[1] << ' ' << t.firstVertex + v[2] << '\n';
        });
        dataArray(out, "Int64", "offsets", 1, cells, [](std::ostream& o, std::size_t c) { o << 3 * (c + 1) << '\n'; });
        dataArray(out, "UInt8", "types", 1, cells, [](std::ostream& o, std::size_t) { o << "5\n"; });
        out << "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    }, /*syncFolder*/ false);
}

void writePvd(const std::string& path, const std::string& base, const std::vector<double>& times) {
    const std::string file = std::filesystem::path(base).filename().string();
    replaceFile(path, [&](std::ostream& out) {
        out.precision(12);
        out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
        for (std::size_t k = 0; k < times.size(); ++k)
            out << "<DataSet timestep=\"" << times[k] << "\" file=\"" << file << "_" << k << ".vtu\"/>\n";
        out << "</Collection>\n</VTKFile>\n";
    }, /*syncFolder*/ false);
}

}  // namespace talus
