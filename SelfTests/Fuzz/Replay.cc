// Replays stored inputs through the entry functions of the fuzz targets (FuzzEntries.h):
//   talus-fuzz-replay TARGET FILE_OR_FOLDER...
// Every input must end in success or the reader's clean error; an escaping exception (or a
// sanitizer's report, in a Sanitize build) fails the replay, naming the input.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "FuzzEntries.h"

int main(int argc, char** argv) {
    using Entry = bool (*)(const std::uint8_t*, std::size_t);
    const std::map<std::string, Entry> entries = {
        {"lammps-data", talus::fuzz::lammpsData}, {"talus-restart", talus::fuzz::talusRestart},
        {"cg-data", talus::fuzz::cgData},         {"cg-fstat", talus::fuzz::cgFstat},
        {"cg-restart", talus::fuzz::cgRestart},   {"command-line", talus::fuzz::commandLine},
    };
    if (argc < 3 || !entries.count(argv[1])) {
        std::fprintf(stderr, "usage: %s TARGET FILE_OR_FOLDER... (targets:", argv[0]);
        for (const auto& [name, entry] : entries) std::fprintf(stderr, " %s", name.c_str());
        std::fprintf(stderr, ")\n");
        return 2;
    }
    const Entry entry = entries.at(argv[1]);
    std::vector<std::filesystem::path> inputs;
    for (int k = 2; k < argc; ++k) {
        if (std::filesystem::is_directory(argv[k])) {
            for (const auto& file : std::filesystem::directory_iterator(argv[k]))
                if (file.is_regular_file()) inputs.push_back(file.path());
        } else {
            inputs.emplace_back(argv[k]);
        }
    }
    std::sort(inputs.begin(), inputs.end());
    int failures = 0, accepted = 0;
    for (const auto& path : inputs) {
        std::ifstream in(path, std::ios::binary);
        const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        if (!in.good() && !in.eof()) {
            std::fprintf(stderr, "cannot read %s\n", path.c_str());
            return 2;
        }
        try {
            accepted += entry(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        } catch (const std::exception& e) {
            std::printf("FAIL %s: %s\n", path.c_str(), e.what());
            ++failures;
        } catch (...) {
            std::printf("FAIL %s: an exception of unknown type\n", path.c_str());
            ++failures;
        }
    }
    std::printf("%s: %zu inputs replayed (%d accepted, the others refused with a clean error), %d failures\n", argv[1],
                inputs.size(), accepted, failures);
    return failures == 0 ? 0 : 1;
}
