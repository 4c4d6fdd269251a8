// Writing output so that neither a kill nor a full disk leaves a file that looks whole but is
// not: a file that is replaced as a whole (the restart file, a .vtu frame, the .pvd index) is
// written to PATH.tmp in the same folder, flushed, synced to the disk and renamed over PATH
// (rename is atomic: a reader, or a run killed at any moment, sees the old file or the new one,
// never a mixture); every failure is a talus::Error naming the file and the system's reason
// ("No space left on device", "Not a directory", ...).
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <ostream>
#include <string>

namespace talus {

// Throws Error("cannot write PATH: <strerror(errno)>").
[[noreturn]] void throwWriteError(const std::string& path);

// Flushes stdio's buffer of `file` (written to `path`) and syncs it to the disk.
void flushToDisk(std::FILE* file, const std::string& path);

// A restarted run's appended file: cut back to the `bytes` the restart file recorded (dropping
// what a stopped run wrote after its restart point); an Error if it is shorter or missing.
void cutBackToRestartPoint(const std::string& path, std::uint64_t bytes);

// Writes PATH anew through `write` as described above. With syncFolder, the folder is synced
// after the rename, which makes this rename and every earlier one in the folder survive a power
// cut (one folder sync after a frame's files suffices; each costs a disk round trip).
void replaceFile(const std::string& path, const std::function<void(std::ostream&)>& write, bool syncFolder = true);

}  // namespace talus
