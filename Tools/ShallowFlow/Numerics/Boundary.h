// The boundary conditions of the 1-D domain, imposed through two ghost cells at each end (what the
// second-order reconstruction reaches).
#pragma once

#include <string>
#include <vector>

#include "Model/State.h"

namespace talus::shallow {

struct BoundaryCondition {
    enum class Kind {
        Inflow,        // given h, u, phi in the ghost cells (a Dirichlet inflow; meant supercritical)
        Transmissive,  // the ghosts copy the last cell: zero gradient, waves leave the domain
        Wall,          // the ghosts mirror the cells with u reversed: no flux of mass through it
        Periodic       // the ghosts are the cells at the other end (both ends must be periodic)
    };
    Kind kind = Kind::Transmissive;
    Primitive inflow;  // for Inflow
};

// Parses "inflow", "transmissive", "wall" or "periodic" for the option named `option`.
BoundaryCondition::Kind parseBoundaryKind(const std::string& text, const std::string& option);

inline constexpr std::size_t ghostCells = 2;

// Fills cells [0, ghostCells) and [n - ghostCells, n) of `cells` from its interior.
void fillGhostCells(std::vector<Primitive>& cells, const BoundaryCondition& left, const BoundaryCondition& right);

}  // namespace talus::shallow
