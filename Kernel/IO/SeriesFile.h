// A driver's own time series, NAME.SUFFIX (a header line, then one line per sample), that a
// restarted run continues exactly, as OutputFiles continues .data: at every saved frame the
// file is synced to the disk and its size kept in the restart file (Simulation::keepInRestart,
// value "file.SUFFIX"); a restarted run cuts it back to that size before it appends, dropping the
// lines a killed run wrote after its restart point (the restarted run writes them again). A
// fresh run starts the file anew. Only rank 0 writes: the values given are whole-scene numbers
// that every rank holds alike (Sampling/ParticleSums.h sums them over the ranks).
// A table names its columns once, in the constructor; write() then takes one value per column
// and checks their number. Numbers are written as an ostream writes them (6 significant digits
// unless setPrecision), integers (counts, flags) as integers. Every failed write is a talus::Error
// naming the file and the reason (IO/DurableFile.h).
#pragma once

#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <type_traits>
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

    // A table: the header is "# " and the column names, then `note` (units, what a column means).
    SeriesFile(Simulation& simulation, std::string suffix, const std::vector<std::string>& columns,
               const std::string& note = "");

    // One value of a table's row: a number, or an integer (a count, a flag) written as one.
    struct Value {
        template <class T, std::enable_if_t<std::is_integral_v<T>, int> = 0>
        Value(T integer) : integer(static_cast<long long>(integer)), isInteger(true) {}
        Value(double number) : number(number) {}
        double number = 0;
        long long integer = 0;
        bool isInteger = false;
    };
    // Appends one row of a table, one value per column (on rank 0; the others return).
    void write(std::initializer_list<Value> row);
    void setPrecision(int digits) { precision_ = digits; }

    // Appends whole lines (ending in '\n'), flushed to the system.
    void append(const std::string& lines);

private:
    void open();
    std::vector<double> save();
    void restore(const std::vector<double>& saved);

    Simulation& simulation_;
    std::string suffix_, header_, path_;
    std::size_t columns_ = 0;  // of a table (0: free lines)
    int precision_ = 6;
    std::FILE* file_ = nullptr;
    std::uint64_t bytes_ = 0;             // the file's size
    std::uint64_t restartBytes_ = 0;      // the size the restart file kept
    bool restarted_ = false;
};

}  // namespace talus
