// Where talus-cg writes the fields of each frame (or of the time average): one interface, one
// implementation per file format (Documentation/CoarseGraining.md "Output formats"):
//
//   csv   CsvFieldWriter   (CsvWriter.h): '#' lines, column names, one row per point
//   hdf5  Hdf5FieldWriter  (Hdf5FieldWriter.h): datasets per frame plus an XDMF file for ParaView
//   stat  StatFieldWriter  (StatFieldWriter.h): MercuryDPM's .stat layout
//   vtk   VtkFieldWriter   (VtkFieldWriter.h): a .pvd series of XML ImageData (.vti) files
//
// Every writer gets the additive sums of FieldSums.h and derives what it writes from them.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "Fields/Coordinates.h"
#include "Fields/FieldSums.h"
#include "IO/ParticleFrame.h"
#include "Kernels/KernelProfile.h"
#include "Kernels/WidthMatrix.h"

namespace talus::cg {

enum class OutputFormat { Csv, Hdf5, Stat, Vtk };

// "csv", "hdf5" (or "h5"), "stat", "vtk"; throws InputError naming --output-format otherwise.
OutputFormat outputFormatFromName(const std::string& name);
// The default file name for NAME: NAME.cg.csv, NAME.cg.h5, NAME.stat, NAME.cg.pvd.
std::string defaultOutputPath(OutputFormat format, const std::string& base);

// What every writer needs to know about the points and the run.
struct FieldOutputSetup {
    std::string path;
    Coordinates coordinates = Coordinates::fromName("XYZ");
    FieldSums layout;
    std::vector<Vec3> points;  // in grid order (first resolved axis slowest) for a grid
    bool grid = false;         // true: `points` is the grid gridPoints(coordinates, count, lo, hi)
    std::array<long, 3> count{1, 1, 1};  // grid points per axis (1 on averaged axes)
    Vec3 lo{0, 0, 0}, hi{0, 0, 0};       // grid range, or the domain box of the first frame
    bool timeAverage = false;
    KernelShape shape = KernelShape::Lucy;
    WidthMatrix width = WidthMatrix::isotropic(1.0);
    std::vector<std::string> comments;   // how the fields were made, one line each
};

class FieldWriter {
public:
    virtual ~FieldWriter() = default;
    // The fields of one frame at time `time` (sums[p * layout.count() + f]); for a time average
    // `firstTime` and `time` are the times of the first and last frames averaged.
    virtual void writeFrame(double firstTime, double time, const std::vector<double>& sums) = 0;
    // Finishes the file(s); throws InputError when writing failed.
    virtual void close() = 0;
};

// Throws InputError for hdf5 in a build without HDF5 (before any file is read).
void requireOutputFormatAvailable(OutputFormat format);

// Throws InputError as requireOutputFormatAvailable.
std::unique_ptr<FieldWriter> makeFieldWriter(OutputFormat format, const FieldOutputSetup& setup);

// Whether this build writes HDF5 (CMake option TALUS_WITH_HDF5 and HDF5 found).
bool hdf5Available();

}  // namespace talus::cg
