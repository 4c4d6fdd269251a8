// The options of talus-cg (Documentation/CoarseGraining.md lists them with examples).
// Parsing errors throw InputError naming the offending option.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "IO/ParticleFrame.h"
#include "Kernels/KernelProfile.h"

namespace talus::cg {

// A log-spaced range of widths for --width-scan: `count` widths from `min` to `max`.
struct WidthScanRange {
    double min = 0, max = 0;
    long count = 0;
};

struct ProgramOptions {
    bool help = false;
    std::string name;          // NAME: NAME.data, NAME.fstat, NAME.restart
    std::string dataPath;      // --data (default NAME.data)
    std::string fstatPath;     // --fstat (default NAME.fstat when it exists)
    std::string restartPath;   // --restart (default NAME.restart when it exists; "none": no)
    std::optional<bool> stress;          // --stress on|off (default: on when a .fstat is found)
    std::string outputPath;    // -o (default NAME.cg.csv, NAME.cg.h5, NAME.stat; NAME.widthscan.csv for --width-scan)
    std::string outputFormat = "csv";  // --output-format csv|hdf5|stat (App/FieldWriter.h)

    KernelShape shape = KernelShape::Lucy;  // --function
    std::optional<double> width;            // -w / --width
    std::optional<Vec3> widths;             // --widths wx wy wz
    std::optional<std::array<double, 9>> widthMatrix;  // --width-matrix bxx bxy bxz byy byz bzz
    std::string coordinates = "XYZ";        // --coordinates
    // Cylindrical coordinates (RZ, R; Fields/CylindricalCoarseGrainer.h): the drum axis.
    std::optional<int> axis;                // --axis x|y|z (default: the restart file's cylinder wall)
    std::optional<Vec3> axisPoint;          // --axis-point X Y Z (a point of the axis)
    std::optional<std::array<double, 2>> radiusRange;  // -r MIN MAX

    std::vector<long> counts;               // -n
    std::array<std::optional<std::array<double, 2>>, 3> range;  // -x -y -z
    std::string pointsPath;                 // --points

    std::optional<std::array<bool, 3>> periodic;  // --periodic x,y | none
    std::optional<std::vector<double>> densities; // --density d0,d1,...
    bool excludeFixed = false;                    // --fixed include|exclude|boundary (exclude, boundary)
    bool fixedAsBoundary = false;                 // --fixed boundary (CoarseGrainingSetup::excludedAreBoundary)
    std::vector<int> fixedSpecies;                // --fixed-species K,..: the fixed particles by species, frame by frame

    double timeMin = -1e300, timeMax = 1e300;     // --time-min, --time-max
    bool timeAverage = false;                     // --time-average
    // Time smoothing (Fields/TimeSmoothing.h): a temporal kernel of width WT over the frames.
    std::optional<double> timeSmoothing;          // --time-smoothing WT
    KernelShape timeShape = KernelShape::Lucy;    // --time-function
    std::vector<double> outputTimes;              // --output-times T1,T2,... (default: the frames)
    std::optional<double> outputStep;             // --output-step DT (times first frame + k DT)
    double progressInterval = 5;                  // --progress-interval (wall seconds)

    bool depthAverage = false;                    // --depth-average (Fields/DepthAverage.h)
    std::optional<double> bulkDensity;            // --bulk-density (default: mass-weighted mean density)
    std::optional<int> mixingSpecies;             // --mixing K (Fields/MixingIndex.h)
    std::string mixingPath;                       // --mixing-output (default: -o with .mixing.csv for .csv)

    // --width-scan (App/WidthScanRun.h, Fields/WidthScan.h; Theory/CoarseGraining.md "Choosing the
    // widths"): the two scanned directions are those given a range (default x 0.1..1000 and z
    // 0.1..10).
    bool widthScan = false;
    std::array<std::optional<WidthScanRange>, 3> scanRange;  // --scan-x, --scan-y, --scan-z MIN MAX COUNT
    std::vector<Vec3> scanPoints;                 // --scan-point X Y Z (repeatable), or --points FILE
    std::string scanField;                        // --scan-field (default Concentration_s1, Density for one species)
    double scanTolerance = 0.05;                  // --scan-tolerance (field change per decade of width)
    long scanMinParticles = 10;                   // --scan-min-particles
    std::optional<double> scanMinWidth;           // --scan-min-width (default: the mean particle diameter)
};

ProgramOptions parseOptions(int argc, const char* const* argv);
std::string usage();

}  // namespace talus::cg
