#include "Numerics/Solver.h"

#include <algorithm>
#include <cmath>

#include "Model/InputError.h"

namespace talus::shallow {

Solver::Solver(const Grid& grid, const ModelParameters& model, const NumericsSettings& numerics,
               const BoundaryCondition& left, const BoundaryCondition& right)
    : grid_(grid),
      fluxModel_{model.shapeFactor(), model.basalSlip, model.cosAngle()},
      friction_((model.validate(), model)),  // the parameters are checked before the law reads them
      sinAngle_(model.sinAngle()),
      numerics_(numerics),
      left_(left),
      right_(right) {
    if (!(numerics.cfl > 0 && numerics.cfl <= 1)) {
        throw InputError("--cfl: " + str(numerics.cfl) + " must be in (0, 1]");
    }
    if (!(numerics.dryHeight > 0)) throw InputError("--dry-height: " + str(numerics.dryHeight) + " must be positive");
    if (grid.cells < 2) throw InputError("--cells: " + std::to_string(grid.cells) + " must be at least 2");
    if (!(grid.length > 0)) throw InputError("--length: " + str(grid.length) + " must be positive");
    using Kind = BoundaryCondition::Kind;
    if ((left.kind == Kind::Periodic) != (right.kind == Kind::Periodic)) {
        throw InputError("--left/--right: a periodic domain needs both ends periodic");
    }
    for (const auto& [b, option] : {std::pair{left, "--left"}, std::pair{right, "--right"}}) {
        if (b.kind != Kind::Inflow) continue;
        if (!(b.inflow.h >= 0)) throw InputError(std::string(option) + " inflow: height " + str(b.inflow.h) + " must not be negative");
        if (!(b.inflow.phi >= 0 && b.inflow.phi <= 1)) {
            throw InputError(std::string(option) + " inflow: concentration " + str(b.inflow.phi) + " must be in [0, 1]");
        }
        if (!std::isfinite(b.inflow.u)) throw InputError(std::string(option) + " inflow: velocity must be finite");
    }
    cells_.assign(grid.cells, Conserved{});
}

void Solver::setCells(const std::vector<Conserved>& cells) {
    if (cells.size() != grid_.cells) {
        throw InputError("initial state: " + std::to_string(cells.size()) + " cells for a grid of " +
                         std::to_string(grid_.cells));
    }
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const Conserved& c = cells[i];
        const std::string where = "initial state, cell " + std::to_string(i) + " (x = " + str(grid_.centre(i)) + "): ";
        if (!(c.h >= 0) || !std::isfinite(c.h)) throw InputError(where + "height " + str(c.h) + " must not be negative");
        if (!std::isfinite(c.hu)) throw InputError(where + "momentum must be finite");
        if (!(c.hphi >= 0 && c.hphi <= c.h)) {
            throw InputError(where + "concentration " + str(c.h > 0 ? c.hphi / c.h : c.hphi) + " must be in [0, 1]");
        }
    }
    cells_ = cells;
}

std::vector<Primitive> Solver::primitives() const {
    std::vector<Primitive> p(cells_.size());
    std::transform(cells_.begin(), cells_.end(), p.begin(),
                   [&](const Conserved& c) { return toPrimitive(c, numerics_.dryHeight); });
    return p;
}

double Solver::computeFluxes(const std::vector<Conserved>& u) {
    const std::size_t n = u.size(), g = ghostCells;
    withGhosts_.resize(n + 2 * g);
    for (std::size_t i = 0; i < n; ++i) withGhosts_[i + g] = toPrimitive(u[i], numerics_.dryHeight);
    fillGhostCells(withGhosts_, left_, right_);
    reconstruct(numerics_.limiter, withGhosts_, west_, east_);
    // Face f lies between cells f - 1 and f (interior numbering): extended cells g + f - 1 and g + f.
    faceFluxes_.resize(n + 1);
    double fastest = 0;
    for (std::size_t f = 0; f <= n; ++f) {
        double speed = 0;
        faceFluxes_[f] = hllFlux(fluxModel_, east_[g + f - 1], west_[g + f], speed);
        fastest = std::max(fastest, speed);
    }
    return fastest;
}

void Solver::applyFriction(Conserved& c, double dt) const {
    // eq. (5): the friction -h mu cos(t) u/|u|, implicit in u (FrictionLaw::velocityAfterFriction).
    const Primitive p = toPrimitive(c, numerics_.dryHeight);
    c.hu = p.h > 0 ? c.h * friction_.velocityAfterFriction(p.h, p.phi, p.u, dt) : 0.0;
}

bool Solver::eulerStage(const std::vector<Conserved>& u, double dt, double frictionStep,
                        std::vector<Conserved>& target) const {
    const double ratio = dt / grid_.spacing();
    const std::size_t n = u.size();
    target.resize(n);
    double highest = 0;
    for (const Conserved& c : u) highest = std::max(highest, c.h);
    // A negative height from round-off in a draining cell is of the order of eps times the
    // heights around it; anything beyond that is a time step too long for positivity.
    const double roundOff = -64 * 2.2e-16 * highest;
    for (std::size_t i = 0; i < n; ++i) {
        const Conserved& fw = faceFluxes_[i];
        const Conserved& fe = faceFluxes_[i + 1];
        Conserved next{u[i].h - ratio * (fe.h - fw.h),
                       u[i].hu - ratio * (fe.hu - fw.hu) + dt * u[i].h * sinAngle_,  // eq. (5): h sin(t)
                       u[i].hphi - ratio * (fe.hphi - fw.hphi)};
        if (next.h < 0) {
            if (next.h < roundOff) return false;
            next.h = 0;
        }
        if (frictionStep > 0) applyFriction(next, frictionStep);
        target[i] = next;
    }
    return true;
}

double Solver::step(double maxStep) {
    const double fastest = computeFluxes(cells_);
    double dt = fastest > 0 ? numerics_.cfl * grid_.spacing() / fastest : maxStep;
    dt = std::min(dt, maxStep);
    while (true) {
        // Heun's method as a convex combination of forward-Euler stages E (Shu & Osher 1988),
        // U1 = E(U), U(t + dt) = (U + E(U1)) / 2, with the friction implicit: over dt in the first
        // stage, and over dt/2 on the combination (the half step it carries in Heun's average).
        // Both are fixed points exactly where friction balances gravity, and a stop in the first
        // stage stays a stop (a friction term inside E(U1) would be halved by the average and
        // leave the flow creeping towards rest, never at it).
        bool positive = eulerStage(cells_, dt, dt, stage1_);
        if (positive) {
            computeFluxes(stage1_);
            positive = eulerStage(stage1_, dt, 0.0, stage2_);
        }
        if (positive) break;
        ++retriedSteps_;
        dt *= 0.5;
        computeFluxes(cells_);
        if (dt < 1e-12 * grid_.spacing()) throw std::runtime_error("time step collapsed at t = " + str(time_));
    }
    for (std::size_t i = 0; i < cells_.size(); ++i) {
        Conserved& c = cells_[i];
        c.h = 0.5 * (c.h + stage2_[i].h);
        c.hu = 0.5 * (c.hu + stage2_[i].hu);
        c.hphi = 0.5 * (c.hphi + stage2_[i].hphi);
        applyFriction(c, 0.5 * dt);
    }
    time_ += dt;
    ++steps_;
    return dt;
}

void Solver::advanceTo(double endTime) {
    while (time_ < endTime) {
        const double remaining = endTime - time_;
        // The last step lands on the end time exactly (time_ + remaining may round off it).
        if (step(remaining) == remaining) time_ = endTime;
    }
}

}  // namespace talus::shallow
