// The species (materials) of a simulation and the contact law of every pair of species.
//
// Each species has a density and a contact law; a pair of different species uses the law's
// mixing rule unless the driver sets the pair's parameters explicitly (setPair). All species of
// one simulation use the same kind of law, so the force loop is compiled once per kind and
// reads a dense table (PairTable) with no dispatch per contact (Documentation/Architecture.md "Data
// layout").
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "Species/ContactLaws.h"

namespace talus {

struct Species {
    std::string name;
    double density;
    ContactLaw law;
};

template <class Law>
struct PairTable {
    std::size_t count = 0;
    std::vector<Law> laws;  // laws[a * count + b], symmetric
    // A batched law's numbers for the force loop's lanes (Law::lane), made once with the table.
    std::vector<LaneLaw> lanes;
    const Law& operator()(std::size_t a, std::size_t b) const { return laws[a * count + b]; }
    const LaneLaw& lane(std::size_t a, std::size_t b) const { return lanes[a * count + b]; }
};

class SpeciesTable {
public:
    std::size_t add(std::string name, double density, ContactLaw law);
    // A new species that behaves exactly like `source` with every species, itself and the other
    // copies included (explicit pair laws with everything present now); returns its index. Copies
    // tell groups of particles apart without changing their physics (the maser's particles,
    // Boundaries/MaserBoundary.h), so add them after the source's pair laws are final.
    std::size_t addCopy(std::size_t source, std::string name);

    std::size_t size() const { return species_.size(); }
    const Species& operator[](std::size_t i) const { return species_.at(i); }
    Species& operator[](std::size_t i) { return species_.at(i); }

    // Explicit parameters for the pair (a, b), replacing the mixing rule.
    void setPair(std::size_t a, std::size_t b, ContactLaw law);
    // The law used between a and b (a == b: the species' own law).
    ContactLaw pairLaw(std::size_t a, std::size_t b) const;
    // Access to a pair's parameters for editing (e.g. pair<LinearSpringDashpot>(0,
    // 1).friction = 0.375); the first call copies the mixed law.
    template <class Law>
    Law& pair(std::size_t a, std::size_t b) {
        auto key = keyOf(a, b);
        auto it = pairs_.find(key);
        if (it == pairs_.end()) it = pairs_.emplace(key, pairLaw(a, b)).first;
        Law* law = std::get_if<Law>(&it->second);
        require(law != nullptr, "species pair (" + std::to_string(a) + ", " + std::to_string(b) +
                                    ") does not use the " + Law::name + " contact law");
        return *law;
    }

    // Checks densities, every pair's parameters, and that all species use one kind of law.
    void validate() const;

    // The pair table of the kind of law the species use (call validate first).
    using PairTables = ContactLawList::VariantOf<PairTable>;
    PairTables tables() const {
        return std::visit([this]<class Law>(const Law&) -> PairTables { return table<Law>(); }, species_.at(0).law);
    }
    // Whether the contacts of this kind of law keep a rolling spring (ContactHistory::rollingSpring).
    bool keepsRollingSprings() const {
        return !species_.empty() &&
               std::visit([]<class Law>(const Law&) { return Law::rollingResistance; }, species_[0].law);
    }

    template <class Law>
    PairTable<Law> table() const {
        PairTable<Law> t;
        t.count = size();
        t.laws.reserve(t.count * t.count);
        for (std::size_t a = 0; a < t.count; ++a)
            for (std::size_t b = 0; b < t.count; ++b) t.laws.push_back(std::get<Law>(pairLaw(a, b)));
        if constexpr (Law::batched)
            for (const Law& law : t.laws) t.lanes.push_back(law.lane());
        return t;
    }

    const std::map<std::pair<std::size_t, std::size_t>, ContactLaw>& explicitPairs() const { return pairs_; }
    void clear() { species_.clear(); pairs_.clear(); }

private:
    static std::pair<std::size_t, std::size_t> keyOf(std::size_t a, std::size_t b) {
        return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    }
    void checkIndex(std::size_t i) const;

    std::vector<Species> species_;
    std::map<std::pair<std::size_t, std::size_t>, ContactLaw> pairs_;
};

}  // namespace talus
