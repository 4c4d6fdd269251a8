#include "Run/ModelSummary.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace talus {

namespace {

// The parts of the law that act, over the pairs of species present: "friction 0.5 (tangential
// springs kept)" or "frictionless (no tangential force)", rolling resistance, contact ends.
template <class Law>
std::string lawParts(const PairTable<Law>& table, const std::vector<bool>& present, bool spheres, bool shaped) {
    double lowest = INFINITY, highest = 0, rolling = 0;
    bool endsTreated = false, endsPlain = false;
    for (std::size_t a = 0; a < table.count; ++a)
        for (std::size_t b = a; b < table.count; ++b) {
            if (!present[a] || !present[b]) continue;
            const Law& law = table(a, b);
            lowest = std::min(lowest, law.friction), highest = std::max(highest, law.friction);
            if constexpr (requires { law.rollingFriction; }) rolling = std::max(rolling, law.rollingFriction);
            if constexpr (requires { law.treatContactEnds; }) (law.treatContactEnds ? endsTreated : endsPlain) = true;
        }
    std::ostringstream s;
    s << Law::name << " contacts: ";
    if (!std::isfinite(lowest)) return s.str() + "no species present";
    if (highest <= 0)
        s << "frictionless (no tangential force)";
    else {
        s << "friction " << lowest;
        if (highest > lowest) s << " to " << highest;
        s << " (tangential springs kept per contact)";
    }
    if constexpr (Law::rollingResistance) {
        if (rolling > 0)
            s << ", rolling resistance up to " << rolling << " (rolling springs kept)";
        else
            s << ", no rolling resistance (rolling friction 0)";
    }
    // (Contacts with a superquadric take the law's plain step: Contacts/ShapedContactForces.h.)
    if (endsTreated && !spheres)
        s << ", contact ends plain velocity Verlet (superquadric contacts)";
    else if (endsTreated)
        s << ", contact ends treated" << (endsPlain ? " for some pairs" : "")
          << (shaped ? " between spheres (superquadric contacts: plain velocity Verlet)" : "");
    if (endsPlain && !endsTreated) s << ", contact ends plain velocity Verlet";
    return s.str();
}

const char* axisNames[] = {"x", "y", "z"};

std::string counted(std::size_t n, const std::string& what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

}  // namespace

std::string describeModel(const SimulationState& s, bool automaticSkin) {
    const ParticleStore& p = s.particles;
    std::size_t spheres = 0, shaped = 0, fixed = 0;
    std::vector<bool> present(s.species.size(), false);
    for (std::size_t i = 0; i < p.size(); ++i) {
        ++(p.hasShapes() && p.shape[i] >= 0 ? shaped : spheres);
        fixed += p.fixed[i] != 0;
        present[p.species[i]] = true;
    }
    for (const Wall& w : s.walls) present[w.species] = true;
    std::size_t cylinders = 0, revolved = 0, triangles = 0;
    for (const Wall& w : s.walls) {
        cylinders += w.isCylinder();
        revolved += w.isRevolved();
        triangles += w.isTriangle();
    }
    const std::size_t planes = s.walls.size() - cylinders - revolved - triangles;

    std::ostringstream out;
    out << "models ";
    if (spheres > 0 || shaped == 0) out << counted(spheres, "sphere") << (shaped > 0 ? " and " : "");
    if (shaped > 0) out << counted(shaped, "superquadric");
    if (fixed > 0) out << " (" << fixed << " fixed)";
    const std::size_t speciesPresent = static_cast<std::size_t>(std::count(present.begin(), present.end(), true));
    out << ", " << speciesPresent << " species; ";
    if (s.species.size() > 0)
        out << std::visit([&](const auto& table) { return lawParts(table, present, spheres > 0, shaped > 0); }, s.species.tables());
    out << "; rotation integrated";
    if (shaped > 0) out << " (rigid bodies: angular momentum and orientation)";
    if (s.gravity == Vec3::Zero())
        out << "; no gravity";
    else
        out << "; gravity (" << s.gravity.x() << ", " << s.gravity.y() << ", " << s.gravity.z() << ")";
    out << "; walls: ";
    if (s.walls.empty())
        out << "none";
    else {
        const char* separator = "";
        for (const auto& [count, kind] : {std::pair{planes, "plane"}, std::pair{cylinders, "cylinder"},
                                          std::pair{revolved, "revolved segment"}})
            if (count > 0) {
                out << separator << counted(count, kind);
                separator = ", ";
            }
        if (triangles > 0) {
            out << separator << counted(triangles, "triangle") << " in " << s.meshes.size()
                << (s.meshes.size() == 1 ? " mesh" : " meshes");
            const auto moving = std::count_if(s.meshes.begin(), s.meshes.end(), [](const auto& m) { return m->moves(); });
            if (moving > 0) out << " (" << moving << " moving)";
        }
    }
    if (s.domain.anyPeriodic()) {
        out << "; periodic along";
        for (int k = 0; k < 3; ++k)
            if (s.domain.periodic[k]) out << " " << axisNames[k];
    }
    out << "; list skin " << s.settings.skin << (automaticSkin ? " (0.2 x the smallest radius)" : "");
    return out.str();
}

}  // namespace talus
