#include "App/Options.h"

#include <cctype>
#include <cmath>

#include "App/FieldWriter.h"
#include "Fields/Coordinates.h"
#include "IO/InputError.h"
#include "IO/TextFile.h"

namespace talus::cg {

namespace {

class Arguments {
public:
    Arguments(int argc, const char* const* argv) : args_(argv + 1, argv + argc) {}
    bool done() const { return at_ >= args_.size(); }
    std::string next() { return args_[at_++]; }
    bool hasValue() const { return at_ < args_.size(); }
    const std::string& peek() const { return args_[at_]; }

    std::string text(const std::string& option) {
        if (!hasValue()) throw InputError(option + ": missing value");
        return next();
    }
    double real(const std::string& option) {
        const std::string token = text(option);
        double value = 0;
        if (!toReal(token, value) || !std::isfinite(value)) throw InputError(option + ": '" + token + "' is not a number");
        return value;
    }
    long integer(const std::string& option) {
        const std::string token = text(option);
        long value = 0;
        if (!toInteger(token, value)) throw InputError(option + ": '" + token + "' is not an integer");
        return value;
    }
    bool onOff(const std::string& option) {
        const std::string token = text(option);
        if (token == "on") return true;
        if (token == "off") return false;
        throw InputError(option + ": expected on or off, found '" + token + "'");
    }

private:
    std::vector<std::string> args_;
    std::size_t at_ = 0;
};

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::string item;
    for (char c : text) {
        if (c == ',') {
            items.push_back(item);
            item.clear();
        } else {
            item += c;
        }
    }
    items.push_back(item);
    return items;
}

// MercuryCG writes options with one dash (-coordinates, -function, -timeaverage): accept those
// spellings as well as ours.
std::string canonical(const std::string& option) {
    if (option.size() > 2 && option[0] == '-' && option[1] != '-') {
        const std::string word = option.substr(1);
        if (word == "timeaverage") return "--time-average";
        if (word == "tmin") return "--time-min";
        if (word == "tmax") return "--time-max";
        if (word == "help" || word == "coordinates" || word == "function" || word == "width" || word == "points" ||
            word == "periodic" || word == "density" || word == "stress" || word == "output") {
            return "--" + word;
        }
    }
    return option;
}

// --fixed include|exclude|boundary: whether the fixed particles (of the restart file) are in the
// particle fields, and whether their contacts with flowing particles are a boundary.
void parseFixedParticles(const std::string& option, const std::string& mode, ProgramOptions& o) {
    if (mode != "include" && mode != "exclude" && mode != "boundary") {
        throw InputError(option + ": expected include, exclude or boundary, found '" + mode + "'");
    }
    o.excludeFixed = mode != "include";
    o.fixedAsBoundary = mode == "boundary";
}

}  // namespace

ProgramOptions parseOptions(int argc, const char* const* argv) {
    ProgramOptions o;
    Arguments args(argc, argv);
    while (!args.done()) {
        const std::string given = args.next();
        const std::string option = canonical(given);
        if (option == "--help" || option == "-h") {
            o.help = true;
        } else if (option == "--data") {
            o.dataPath = args.text(given);
        } else if (option == "--fstat") {
            o.fstatPath = args.text(given);
        } else if (option == "--restart") {
            o.restartPath = args.text(given);
        } else if (option == "--stress") {
            o.stress = args.onOff(given);
        } else if (option == "-o" || option == "--output") {
            o.outputPath = args.text(given);
        } else if (option == "--function") {
            o.shape = kernelShapeFromName(args.text(given));
        } else if (option == "-w" || option == "--width") {
            o.width = args.real(given);
        } else if (option == "--widths") {
            o.widths = Vec3{args.real(given), args.real(given), args.real(given)};
        } else if (option == "--width-matrix") {
            double b[6];
            for (double& value : b) value = args.real(given);
            o.widthMatrix = std::array<double, 9>{b[0], b[1], b[2], b[1], b[3], b[4], b[2], b[4], b[5]};
        } else if (option == "--coordinates") {
            o.coordinates = args.text(given);
        } else if (option == "--axis") {
            const std::string letter = args.text(given);
            if (letter != "x" && letter != "y" && letter != "z" && letter != "X" && letter != "Y" && letter != "Z") {
                throw InputError(given + ": expected the drum axis direction x, y or z, found '" + letter + "'");
            }
            o.axis = std::tolower(static_cast<unsigned char>(letter[0])) - 'x';
        } else if (option == "--axis-point") {
            o.axisPoint = Vec3{args.real(given), args.real(given), args.real(given)};
        } else if (option == "-r") {
            const double lo = args.real(given), hi = args.real(given);
            if (!(lo >= 0) || !(hi > lo)) {
                throw InputError(given + ": the radius range must have 0 <= min < max, found " + str(lo) + " " + str(hi));
            }
            o.radiusRange = std::array<double, 2>{lo, hi};
        } else if (option == "-n") {
            o.counts.clear();
            o.counts.push_back(args.integer(given));
            long value = 0;
            while (o.counts.size() < 3 && args.hasValue() && toInteger(args.peek(), value)) {
                args.next();
                o.counts.push_back(value);
            }
        } else if (option == "-x" || option == "-y" || option == "-z") {
            const int axis = option[1] - 'x';
            const double lo = args.real(given), hi = args.real(given);
            if (!(hi > lo)) throw InputError(given + ": the range must have max > min, found " + str(lo) + " " + str(hi));
            o.range[axis] = std::array<double, 2>{lo, hi};
        } else if (option == "--points") {
            o.pointsPath = args.text(given);
        } else if (option == "--periodic") {
            const std::string list = args.text(given);
            std::array<bool, 3> periodic{false, false, false};
            if (list != "none") {
                for (const std::string& item : splitList(list)) {
                    if (item != "x" && item != "y" && item != "z" && item != "X" && item != "Y" && item != "Z") {
                        throw InputError(given + ": expected a list of x, y, z (e.g. x,y) or none, found '" + list + "'");
                    }
                    periodic[std::tolower(static_cast<unsigned char>(item[0])) - 'x'] = true;
                }
            }
            o.periodic = periodic;
        } else if (option == "--density") {
            std::vector<double> densities;
            for (const std::string& item : splitList(args.text(given))) {
                double value = 0;
                if (!toReal(item, value) || !(value > 0)) throw InputError(given + ": '" + item + "' is not a positive density");
                densities.push_back(value);
            }
            o.densities = densities;
        } else if (option == "--fixed") {
            parseFixedParticles(given, args.text(given), o);
        } else if (option == "--fixed-species") {
            o.fixedSpecies.clear();
            for (const std::string& item : splitList(args.text(given))) {
                long value = -1;
                if (!toInteger(item, value) || value < 0 || value > 1000)
                    throw InputError(given + ": '" + item + "' is not a species index (0, 1, ...)");
                o.fixedSpecies.push_back(static_cast<int>(value));
            }
        } else if (option == "--time-min") {
            o.timeMin = args.real(given);
        } else if (option == "--time-max") {
            o.timeMax = args.real(given);
        } else if (option == "--time-average") {
            o.timeAverage = true;
        } else if (option == "--time-smoothing") {
            o.timeSmoothing = args.real(given);
            if (!(*o.timeSmoothing > 0)) throw InputError(given + ": the width must be positive, found " + str(*o.timeSmoothing));
        } else if (option == "--time-function") {
            const std::string name = args.text(given);
            try {
                o.timeShape = kernelShapeFromName(name);
            } catch (const InputError&) {
                throw InputError(given + ": unknown time-smoothing function '" + name + "' (Lucy, Gauss or Heaviside)");
            }
        } else if (option == "--output-times") {
            o.outputTimes.clear();
            for (const std::string& item : splitList(args.text(given))) {
                double value = 0;
                if (!toReal(item, value) || !std::isfinite(value)) throw InputError(given + ": '" + item + "' is not a time");
                o.outputTimes.push_back(value);
            }
        } else if (option == "--output-step") {
            o.outputStep = args.real(given);
            if (!(*o.outputStep > 0)) throw InputError(given + ": the step must be positive, found " + str(*o.outputStep));
        } else if (option == "--progress-interval") {
            o.progressInterval = args.real(given);
        } else if (option == "--depth-average") {
            o.depthAverage = true;
        } else if (option == "--bulk-density") {
            o.bulkDensity = args.real(given);
            if (!(*o.bulkDensity > 0)) throw InputError(given + ": the bulk density must be positive, found " + str(*o.bulkDensity));
        } else if (option == "--mixing") {
            const long species = args.integer(given);
            if (species < 0) throw InputError(given + ": the species index must be 0 or more, found " + std::to_string(species));
            o.mixingSpecies = static_cast<int>(species);
        } else if (option == "--mixing-output") {
            o.mixingPath = args.text(given);
        } else if (option == "--output-format") {
            o.outputFormat = args.text(given);
            outputFormatFromName(o.outputFormat);  // throws for an unknown name
        } else if (option == "--width-scan") {
            o.widthScan = true;
        } else if (option == "--scan-x" || option == "--scan-y" || option == "--scan-z") {
            WidthScanRange range;
            range.min = args.real(given);
            range.max = args.real(given);
            range.count = args.integer(given);
            if (!(range.min > 0)) throw InputError(given + ": widths must be positive, found MIN " + str(range.min));
            if (!(range.max > range.min)) {
                throw InputError(given + ": empty range: MAX " + str(range.max) + " must be above MIN " + str(range.min));
            }
            if (range.count < 2) throw InputError(given + ": COUNT must be at least 2, found " + std::to_string(range.count));
            o.scanRange[option.back() - 'x'] = range;
        } else if (option == "--scan-point") {
            o.scanPoints.push_back(Vec3{args.real(given), args.real(given), args.real(given)});
        } else if (option == "--scan-field") {
            o.scanField = args.text(given);
        } else if (option == "--scan-tolerance") {
            o.scanTolerance = args.real(given);
            if (!(o.scanTolerance > 0)) throw InputError(given + ": the tolerance must be positive, found " + str(o.scanTolerance));
        } else if (option == "--scan-min-width") {
            o.scanMinWidth = args.real(given);
            if (!(*o.scanMinWidth >= 0)) throw InputError(given + ": must be 0 or more, found " + str(*o.scanMinWidth));
        } else if (option == "--scan-min-particles") {
            o.scanMinParticles = args.integer(given);
            if (o.scanMinParticles < 1) throw InputError(given + ": must be at least 1, found " + std::to_string(o.scanMinParticles));
        } else if (!given.empty() && given[0] == '-') {
            throw InputError("unknown option '" + given + "' (see --help)");
        } else if (o.name.empty()) {
            o.name = given;
            if (o.name.ends_with(".data")) o.name.resize(o.name.size() - 5);
        } else {
            throw InputError("unexpected argument '" + given + "': only one run NAME is taken (see --help)");
        }
    }
    if (o.help) return o;
    if (!o.fixedSpecies.empty() && !o.excludeFixed)
        throw InputError("--fixed-species names the fixed particles; say what to do with them: --fixed exclude or boundary");
    if (!o.fixedSpecies.empty() && o.widthScan)
        throw InputError("--fixed-species: not available with --width-scan, which takes the fixed particles from the "
                         "restart file (--fixed exclude without --fixed-species)");
    if (o.name.empty() && o.dataPath.empty()) throw InputError("no input: give a run NAME (reads NAME.data) or --data FILE (see --help)");
    if (int(o.width.has_value()) + int(o.widths.has_value()) + int(o.widthMatrix.has_value()) > 1) {
        throw InputError("--width, --widths and --width-matrix exclude each other: give one");
    }
    if (!o.pointsPath.empty() && !o.counts.empty() && !o.widthScan) throw InputError("-n and --points exclude each other: give one");
    if ((o.depthAverage || o.mixingSpecies) && !o.pointsPath.empty()) {
        throw InputError(std::string(o.depthAverage ? "--depth-average" : "--mixing") +
                         " integrates over a regular grid: it cannot be used with --points");
    }
    if (Coordinates::fromName(o.coordinates).isDomainAverage()) {
        const bool range = o.range[0] || o.range[1] || o.range[2];
        if (!o.counts.empty() || range || !o.pointsPath.empty() || o.depthAverage || o.mixingSpecies || o.widthScan) {
            throw InputError(std::string(!o.counts.empty() ? "-n" : range ? "-x/-y/-z" : !o.pointsPath.empty() ? "--points"
                                         : o.depthAverage ? "--depth-average" : o.mixingSpecies ? "--mixing" : "--width-scan") +
                             ": --coordinates O gives one value per frame for the whole domain box: there are no points to choose");
        }
    }
    const bool cylindrical = Coordinates::fromName(o.coordinates).isCylindrical();
    if (!cylindrical && (o.axis || o.axisPoint || o.radiusRange)) {
        throw InputError(std::string(o.axis ? "--axis" : o.axisPoint ? "--axis-point" : "-r") +
                         ": only used with cylindrical coordinates (--coordinates RZ or R)");
    }
    if (cylindrical) {
        for (int k = 0; k < 3; ++k) {
            if (o.range[k] && (!o.axis || *o.axis != k)) {
                throw InputError(std::string("-") + axisLetter(k) + ": cylindrical coordinates resolve the distance from the axis (-r MIN MAX)" +
                                 " and the coordinate along the axis (the range flag of --axis)");
            }
        }
        if (o.depthAverage || o.mixingSpecies || o.widthScan) {
            throw InputError(std::string(o.depthAverage ? "--depth-average" : o.mixingSpecies ? "--mixing" : "--width-scan") +
                             ": not available in cylindrical coordinates (--coordinates " + o.coordinates + ")");
        }
        if (o.outputFormat != "csv" && o.outputFormat != "vtk") {
            throw InputError("--output-format " + o.outputFormat + ": cylindrical coordinates are written as csv or vtk only");
        }
    }
    if (o.timeSmoothing && o.timeAverage) throw InputError("--time-smoothing and --time-average exclude each other: give one");
    if (!o.timeSmoothing && (!o.outputTimes.empty() || o.outputStep)) {
        throw InputError(std::string(o.outputStep ? "--output-step" : "--output-times") + ": only used with --time-smoothing WT");
    }
    if (!o.outputTimes.empty() && o.outputStep) throw InputError("--output-times and --output-step exclude each other: give one");
    if (o.timeSmoothing && o.widthScan) throw InputError("--time-smoothing: not used by --width-scan");
    if (o.bulkDensity && !o.depthAverage) throw InputError("--bulk-density: only used with --depth-average");
    if (!o.mixingPath.empty() && !o.mixingSpecies) throw InputError("--mixing-output: needs --mixing K");
    if (o.outputFormat != "csv" && o.mixingSpecies) {
        throw InputError("--output-format " + o.outputFormat + ": mixing indices are written as csv only");
    }
    if (o.outputFormat != "csv" && o.outputFormat != "vtk" && o.depthAverage) {
        throw InputError("--output-format " + o.outputFormat + ": depth averages are written as csv or vtk");
    }
    const bool scanOption = o.scanRange[0] || o.scanRange[1] || o.scanRange[2] || !o.scanPoints.empty() ||
                            !o.scanField.empty();
    if (scanOption && !o.widthScan) throw InputError("--scan-x/y/z, --scan-point, --scan-field: only used with --width-scan");
    if (o.widthScan) {
        const int ranges = int(o.scanRange[0].has_value()) + int(o.scanRange[1].has_value()) + int(o.scanRange[2].has_value());
        if (ranges == 0) {
            // The thesis's scan of a chute (Denissen 2019, sec. 4.2.2): wx 0.1..1000, wz 0.1..10;
            // fewer steps.
            o.scanRange[0] = WidthScanRange{0.1, 1000, 41};
            o.scanRange[2] = WidthScanRange{0.1, 10, 21};
        } else if (ranges != 2) {
            throw InputError("--width-scan: give the ranges of exactly two directions (two of --scan-x, --scan-y, --scan-z), found " +
                             std::to_string(ranges));
        }
        if (o.scanPoints.empty() == o.pointsPath.empty()) {
            throw InputError("--width-scan: give the points either by --scan-point X Y Z (repeatable) or by --points FILE");
        }
        if (o.widthMatrix) throw InputError("--width-scan: scans diagonal widths; --width-matrix cannot be used");
        if (o.depthAverage || o.mixingSpecies || !o.counts.empty()) {
            throw InputError("--width-scan: evaluates at the scan points only; -n, --depth-average and --mixing cannot be used");
        }
        if (o.outputFormat != "csv") throw InputError("--width-scan: writes csv only, found --output-format " + o.outputFormat);
    }
    if (o.timeMax < o.timeMin) throw InputError("--time-max " + str(o.timeMax) + " is below --time-min " + str(o.timeMin));
    return o;
}

std::string usage() {
    return R"(usage: talus-cg NAME [options]     (reads NAME.data, and NAME.fstat, NAME.restart when present)

Coarse-grains DEM output (.data/.fstat of Talus or MercuryDPM) into continuum fields
(Documentation/CoarseGraining.md, Documentation/Theory/CoarseGraining.md): density, volume fraction, momentum, velocity,
kinetic stress, contact stress, the boundary's force density (InteractionForce), per-species
density and concentration.

input:
  --data FILE             particle file (default NAME.data)
  --fstat FILE            contact file for the contact stress (default NAME.fstat when present)
  --stress on|off         contact stress (default: on when a .fstat file is found)
  --restart FILE|none     densities, periodic directions, fixed particles, superquadric shapes
                          (default NAME.restart when present)
  --density d0,d1,...     density of each species (default from the restart file, else 6/pi)
  --periodic x,y|none     periodic directions (default from the restart file, else none)
  --fixed include|exclude|boundary
                          fixed particles (from the restart file) in the particle fields (include,
                          the default) or not (exclude); boundary: not, and their contacts with
                          flowing particles act as a boundary, as walls always do: stress only from
                          the flowing particle's centre to the contact point, the force as the
                          InteractionForce density at the contact point
  --fixed-species K,..    the fixed particles are those of these species, in every frame (instead
                          of the restart file's flags, which fit only frames of its particle count:
                          runs that add or delete particles, e.g. a maser-fed chute's base 2,5)

coarse-graining function:
  --function NAME         Lucy (default), Gauss or Heaviside
  -w, --width W           isotropic width (default 1): Lucy and Heaviside cut-off radius, Gauss standard deviation
  --widths WX WY WZ       a width per direction (diagonal anisotropic kernel)
  --width-matrix BXX BXY BXZ BYY BYZ BZZ
                          a symmetric positive definite width matrix B = A^-1 (rotated anisotropic kernel)
  --coordinates C         XYZ (default), XY, XZ, YZ, X, Y or Z: the resolved directions; the others
                          are averaged over the domain box of the .data header. RZ: cylindrical
                          coordinates about a drum axis (distance r and the coordinate along the
                          axis, averaged over the angle); R: also averaged along the axis; O: the
                          domain average (one value per frame: sums over the box / its volume)
  --axis x|y|z            drum axis direction for RZ and R (default: the restart file's cylinder wall)
  --axis-point X Y Z      a point of the drum axis (default: the restart file's cylinder wall)

where:
  -n N [N [N]]            grid points per resolved direction (default 100 in 1-D, 50 in 2-D, 20 in 3-D)
  -x MIN MAX, -y .., -z ..  grid range (default the domain box); points at the cell centres; for RZ
                          the flag of the axis direction gives the range along the axis (default:
                          the box if periodic along it, else the particles' range plus the kernel)
  -r MIN MAX              RZ and R: range of the distance from the axis (default 0 to the drum
                          radius of the restart file, else to the farthest particle surface)
  --points FILE           evaluate at the points of FILE instead (x y z, or the resolved coordinates, per line)

when:
  --time-min T, --time-max T   frames with T_min <= t <= T_max (default all)
  --time-average          average the fields over the selected frames (default: write every frame)
  --time-smoothing WT     smooth in time with a kernel of width WT over the frames (weights
                          normalised to sum 1 at each output time, renormalised near the ends)
  --time-function NAME    the temporal kernel: Lucy (default), Gauss or Heaviside
  --output-times T1,T2,.. output times of --time-smoothing (default: the frames' times)
  --output-step DT        output times every DT from the first frame to the last

derived (Documentation/CoarseGraining.md "Depth averages", "Mixing and segregation indices"):
  --depth-average         write, per column of the grid (per x for XZ, one row for Z), the mass per
                          area, bulk density, height, depth-averaged velocity and concentrations
                          instead of the fields; z must be resolved and its range cover the flow
  --bulk-density RHO      bulk density for the height h = mass per area / RHO (default: the
                          mass-weighted mean density of the column)
  --mixing K              mixing index M and segregation index S (Theory/CoarseGraining.md) with species K as the
                          spheres, for every frame written (or the time average)
  --mixing-output FILE    where M and S go (default: the output file with .mixing.csv for .csv)

width scan (Documentation/CoarseGraining.md "Choosing the widths"):
  --width-scan            scan diagonal widths of two directions on a log grid at the scan points, write
                          the field and its sensitivity per width pair, and choose the widths at the
                          centre of the largest plateau of insensitivity common to all points
  --scan-x MIN MAX COUNT, --scan-y .., --scan-z ..
                          COUNT log-spaced widths from MIN to MAX for the two scanned directions
                          (default --scan-x 0.1 1000 41 --scan-z 0.1 10 21); the third width comes
                          from --widths or --width (default 1)
  --scan-point X Y Z      a point of the scan (repeatable), or --points FILE
  --scan-field NAME       the field, a column name of the csv output (default Concentration_s1, or
                          Density for one species)
  --scan-tolerance T      insensitive: the field changes by at most T per decade of width towards
                          every neighbour of the scan grid (relative to the largest |field| of the
                          point unless the field is a concentration or volume fraction; default 0.05)
  --scan-min-particles N  widths whose kernel holds fewer particle centres are not trusted (default 10)
  --scan-min-width W      scanned widths below W are not trusted (default: the mean particle diameter;
                          narrower kernels resolve single particles or layers)

output:
  -o, --output FILE       output file (default NAME.cg.csv, NAME.cg.h5, NAME.stat, NAME.widthscan.csv)
  --output-format F       csv (default), hdf5 (HDF5 and an XDMF .xmf file for ParaView), stat
                          (MercuryDPM's .stat layout, Documentation/FileFormats/stat.md) or vtk
                          (a .pvd series of VTK files, one per frame: image data .vti for a
                          grid, vertices .vtu for --points)
  --progress-interval S   wall seconds between progress lines on stderr (default 5)
  --help                  this text
)";
}

}  // namespace talus::cg
