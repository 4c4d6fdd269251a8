#include "App/RunInputs.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "IO/InputError.h"

namespace talus::cg {

namespace {

bool exists(const std::string& path) {
    std::error_code error;
    return !path.empty() && std::filesystem::is_regular_file(path, error);
}

// --fixed exclude|boundary: the fixed particles of the restart file, or with --fixed-species
// those of the species named, marked in each frame.
void applyFixedParticles(const ProgramOptions& options, RunInputs& in) {
    if (!options.excludeFixed) return;
    in.setup.excludedAreBoundary = options.fixedAsBoundary;
    if (!options.fixedSpecies.empty()) return;  // (frame by frame: fixedBySpecies)
    if (!in.restart) {
        throw InputError(std::string("--fixed ") + (options.fixedAsBoundary ? "boundary" : "exclude") +
                         ": needs a restart file to know which particles are fixed (--restart FILE)");
    }
    in.setup.excluded = in.restart->fixed;
    in.setup.excludedAreBoundary = options.fixedAsBoundary;
}

}  // namespace

std::vector<bool> fixedBySpecies(const ParticleFrame& frame, const std::vector<int>& species) {
    std::vector<bool> fixed(frame.size(), false);
    for (std::size_t i = 0; i < frame.size(); ++i)
        fixed[i] = std::find(species.begin(), species.end(), frame.species[i]) != species.end();
    return fixed;
}

void resolveDrumAxis(const ProgramOptions& options, RunInputs& in, std::ostream& log) {
    Coordinates& coordinates = in.setup.coordinates;
    const std::string flag = "--coordinates " + coordinates.name();
    // A cylinder wall of the restart file along x, y or z (Talus drums, addCylinderWall).
    const CylinderWall* wall = nullptr;
    int wallAxis = -1;
    if (in.restart) {
        for (const CylinderWall& c : in.restart->cylinders) {
            int along = -1;
            for (int k = 0; k < 3; ++k) {
                const bool unit = std::abs(std::abs(c.axisDirection[k]) - 1) < 1e-12;
                const bool others = std::abs(c.axisDirection[(k + 1) % 3]) < 1e-12 && std::abs(c.axisDirection[(k + 2) % 3]) < 1e-12;
                if (unit && others) along = k;
            }
            if (along >= 0 && (!options.axis || *options.axis == along)) {
                wall = &c;
                wallAxis = along;
                break;
            }
        }
    }
    if (!options.axis && !wall) {
        throw InputError(flag + ": no drum axis: give --axis x|y|z and --axis-point X Y Z (" +
                         (in.restart ? in.restartPath + " has no cylinder wall along x, y or z" : std::string("no restart file")) + ")");
    }
    if (!options.axisPoint && !wall) {
        throw InputError("--axis-point: give a point of the drum axis, X Y Z (" +
                         (in.restart ? in.restartPath + " has no cylinder wall along " + std::string(1, axisLetter(*options.axis))
                                     : std::string("no restart file")) + ")");
    }
    const int axis = options.axis ? *options.axis : wallAxis;
    const Vec3 point = options.axisPoint ? *options.axisPoint : Vec3{wall->axisPoint[0], wall->axisPoint[1], wall->axisPoint[2]};
    coordinates.setAxis(axis, point);
    if (wall) in.drumRadius = wall->radius;
    log << "talus-cg: drum axis along " << axisLetter(axis) << " through (" << str(point[0]) << ", " << str(point[1]) << ", "
        << str(point[2]) << ")" << (options.axis && options.axisPoint ? "" : " (from " + in.restartPath + ")")
        << (wall ? ", drum radius " + str(wall->radius) : std::string()) << "\n";
}

std::string commaList(const std::vector<double>& values) {
    std::string text;
    for (double v : values) {
        if (!text.empty()) text += ',';
        text += str(v);
    }
    return text;
}

std::string periodicText(const std::array<bool, 3>& periodic) {
    std::string text;
    for (int k = 0; k < 3; ++k) {
        if (!periodic[k]) continue;
        if (!text.empty()) text += ',';
        text += axisLetter(k);
    }
    return text.empty() ? "none" : text;
}

RunInputs resolveRunInputs(const ProgramOptions& options, std::ostream& log, bool wantStress) {
    RunInputs in;
    in.dataPath = options.dataPath.empty() ? options.name + ".data" : options.dataPath;
    in.base = options.name.empty() ? in.dataPath.substr(0, in.dataPath.size() - (in.dataPath.ends_with(".data") ? 5 : 0))
                                   : options.name;

    // Restart file: densities, periodic directions, fixed particles.
    in.restartPath = options.restartPath;
    if (in.restartPath.empty() && exists(in.base + ".restart")) in.restartPath = in.base + ".restart";
    if (in.restartPath == "none") in.restartPath.clear();
    if (!in.restartPath.empty()) {
        in.restart = readRestartFile(in.restartPath);
        log << "talus-cg: " << in.restartPath << " (" << in.restart->writer << "): densities " << commaList(in.restart->speciesDensity)
            << ", periodic " << periodicText(in.restart->periodic) << ", " << in.restart->fixed.size() << " particles"
            << shapesSummary(*in.restart) << "\n";
    }

    CoarseGrainingSetup& setup = in.setup;
    setup.shape = options.shape;
    setup.coordinates = Coordinates::fromName(options.coordinates);
    if (setup.coordinates.isCylindrical()) resolveDrumAxis(options, in, log);
    if (options.widthMatrix) setup.width = WidthMatrix::full(*options.widthMatrix);
    else if (options.widths) setup.width = WidthMatrix::diagonal((*options.widths)[0], (*options.widths)[1], (*options.widths)[2]);
    else setup.width = WidthMatrix::isotropic(options.width.value_or(1.0));
    setup.speciesDensity = options.densities ? *options.densities
                           : in.restart      ? in.restart->speciesDensity
                                             : std::vector<double>{6.0 / std::numbers::pi};
    if (!options.densities && !in.restart) {
        // The default 6/pi (Theory/Chutes.md "Units and axes": d = 1 has mass 1) for every species
        // the data will show.
        setup.speciesDensity.assign(16, 6.0 / std::numbers::pi);
    }
    setup.periodic = options.periodic ? *options.periodic : in.restart ? in.restart->periodic : std::array<bool, 3>{false, false, false};
    applyFixedParticles(options, in);

    in.fstatPath = options.fstatPath;
    if (in.fstatPath.empty() && exists(in.base + ".fstat")) in.fstatPath = in.base + ".fstat";
    setup.contactStress = options.stress.value_or(wantStress && !in.fstatPath.empty());
    if (setup.contactStress && in.fstatPath.empty()) {
        throw InputError("--stress on: no contact file (" + in.base + ".fstat not found; give --fstat FILE)");
    }
    return in;
}

void fitSpeciesToFrame(const ProgramOptions& options, RunInputs& inputs, const ParticleFrame& frame) {
    if (options.densities || inputs.restart) return;
    int species = 1;
    for (int s : frame.species) species = std::max(species, s + 1);
    if (species > 16) throw InputError(inputs.dataPath + ": species index " + std::to_string(species - 1) + " needs --density");
    inputs.setup.speciesDensity.resize(species);
}

FrameStream::FrameStream(const RunInputs& inputs, const ProgramOptions& options)
    : inputs_(inputs), timeMin_(options.timeMin), timeMax_(options.timeMax), data_(inputs.dataPath) {
    if (inputs.setup.contactStress) fstat_.emplace(inputs.fstatPath);
}

bool FrameStream::next(ParticleFrame& frame, ContactFrame& contacts) {
    while (true) {
        const long headerLine = data_.file().lineNumber() + 1;
        // (Without contacts, the frames before the window are skipped unparsed; a .fstat file
        // is read frame for frame with the .data file.)
        if (!data_.readFrame(frame, fstat_ ? -std::numeric_limits<double>::infinity() : timeMin_)) return false;
        const double time = frame.time;
        ++frameIndex_;
        if (fstat_) {
            // Room for 8 lines per particle (both sides of 4 contacts: a dense packing has about
            // 3 per particle); pages not written to cost nothing.
            if (!fstat_->readFrame(contacts, 8 * frame.size())) {
                throw InputError(inputs_.fstatPath + ": ends before the frame at t = " + str(time) + " of " + inputs_.dataPath +
                                 " (line " + std::to_string(headerLine) + ")");
            }
            if (std::abs(contacts.time - time) > 1e-9 * std::max(1.0, std::abs(time))) {
                throw InputError(inputs_.fstatPath + " line " + std::to_string(contacts.headerLine) + ": frame time " +
                                 str(contacts.time) + " differs from the time " + str(time) + " of frame " +
                                 std::to_string(frameIndex_) + " of " + inputs_.dataPath + " (line " +
                                 std::to_string(frame.headerLine) + ")");
            }
        }
        if (time < timeMin_) continue;
        if (time > timeMax_) return false;
        if (inputs_.restart) applyRestartShapes(*inputs_.restart, frame, inputs_.dataPath);
        return true;
    }
}

double FrameStream::fractionRead() {
    TextFile& file = data_.file();
    return double(file.bytesRead()) / double(std::max<std::uintmax_t>(file.size(), 1));
}

}  // namespace talus::cg
