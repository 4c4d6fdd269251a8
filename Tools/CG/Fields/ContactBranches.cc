#include "Fields/ContactBranches.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "IO/InputError.h"

namespace talus::cg {

namespace {
std::string lineOf(const std::string& path, long line) { return path + " line " + std::to_string(line); }
}  // namespace

void forEachContactBranch(const ParticleFrame& frame, const ContactFrame& contacts, const CoarseGrainingSetup& setup,
                          const std::string& dataPath, const std::string& fstatPath,
                          const std::function<void(const ContactBranch&)>& visit,
                          const std::function<bool(const Vec3&)>& wanted) {
    const std::size_t n = frame.size();
    // A pair may be written once (Talus and MercuryDPM skip the side of a fixed particle) or
    // once from each side (fstat.md): the lines of a pair are grouped (sorted by pair key; each
    // wall line alone) and become one branch carrying the mean of their forces, so every
    // contact counts once whichever convention the file follows, and a pair written twice is
    // spread once (half the work and memory of a frame).
    std::vector<std::pair<std::uint64_t, std::uint32_t>> order;  // (pair key, line index)
    order.reserve(contacts.contacts.size());
    for (std::size_t k = 0; k < contacts.contacts.size(); ++k) {
        const ContactLine& c = contacts.contacts[k];
        if (c.i >= static_cast<long>(n) || c.j >= static_cast<long>(n)) {
            throw InputError(lineOf(fstatPath, c.line) + ": particle " + std::to_string(std::max(c.i, c.j)) +
                             " is not in the .data frame at t = " + str(frame.time) + " (" + std::to_string(n) +
                             " particles; files of runs that deleted particles are not supported yet)");
        }
        const std::uint64_t pairKey = c.isWall() ? (std::uint64_t{1} << 63) | k
                                                 : (static_cast<std::uint64_t>(std::min(c.i, c.j)) << 32) |
                                                       static_cast<std::uint64_t>(std::max(c.i, c.j));
        if (wanted && !wanted(c.point)) continue;  // (after the checks of its indices)
        // (Lines that are each a contact of their own keep their order, each its own group.)
        order.emplace_back(contacts.eachContactOnce ? std::uint64_t{k} : pairKey, static_cast<std::uint32_t>(k));
    }
    if (!contacts.eachContactOnce) std::sort(order.begin(), order.end());
    // (1/length once per frame, not a division per axis and contact.)
    Vec3 length, inverseLength;
    for (int k = 0; k < 3; ++k) {
        length[k] = frame.box.length(k);
        inverseLength[k] = length[k] > 0 ? 1 / length[k] : 0.0;
    }
    auto minimumImage = [&](Vec3 d) {
        for (int k = 0; k < 3; ++k) {
            if (length[k] > 0) d[k] -= length[k] * std::round(d[k] * inverseLength[k]);
        }
        return d;
    };
    // Whether particle p is part of the boundary (--fixed boundary and fixed).
    auto inBoundary = [&](long p) {
        return setup.excludedAreBoundary && !setup.excluded.empty() && setup.excluded[static_cast<std::size_t>(p)];
    };
    // The branch of one line (weight 1) and the particle at its centre; false for a contact within
    // the boundary.
    auto branchOf = [&](const ContactLine& c, ContactBranch& branch, long& flowing) {
        const Vec3& xi = frame.position[c.i];
        const double ri = frame.radius[c.i];
        const Vec3 toCentre = minimumImage({xi[0] - c.point[0], xi[1] - c.point[1], xi[2] - c.point[2]});
        const bool shaped = frame.isShaped(c.i);
        // The contact point lies r_i - dn/2 from the centre of i (fstat.md): a cheap check that
        // the two files describe the same particles.
        const auto distance = [&] {
            return std::sqrt(toCentre[0] * toCentre[0] + toCentre[1] * toCentre[1] + toCentre[2] * toCentre[2]);
        };
        const double expected = ri - 0.5 * c.overlap;
        const double scaleOfC = std::max({std::abs(c.point[0]), std::abs(c.point[1]), std::abs(c.point[2]), 1.0});
        // (A superquadric's contact point lies within its bounding radius r, give or take the overlap.)
        if (!contacts.fromTheRun && (shaped ? !(distance() <= ri + std::abs(c.overlap) + 1e-8 * scaleOfC)
                                            : std::abs(distance() - expected) > 1e-6 * ri + 1e-8 * scaleOfC)) {
            throw InputError(lineOf(fstatPath, c.line) + ": the contact point is " + str(distance()) +
                             " from the centre of particle " + std::to_string(c.i) + " in " + dataPath +
                             " (frame t = " + str(frame.time) + "), but " +
                             (shaped ? "its bounding radius is " + str(ri) : "r - dn/2 = " + str(expected)) +
                             ": the .fstat and .data files do not describe the same particles");
        }
        // Which side flows: a wall, or a fixed particle under --fixed boundary, is the boundary;
        // a contact within the boundary is not part of the flow.
        const bool iBoundary = inBoundary(c.i);
        const bool jBoundary = c.isWall() || inBoundary(c.j);
        if (iBoundary && jBoundary) return false;
        // The flowing particle m (at x_m), the force f on it, and the branch b from the far end
        // of the segment to x_m (Theory/CoarseGraining.md eq. (10)): the partner's centre for a
        // pair (its image next to i: the normal points from j to i), the contact point for a
        // boundary contact.
        Vec3 xm = xi, f = c.force, b;
        if (!jBoundary && !iBoundary) {
            // A superquadric's centre is not r - dn along the normal from the contact: the line
            // of centres itself.
            const Vec3& xj = frame.position[c.j];
            const double length = ri + frame.radius[c.j] - c.overlap;
            if (shaped || frame.isShaped(c.j)) b = minimumImage({xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]});
            else for (int k = 0; k < 3; ++k) b[k] = length * c.normal[k];
        } else if (!iBoundary) {
            b = toCentre;
        } else {
            // The line describes the fixed side i: the flowing particle is j, pushed by -f.
            xm = frame.position[c.j];
            for (int k = 0; k < 3; ++k) f[k] = -f[k];
            b = minimumImage({xm[0] - c.point[0], xm[1] - c.point[1], xm[2] - c.point[2]});
        }
        branch.centre = xm;
        branch.branch = b;
        branch.force = f;
        branch.boundary = iBoundary || jBoundary;
        flowing = iBoundary ? c.j : c.i;
        return true;
    };
    ContactBranch branch, other;
    long centreParticle = 0, otherParticle = 0;
    for (std::size_t first = 0; first < order.size();) {
        std::size_t end = first + 1;
        while (end < order.size() && order[end].first == order[first].first) ++end;
        // The first line's branch; the force on its centre particle the mean over the lines (the
        // other side's force on its own particle turned round: both sides describe the same
        // contact, equal up to the printed digits), so the tensor f (x) b is the mean of the lines'.
        if (branchOf(contacts.contacts[order[first].second], branch, centreParticle)) {
            for (std::size_t k = first + 1; k < end; ++k) {
                branchOf(contacts.contacts[order[k].second], other, otherParticle);
                const double sign = otherParticle == centreParticle ? 1.0 : -1.0;
                for (int c = 0; c < 3; ++c) branch.force[c] += sign * other.force[c];
            }
            if (end - first > 1) {
                for (double& f : branch.force) f /= static_cast<double>(end - first);
            }
            visit(branch);
        }
        first = end;
    }
}

}  // namespace talus::cg
