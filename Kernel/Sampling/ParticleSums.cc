#include "Sampling/ParticleSums.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "Simulation.h"

namespace talus {

Selection allParticles() {
    return [](const ParticleStore&, std::size_t) { return true; };
}
Selection mobileParticles() {
    return [](const ParticleStore& p, std::size_t i) { return !p.fixed[i]; };
}
Selection inBox(const Vec3& lo, const Vec3& hi) {
    return [lo, hi](const ParticleStore& p, std::size_t i) {
        const Vec3& x = p.position[i];
        return x.x() >= lo.x() && x.x() < hi.x() && x.y() >= lo.y() && x.y() < hi.y() && x.z() >= lo.z() && x.z() < hi.z();
    };
}
Selection both(Selection a, Selection b) {
    return [a = std::move(a), b = std::move(b)](const ParticleStore& p, std::size_t i) { return a(p, i) && b(p, i); };
}

double particleVolume(const Simulation& s, const ParticleStore& p, std::size_t i) {
    if (p.isShaped(i)) return s.scene().shapes()[static_cast<std::size_t>(p.shape[i])].volume();
    return 4.0 / 3.0 * pi * std::pow(p.radius[i], 3);
}

namespace {

// T = L.omega/2 for a rigid body, which for a sphere is |omega|^2 I/2 (0 for a fixed particle).
double rotationalEnergy(const ParticleStore& p, std::size_t i) {
    if (p.isShaped(i)) return 0.5 * p.angularMomentum[i].dot(p.angularVelocity[i]);
    return p.invInertia[i] > 0 ? 0.5 * p.angularVelocity[i].squaredNorm() / p.invInertia[i] : 0;
}

}  // namespace

Totals totalsOver(const Simulation& simulation, const Selection& selection) {
    const ParticleStore& p = simulation.scene().particles();
    std::vector<double> sum(11, 0.0);  // count, mass, volume, translational and rotational energy, momentum, m x
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (!selection(p, i)) continue;
        const double m = p.mass[i];
        sum[0] += 1;
        sum[1] += m;
        sum[2] += particleVolume(simulation, p, i);
        sum[3] += 0.5 * m * p.velocity[i].squaredNorm();
        sum[4] += rotationalEnergy(p, i);
        for (int k = 0; k < 3; ++k) {
            sum[5 + k] += m * p.velocity[i][k];
            sum[8 + k] += m * p.position[i][k];
        }
    }
    simulation.ranks().sum(sum);
    Totals t;
    t.count = sum[0], t.mass = sum[1], t.volume = sum[2], t.translationalEnergy = sum[3], t.rotationalEnergy = sum[4];
    t.momentum = Vec3(sum[5], sum[6], sum[7]);
    t.massMoment = Vec3(sum[8], sum[9], sum[10]);
    return t;
}

std::vector<double> sumsOver(const Simulation& simulation, const Selection& selection,
                             const std::vector<ParticleQuantity>& quantities) {
    const ParticleStore& p = simulation.scene().particles();
    std::vector<double> sum(quantities.size(), 0.0);
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (!selection(p, i)) continue;
        for (std::size_t q = 0; q < quantities.size(); ++q) sum[q] += quantities[q](p, i);
    }
    simulation.ranks().sum(sum);
    return sum;
}

double sumOver(const Simulation& simulation, const Selection& selection, const ParticleQuantity& quantity) {
    return sumsOver(simulation, selection, {quantity})[0];
}

std::vector<double> sumOverScene(const Simulation& simulation, std::vector<double> parts) {
    simulation.ranks().sum(parts);
    return parts;
}

double maxOver(const Simulation& simulation, const Selection& selection, const ParticleQuantity& quantity) {
    const ParticleStore& p = simulation.scene().particles();
    double largest = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.owned(); ++i)
        if (selection(p, i)) largest = std::max(largest, quantity(p, i));
    return simulation.ranks().max(largest);
}

double minOver(const Simulation& simulation, const Selection& selection, const ParticleQuantity& quantity) {
    return -maxOver(simulation, selection, [&quantity](const ParticleStore& p, std::size_t i) { return -quantity(p, i); });
}

void forEachSelected(Simulation& simulation, const Selection& selection, const std::function<void(std::size_t)>& action) {
    const std::size_t owned = simulation.scene().particles().owned();  // (those added are appended after these)
    for (std::size_t i = 0; i < owned; ++i)
        if (selection(simulation.scene().particles(), i)) action(i);
}

ParticleStore gatherParticles(const Simulation& simulation, const Selection& selection) {
    const ParticleStore& p = simulation.scene().particles();
    std::vector<std::size_t> selected;
    for (std::size_t i = 0; i < p.owned(); ++i)
        if (selection(p, i)) selected.push_back(i);
    ParticleStore out;
    // One process holds the whole scene (one rank, or setupInitialConditions, which every rank
    // runs on the whole scene): a copy in slot order, the selected slots first, the rest cut off.
    if (!simulation.ranks().isSplit()) {
        out = p;
        out.dropGhosts();
        std::vector<std::size_t> order = selected;
        std::vector<bool> taken(out.size(), false);
        for (std::size_t i : selected) taken[i] = true;
        for (std::size_t i = 0; i < out.size(); ++i)
            if (!taken[i]) order.push_back(i);
        out.permute(order);
        out.forEachArray([&](auto& array) { array.resize(selected.size()); });
        return out;
    }
    // On ranks: each rank writes its particles' numbers into its own stretch of one list, zeros
    // elsewhere; the sum over ranks is then every rank's numbers exactly (x + 0 = x).
    constexpr std::size_t fields = 21;
    const RankContext& ranks = simulation.ranks();
    std::vector<double> counts(static_cast<std::size_t>(ranks.count()), 0.0);
    counts[static_cast<std::size_t>(ranks.rank())] = static_cast<double>(selected.size());
    ranks.sum(counts);
    const auto before = static_cast<std::size_t>(std::accumulate(counts.begin(), counts.begin() + ranks.rank(), 0.0));
    const auto total = static_cast<std::size_t>(std::accumulate(counts.begin(), counts.end(), 0.0));
    std::vector<double> numbers(total * fields, 0.0);
    for (std::size_t k = 0; k < selected.size(); ++k) {
        const std::size_t i = selected[k];
        double* n = &numbers[(before + k) * fields];
        const Quat q = p.isShaped(i) ? p.orientation[i] : Quat::Identity();
        const double row[fields] = {p.position[i].x(), p.position[i].y(), p.position[i].z(), p.velocity[i].x(),
                                    p.velocity[i].y(), p.velocity[i].z(), p.angularVelocity[i].x(),
                                    p.angularVelocity[i].y(), p.angularVelocity[i].z(), p.radius[i], p.mass[i],
                                    p.invMass[i], p.invInertia[i], double(p.species[i]), double(p.id[i]),
                                    double(p.fixed[i]), p.isShaped(i) ? double(p.shape[i]) : -1.0, q.w(), q.x(), q.y(), q.z()};
        std::copy(row, row + fields, n);
    }
    simulation.ranks().sum(numbers);
    std::vector<std::size_t> byId(total);
    std::iota(byId.begin(), byId.end(), 0);
    std::sort(byId.begin(), byId.end(), [&](std::size_t a, std::size_t b) {
        return numbers[a * fields + 14] < numbers[b * fields + 14];
    });
    if (p.hasShapes()) out.enableShapes();
    out.reserve(total);
    for (std::size_t k : byId) {
        const double* n = &numbers[k * fields];
        out.position.emplace_back(n[0], n[1], n[2]);
        out.velocity.emplace_back(n[3], n[4], n[5]);
        out.angularVelocity.emplace_back(n[6], n[7], n[8]);
        out.force.emplace_back(Vec3::Zero());
        out.torque.emplace_back(Vec3::Zero());
        out.radius.push_back(n[9]);
        out.mass.push_back(n[10]);
        out.invMass.push_back(n[11]);
        out.invInertia.push_back(n[12]);
        out.species.push_back(static_cast<std::uint32_t>(n[13]));
        out.id.push_back(static_cast<std::uint64_t>(n[14]));
        out.fixed.push_back(static_cast<std::uint8_t>(n[15]));
        out.motion.push_back(-1);
        if (!p.hasShapes()) continue;
        out.shape.push_back(static_cast<std::int32_t>(n[16]));
        out.orientation.emplace_back(n[17], n[18], n[19], n[20]);
        out.angularMomentum.emplace_back(Vec3::Zero());
        out.principalInertia.emplace_back(Vec3::Zero());
    }
    return out;
}

}  // namespace talus
