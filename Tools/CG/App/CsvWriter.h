// The CSV output of talus-cg: '#' lines that say how the fields were made (input, kernel,
// widths, coordinates, frames) and the unit of every column, one line of column names, then one
// row per point (and per frame when frames are not averaged).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "Fields/Coordinates.h"
#include "Fields/DerivedFields.h"
#include "IO/ParticleFrame.h"

namespace talus::cg {

class CsvWriter {
public:
    // Opens `path` (throws InputError naming it when it cannot be written).
    CsvWriter(const std::string& path, const Coordinates& coordinates, bool withTime,
              const std::vector<OutputColumn>& fields, const std::vector<std::string>& comments);
    // The same with the coordinate columns of the slots `axes` (0 = x, 1 = y, 2 = z), e.g. only x
    // for depth averages of an XZ grid; named by `coordinates` when given (r for cylindrical ones).
    CsvWriter(const std::string& path, const std::vector<int>& axes, bool withTime,
              const std::vector<OutputColumn>& fields, const std::vector<std::string>& comments,
              const Coordinates* coordinates = nullptr);
    ~CsvWriter();
    CsvWriter(const CsvWriter&) = delete;
    CsvWriter& operator=(const CsvWriter&) = delete;

    void writeRow(double time, const Vec3& point, const std::vector<double>& values);
    // Flushes and closes; throws InputError when the disk refused the data.
    void close();

private:
    std::string path_;
    std::FILE* file_ = nullptr;
    std::string row_;  // (the row being written)
    std::vector<int> axes_;
    bool withTime_;
};

}  // namespace talus::cg
