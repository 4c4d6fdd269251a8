// Species from material properties: each material's density, Young's modulus and Poisson ratio,
// and for each pair of materials the restitution and sliding friction, as engineering papers and
// benchmark inputs give them (SI units, or any consistent set: nothing here assumes a scale).
// Every pair, a material with itself included, gets a Hertz-Mindlin law with the effective moduli
// of the two materials (Theory/ContactLaws.md eq. (20a)), so that two materials mix by their
// elasticity and not by the mean of two laws (HertzMindlin::mix). A wall is given a material too:
// its species is the material's, its density unused.
//
//   MaterialTable materials;
//   materials.add({"M1", 2500, 1e9, 0.2});
//   materials.add({"steel", 7200, 210e9, 0.2});
//   materials.setPair("M1", "M1", {.restitution = 0.5, .friction = 0.3});
//   materials.setPair("M1", "steel", {.restitution = 0.4, .friction = 0.2});
//   materials.setPair("steel", "steel", {.restitution = 0.6, .friction = 0.5});
//   const std::vector<std::size_t> species = materials.addTo(scene().species(), 5.0);  // impact speed 5 m/s
#pragma once

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "Error.h"
#include "Species/HertzMindlin.h"
#include "Species/SpeciesTable.h"

namespace talus {

struct Material {
    std::string name;
    double density = 0;
    double youngsModulus = 0;  // E
    double poissonRatio = 0;   // nu, in (-1, 0.5)
};

// What two materials do on contact besides their elasticity.
struct MaterialPairProperties {
    double restitution = 1;  // e, in (0, 1]
    double friction = 0;     // sliding friction mu
};

class MaterialTable {
public:
    // Returns the material's index (its species' index relative to the first one addTo adds).
    std::size_t add(const Material& m) {
        require(!m.name.empty() && m.name.find_first_of(" \t\n") == std::string::npos,
                "material name '" + m.name + "': one word, not empty");
        require(index_.count(m.name) == 0, "material '" + m.name + "' is given twice");
        require(std::isfinite(m.density) && m.density > 0, "material '" + m.name + "': density must be positive");
        HertzMindlin::checkMaterial(m.youngsModulus, m.poissonRatio, "material '" + m.name + "'");
        index_[m.name] = materials_.size();
        materials_.push_back(m);
        return materials_.size() - 1;
    }

    void setPair(const std::string& a, const std::string& b, MaterialPairProperties p) {
        const std::string what = "material pair ('" + a + "', '" + b + "')";
        indexOf(a), indexOf(b);
        require(p.restitution > 0 && p.restitution <= 1, what + ": restitution must lie in (0, 1]");
        require(std::isfinite(p.friction) && p.friction >= 0, what + ": friction must not be negative");
        pairs_[key(a, b)] = p;
    }

    const Material& operator[](const std::string& name) const { return materials_[indexOf(name)]; }
    std::size_t size() const { return materials_.size(); }

    // The Hertz-Mindlin law of a pair; its time-step check at `impactSpeed` (the largest normal
    // speed a contact of the scene is expected to start with).
    HertzMindlin law(const std::string& a, const std::string& b, double impactSpeed) const {
        const auto p = pairs_.find(key(a, b));
        require(p != pairs_.end(), "material pair ('" + a + "', '" + b +
                                       "') has no restitution and friction: give them with setPair");
        const Material &ma = (*this)[a], &mb = (*this)[b];
        HertzMindlin law = HertzMindlin::betweenMaterials(ma.youngsModulus, ma.poissonRatio, mb.youngsModulus,
                                                          mb.poissonRatio, p->second.restitution);
        law.friction = p->second.friction;
        require(std::isfinite(impactSpeed) && impactSpeed > 0, "impact speed must be positive");
        law.characteristicVelocity = impactSpeed;
        return law;
    }

    // One species per material (named as the material), in the order of add, and every pair's law
    // set explicitly; every pair of materials must have been given. Returns the species' indices.
    std::vector<std::size_t> addTo(SpeciesTable& species, double impactSpeed) const {
        std::vector<std::size_t> added;
        for (const Material& m : materials_) added.push_back(species.add(m.name, m.density, law(m.name, m.name, impactSpeed)));
        for (std::size_t a = 0; a < materials_.size(); ++a)
            for (std::size_t b = a + 1; b < materials_.size(); ++b)
                species.setPair(added[a], added[b], law(materials_[a].name, materials_[b].name, impactSpeed));
        return added;
    }

private:
    std::size_t indexOf(const std::string& name) const {
        const auto it = index_.find(name);
        require(it != index_.end(), "material '" + name + "' is not in the table (add it first)");
        return it->second;
    }
    static std::pair<std::string, std::string> key(const std::string& a, const std::string& b) {
        return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    }

    std::vector<Material> materials_;
    std::map<std::string, std::size_t> index_;
    std::map<std::pair<std::string, std::string>, MaterialPairProperties> pairs_;
};

}  // namespace talus
