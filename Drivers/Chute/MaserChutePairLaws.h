// The species and pair laws of the maser-fed chute (Documentation/Chutes/MaserFedChute.md), for
// its two --contact-law choices. chapter-4: e = 0.88 and tc = 0.005 for every pair type, so each
// pair's stiffness and damping follow from its reduced mass (a fixed base sphere has infinite
// mass: the reduced mass is the other's). table-3C1 (the thesis's Table 3.C.1): tc and e of two
// large spheres from kn = 2e5 and gamma_n = 25 in the thesis's units (dL = mL = g = 1, so
// m* = 1/2), tc/sqrt(d) and e the same for every pair type (d: the pair's mean diameter), and the
// base, fixed large particles there, with the large spheres' friction towards both sizes (with
// baseOfSmall, a base of small beads: the small spheres' friction towards both).
// Friction 0.5 for large, 0.25 for small spheres and 0.375 between them.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <variant>

#include "Sampling/Messages.h"
#include "Simulation.h"

namespace talus {

// Adds the species large, small and base (in this order) and sets every pair's law; prints them.
inline void addMaserChuteSpecies(Simulation& s, const std::string& contactLaw, double dL, double dS, double mL,
                                 double mS, double density, double baseDiameter, bool baseOfSmall = false) {
    require(contactLaw == "chapter-4" || contactLaw == "table-3C1",
            "--contact-law must be chapter-4 or table-3C1, got '" + contactLaw + "'");
    const bool thesis = contactLaw == "table-3C1";
    const double kn = 2e5, gn = 25, m = 0.5;
    const double tcPerRootDiameter = pi / std::sqrt(kn / m - gn * gn / (4 * m * m)), eThesis = std::exp(-tcPerRootDiameter * gn / (2 * m));
    auto law = [&](double reducedMass, double diameter, double friction) {
        return (thesis ? LinearSpringDashpot::fromCollision(tcPerRootDiameter * std::sqrt(diameter), eThesis, reducedMass)
                       : LinearSpringDashpot::fromCollision(0.005, 0.88, reducedMass))
            .withFriction(friction);
    };
    // Each pair type once: its reduced mass, the diameter its tc scales with, its friction.
    enum : std::size_t { large, small, base };
    const double dB = baseDiameter, muLS = 0.375;
    struct PairType {
        const char* label;
        std::size_t a, b;
        double reducedMass, diameter, friction;
    };
    const PairType pairs[] = {{"large-large", large, large, mL / 2, dL, 0.5},
                              {"small-small", small, small, mS / 2, dS, 0.25},
                              {"large-small", large, small, mL * mS / (mL + mS), (dL + dS) / 2, muLS},
                              {"base-large", base, large, mL, (dB + dL) / 2, baseOfSmall ? muLS : 0.5},
                              {"base-small", base, small, mS, (dB + dS) / 2, thesis && !baseOfSmall ? muLS : 0.25}};
    auto lawOf = [&](const PairType& t) { return law(t.reducedMass, t.diameter, t.friction); };
    s.scene().addSpecies("large", density, lawOf(pairs[0]));
    s.scene().addSpecies("small", density, lawOf(pairs[1]));
    s.scene().addSpecies("base", density, law(mL, dL, 0.5));  // (base with base: both fixed, never in contact)
    for (const PairType& t : pairs)
        if (t.a != t.b) s.scene().species().setPair(t.a, t.b, lawOf(t));
    say(s, "%s: contact law %s\n", s.settings().name.c_str(), contactLaw.c_str());
    for (const PairType& t : pairs) {
        const auto l = std::get<LinearSpringDashpot>(s.scene().species().pairLaw(t.a, t.b));
        say(s, "  %-11s reduced mass %.10g  kn %.10g  gamma_n %.10g  kt %.10g  gamma_t %.10g  mu %.10g\n", t.label,
            t.reducedMass, l.normalStiffness, l.normalDamping, l.tangentialStiffness, l.tangentialDamping, l.friction);
    }
}

}  // namespace talus
