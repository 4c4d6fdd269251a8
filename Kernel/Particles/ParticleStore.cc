#include "Particles/ParticleStore.h"

#include <utility>

namespace talus {

void ParticleStore::removeBySwap(std::size_t i) {
    forEachArray([i](auto& array) {
        if (i + 1 != array.size()) array[i] = std::move(array.back());
        array.pop_back();
    });
}

void ParticleStore::permute(const std::vector<std::size_t>& order) {
    forEachArray([&order](auto& array) {
        std::remove_reference_t<decltype(array)> sorted;
        sorted.reserve(order.size());
        for (std::size_t k : order) sorted.push_back(array[k]);
        array.swap(sorted);
    });
}

void ParticleStore::enableShapes() {
    if (hasShapes()) return;
    shapesEnabled_ = true;
    orientation.assign(size(), Quat::Identity());
    angularMomentum.assign(size(), Vec3::Zero());
    principalInertia.assign(size(), Vec3::Zero());
    shape.assign(size(), -1);
}

void ParticleStore::reserve(std::size_t n) {
    forEachArray([n](auto& array) { array.reserve(n); });
}

}  // namespace talus
