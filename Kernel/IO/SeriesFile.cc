#include "IO/SeriesFile.h"

#include <cerrno>

#include "Error.h"
#include "IO/DurableFile.h"
#include "Simulation.h"

namespace talus {

SeriesFile::SeriesFile(Simulation& simulation, std::string suffix, std::string header)
    : simulation_(simulation), suffix_(std::move(suffix)), header_(std::move(header)) {
    simulation_.keepInRestart("file." + suffix_, [this] { return save(); },
                              [this](const std::vector<double>& saved) { restore(saved); });
}

SeriesFile::~SeriesFile() {
    if (file_) std::fclose(file_);
}

void SeriesFile::open() {
    path_ = simulation_.name() + "." + suffix_;
    if (restarted_) cutBackToRestartPoint(path_, restartBytes_);  // lines after the restart point go
    errno = 0;
    file_ = std::fopen(path_.c_str(), restarted_ ? "ab" : "wb");
    if (!file_) throwWriteError(path_);
    bytes_ = restarted_ ? restartBytes_ : 0;
    if (bytes_ == 0) append(header_);
}

void SeriesFile::append(const std::string& lines) {
    if (simulation_.rank() != 0) return;
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
