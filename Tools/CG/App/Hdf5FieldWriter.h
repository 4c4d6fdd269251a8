// HDF5 output of talus-cg with an XDMF companion file (Documentation/FileFormats/vtu.md:
// ParaView-readable HDF5 with XDMF; layout in Documentation/CoarseGraining.md "Output formats"):
//
//   NAME.h5   /grid/x, /grid/y, /grid/z   cell-centre coordinates per axis (a grid; length 1 and
//                                          value 0 on averaged axes), or /points (N x 3) for a list
//             /time                        the time of every frame written
//             /frames/NNNNNN/<Field>       one dataset per derived field (CSV column names), of
//                                          shape (nz, ny, nx) for a grid (x varies fastest, as
//                                          XDMF and VTK expect), (N) for a point list
//             attribute "description"      the CSV file's '#' lines
//   NAME.xmf  one structured grid (3DRectMesh, VXVYVZ) or one Polyvertex point set per frame,
//             a temporal collection over the frames; every field a node-centred scalar
//
// Uses HDF5's C API; compiled only when HDF5 is found (TALUS_CG_WITH_HDF5).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "App/FieldWriter.h"
#include "Fields/DerivedFields.h"

namespace talus::cg {

class Hdf5FieldWriter : public FieldWriter {
public:
    // Creates setup.path (throws InputError naming -o); the .xmf file is setup.path with its
    // extension replaced by .xmf, written by close().
    explicit Hdf5FieldWriter(const FieldOutputSetup& setup);
    ~Hdf5FieldWriter() override;
    Hdf5FieldWriter(const Hdf5FieldWriter&) = delete;
    Hdf5FieldWriter& operator=(const Hdf5FieldWriter&) = delete;

    void writeFrame(double firstTime, double time, const std::vector<double>& sums) override;
    void close() override;

    static std::string xdmfPath(const std::string& hdf5Path);

private:
    void writeDataset(std::int64_t group, const std::string& name, const std::vector<double>& values,
                      const std::vector<unsigned long long>& shape);
    void writeXdmf() const;

    FieldOutputSetup setup_;
    std::vector<OutputColumn> columns_;
    std::int64_t file_ = -1;  // hid_t (int64_t in HDF5 1.10 and later)
    std::vector<double> times_;
};

}  // namespace talus::cg
