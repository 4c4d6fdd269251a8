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

std::string VtkFieldWriter::framePath(const std::string& pvdPath, std::size_t index) {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "_%06zu.vti", index);
    return pvdPath.substr(0, pvdPath.size() - 4) + suffix;
}

VtkFieldWriter::VtkFieldWriter(const FieldOutputSetup& setup)
    : setup_(setup), columns_(derivedColumns(setup.layout)), arrays_(fieldArrays(setup.layout)) {
    requireOutputFormatAvailable(OutputFormat::Vtk, setup_.grid);
    if (!setup_.path.ends_with(".pvd")) {
        throw InputError("-o " + setup_.path + ": --output-format vtk writes a .pvd collection and one .vti image per frame "
                         "beside it: give the .pvd name (e.g. -o fields.pvd)");
    }
}

void VtkFieldWriter::writeFrame(double firstTime, double time, const std::vector<double>& sums) {
    const std::string path = framePath(setup_.path, times_.size());
    std::ofstream out(path, std::ios::binary);
    if (!out) throw InputError("-o: cannot write " + path);
    const long nx = setup_.count[0], ny = setup_.count[1], nz = setup_.count[2];
    const std::size_t n = setup_.points.size();
    // Origin: the first cell centre; spacing: the cell size (1 on averaged axes, one point at 0).
    std::string extent, origin, spacing;
    for (int k = 0; k < 3; ++k) {
        const bool resolved = setup_.coordinates.resolves(k);
        const double cell = resolved ? (setup_.hi[k] - setup_.lo[k]) / double(setup_.count[k]) : 1.0;
        const char* separator = k ? " " : "";
        extent.append(separator).append("0 ").append(std::to_string(setup_.count[k] - 1));
        origin.append(separator).append(exact(resolved ? setup_.lo[k] + 0.5 * cell : 0.0));
        spacing.append(separator).append(exact(cell));
    }
    out << "<?xml version=\"1.0\"?>\n";
    out << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
    out << "  <ImageData WholeExtent=\"" << extent << "\" Origin=\"" << origin << "\" Spacing=\"" << spacing << "\">\n";
    // ParaView takes a dataset's time from TimeValue; the window of a time average beside it.
    out << "    <FieldData>\n      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">"
        << exact(time) << "</DataArray>\n";
    if (setup_.timeAverage) {
        out << "      <DataArray type=\"Float64\" Name=\"FirstTime\" NumberOfTuples=\"1\" format=\"ascii\">" << exact(firstTime)
            << "</DataArray>\n";
    }
    out << "    </FieldData>\n";
    out << "    <Piece Extent=\"" << extent << "\">\n      <PointData Scalars=\"Density\" Vectors=\"Velocity\">\n";
    std::uint64_t offset = 0;
    for (const FieldArray& a : arrays_) {
        out << "        <DataArray type=\"Float64\" Name=\"" << a.name << "\" NumberOfComponents=\"" << a.columns.size() << "\"";
        for (std::size_t c = 0; c < a.componentNames.size(); ++c) {
            out << " ComponentName" << c << "=\"" << a.componentNames[c] << "\"";
        }
        out << " format=\"appended\" offset=\"" << offset << "\"/>\n";
        offset += sizeof(std::uint64_t) + n * a.columns.size() * sizeof(double);
    }
    out << "      </PointData>\n      <CellData/>\n    </Piece>\n  </ImageData>\n  <AppendedData encoding=\"raw\">\n   _";

    // The derived fields of every point (grid order: z fastest), then each array x fastest.
    const std::size_t fields = columns_.size();
    std::vector<double> row, table(n * fields);
    for (std::size_t p = 0; p < n; ++p) {
        row.clear();
        appendDerivedFields(setup_.layout, sums.data() + p * setup_.layout.count(), row);
        for (std::size_t f = 0; f < fields; ++f) table[p * fields + f] = row[f];
    }
    static_assert(std::endian::native == std::endian::little, "the .vti files are declared little-endian");
    std::vector<double> block;
    for (const FieldArray& a : arrays_) {
        block.clear();
        for (long k = 0; k < nz; ++k)
            for (long j = 0; j < ny; ++j)
                for (long i = 0; i < nx; ++i) {
                    const std::size_t p = static_cast<std::size_t>((i * ny + j) * nz + k);  // gridPoints' order
                    for (int column : a.columns) block.push_back(table[p * fields + static_cast<std::size_t>(column)]);
                }
        const std::uint64_t bytes = block.size() * sizeof(double);
        out.write(reinterpret_cast<const char*>(&bytes), sizeof bytes);
        out.write(reinterpret_cast<const char*>(block.data()), static_cast<std::streamsize>(bytes));
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
        out << "    <DataSet timestep=\"" << exact(times_[t]) << "\" part=\"0\" file=\"" << fileName(framePath(setup_.path, t))
            << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
    out.close();
    if (!out) throw InputError("-o: writing " + setup_.path + " failed (disk full?)");
}

}  // namespace talus::cg
