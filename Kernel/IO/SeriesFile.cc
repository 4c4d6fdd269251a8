#include "IO/SeriesFile.h"

#include <cerrno>
#include <sstream>

#include "Error.h"
#include "IO/DurableFile.h"
#include "Simulation.h"

namespace talus {

SeriesFile::SeriesFile(Simulation& simulation, std::string suffix, std::string header)
    : simulation_(simulation), suffix_(std::move(suffix)), header_(std::move(header)) {
    simulation_.run().keepInRestart("file." + suffix_, [this] { return save(); },
                              [this](const std::vector<double>& saved) { restore(saved); });
}

namespace {
// "# name name ... note\n"
std::string tableHeader(const std::string& suffix, const std::vector<std::string>& columns, const std::string& note) {
    require(!columns.empty(), "series file '" + suffix + "': no columns");
    std::string header = "#";
    for (const std::string& c : columns) header.append(" ").append(c);
    if (!note.empty()) header.append(" ").append(note);
    return header.append("\n");
}
}  // namespace

SeriesFile::SeriesFile(Simulation& simulation, std::string suffix, const std::vector<std::string>& columns,
                       const std::string& note)
    : SeriesFile(simulation, suffix, tableHeader(suffix, columns, note)) {
    columns_ = columns.size();
}

void SeriesFile::write(std::initializer_list<Value> row) {
    require(row.size() == columns_, "series file '" + suffix_ + "': a row of " + std::to_string(row.size()) +
                                        " values for " + std::to_string(columns_) + " columns");
    if (simulation_.ranks().rank() != 0) return;
    std::ostringstream line;
    line.precision(precision_);
    const char* separator = "";
    for (const Value& v : row) {
        line << separator;
        if (v.isInteger)
            line << v.integer;
        else
            line << v.number;
        separator = " ";
    }
    line << '\n';
    append(line.str());
}

SeriesFile::~SeriesFile() {
    if (file_) std::fclose(file_);
}

void SeriesFile::open() {
    path_ = simulation_.settings().name + "." + suffix_;
    // (A run saved before its first line wrote no file: its restart starts the file anew.)
    const bool continuing = restarted_ && restartBytes_ > 0;
    if (continuing) cutBackToRestartPoint(path_, restartBytes_);  // lines after the restart point go
    errno = 0;
    file_ = std::fopen(path_.c_str(), continuing ? "ab" : "wb");
    if (!file_) throwWriteError(path_);
    bytes_ = continuing ? restartBytes_ : 0;
    if (bytes_ == 0) append(header_);
}

void SeriesFile::append(const std::string& lines) {
    if (simulation_.ranks().rank() != 0) return;
    if (!file_) open();
    errno = 0;
    if (std::fwrite(lines.data(), 1, lines.size(), file_) != lines.size() || std::fflush(file_) != 0)
        throwWriteError(path_);
    bytes_ += lines.size();
}

// (A run that wrote no line since its start or restart keeps the size it began with.)
std::vector<double> SeriesFile::save() {
    if (!file_) return {static_cast<double>(restarted_ ? restartBytes_ : 0)};
    flushToDisk(file_, path_);
    return {static_cast<double>(bytes_)};
}

void SeriesFile::restore(const std::vector<double>& saved) {
    require(saved.size() == 1 && saved[0] >= 0 && saved[0] < 0x1p53,
            "restart file: 'file." + suffix_ + "' is not a file size");
    restartBytes_ = static_cast<std::uint64_t>(saved[0]);
    restarted_ = true;
}

}  // namespace talus
