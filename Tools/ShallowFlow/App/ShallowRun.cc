#include "App/ShallowRun.h"

#include <chrono>
#include <fstream>

#include "App/InitialProfile.h"
#include "Model/InputError.h"
#include "Output/FlowDiagnostics.h"

namespace talus::shallow {

namespace {

std::ofstream openOutput(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw InputError("--output: cannot write '" + path + "'");
    out.precision(10);
    return out;
}

}  // namespace

void runShallowFlow(const ProgramOptions& o, std::ostream& log) {
    BoundaryCondition left{o.left, {}}, right{o.right, {}};
    Primitive inflow{o.inflowHeight, 0, o.inflowConcentration};
    const bool needsInflow = o.left == BoundaryCondition::Kind::Inflow || o.right == BoundaryCondition::Kind::Inflow ||
                             o.initial == "inflow";
    if (needsInflow) {
        inflow.u = o.inflowVelocity ? *o.inflowVelocity
                   : o.inflowHeight > 0 ? FrictionLaw(o.model).steadySpeed(o.inflowHeight, o.inflowConcentration)
                                        : 0.0;
    }
    left.inflow = right.inflow = inflow;
    Solver solver(o.grid, o.model, o.numerics, left, right);
    solver.setCells(initialProfile(o.initial, o.grid, inflow));

    log << "talus-shallow: " << o.grid.cells << " cells of " << o.grid.spacing() << ", angle " << o.model.angleDegrees
        << " deg, alpha " << o.model.shapeFactor() << ", cfl " << o.numerics.cfl << ", limiter " << name(o.numerics.limiter)
        << "\n";
    if (needsInflow) {
        log.precision(12);
        log << "  inflow h = " << inflow.h << ", u = " << inflow.u << ", phi = " << inflow.phi << "\n";
        log.precision(6);
    }

    std::ofstream profiles = openOutput(o.output + ".profiles.csv");
    std::ofstream fronts = openOutput(o.output + ".fronts.csv");
    profiles << "t,x,h,u,phi,hphi\n";
    fronts << "t,front,head_height,head_position,shock,volume,small_volume,steps,wall_seconds\n";

    const auto start = std::chrono::steady_clock::now();
    const auto wallSeconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const double progressInterval = o.progressInterval > 0 ? o.progressInterval : o.endTime / 10;
    double nextProgress = progressInterval;
    std::size_t nextOutput = 0;
    while (true) {
        while (nextOutput < o.outputTimes.size() && o.outputTimes[nextOutput] <= solver.time()) {
            const FlowDiagnostics d =
                diagnose(o.grid, solver.cells(), o.numerics.dryHeight, o.frontHeight, o.shockConcentration);
            fronts << solver.time() << "," << d.frontPosition << "," << d.headHeight << "," << d.headPosition << ","
                   << d.shockPosition << "," << d.volume << "," << d.smallVolume << "," << solver.steps() << ","
                   << wallSeconds() << "\n";
            const std::vector<Primitive> p = solver.primitives();
            for (std::size_t i = 0; i < p.size(); ++i) {
                profiles << solver.time() << "," << o.grid.centre(i) << "," << p[i].h << "," << p[i].u << "," << p[i].phi
                         << "," << solver.cells()[i].hphi << "\n";
            }
            ++nextOutput;
        }
        if (solver.time() >= o.endTime) break;
        // Step to the next output, progress line or the end, whichever comes first.
        double target = o.endTime;
        if (nextOutput < o.outputTimes.size()) target = std::min(target, o.outputTimes[nextOutput]);
        target = std::min(target, nextProgress);
        solver.advanceTo(target);
        if (solver.time() >= nextProgress) {
            const double wall = wallSeconds();
            const FlowDiagnostics d =
                diagnose(o.grid, solver.cells(), o.numerics.dryHeight, o.frontHeight, o.shockConcentration);
            log << "  t = " << solver.time() << "  wall " << wall << " s  "
                << static_cast<double>(o.grid.cells) * static_cast<double>(solver.steps()) / std::max(wall, 1e-9)
                << " cell-steps/s  front " << d.frontPosition << "  head " << d.headHeight << "  shock "
                << d.shockPosition << "\n";
            nextProgress += progressInterval;
        }
    }
    log << "talus-shallow: t = " << solver.time() << " in " << solver.steps() << " steps (" << solver.retriedSteps()
        << " redone with half the step), wall " << wallSeconds() << " s; wrote " << o.output << ".profiles.csv and "
        << o.output << ".fronts.csv\n";
}

}  // namespace talus::shallow
