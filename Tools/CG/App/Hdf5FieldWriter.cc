#include "App/Hdf5FieldWriter.h"

#include <hdf5.h>

#include <cstdio>
#include <fstream>

#include "IO/InputError.h"

namespace talus::cg {

static_assert(sizeof(hid_t) == sizeof(std::int64_t), "hid_t is 64 bits from HDF5 1.10 on");

namespace {

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    return text;
}

void writeStringAttribute(hid_t object, const char* name, const std::string& value) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, value.size() + 1);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(attribute, type, value.c_str());
    H5Aclose(attribute);
    H5Sclose(space);
    H5Tclose(type);
}

void writeNumberAttribute(hid_t object, const char* name, double value) {
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate2(object, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(attribute, H5T_NATIVE_DOUBLE, &value);
    H5Aclose(attribute);
    H5Sclose(space);
}

std::string frameGroup(std::size_t index) {
    char name[32];
    std::snprintf(name, sizeof name, "/frames/%06zu", index);
    return name;
}

std::string fileName(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

std::string Hdf5FieldWriter::xdmfPath(const std::string& hdf5Path) {
    const std::size_t dot = hdf5Path.find_last_of('.');
    const std::size_t slash = hdf5Path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return hdf5Path + ".xmf";
    return hdf5Path.substr(0, dot) + ".xmf";
}

Hdf5FieldWriter::Hdf5FieldWriter(const FieldOutputSetup& setup) : setup_(setup), columns_(derivedColumns(setup.layout)) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by InputError below
    file_ = H5Fcreate(setup.path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file_ < 0) throw InputError("-o: cannot create the HDF5 file " + setup.path);
    writeStringAttribute(file_, "description", joined(setup.comments));
    writeStringAttribute(file_, "coordinates", setup.coordinates.name());
    if (setup.grid) {
        const hid_t group = H5Gcreate2(file_, "/grid", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        for (int k = 0; k < 3; ++k) {
            // The cell centres of gridPoints(): the same numbers as the points' coordinates.
            std::vector<double> axis;
            for (long i = 0; i < setup.count[k]; ++i) {
                axis.push_back(setup.coordinates.resolves(k)
                                   ? setup.lo[k] + (double(i) + 0.5) * (setup.hi[k] - setup.lo[k]) / double(setup.count[k])
                                   : 0.0);
            }
            writeDataset(group, std::string(1, char('x' + k)), axis, {static_cast<unsigned long long>(axis.size())});
        }
        H5Gclose(group);
    } else {
        std::vector<double> xyz;
        for (const Vec3& p : setup.points) xyz.insert(xyz.end(), p.begin(), p.end());
        writeDataset(file_, "points", xyz, {static_cast<unsigned long long>(setup.points.size()), 3ULL});
    }
    H5Gclose(H5Gcreate2(file_, "/frames", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
}

Hdf5FieldWriter::~Hdf5FieldWriter() {
    if (file_ >= 0) H5Fclose(file_);
}

void Hdf5FieldWriter::writeDataset(std::int64_t group, const std::string& name, const std::vector<double>& values,
                                   const std::vector<unsigned long long>& shape) {
    std::vector<hsize_t> dims(shape.begin(), shape.end());
    const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
    const hid_t dataset = H5Dcreate2(group, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const herr_t status = dataset < 0 ? -1 : H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    if (dataset >= 0) H5Dclose(dataset);
    H5Sclose(space);
    if (status < 0) throw InputError("-o: writing the dataset " + name + " to " + setup_.path + " failed (disk full?)");
}

void Hdf5FieldWriter::writeFrame(double firstTime, double time, const std::vector<double>& sums) {
    const std::string groupName = frameGroup(times_.size());
    const hid_t group = H5Gcreate2(file_, groupName.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (group < 0) throw InputError("-o: cannot write the group " + groupName + " to " + setup_.path);
    writeNumberAttribute(group, "time", time);
    if (setup_.timeAverage) writeNumberAttribute(group, "firstTime", firstTime);

    const std::size_t n = setup_.points.size();
    const std::size_t fields = columns_.size();
    std::vector<double> values, table(n * fields);
    for (std::size_t p = 0; p < n; ++p) {
        values.clear();
        appendDerivedFields(setup_.layout, sums.data() + p * setup_.layout.count(), values);
        for (std::size_t f = 0; f < fields; ++f) table[f * n + p] = values[f];
    }
    const long nx = setup_.count[0], ny = setup_.count[1], nz = setup_.count[2];
    std::vector<double> field(n);
    for (std::size_t f = 0; f < fields; ++f) {
        const double* column = table.data() + f * n;
        if (setup_.grid) {
            // Our points run with z fastest (gridPoints); XDMF's 3DRectMesh wants x fastest.
            for (long i = 0; i < nx; ++i)
                for (long j = 0; j < ny; ++j)
                    for (long k = 0; k < nz; ++k) field[(k * ny + j) * nx + i] = column[(i * ny + j) * nz + k];
            writeDataset(group, columns_[f].name, field,
                         {static_cast<unsigned long long>(nz), static_cast<unsigned long long>(ny), static_cast<unsigned long long>(nx)});
        } else {
            field.assign(column, column + n);
            writeDataset(group, columns_[f].name, field, {static_cast<unsigned long long>(n)});
        }
    }
    H5Gclose(group);
    times_.push_back(time);
}

void Hdf5FieldWriter::close() {
    if (file_ < 0) return;
    writeDataset(file_, "time", times_, {static_cast<unsigned long long>(times_.size())});
    const herr_t status = H5Fclose(file_);
    file_ = -1;
    if (status < 0) throw InputError("-o: closing " + setup_.path + " failed (disk full?)");
    writeXdmf();
}

void Hdf5FieldWriter::writeXdmf() const {
    const std::string path = xdmfPath(setup_.path);
    std::ofstream out(path);
    if (!out) throw InputError("-o: cannot write " + path);
    const std::string h5 = fileName(setup_.path);
    const std::size_t n = setup_.points.size();
    const long nx = setup_.count[0], ny = setup_.count[1], nz = setup_.count[2];
    const std::string dims = setup_.grid ? std::to_string(nz) + " " + std::to_string(ny) + " " + std::to_string(nx) : std::to_string(n);
    out << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n <Domain>\n";
    out << "  <Grid Name=\"talus-cg\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (std::size_t t = 0; t < times_.size(); ++t) {
        const std::string group = frameGroup(t);
        out << "   <Grid Name=\"frame" << t << "\" GridType=\"Uniform\">\n";
        out << "    <Time Value=\"" << str(times_[t]) << "\"/>\n";
        if (setup_.grid) {
            out << "    <Topology TopologyType=\"3DRectMesh\" Dimensions=\"" << dims << "\"/>\n";
            out << "    <Geometry GeometryType=\"VXVYVZ\">\n";
            const long count[3] = {nx, ny, nz};
            for (int k = 0; k < 3; ++k) {
                out << "     <DataItem Dimensions=\"" << count[k] << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5
                    << ":/grid/" << char('x' + k) << "</DataItem>\n";
            }
        } else {
            out << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\"/>\n";
            out << "    <Geometry GeometryType=\"XYZ\">\n";
            out << "     <DataItem Dimensions=\"" << n << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5
                << ":/points</DataItem>\n";
        }
        out << "    </Geometry>\n";
        for (const OutputColumn& c : columns_) {
            out << "    <Attribute Name=\"" << c.name << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
            out << "     <DataItem Dimensions=\"" << dims << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ":"
                << group << "/" << c.name << "</DataItem>\n    </Attribute>\n";
        }
        out << "   </Grid>\n";
    }
    out << "  </Grid>\n </Domain>\n</Xdmf>\n";
    out.close();
    if (!out) throw InputError("-o: writing " + path + " failed (disk full?)");
}

}  // namespace talus::cg
