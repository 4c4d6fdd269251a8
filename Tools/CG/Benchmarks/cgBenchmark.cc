// talus-cg-benchmark: the speed of the coarse-graining library (issue 5) and its accuracy
// against the grid spacing and the kernel width. Results and method:
// Documentation/CoarseGraining/Performance.md. A program, not a timed unit test: timings depend
// on the machine and its load; the ctest smoke run only checks that it works.
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "Benchmarks/AccuracyStudy.h"
#include "Benchmarks/FilePathBenchmark.h"
#include "Benchmarks/SpeedBenchmark.h"

using namespace talus::cg::benchmark;

namespace {

const char* usage =
    "usage: talus-cg-benchmark [options]\n"
    "  --particles N,N,...    particle counts of the speed benchmark (default 10000,100000; 0: skip it)\n"
    "  --points-per-axis n    grid of n^3 points (default 22: 10648 points)\n"
    "  --width W              Lucy width of the speed benchmark (default 1; particle radius 0.5)\n"
    "  --species 1|2          species in the random frames (default 2)\n"
    "  --repeats R            repetitions per particle count, the fastest is reported (default 3)\n"
    "  --study full|quick|off the speed-against-error study (default full)\n"
    "  --file-path N          the whole path from .data and .fstat files to fields for about N particles\n"
    "                         on a lattice with their contacts, stage by stage (default 0: off)\n"
    "  --directory DIR        where --file-path writes its files, and keeps them (default: a temporary\n"
    "                         folder, removed afterwards)\n";

std::vector<long> parseCounts(const std::string& text) {
    std::vector<long> counts;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        const long n = std::stol(item);
        if (n < 0) throw std::invalid_argument("--particles: counts must be 0 or more, found " + item);
        if (n > 0) counts.push_back(n);
    }
    return counts;
}

struct Settings {
    SpeedSettings speed;
    AccuracySettings accuracy;
    FilePathSettings filePath;
    bool study = true;
};

Settings parseArguments(int argc, char** argv) {
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string option = argv[i];
        if (option == "--help") {
            std::cout << usage;
            std::exit(0);
        }
        if (i + 1 >= argc) throw std::invalid_argument(option + ": a value is missing (--help lists the options)");
        const std::string value = argv[++i];
        if (option == "--particles") {
            s.speed.particleCounts = parseCounts(value);
        } else if (option == "--points-per-axis") {
            s.speed.pointsPerAxis = std::stol(value);
            if (s.speed.pointsPerAxis < 1) throw std::invalid_argument("--points-per-axis: must be at least 1");
        } else if (option == "--width") {
            s.speed.width = std::stod(value);
            if (!(s.speed.width > 0)) throw std::invalid_argument("--width: must be positive");
        } else if (option == "--species") {
            s.speed.speciesCount = std::stoi(value);
            if (s.speed.speciesCount != 1 && s.speed.speciesCount != 2) throw std::invalid_argument("--species: 1 or 2");
        } else if (option == "--repeats") {
            s.speed.repeats = std::stoi(value);
            if (s.speed.repeats < 1) throw std::invalid_argument("--repeats: must be at least 1");
        } else if (option == "--file-path") {
            s.filePath.particles = std::stol(value);
            if (s.filePath.particles < 0) throw std::invalid_argument("--file-path: must be 0 or more");
        } else if (option == "--directory") {
            s.filePath.directory = value;
        } else if (option == "--study") {
            if (value == "quick") {
                // The smoke test: a few thousandths of a second, every code path of the study.
                s.accuracy.widths = {1};
                s.accuracy.spacings = {0.5, 0.25};
            } else if (value == "off") {
                s.study = false;
            } else if (value != "full") {
                throw std::invalid_argument("--study: full, quick or off, found '" + value + "'");
            }
        } else {
            throw std::invalid_argument("unknown option '" + option + "' (--help lists the options)");
        }
    }
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Settings settings = parseArguments(argc, argv);
        ProgressLog progress;
        if (!settings.speed.particleCounts.empty()) runSpeedBenchmark(settings.speed, std::cout, progress);
        if (settings.filePath.particles > 0) {
            FilePathSettings filePath = settings.filePath;
            filePath.repeats = settings.speed.repeats;
            runFilePathBenchmark(filePath, std::cout, progress);
        }
        if (settings.study) runAccuracyStudy(settings.accuracy, std::cout, progress);
        std::cerr << "talus-cg-benchmark: done\n";
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "talus-cg-benchmark: " << error.what() << "\n";
        return 1;
    }
}
