#include "Chute/ChuteStatistics.h"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "Error.h"
#include "IO/DurableFile.h"
#include "Math/Vector.h"
#include "Simulation.h"

namespace talus {

namespace {

// The sums a snapshot is made of: mass, m z, m vx, kinetic energy, volume, small volume, and
// the volume-weighted heights v z of the small and of the other particles.
std::vector<double> chuteSums(const ParticleStore& p, std::size_t smallSpecies, double xMin, double xMax) {
    std::vector<double> sum(8, 0.0);
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (p.fixed[i] || !(p.position[i].x() >= xMin && p.position[i].x() < xMax)) continue;
        const double m = p.mass[i], v = 4.0 / 3.0 * pi * std::pow(p.radius[i], 3);
        sum[0] += m;
        sum[1] += m * p.position[i].z();
        sum[2] += m * p.velocity[i].x();
        sum[3] += 0.5 * m * p.velocity[i].squaredNorm() +
                  (p.invInertia[i] > 0 ? 0.5 * p.angularVelocity[i].squaredNorm() / p.invInertia[i] : 0);
        sum[4] += v;
        const bool small = p.species[i] == smallSpecies;
        if (small) sum[5] += v;
        sum[small ? 6 : 7] += v * p.position[i].z();
    }
    return sum;
}

ChuteSnapshot snapshotOf(const std::vector<double>& sum, double length, double width, double time) {
    ChuteSnapshot s;
    s.time = time;
    const double mass = sum[0], massZ = sum[1], volume = sum[4], smallVolume = sum[5];
    s.massFlux = sum[2];
    s.kineticEnergy = sum[3];
    if (mass > 0) {
        s.meanVelocity = s.massFlux / mass;
        s.height = 2 * massZ / mass;
    }
    s.massFlux /= length * width;
    s.kineticEnergy /= length * width;
    s.smallConcentration = volume > 0 ? smallVolume / volume : 0;
    const double otherVolume = volume - smallVolume;
    if (smallVolume > 0 && otherVolume > 0 && s.height > 0)
        s.segregation = (sum[7] / otherVolume - sum[6] / smallVolume) / (s.height / 2);
    return s;
}

// The fields of a snapshot, in the order of snapshotNumbers.
template <class Snapshot, class F>
void forEachField(Snapshot& s, F&& f) {
    for (auto* field : {&s.time, &s.kineticEnergy, &s.massFlux, &s.meanVelocity, &s.height, &s.smallConcentration,
                        &s.segregation})
        f(*field);
}
constexpr std::size_t snapshotFields = 7;

}  // namespace

ChuteSnapshot measureChute(const ParticleStore& p, double length, double width, std::size_t smallSpecies, double time,
                           double xMin, double xMax) {
    return snapshotOf(chuteSums(p, smallSpecies, xMin, xMax), length, width, time);
}

ChuteSnapshot measureChute(const Simulation& s, double length, double width, std::size_t smallSpecies, double xMin,
                           double xMax) {
    std::vector<double> sum = chuteSums(s.scene().particles(), smallSpecies, xMin, xMax);
    s.ranks().sum(sum);
    return snapshotOf(sum, length, width, s.time());
}

std::vector<double> snapshotNumbers(const std::vector<ChuteSnapshot>& snapshots) {
    std::vector<double> numbers;
    numbers.reserve(snapshots.size() * snapshotFields);
    for (const ChuteSnapshot& s : snapshots) forEachField(s, [&](double x) { numbers.push_back(x); });
    return numbers;
}

std::vector<ChuteSnapshot> snapshotsFromNumbers(const std::vector<double>& numbers) {
    require(numbers.size() % snapshotFields == 0, "chute snapshots: " + std::to_string(numbers.size()) +
                                                      " numbers are not a whole number of snapshots");
    std::vector<ChuteSnapshot> snapshots(numbers.size() / snapshotFields);
    std::size_t at = 0;
    for (ChuteSnapshot& s : snapshots) forEachField(s, [&](double& x) { x = numbers[at++]; });
    return snapshots;
}

MeanAndError batchMean(const std::vector<double>& samples, std::size_t batches) {
    MeanAndError r;
    if (samples.empty()) return r;
    for (double x : samples) r.mean += x;
    r.mean /= samples.size();
    const std::size_t per = samples.size() / batches;
    if (batches < 2 || per == 0) return r;
    std::vector<double> means(batches, 0);
    for (std::size_t b = 0; b < batches; ++b) {
        for (std::size_t k = 0; k < per; ++k) means[b] += samples[b * per + k];
        means[b] /= per;
    }
    double meanOfMeans = 0, variance = 0;
    for (double m : means) meanOfMeans += m;
    meanOfMeans /= batches;
    for (double m : means) variance += (m - meanOfMeans) * (m - meanOfMeans);
    variance /= batches - 1;
    r.error = std::sqrt(variance / batches);
    return r;
}

DepthProfile::DepthProfile(double bin, double top, double length, double width, std::size_t smallSpecies)
    : bin_(bin), length_(length), width_(width), smallSpecies_(smallSpecies) {
    require(bin > 0 && top > bin, "depth profile: bin must be positive and below the top");
    const auto n = static_cast<std::size_t>(std::ceil(top / bin));
    volume_.assign(n, 0);
    smallVolume_.assign(n, 0);
    mass_.assign(n, 0);
    momentum_.assign(n, 0);
}

void DepthProfile::add(const ParticleStore& p, const Simulation* s) {
    ++samples_;
    const std::size_t n = volume_.size();
    std::vector<double> sample(4 * n, 0.0);  // volume, small volume, mass, momentum per slab
    for (std::size_t i = 0; i < p.owned(); ++i) {
        if (p.fixed[i] || p.position[i].z() < 0) continue;
        const auto k = static_cast<std::size_t>(p.position[i].z() / bin_);
        if (k >= n) continue;
        const double v = 4.0 / 3.0 * pi * std::pow(p.radius[i], 3);
        sample[k] += v;
        if (p.species[i] == smallSpecies_) sample[n + k] += v;
        sample[2 * n + k] += p.mass[i];
        sample[3 * n + k] += p.mass[i] * p.velocity[i].x();
    }
    if (s && s->ranks().isSplit()) s->ranks().sum(sample);
    std::size_t at = 0;
    for (auto* sums : {&volume_, &smallVolume_, &mass_, &momentum_})
        for (std::size_t k = 0; k < n; ++k) (*sums)[k] += sample[at++];
}

std::vector<double> DepthProfile::state() const {
    std::vector<double> v = {static_cast<double>(samples_)};
    for (const auto* sums : {&volume_, &smallVolume_, &mass_, &momentum_}) v.insert(v.end(), sums->begin(), sums->end());
    return v;
}

void DepthProfile::restore(const std::vector<double>& v) {
    const std::size_t n = volume_.size();
    require(v.size() == 1 + 4 * n, "depth profile: the saved sums have " + std::to_string(v.size()) + " numbers, not " +
                                       std::to_string(1 + 4 * n));
    samples_ = static_cast<std::size_t>(v[0]);
    std::size_t at = 1;
    for (auto* sums : {&volume_, &smallVolume_, &mass_, &momentum_})
        for (std::size_t k = 0; k < n; ++k) (*sums)[k] = v[at++];
}

void DepthProfile::write(const std::string& path, const Simulation* s) const {
    if (s && s->ranks().rank() != 0) return;
    replaceFile(path, [&](std::ostream& out) {
        out << "# z volumeFraction vx smallConcentration   (" << samples_ << " samples, slabs of " << bin_ << ")\n";
        const double slab = bin_ * length_ * width_ * static_cast<double>(std::max<std::size_t>(samples_, 1));
        for (std::size_t k = 0; k < volume_.size(); ++k)
            out << (k + 0.5) * bin_ << ' ' << volume_[k] / slab << ' ' << (mass_[k] > 0 ? momentum_[k] / mass_[k] : 0)
                << ' ' << (volume_[k] > 0 ? smallVolume_[k] / volume_[k] : 0) << '\n';
    });
}

}  // namespace talus
