// Reads the frames of a .data file one at a time (Documentation/FileFormats/data.md): a header
// `N t xmin ymin zmin xmax ymax zmax`, then N lines `x y z vx vy vz r thx thy thz wx wy wz info`.
// Talus and MercuryDPM write the same 3-D layout; the 2-D layout is refused with a clear error.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "IO/ParticleFrame.h"
#include "IO/TextFile.h"

namespace talus::cg {

class DataFileReader {
public:
    explicit DataFileReader(const std::string& path);

    // Reads the next frame into `frame`; false at the end of the file (after a whole frame).
    // Truncated frames, wrong column counts and bad numbers throw InputError naming file and line.
    // Frames before skipBefore are skipped as skipFrame does (their lines counted, not parsed).
    bool readFrame(ParticleFrame& frame, double skipBefore = -std::numeric_limits<double>::infinity());
    // Skips the next frame cheaply (header checked, particle lines counted, not parsed);
    // returns its time, or false at the end of the file.
    bool skipFrame(double& time);

    TextFile& file() { return file_; }

private:
    bool readHeader(ParticleFrame& frame, long& count);
    void skipLines(long count, double time, long headerLine);

    TextFile file_;
    std::string line_;
    std::vector<std::string_view> fields_;
};

// All frames of a file (for tests and small files).
std::vector<ParticleFrame> readAllDataFrames(const std::string& path);

}  // namespace talus::cg
