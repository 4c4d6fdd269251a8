#include "IO/MercuryFormats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "Formats/DataFormat.h"
#include "Formats/FstatFormat.h"

namespace talus {

namespace {

// Appends printf-formatted text (numbers only, so 64 bytes per field suffice).
template <class... Args>
void append(std::string& out, const char* format, Args... args) {
    char buffer[512];
    const int n = std::snprintf(buffer, sizeof buffer, format, args...);
    out.append(buffer, static_cast<std::size_t>(std::min<int>(n, sizeof buffer - 1)));
}

}  // namespace

std::vector<std::uint32_t> slotsById(const ParticleStore& particles) {
    std::vector<std::uint32_t> order(particles.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return particles.id[a] < particles.id[b]; });
    return order;
}

// .data: the header and a line per particle in the columns of Formats/DataFormat.h.
// Sphere orientation is not tracked, so their three angle columns are 0; a non-spherical
// particle's are the roll, pitch and yaw angles (Tait-Bryan Z-Y-X) of its orientation, as
// MercuryDPM writes them, and r is its bounding radius.
void appendDataFrame(std::string& out, const SimulationState& state, const std::vector<std::uint32_t>& order,
                     const Spill& spill) {
    const ParticleStore& p = state.particles;
    const Domain& d = state.domain;
    append(out, formats::data::headerLine, p.size(), state.time, d.lo.x(), d.lo.y(), d.lo.z(),
           d.hi.x(), d.hi.y(), d.hi.z());
    for (std::uint32_t i : order) {
        const Vec3 &x = p.position[i], &v = p.velocity[i], &w = p.angularVelocity[i];
        Vec3 th = Vec3::Zero();
        if (p.isShaped(i)) {
            const Quat& q = p.orientation[i];
            th.x() = std::atan2(2 * (q.w() * q.x() + q.y() * q.z()), 1 - 2 * (q.x() * q.x() + q.y() * q.y()));
            th.y() = std::asin(std::clamp(2 * (q.w() * q.y() - q.z() * q.x()), -1.0, 1.0));
            th.z() = std::atan2(2 * (q.w() * q.z() + q.x() * q.y()), 1 - 2 * (q.y() * q.y() + q.z() * q.z()));
        }
        // (in the order of formats::data::Column)
        append(out, formats::data::particleLine, x.x(), x.y(), x.z(), v.x(), v.y(), v.z(), p.radius[i], th.x(), th.y(),
               th.z(), w.x(), w.y(), w.z(), p.species[i]);
        if (spill && out.size() >= spillBytes) spill(out);
    }
}

// .fstat: three header lines, then a line per contact side in the columns of
// Formats/FstatFormat.h; i, j are global ids, walls are j = -(wall + 1). A pair is written from both sides
// (n and t negated on the second) except from the side of a fixed particle; a wall contact
// once, with n and t pointing into the wall as MercuryDPM writes them.
void appendFstatFrame(std::string& out, const SimulationState& state, const ContactRecordList& contacts,
                      const Spill& spill) {
    const ParticleStore& p = state.particles;
    const Domain& d = state.domain;
    double rmin = NAN, rmax = NAN;
    if (!p.empty()) {
        auto [lo, hi] = std::minmax_element(p.radius.begin(), p.radius.end());
        rmin = *lo;
        rmax = *hi;
    }
    append(out, formats::fstat::header, state.time, formats::fstat::contactPointMarker, d.lo.x(), d.lo.y(), d.lo.z(),
           d.hi.x(), d.hi.y(), d.hi.z(), rmin, rmax);
    auto line = [&](std::uint64_t i, long long j, const ContactRecord& c, double sign) {
        const double ft = c.tangentialForce.norm();
        const Vec3 t = ft > 0 ? Vec3(c.tangentialForce / ft) : Vec3::Zero();
        const Vec3 n = sign * c.normal, tt = sign * t;
        // (in the order of formats::fstat::Column)
        append(out, formats::fstat::contactLine, state.time, static_cast<unsigned long long>(i), j, c.contactPoint.x(),
               c.contactPoint.y(), c.contactPoint.z(), c.overlap, -c.springLength, c.normalForce, ft, n.x(), n.y(), n.z(), tt.x(), tt.y(),
               tt.z());
    };
    for (const ContactRecord& c : contacts) {
        const std::uint64_t idI = p.id[c.i];
        if (c.j < 0) {
            line(idI, c.j, c, -1.0);
            continue;
        }
        const auto j = static_cast<std::uint32_t>(c.j);
        const auto idJ = static_cast<long long>(p.id[j]);
        if (!p.fixed[c.i]) line(idI, idJ, c, 1.0);
        if (!p.fixed[j]) line(static_cast<std::uint64_t>(idJ), static_cast<long long>(idI), c, -1.0);
        if (spill && out.size() >= spillBytes) spill(out);
    }
}

std::string eneHeader() {
    return "time gravitEnergy traKineticEnergy rotKineticEnergy elasticEnergy centerOfMassX centerOfMassY "
           "centerOfMassZ contacts\n";
}

// .ene: right-aligned fields of width 16 with 10 significant digits (MercuryDPM's layout).
void appendEneLine(std::string& out, double time, const Energies& e, std::size_t contacts) {
    append(out, "%16.10g %16.10g %16.10g %16.10g %16.10g %16.10g %16.10g %16.10g %16zu\n", time, e.gravitational,
           e.kinetic, e.rotational, e.elastic, e.centreOfMass.x(), e.centreOfMass.y(), e.centreOfMass.z(), contacts);
}

}  // namespace talus
