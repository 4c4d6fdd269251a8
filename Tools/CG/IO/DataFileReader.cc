#include "IO/DataFileReader.h"

#include <algorithm>
#include <cmath>

#include "Formats/DataFormat.h"
#include "IO/InputError.h"

namespace talus::cg {

namespace column = formats::data;  // the header fields and particle columns

DataFileReader::DataFileReader(const std::string& path) : file_(path) {}

bool DataFileReader::readHeader(ParticleFrame& frame, long& count) {
    // Blank lines between frames are tolerated; a file may end with one.
    do {
        if (!file_.nextLine(line_)) return false;
        splitFields(line_, fields_);
    } while (fields_.empty());
    if (fields_.size() == column::headerFields2d) {
        file_.fail("a 2-D .data header (6 fields: N t xmin ymin xmax ymax); only the 3-D layout "
                   "(8 fields) is supported");
    }
    if (fields_.size() != column::headerFields) {
        file_.fail("expected a frame header of 8 fields (N t xmin ymin zmin xmax ymax zmax), found " +
                   std::to_string(fields_.size()));
    }
    count = parseCount(fields_[column::particleCount], file_, "the particle count N");
    frame.time = parseReal(fields_[column::time], file_, "the time t");
    for (int k = 0; k < 3; ++k) {
        frame.box.lo[k] = parseReal(fields_[column::lowerCorner + k], file_, "the domain minimum");
        frame.box.hi[k] = parseReal(fields_[column::upperCorner + k], file_, "the domain maximum");
        if (frame.box.hi[k] < frame.box.lo[k]) {
            file_.fail("the domain maximum " + str(frame.box.hi[k]) + " lies below the minimum " + str(frame.box.lo[k]) +
                       " along " + "xyz"[k] + " (an inverted box)");
        }
    }
    frame.headerLine = file_.lineNumber();
    return true;
}

bool DataFileReader::readFrame(ParticleFrame& frame, double skipBefore) {
    long count = 0;
    while (true) {
        if (!readHeader(frame, count)) return false;
        if (frame.time >= skipBefore) break;
        skipLines(count, frame.time, frame.headerLine);
    }
    frame.clear();
    // A particle line has 14 numbers (column::columns): at least 28 bytes. A corrupt count
    // reserves no more than the file can hold.
    const auto reserved = static_cast<std::size_t>(std::min<std::uintmax_t>(count, file_.size() / (2 * column::columns)));
    frame.position.reserve(reserved);
    frame.velocity.reserve(reserved);
    frame.radius.reserve(reserved);
    frame.species.reserve(reserved);
    for (long p = 0; p < count; ++p) {
        if (!file_.nextLine(line_)) {
            file_.failAtLine(file_.lineNumber() + 1,
                             "file ends after " + std::to_string(p) + " of the " +
                                 std::to_string(count) + " particle lines of the frame at t = " +
                                 str(frame.time) + " (header line " +
                                 std::to_string(frame.headerLine) + "): truncated file?");
        }
        splitFields(line_, fields_);
        if (fields_.size() != column::columns) {
            file_.fail("expected " + std::to_string(column::columns) + " columns, found " +
                       std::to_string(fields_.size()));
        }
        Vec3 x, v;
        for (int k = 0; k < 3; ++k) {
            x[k] = parseReal(fields_[column::position + k], file_, "the position");
            v[k] = parseReal(fields_[column::velocity + k], file_, "the velocity");
        }
        const double r = parseReal(fields_[column::radius], file_, "the radius");
        if (!(r > 0)) file_.fail("radius must be positive, found " + std::string(fields_[column::radius]));
        // The info column is a floating-point value in general (data.md); here it must be the
        // species index, since masses come from per-species densities.
        const double info = parseReal(fields_[column::info], file_, "the info column (species)");
        if (!(info >= 0) || info != std::floor(info) || info > 1e6) {
            file_.fail("info column is " + std::string(fields_[column::info]) +
                       ", not a species index (0, 1, ...)");
        }
        frame.position.push_back(x);
        frame.velocity.push_back(v);
        frame.radius.push_back(r);
        frame.species.push_back(static_cast<int>(info));
    }
    return true;
}

void DataFileReader::skipLines(long count, double time, long headerLine) {
    for (long p = 0; p < count; ++p) {
        if (!file_.nextLine(line_)) {
            file_.failAtLine(file_.lineNumber() + 1,
                             "file ends after " + std::to_string(p) + " of the " + std::to_string(count) +
                                 " particle lines of the frame at t = " + str(time) + " (header line " +
                                 std::to_string(headerLine) + "): truncated file?");
        }
    }
}

bool DataFileReader::skipFrame(double& time) {
    ParticleFrame header;
    long count = 0;
    if (!readHeader(header, count)) return false;
    skipLines(count, header.time, header.headerLine);
    time = header.time;
    return true;
}

std::vector<ParticleFrame> readAllDataFrames(const std::string& path) {
    DataFileReader reader(path);
    std::vector<ParticleFrame> frames;
    ParticleFrame frame;
    while (reader.readFrame(frame)) frames.push_back(frame);
    if (frames.empty()) throw InputError(path + ": no frames (empty .data file)");
    return frames;
}

}  // namespace talus::cg
