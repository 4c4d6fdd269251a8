// The inputs of one talus-cg run, shared by the field evaluation (CoarseGrainingRun.h) and the
// width scan (WidthScanRun.h): which files are read (restart, .fstat), the coarse-graining setup
// they imply (densities, periodic directions, fixed particles), and the frames of the selected
// time window read in step from the .data and .fstat files.
#pragma once

#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "App/Options.h"
#include "Fields/CoarseGrainer.h"
#include "IO/DataFileReader.h"
#include "IO/FstatFileReader.h"
#include "IO/RestartFileReader.h"

namespace talus::cg {

struct RunInputs {
    std::string dataPath;
    std::string base;          // NAME, or the .data path without its extension
    std::string restartPath;   // empty: none
    std::string fstatPath;     // empty: none found
    std::optional<RestartInfo> restart;
    CoarseGrainingSetup setup;  // shape, width, coordinates, densities, periodic, excluded, contact stress
    std::optional<double> drumRadius;  // cylindrical coordinates: the radius of the restart's cylinder wall
};

// Cylindrical coordinates: the drum axis from --axis/--axis-point, else from a cylinder wall of
// the restart file along x, y or z; throws InputError naming the missing flag.
void resolveDrumAxis(const ProgramOptions& options, RunInputs& inputs, std::ostream& log);

// "x,y" or "none".
std::string periodicText(const std::array<bool, 3>& periodic);
// "1,2.5,3": numbers as the log lines show them.
std::string commaList(const std::vector<double>& values);

// Resolves the options against the files found; says on `log` what the restart file gave.
// `wantStress`: the contact stress is evaluated when a .fstat file is found (or --stress on).
RunInputs resolveRunInputs(const ProgramOptions& options, std::ostream& log, bool wantStress = true);

// --fixed-species: one flag per particle of the frame, set for the species named.
std::vector<bool> fixedBySpecies(const ParticleFrame& frame, const std::vector<int>& species);

// Without densities from --density or a restart file every species gets 6/pi: cut the default
// list to the species the first frame shows (throws when a species index is beyond 15).
void fitSpeciesToFrame(const ProgramOptions& options, RunInputs& inputs, const ParticleFrame& frame);

// The frames with --time-min <= t <= --time-max, with their contacts when the setup evaluates
// the contact stress; .data and .fstat frames must have the same times.
class FrameStream {
public:
    explicit FrameStream(const RunInputs& inputs, const ProgramOptions& options);
    // The next frame in the window; false after the last one.
    bool next(ParticleFrame& frame, ContactFrame& contacts);
    bool withContacts() const { return fstat_.has_value(); }
    // Fraction of the .data file read, for progress estimates.
    double fractionRead();

private:
    const RunInputs& inputs_;
    double timeMin_, timeMax_;
    DataFileReader data_;
    std::optional<FstatFileReader> fstat_;
    long frameIndex_ = 0;
};

}  // namespace talus::cg
