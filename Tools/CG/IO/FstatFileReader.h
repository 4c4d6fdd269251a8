// Reads the frames of a .fstat file (Documentation/FileFormats/fstat.md): per frame three '#'
// header lines, then one line per contact side `t i j cx cy cz dn dt fn |ft| nx ny nz tx ty tz`.
// The reader applies the sign conventions, so that `force` is always the force ON particle i;
// j < 0 is wall -(j+1).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "IO/ParticleFrame.h"
#include "IO/TextFile.h"

namespace talus::cg {

struct ContactLine {
    long i = 0;           // particle (line index in the .data frame)
    long j = 0;           // partner particle, or -(w+1) for wall w
    Vec3 point{};         // contact point
    Vec3 normal{};        // pairs: unit vector from j to i; walls: into the wall (as written)
    double overlap = 0;   // dn
    Vec3 force{};         // force on i: fn n + ft t for pairs, -(fn n + ft t) for walls
    long line = 0;        // line in the .fstat file, for messages
    bool isWall() const { return j < 0; }
};

struct ContactFrame {
    double time = 0;
    long headerLine = 0;
    std::vector<ContactLine> contacts;
    // Each contact is one line (a run's own contacts, InRun/InRunFrame.h), so no pair needs its
    // lines grouped; a file may write a pair from both sides (fstat.md).
    bool eachContactOnce = false;
    // The contacts and particles of one run's step (InRun/InRunFrame.h), consistent by
    // construction: no line is checked against its particles (a file's are).
    bool fromTheRun = false;
};

class FstatFileReader {
public:
    explicit FstatFileReader(const std::string& path);

    // Reads the next frame; false at the end of the file. `expectedLines`: room made for that many
    // contact lines before reading (growing a vector of 10^5 lines by doubling touches twice the
    // memory, and fresh memory costs page faults); 0 for none.
    bool readFrame(ContactFrame& frame, std::size_t expectedLines = 0);
    TextFile& file() { return file_; }

private:
    TextFile file_;
    std::string line_;
    std::vector<std::string_view> fields_;
};

std::vector<ContactFrame> readAllFstatFrames(const std::string& path);

}  // namespace talus::cg
