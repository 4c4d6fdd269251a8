#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "FuzzEntries.h"

namespace talus::fuzz {

std::string scratchFile(const char* target, const std::uint8_t* data, std::size_t size) {
    const char* tmp = std::getenv("TMPDIR");
    const std::string path = std::string(tmp && *tmp ? tmp : "/tmp") + "/talus-fuzz-" + std::to_string(getpid()) + "-" + target;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) throw std::runtime_error("cannot write the scratch file " + path);  // (not a finding of the reader)
    return path;
}

void promise(bool holds, const std::string& what) {
    if (!holds) throw std::logic_error("accepted garbage: " + what);
}

}  // namespace talus::fuzz
