#include "Boundaries/SizeDistribution.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "Boundaries/Region.h"
#include "Error.h"

namespace talus {

double SizeClass::meanVolume() const {
    const double a = minRadius, b = maxRadius;
    return 4.0 / 3.0 * pi * (a + b) * (a * a + b * b) / 4;
}

SizeDistribution& SizeDistribution::add(std::size_t species, double radius, double weight) {
    return addRange(species, radius, radius, weight);
}

SizeDistribution& SizeDistribution::addRange(std::size_t species, double minRadius, double maxRadius, double weight) {
    const std::string which = "size distribution: size class " + std::to_string(classes_.size());
    require(std::isfinite(minRadius) && minRadius > 0, which + ": radius must be positive, got " + str(minRadius));
    require(std::isfinite(maxRadius) && maxRadius > 0, which + ": radius must be positive, got " + str(maxRadius));
    require(minRadius <= maxRadius,
            which + ": minRadius " + str(minRadius) + " is larger than maxRadius " + str(maxRadius));
    require(std::isfinite(weight) && weight >= 0, which + ": weight must not be negative, got " + str(weight));
    const SizeClass c{species, minRadius, maxRadius, weight};
    const double drawWeight = byVolume_ ? weight / c.meanVolume() : weight;
    classes_.push_back(c);
    cumulative_.push_back((cumulative_.empty() ? 0 : cumulative_.back()) + drawWeight);
    return *this;
}

void SizeDistribution::validate() const {
    require(!classes_.empty(), "insertion: empty size distribution (add a size class with SizeDistribution::add)");
    require(cumulative_.back() > 0, "size distribution: all weights are zero (give some size class a positive weight)");
}

SizeDistribution::Draw SizeDistribution::sample(std::mt19937_64& random) const {
    if (cumulative_.empty() || !(cumulative_.back() > 0)) validate();
    const double u = uniformTop53(random) * cumulative_.back();
    // The first class whose running sum exceeds u; classes of weight 0 are never drawn.
    const std::size_t k = std::upper_bound(cumulative_.begin(), cumulative_.end(), u) - cumulative_.begin();
    const SizeClass& c = classes_[std::min(k, classes_.size() - 1)];
    return {c.species, c.minRadius + uniformTop53(random) * (c.maxRadius - c.minRadius)};
}

double SizeDistribution::probability(std::size_t k) const {
    validate();
    require(k < classes_.size(), "size distribution: size class " + std::to_string(k) + " does not exist");
    return (cumulative_[k] - (k == 0 ? 0 : cumulative_[k - 1])) / cumulative_.back();
}

double SizeDistribution::largestRadius() const {
    double r = 0;
    for (const SizeClass& c : classes_) r = std::max(r, c.maxRadius);
    return r;
}

}  // namespace talus
