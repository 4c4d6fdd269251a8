#include "App/VtkFieldWriter.h"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <fstream>

#include "IO/InputError.h"

namespace talus::cg {

namespace {

std::string fileName(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The number with all 17 significant digits: the attributes (origin, spacing, times) read back
// as the same doubles.
std::string exact(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

}  // namespace

std::string VtkFieldWriter::framePath(const std::string& pvdPath, std::size_t index, bool grid) {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "_%06zu.%s", index, grid ? "vti" : "vtu");
    return pvdPath.substr(0, pvdPath.size() - 4) + suffix;
}

VtkFieldWriter::VtkFieldWriter(const FieldOutputSetup& setup, std::vector<OutputColumn> columns)
    : VtkFieldWriter(setup) {
    columns_ = std::move(columns);
    fieldsOfSums_ = false;
    arrays_.clear();
    for (std::size_t c = 0; c < columns_.size(); ++c) arrays_.push_back({columns_[c].name, {static_cast<int>(c)}, {}});
}

VtkFieldWriter::VtkFieldWriter(const FieldOutputSetup& setup)
    : setup_(setup), columns_(derivedColumns(setup.layout)), arrays_(fieldArrays(setup.layout)) {
    if (!setup_.path.ends_with(".pvd")) {
        throw InputError("-o " + setup_.path + ": --output-format vtk writes a .pvd collection and one .vti image (grid) or "
                         ".vtu point set (point list) per frame beside it: give the .pvd name (e.g. -o fields.pvd)");
    }
}

std::size_t VtkFieldWriter::pointOfVtkId(std::size_t id) const {
    if (!setup_.grid) return id;  // a point list in its own order
    // VTK numbers an image's points x fastest (id = i + nx (j + ny k)); gridPoints z fastest.
    const std::size_t nx = static_cast<std::size_t>(setup_.count[0]), ny = static_cast<std::size_t>(setup_.count[1]),
                      nz = static_cast<std::size_t>(setup_.count[2]);
    const std::size_t i = id % nx, j = id / nx % ny, k = id / (nx * ny);
    return (i * ny + j) * nz + k;
}

void VtkFieldWriter::writeFrame(double firstTime, double time, const std::vector<double>& sums) {
    // The derived fields of every point.
    const std::size_t n = setup_.points.size(), fields = columns_.size();
    std::vector<double> row, table(n * fields);
    for (std::size_t p = 0; p < n; ++p) {
        row.clear();
        appendDerivedFields(setup_.layout, sums.data() + p * setup_.layout.count(), row);
        for (std::size_t f = 0; f < fields; ++f) table[p * fields + f] = row[f];
    }
    writeValues(firstTime, time, table);
}

void VtkFieldWriter::writeValues(double firstTime, double time, const std::vector<double>& table) {
    const std::string path = framePath(setup_.path, times_.size(), setup_.grid);
    std::ofstream out(path, std::ios::binary);
    if (!out) throw InputError("-o: cannot write " + path);
    const std::size_t n = setup_.points.size();
    const char* kind = setup_.grid ? "ImageData" : "UnstructuredGrid";
    out << "<?xml version=\"1.0\"?>\n";
    out << "<VTKFile type=\"" << kind << "\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
    std::string extent;
    if (setup_.grid) {
        // Origin: the first cell centre; spacing: the cell size (1 on averaged axes, one point at 0).
        std::string origin, spacing;
        for (int k = 0; k < 3; ++k) {
            const bool resolved = setup_.coordinates.resolves(k);
            const double cell = resolved ? (setup_.hi[k] - setup_.lo[k]) / double(setup_.count[k]) : 1.0;
            const char* separator = k ? " " : "";
            extent.append(separator).append("0 ").append(std::to_string(setup_.count[k] - 1));
            origin.append(separator).append(exact(resolved ? setup_.lo[k] + 0.5 * cell : 0.0));
            spacing.append(separator).append(exact(cell));
        }
        out << "  <ImageData WholeExtent=\"" << extent << "\" Origin=\"" << origin << "\" Spacing=\"" << spacing << "\">\n";
    } else {
        out << "  <UnstructuredGrid>\n";
    }
    // ParaView takes a dataset's time from TimeValue; the window of a time average beside it.
    out << "    <FieldData>\n      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">"
        << exact(time) << "</DataArray>\n";
    if (setup_.timeAverage) {
        out << "      <DataArray type=\"Float64\" Name=\"FirstTime\" NumberOfTuples=\"1\" format=\"ascii\">" << exact(firstTime)
            << "</DataArray>\n";
    }
    out << "    </FieldData>\n";
    // Every array's data goes into the appended block, in the order the header lists them.
    std::uint64_t offset = 0;
    auto appended = [&](const char* type, const std::string& name, std::size_t components, std::size_t bytesEach) {
        out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
            << "\" format=\"appended\" offset=\"" << offset << "\"";
        offset += sizeof(std::uint64_t) + n * components * bytesEach;
    };
    if (setup_.grid) {
        out << "    <Piece Extent=\"" << extent << "\">\n";
    } else {
        // The points as vertices (VTK cell type 1): a point set ParaView shows as points.
        out << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n      <Points>\n";
        appended("Float64", "Points", 3, sizeof(double));
        out << "/>\n      </Points>\n      <Cells>\n";
        appended("Int64", "connectivity", 1, sizeof(std::int64_t));
        out << "/>\n";
        appended("Int64", "offsets", 1, sizeof(std::int64_t));
        out << "/>\n";
        appended("UInt8", "types", 1, 1);
        out << "/>\n      </Cells>\n";
    }
    if (fieldsOfSums_) {  // (ParaView's default colouring and glyphs)
        out << "      <PointData Scalars=\"Density\" Vectors=\"Velocity\">\n";
    } else {
        out << "      <PointData>\n";
    }
    for (const FieldArray& a : arrays_) {
        appended("Float64", a.name, a.columns.size(), sizeof(double));
        for (std::size_t c = 0; c < a.componentNames.size(); ++c) {
            out << " ComponentName" << c << "=\"" << a.componentNames[c] << "\"";
        }
        out << "/>\n";
    }
    out << "      </PointData>\n      <CellData/>\n    </Piece>\n  </" << kind << ">\n  <AppendedData encoding=\"raw\">\n   _";

    static_assert(std::endian::native == std::endian::little, "the VTK files are declared little-endian");
    auto writeBlock = [&](const void* data, std::uint64_t bytes) {
        out.write(reinterpret_cast<const char*>(&bytes), sizeof bytes);
        out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
    };
    if (!setup_.grid) {
        std::vector<double> points;
        for (const Vec3& r : setup_.points) points.insert(points.end(), r.begin(), r.end());
        writeBlock(points.data(), points.size() * sizeof(double));
        std::vector<std::int64_t> connectivity(n), offsets(n);
        for (std::size_t p = 0; p < n; ++p) {
            connectivity[p] = static_cast<std::int64_t>(p);
            offsets[p] = static_cast<std::int64_t>(p + 1);
        }
        writeBlock(connectivity.data(), n * sizeof(std::int64_t));
        writeBlock(offsets.data(), n * sizeof(std::int64_t));
        const std::vector<std::uint8_t> types(n, 1);
        writeBlock(types.data(), n);
    }
    // Each array in VTK's order of the points.
    const std::size_t fields = columns_.size();
    std::vector<double> block;
    for (const FieldArray& a : arrays_) {
        block.clear();
        for (std::size_t id = 0; id < n; ++id) {
            const std::size_t p = pointOfVtkId(id);
            for (int column : a.columns) block.push_back(table[p * fields + static_cast<std::size_t>(column)]);
        }
        writeBlock(block.data(), block.size() * sizeof(double));
    }
    out << "\n  </AppendedData>\n</VTKFile>\n";
    out.close();
    if (!out) throw InputError("-o: writing " + path + " failed (disk full?)");
    times_.push_back(time);
}

void VtkFieldWriter::close() {
    std::ofstream out(setup_.path);
    if (!out) throw InputError("-o: cannot write " + setup_.path);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n  <Collection>\n";
    for (std::size_t t = 0; t < times_.size(); ++t) {
        out << "    <DataSet timestep=\"" << exact(times_[t]) << "\" part=\"0\" file=\"" << fileName(framePath(setup_.path, t, setup_.grid))
            << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
    out.close();
    if (!out) throw InputError("-o: writing " + setup_.path + " failed (disk full?)");
}

}  // namespace talus::cg
