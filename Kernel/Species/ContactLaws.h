// The contact laws Talus knows, in one list. Everything that depends on the kind of law is
// derived from this list by templates: the ContactLaw variant a species holds, the pair tables of
// the force loop (SpeciesTable::tables), the force loop compiled once per law and lane form
// (Math/LaneKernels.cc), the time-step check (collisionTimeOfPair) and the restart file's law
// I/O by name (IO/RestartFile.cc). A law is one file with the members listed in
// Documentation/Architecture.md "Adding a part", plus its line below.
#pragma once

#include <tuple>
#include <variant>

#include "Species/HertzMindlin.h"
#include "Species/LinearSpringDashpot.h"
#include "Species/LinearSpringDashpotRolling.h"

namespace talus {

template <class... Laws>
struct LawList {
    using Variant = std::variant<Laws...>;
    template <template <class> class Of>
    using VariantOf = std::variant<Of<Laws>...>;
    template <template <class> class Of>
    using TupleOf = std::tuple<Of<Laws>...>;
    // Calls f.template operator()<Law>() for the laws in order until one returns true; returns
    // whether one did.
    template <class F>
    static bool findFirst(F&& f) {
        return (f.template operator()<Laws>() || ...);
    }
};

// The registration: one entry per law. The order is the variant's (nothing saved depends on it:
// restart files name their laws).
using ContactLawList = LawList<LinearSpringDashpot, HertzMindlin, LinearSpringDashpotRolling>;

using ContactLaw = ContactLawList::Variant;

inline const char* lawName(const ContactLaw& law) {
    return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::name; }, law);
}

}  // namespace talus
