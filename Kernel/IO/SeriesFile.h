// A driver's own time series, NAME.SUFFIX (a header line, then one line per sample), that a
// restarted run continues exactly, as OutputFiles continues .data: at every saved frame the
// file is synced to the disk and its size kept in the restart file (Simulation::keepInRestart,
// value "file.SUFFIX"); a restarted run cuts it back to that size before it appends, dropping the
// lines a killed run wrote after its restart point (the restarted run writes them again). A
// fresh run starts the file anew. Only rank 0 writes. Every failed write is a talus::Error
// naming the file and the reason (IO/DurableFile.h).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace talus {

class Simulation;

class SeriesFile {
public:
    // Call from the driver's constructor (it registers the kept size); the file is opened at
    // the first line, when the run's name is known.
    SeriesFile(Simulation& simulation, std::string suffix, std::string header);
    ~SeriesFile();
    SeriesFile(const SeriesFile&) = delete;
    SeriesFile& operator=(const SeriesFile&) = delete;

    // Appends whole lines (ending in '\n'), flushed to the system.
    void append(const std::string& lines);

private:
    void open();
    std::vector<double> save();
    void restore(const std::vector<double>& saved);

    Simulation& simulation_;
    std::string suffix_, header_, path_;
    std::FILE* file_ = nullptr;
    std::uint64_t bytes_ = 0;             // the file's size
    std::uint64_t restartBytes_ = 0;      // the size the restart file kept
    bool restarted_ = false;
};

}  // namespace talus
