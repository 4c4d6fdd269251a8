// A size distribution of spheres for a filling (Boundaries/Filling.h): classes of a species and
// radii uniform in a range, drawn by number or by volume (Documentation/UserGuide/Insertion.md).
#pragma once

#include <cstddef>
#include <random>
#include <vector>

namespace talus {

// One class of a size distribution: a species, radii uniform in [minRadius, maxRadius] (equal
// for a monodisperse class), and a weight.
struct SizeClass {
    std::size_t species = 0;
    double minRadius = 0, maxRadius = 0;
    double weight = 1;

    // 4/3 pi <r^3> for r uniform in [minRadius, maxRadius]: <r^3> = (a + b)(a^2 + b^2)/4.
    double meanVolume() const;
};

// A mixture of size classes. The weights are by number (byNumber: class k is drawn with
// probability w_k / sum w) or by volume (byVolume: with probability proportional to
// w_k / meanVolume_k, so that the classes fill volumes in the ratio of their weights). The
// bidisperse mixture of the thesis's table 3.C.1 (equal volumes of d = 1 and d = 0.7937) is
//   SizeDistribution::byVolume().add(large, 0.5).add(small, 0.5 * 0.7937)
class SizeDistribution {
public:
    static SizeDistribution byNumber() { return SizeDistribution(false); }
    static SizeDistribution byVolume() { return SizeDistribution(true); }

    // A monodisperse class; a class of radii uniform in [minRadius, maxRadius]. Both check the
    // class at once (positive radii, minRadius <= maxRadius, weight >= 0).
    SizeDistribution& add(std::size_t species, double radius, double weight = 1);
    SizeDistribution& addRange(std::size_t species, double minRadius, double maxRadius, double weight = 1);

    // Throws unless there is a class and some weight is positive.
    void validate() const;

    struct Draw {
        std::size_t species;
        double radius;
    };
    Draw sample(std::mt19937_64& random) const;

    const std::vector<SizeClass>& classes() const { return classes_; }
    bool weightsByVolume() const { return byVolume_; }
    // The probability that sample() draws class k.
    double probability(std::size_t k) const;
    double largestRadius() const;

private:
    explicit SizeDistribution(bool byVolume) : byVolume_(byVolume) {}

    bool byVolume_;
    std::vector<SizeClass> classes_;
    std::vector<double> cumulative_;  // running sums of the classes' draw weights
};

}  // namespace talus
