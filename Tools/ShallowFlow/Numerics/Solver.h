// The finite-volume solver of the depth-averaged bidisperse model (Theory/DepthAveraged.md eq.
// (4)-(9)) on a uniform 1-D grid of cells: MUSCL reconstruction of h, u, phi, HLL fluxes, the
// gravity source explicit, Shu & Osher's two-stage strong-stability-preserving Runge-Kutta scheme
// (Heun's method) in time, and the basal friction implicit in the velocity (Solver::step says
// where; it is first order in time, and keeps the steady uniform flow and a stop exactly).
// Documentation/ShallowFlow.md describes the scheme and its tests.
#pragma once

#include <vector>

#include "Model/Flux.h"
#include "Model/FrictionLaw.h"
#include "Model/ModelParameters.h"
#include "Model/State.h"
#include "Numerics/Boundary.h"
#include "Numerics/Reconstruction.h"

namespace talus::shallow {

struct Grid {
    double start = 0;   // x of the west face of the first cell
    double length = 1;  // the domain [start, start + length]
    std::size_t cells = 100;
    double spacing() const { return length / static_cast<double>(cells); }
    double centre(std::size_t i) const { return start + (static_cast<double>(i) + 0.5) * spacing(); }
};

struct NumericsSettings {
    // dt = cfl dx / (largest signal speed). The scheme keeps h >= 0 for cfl <= 1/2 (each stage is a
    // forward-Euler step over faces reconstructed within half a cell); above that a step that would
    // leave a negative height is redone with half the time step.
    double cfl = 0.45;
    Limiter limiter = Limiter::VanLeer;
    // Below the dry height u and phi are desingularised (Model/State.h). With alpha > 1 the speed
    // of a flow thinning towards a dry bed grows without bound (along the rarefaction into a dry
    // bed du/dh = -(lambda_2 - u)/h ~ -0.76 u/h for alpha = 1.23, so u ~ h^-0.76), so the dry
    // height sets the fastest signal speed, hence the time step, of a flow with a front. In large
    // diameters, 0.01 is far below a particle layer; the front (h >= 0.5), head and shock of the
    // long chute at t = 500 agree to 2e-6 with a run at 1e-10 (Documentation/ShallowFlow.md).
    double dryHeight = 1e-2;
};

class Solver {
public:
    // Throws InputError for a bad setting (cfl outside (0, 1], a non-positive dry height or grid,
    // only one periodic end) or bad model parameters.
    Solver(const Grid& grid, const ModelParameters& model, const NumericsSettings& numerics,
           const BoundaryCondition& left, const BoundaryCondition& right);

    // The initial state, one value per cell. Throws InputError for a negative h or phi outside
    // [0, 1], naming the cell and its x.
    void setCells(const std::vector<Conserved>& cells);
    const std::vector<Conserved>& cells() const { return cells_; }
    std::vector<Primitive> primitives() const;

    // One time step of at most maxStep (and of the CFL step); returns the step taken.
    double step(double maxStep);
    // Steps until time() reaches endTime exactly.
    void advanceTo(double endTime);

    double time() const { return time_; }
    long long steps() const { return steps_; }
    long long retriedSteps() const { return retriedSteps_; }
    const Grid& grid() const { return grid_; }
    const FrictionLaw& friction() const { return friction_; }

private:
    // The fluxes through the faces of the state `u`; returns the largest signal speed.
    double computeFluxes(const std::vector<Conserved>& u);
    // target = the forward-Euler stage of length dt from `u` with the fluxes already computed
    // (transport and gravity), then friction over frictionStep (none if 0); false if it left a
    // height below round-off.
    bool eulerStage(const std::vector<Conserved>& u, double dt, double frictionStep, std::vector<Conserved>& target) const;
    void applyFriction(Conserved& cell, double dt) const;

    Grid grid_;
    FluxModel fluxModel_;
    FrictionLaw friction_;
    double sinAngle_;
    NumericsSettings numerics_;
    BoundaryCondition left_, right_;

    std::vector<Conserved> cells_, stage1_, stage2_;
    std::vector<Primitive> withGhosts_, west_, east_;
    std::vector<Conserved> faceFluxes_;
    double time_ = 0;
    long long steps_ = 0, retriedSteps_ = 0;
};

}  // namespace talus::shallow
