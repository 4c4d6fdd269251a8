// talus-drum-angle: the dynamic angle of repose (DrumAnalysis.h, surfaceAngle) of every frame of
// a .data file, by the method the drum driver uses in the run: the same number from a run of
// another code written in the .data layout (Tools/Drum/liggghtsDumpToData.py), for a side-by-side
// comparison (Documentation/Drums/RotatingDrum.md "The angle of repose against LIGGGHTS").
//   talus-drum-angle --data FILE.data [--wall-species K] [--from T]
// One line "t angle" a frame; last, the mean and standard deviation of the frames from T on.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "DrumAnalysis.h"
#include "IO/CommandLine.h"
#include "IO/DataFileReader.h"

int main(int argc, char** argv) {
    using namespace talus;
    std::string path;
    int wallSpecies = 2;
    double from = -std::numeric_limits<double>::infinity();
    CommandLine flags;
    flags.add("data", "FILE", "the .data file whose frames to read", [&](const std::string& v) { path = v; });
    flags.add("wall-species", "K", "species index of the drum's wall particles, left out (default 2, the driver's)",
              [&](const std::string& v) { wallSpecies = CommandLine::toInt("wall-species", v); });
    flags.add("from", "T", "the mean and standard deviation over the frames from time T on",
              [&](const std::string& v) { from = CommandLine::toDouble("from", v); });
    try {
        if (!flags.parse(std::vector<std::string>(argv + 1, argv + argc))) {
            std::cout << flags.help("talus-drum-angle");
            return 0;
        }
        if (path.empty()) throw std::runtime_error("--data: give the .data file to read");
        cg::DataFileReader reader(path);
        cg::ParticleFrame frame;
        double sum = 0, sum2 = 0;
        int frames = 0;
        std::vector<std::array<double, 2>> mobile;
        while (reader.readFrame(frame)) {
            mobile.clear();
            for (std::size_t i = 0; i < frame.size(); ++i)
                if (frame.species[i] != wallSpecies) mobile.push_back({frame.position[i][0], frame.position[i][2]});
            const double angle = drum::surfaceAngle(mobile);
            std::printf("%.10g %.10g\n", frame.time, angle);
            if (frame.time >= from && std::isfinite(angle)) sum += angle, sum2 += angle * angle, ++frames;
        }
        if (frames > 0) {
            const double mean = sum / frames, sd = frames > 1 ? std::sqrt(std::max(0.0, (sum2 - frames * mean * mean) / (frames - 1))) : 0;
            std::printf("# mean %.4f sd %.4f over %d frames from t = %g\n", mean, sd, frames, from);
        }
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "talus-drum-angle: " << error.what() << "\n";
        return 1;
    }
}
