#include "Species/SpeciesTable.h"

#include <cmath>

namespace talus {

std::size_t SpeciesTable::add(std::string name, double density, ContactLaw law) {
    require(std::isfinite(density) && density > 0,
            "species '" + name + "': density must be positive, got " + std::to_string(density));
    std::visit([&](const auto& l) { l.validate("species '" + name + "'"); }, law);
    species_.push_back({std::move(name), density, std::move(law)});
    return species_.size() - 1;
}

std::size_t SpeciesTable::addCopy(std::size_t source, std::string name) {
    checkIndex(source);
    const std::size_t present = size();
    const std::size_t copy = add(std::move(name), species_[source].density, species_[source].law);
    // A copy of a copy still pairs with the first copy as its source does: pairLaw(source, x)
    // for every x present already covers it.
    for (std::size_t x = 0; x < present; ++x) setPair(copy, x, pairLaw(source, x));
    setPair(copy, copy, pairLaw(source, source));
    return copy;
}

void SpeciesTable::checkIndex(std::size_t i) const {
    require(i < species_.size(), "species index " + std::to_string(i) + " does not exist (there are " +
                                     std::to_string(species_.size()) + " species)");
}

void SpeciesTable::setPair(std::size_t a, std::size_t b, ContactLaw law) {
    checkIndex(a);
    checkIndex(b);
    pairs_[keyOf(a, b)] = std::move(law);
}

ContactLaw SpeciesTable::pairLaw(std::size_t a, std::size_t b) const {
    checkIndex(a);
    checkIndex(b);
    if (auto it = pairs_.find(keyOf(a, b)); it != pairs_.end()) return it->second;
    if (a == b) return species_[a].law;
    const ContactLaw& la = species_[a].law;
    const ContactLaw& lb = species_[b].law;
    require(la.index() == lb.index(), "species '" + species_[a].name + "' (" + lawName(la) + ") and '" +
                                          species_[b].name + "' (" + lawName(lb) +
                                          ") use different contact laws; one simulation uses one kind");
    return std::visit(
        [&](const auto& l) -> ContactLaw {
            using Law = std::decay_t<decltype(l)>;
            return Law::mix(l, std::get<Law>(lb));
        },
        la);
}

void SpeciesTable::validate() const {
    require(!species_.empty(), "no species defined: call addSpecies before adding particles");
    for (std::size_t a = 0; a < size(); ++a)
        for (std::size_t b = a; b < size(); ++b) {
            ContactLaw law = pairLaw(a, b);
            require(law.index() == species_[0].law.index(),
                    "species pair ('" + species_[a].name + "', '" + species_[b].name + "') uses " + lawName(law) +
                        " but species '" + species_[0].name + "' uses " + lawName(species_[0].law) +
                        "; one simulation uses one kind of contact law");
            std::visit([&](const auto& l) { l.validate("species pair ('" + species_[a].name + "', '" + species_[b].name + "')"); },
                       law);
        }
}

}  // namespace talus
