#include "Boundaries/CylinderFilling.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "Sampling/AddedOnce.h"
#include "Sampling/ParticleSums.h"
#include "Simulation.h"

namespace talus {

CylinderFilling::CylinderFilling(double innerRadius, double length, std::vector<FillingKind> kinds, int maxAttempts)
    : innerRadius_(innerRadius), length_(length), kinds_(std::move(kinds)), maxAttempts_(maxAttempts) {
    require(!kinds_.empty(), "cylinder filling: no kind of particle");
    require(innerRadius > 0 && length > 0 && maxAttempts > 0, "cylinder filling: radius, length and attempts must be positive");
}

int CylinderFilling::fillRound(Simulation& s, std::vector<int>& inserted) const {
    require(inserted.size() == kinds_.size(), "cylinder filling: one count per kind of particle");
    std::vector<double> ownRadius;
    for (const FillingKind& k : kinds_)
        ownRadius.push_back(k.shape >= 0 ? s.shapes().at(static_cast<std::size_t>(k.shape)).boundingRadius() : k.radius);
    const double reach = innerRadius_ - *std::max_element(ownRadius.begin(), ownRadius.end());
    ParticleStore p = gatherParticles(s, allParticles());  // (the bounding spheres not to overlap)
    std::uniform_real_distribution<double> unit(0, 1);
    std::normal_distribution<double> gauss;
    std::mt19937_64& random = s.random();
    int placedInRound = 0;
    while (true) {
        std::size_t kind = kinds_.size();  // the fewest inserted below its target
        for (std::size_t k = 0; k < kinds_.size(); ++k)
            if (inserted[k] < kinds_[k].target && (kind == kinds_.size() || inserted[k] < inserted[kind])) kind = k;
        if (kind == kinds_.size()) break;
        const FillingKind& k = kinds_[kind];
        const double r = ownRadius[kind];
        bool placed = false;
        for (int attempt = 0; attempt < maxAttempts_ && !placed; ++attempt) {
            const Vec3 x(reach * (2 * unit(random) - 1), length_ * unit(random), reach * (2 * unit(random) - 1));
            if (std::hypot(x.x(), x.z()) > innerRadius_ - r) continue;
            bool free = true;
            for (std::size_t i = 0; i < p.size() && free; ++i) {
                Vec3 d = x - p.position[i];
                d.y() -= length_ * std::round(d.y() / length_);
                free = d.norm() >= r + p.radius[i];
            }
            if (!free) continue;
            placed = true;
            p.position.push_back(x), p.radius.push_back(r);
            if (k.shape < 0) {
                addParticleOnce(s, x, k.radius, k.species);
            } else {
                const Quat q = Quat(gauss(random), gauss(random), gauss(random), gauss(random)).normalized();
                addSuperquadricOnce(s, x, static_cast<std::size_t>(k.shape), k.species, q);
            }
            ++inserted[kind];
            ++placedInRound;
        }
        if (!placed) break;
    }
    return placedInRound;
}

}  // namespace talus
