// MercuryDPM's .stat layout (the file written by MercuryDPM's StatisticsVector, the
// `fstatistics` tool), column by column in Documentation/FileFormats/stat.md: a line of the 85
// field names, a line of coarse-graining parameters, then per frame (or for the time average) a
// time line and one line per point: x y z and the 85 fields, then Talus's InteractionForceX Y Z. Fields Talus does not compute are
// written as 0 so that the column positions stay MercuryDPM's.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "App/FieldWriter.h"

namespace talus::cg {

class StatFieldWriter : public FieldWriter {
public:
    // Opens setup.path and writes the two header lines (throws InputError naming -o).
    explicit StatFieldWriter(const FieldOutputSetup& setup);
    ~StatFieldWriter() override;
    StatFieldWriter(const StatFieldWriter&) = delete;
    StatFieldWriter& operator=(const StatFieldWriter&) = delete;

    void writeFrame(double firstTime, double time, const std::vector<double>& sums) override;
    void close() override;

    // The 85 names of MercuryDPM's first line, in its order, then InteractionForceX Y Z.
    static std::vector<std::string> columnNames();

private:
    FieldOutputSetup setup_;
    std::FILE* file_ = nullptr;
};

}  // namespace talus::cg
