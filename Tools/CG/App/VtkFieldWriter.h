// VTK output of talus-cg for ParaView and VTK (Documentation/CoarseGraining.md "Output formats"):
// the fields of a regular grid as XML ImageData, one `.vti` file per frame (or one for a time
// average), those of a point list (--points) as an XML UnstructuredGrid of vertices (`.vtu`),
// and a `.pvd` collection that lists them with their times.
//
//   NAME.cg.pvd              <VTKFile type="Collection">: one DataSet per frame, timestep = t
//   NAME.cg_000000.vti, ...  <VTKFile type="ImageData">: WholeExtent 0..nx-1, 0..ny-1, 0..nz-1
//                            (0 0 on averaged axes), Origin = the first cell centre, Spacing =
//                            the cell size; PointData arrays of Float64 in appended raw binary
//                            (the doubles' bits, UInt64 byte counts), x fastest; FieldData
//                            TimeValue (ParaView's frame time)
//
// Every field the CSV file writes is an array (DerivedFields.h fieldArrays): scalars with 1
// component, vectors (Momentum, Velocity, InteractionForce) with 3, tensors with 9 in row-major
// order XX XY XZ YX ... ZZ (KineticStress, symmetric, filled out from its 6 CSV columns;
// ContactStress and Stress as they are). In cylindrical coordinates the image axes are (r, -, s)
// and the components (R, Theta, Axial), named in each array's ComponentName attributes.
// Depth averages (--depth-average --output-format vtk): the image of the columns' base points,
// one point along z (at z = 0), each column of the CSV (Height, DepthAveragedVelocityX, ...) a
// scalar array.
//   NAME.cg_000000.vtu, ...  (a point list) <VTKFile type="UnstructuredGrid">: the points as
//                            given (Float64), one vertex cell (type 1) each, the same PointData
//                            arrays in the list's order
#pragma once

#include <string>
#include <vector>

#include "App/FieldWriter.h"
#include "Fields/DerivedFields.h"

namespace talus::cg {

class VtkFieldWriter : public FieldWriter {
public:
    // Checks that setup.path is a .pvd name (throws InputError naming -o); the first file is
    // written by writeFrame.
    explicit VtkFieldWriter(const FieldOutputSetup& setup);
    // Values derived elsewhere (depth averages): `columns` per point, each a scalar array.
    VtkFieldWriter(const FieldOutputSetup& setup, std::vector<OutputColumn> columns);

    void writeFrame(double firstTime, double time, const std::vector<double>& sums) override;
    // One frame of values: table[p * columns + c], p in the order of setup.points.
    void writeValues(double firstTime, double time, const std::vector<double>& table);
    // Writes the .pvd collection of the frames written.
    void close() override;

    // The file of frame `index` beside the .pvd file: out.pvd -> out_000000.vti (a grid) or
    // out_000000.vtu (a point list).
    static std::string framePath(const std::string& pvdPath, std::size_t index, bool grid);

private:
    // The point (index into setup.points) that VTK numbers `id`.
    std::size_t pointOfVtkId(std::size_t id) const;

    FieldOutputSetup setup_;
    std::vector<OutputColumn> columns_;
    std::vector<FieldArray> arrays_;
    bool fieldsOfSums_ = true;  // the fields of FieldSums (writeFrame), not a table of other values
    std::vector<double> times_;
};

}  // namespace talus::cg
