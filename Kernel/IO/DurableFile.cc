#include "IO/DurableFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "Error.h"

namespace talus {

namespace {

// fsync through a descriptor of its own (a read-only one syncs the file's data all the same).
void syncPath(const std::string& path, int flags) {
    const int fd = ::open(path.c_str(), flags);
    if (fd < 0) throwWriteError(path);
    const bool synced = ::fsync(fd) == 0 || errno == EINVAL;  // (EINVAL: a file that cannot be synced, /dev/null)
    const int error = errno;
    ::close(fd);
    errno = error;
    if (!synced) throwWriteError(path);
}

}  // namespace

void throwWriteError(const std::string& path) {
    const int error = errno;
    throw Error("cannot write " + path + ": " + (error ? std::strerror(error) : "unknown error"));
}

void flushToDisk(std::FILE* file, const std::string& path) {
    errno = 0;
    if (std::fflush(file) != 0) throwWriteError(path);
    if (::fsync(::fileno(file)) != 0 && errno != EINVAL) throwWriteError(path);
}

void cutBackToRestartPoint(const std::string& path, std::uint64_t bytes) {
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    if (error || size < bytes)
        throw Error("cannot continue " + path + ": the restart file expects at least " + std::to_string(bytes) +
                    " bytes, but it " + (error ? "does not exist" : "has " + std::to_string(size)) +
                    " (restart in the folder of the run that wrote the restart file)");
    std::filesystem::resize_file(path, bytes, error);
    if (error) throw Error("cannot cut " + path + " back to the restart point: " + error.message());
}

void replaceFile(const std::string& path, const std::function<void(std::ostream&)>& write, bool syncFolder) {
    const std::string temporary = path + ".tmp";
    {
        errno = 0;
        std::ofstream out(temporary, std::ios::binary);
        if (!out) throwWriteError(temporary);
        write(out);
        out.flush();
        if (!out) throwWriteError(temporary);
        out.close();
        if (!out) throwWriteError(temporary);
    }
    syncPath(temporary, O_RDONLY);
    errno = 0;
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
        throw Error("cannot rename " + temporary + " to " + path + ": " + std::strerror(errno));
    if (!syncFolder) return;
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    syncPath(folder.empty() ? "." : folder.string(), O_RDONLY | O_DIRECTORY);
}

}  // namespace talus
