#include "Benchmarks/SyntheticFrames.h"

#include <random>

namespace talus::cg::benchmark {

ParticleFrame uniformRandomFrame(long count, double side, int speciesCount, unsigned seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(0, side);
    ParticleFrame frame;
    frame.box = {{0, 0, 0}, {side, side, side}};
    for (long i = 0; i < count; ++i) {
        frame.position.push_back({coordinate(random), coordinate(random), coordinate(random)});
        frame.velocity.push_back({0, 0, 0});
        frame.radius.push_back(0.5);
        frame.species.push_back(static_cast<int>(i % speciesCount));
    }
    return frame;
}

ParticleFrame latticeSlabFrame(int side, int height) {
    ParticleFrame frame;
    frame.box = {{0, 0, 0}, {double(side), double(side), double(height)}};
    for (int i = 0; i < side; ++i) {
        for (int j = 0; j < side; ++j) {
            for (int k = 0; k < height; ++k) {
                frame.position.push_back({i + 0.5, j + 0.5, k + 0.5});
                frame.velocity.push_back({0, 0, 0});
                frame.radius.push_back(0.5);
                frame.species.push_back(0);
            }
        }
    }
    return frame;
}

}  // namespace talus::cg::benchmark
