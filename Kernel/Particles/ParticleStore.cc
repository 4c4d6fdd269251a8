#include "Particles/ParticleStore.h"

#include <algorithm>

#include <utility>

#include "Error.h"

namespace talus {

void ParticleStore::removeBySwap(std::size_t i) {
    require(ghostCount == 0, "removing a particle while the store holds ghosts (an MPI domain split)");
    forEachArray([i](auto& array) {
        if (i + 1 != array.size()) array[i] = std::move(array.back());
        array.pop_back();
    });
}

void ParticleStore::permute(const std::vector<std::size_t>& order) {
    require(ghostCount == 0, "reordering particles while the store holds ghosts (an MPI domain split)");
    forEachArray([&order](auto& array) {
        std::remove_reference_t<decltype(array)> sorted;
        sorted.reserve(order.size());
        for (std::size_t k : order) sorted.push_back(array[k]);
        array.swap(sorted);
    });
}

void ParticleStore::dropGhosts() {
    const std::size_t n = owned();
    forEachArray([n](auto& array) { array.resize(n); });
    ghostCount = 0;
}

std::size_t ParticleStore::moveLastBeforeGhosts() {
    const std::size_t slot = size() - 1 - ghostCount;
    forEachArray([slot](auto& array) { std::rotate(array.begin() + static_cast<std::ptrdiff_t>(slot), array.end() - 1, array.end()); });
    return slot;
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
