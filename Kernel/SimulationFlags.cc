// The command-line flags every driver has (Documentation/UserGuide/WritingADriver.md lists them):
// registered when a Simulation is made, parsed by solve() after the driver's own set-up, so the
// command line has the last word. solve() validates the settings after it (RunSettings::validate).
#include "Simulation.h"

#include "IO/CommandLine.h"
#include "IO/OutputFiles.h"     // (complete types for the members the constructor may have to destroy)
#include "Integration/Integrator.h"
#include "Integration/StepWorkspace.h"
#include "Math/LaneForm.h"
#include "Parallel/Communicator.h"
#include "Parallel/RankContext.h"
#include "SimulationHost.h"

namespace talus {

Simulation::Simulation()
    : work_(std::make_unique<StepWorkspace>()),
      integrator_(std::make_unique<Integrator>()),
      host_(std::make_unique<Host>(*this)),
      ranks_(std::make_unique<RankContext>(worldCommunicator())),
      run_(std::make_unique<Run>()),
      scene_(std::make_unique<Scene>(state_, *ranks_)) {
    RunSettings& c = state_.settings;
    CommandLine& cl = run_->commandLine();
    cl.add("end-time", "T", "simulated time at which the run stops",
           [&c](const std::string& v) { c.endTime = CommandLine::toDouble("end-time", v); });
    cl.add("dt", "DT|auto",
           "time step; auto: the shortest collision time of the scene over --steps-per-collision (printed with its "
           "reason)",
           [&c](const std::string& v) {
               c.timeStep = v == "auto" ? RunSettings::automaticTimeStep : CommandLine::toDouble("dt", v);
           });
    cl.add("steps-per-collision", "N", "for --dt auto: time steps per shortest collision (default 50, at least 10)",
           [&c](const std::string& v) { c.stepsPerCollision = CommandLine::toDouble("steps-per-collision", v); });
    cl.add("largest-step-fraction", "F",
           "the largest time step a run accepts, as a fraction of the shortest collision time (default 0.1; above "
           "it only to study where the integration fails)",
           [&c](const std::string& v) { c.largestStepFraction = CommandLine::toDouble("largest-step-fraction", v); });
    cl.add("impact-speed", "V",
           "for --dt auto and the time-step check: the largest impact speed expected, at which Hertzian collisions "
           "are timed (default: each Hertzian law's characteristic velocity)",
           [&c](const std::string& v) { c.impactSpeed = CommandLine::toDouble("impact-speed", v); });
    cl.add("output-interval", "T", "simulated time between saved frames (0: first and last)",
           [&c](const std::string& v) { c.outputInterval = CommandLine::toDouble("output-interval", v); });
    cl.add("name", "NAME", "output file name (NAME.data, NAME.fstat, ...)",
           [&c](const std::string& v) { c.name = v; });
    cl.add("restart", "FILE", "continue the run saved in FILE (a .restart file)",
           [this](const std::string& v) { run_->restartFile_ = v; });
    cl.add("shape-tolerance", "T",
           "Newton tolerance of the superquadric contacts, relative to the smaller bounding radius (default 1e-10; "
           "Theory/Superquadrics.md, Convergence)",
           [&c](const std::string& v) { c.shapeTolerance = CommandLine::toDouble("shape-tolerance", v); });
    cl.add("skin", "S", "neighbour-list skin distance",
           [&c](const std::string& v) { c.skin = CommandLine::toDouble("skin", v); });
    cl.add("cell-size-ratio", "R", "ratio of the cell sizes of successive HGrid levels",
           [&c](const std::string& v) { c.cellSizeRatio = CommandLine::toDouble("cell-size-ratio", v); });
    cl.add("relist", "on|off",
           "list only the pairs of particles that boundaries add or move, and only the triangles of a moving "
           "mesh that has travelled (on), or build the whole neighbour list anew (off)",
           [&c](const std::string& v) { c.relist = CommandLine::toBool("relist", v); });
    cl.add("reorder", "on|off", "renew the particle order along a space-filling curve at list rebuilds",
           [&c](const std::string& v) { c.reorderParticles = CommandLine::toBool("reorder", v); });
    cl.add("waves", "auto|on|off",
           "advance stretches of the bed several steps at a time while they are cached (time skewing): where they "
           "pay (auto, the default: a box periodic along x and y, one rank, --waves-from particles or more), "
           "wherever the scene allows them (on: spheres, no boundaries), or never",
           [&c](const std::string& v) { c.stepper.waves = wavesNamed(v, "--waves"); });
    cl.add("wave-steps", "N", "steps per wave (default 8); N > 1 also turns waves on, 1 off",
           [&c](const std::string& v) { c.stepper.setWaves(CommandLine::toInt("wave-steps", v)); });
    cl.add("waves-from", "N",
           "particles from which --waves auto takes waves (default " +
               std::to_string(StepperTuning::defaultWavesFromParticles) + ")",
           [&c](const std::string& v) {
               const int n = CommandLine::toInt("waves-from", v);
               require(n >= 0, "--waves-from must not be negative, got " + v);
               c.stepper.wavesFromParticles = static_cast<std::uint64_t>(n);
           });
    cl.add("wave-strip", "C", "columns of cells per strip of the waves (default 8 per step of the waves: 64 for 8)",
           [&c](const std::string& v) {
               const int columns = CommandLine::toInt("wave-strip", v);
               require(columns >= 1, "--wave-strip needs at least one column, got " + v);
               c.stepper.waveStripColumns = columns;  // (waves on or off as before)
           });
    cl.add("drift-pass", "on|off",
           "the first half of each step in one pass over the particles where the scene allows it (on, the default), "
           "or pass by pass: the same trajectories, for measurements",
           [&c](const std::string& v) { c.stepper.driftPass = CommandLine::toBool("drift-pass", v); });
    cl.add("near-skin-fraction", "F",
           "the force loop sweeps the listed pairs within F x the skin (the near list, remade as the particles "
           "move; default 0.15) instead of the whole list; 0: the whole list every step. The same forces",
           [&c](const std::string& v) { c.stepper.nearSkinFraction = CommandLine::toDouble("near-skin-fraction", v); });
    cl.add("sweep-frame", "flow|off",
           "the sweep grows the radii by the speeds relative to the mean velocity (flow, the default) or by the "
           "speeds (off). The same forces",
           [&c](const std::string& v) {
               require(v == "flow" || v == "off", "--sweep-frame must be flow or off, got '" + v + "'");
               c.stepper.sweepInFlowFrame = v == "flow";
           });
    cl.add("sweep", "auto|scalar|lanes|gathers",
           "the form of the force loop's sweep: the fastest, timed at the first long list (auto), or the one named "
           "(a form the lane form lacks is the scalar loop). The same pairs",
           [&c](const std::string& v) { c.stepper.sweepForm = sweepFormNamed(v, "--sweep"); });
    cl.add("overlap-ghosts", "on|off",
           "on ranks, compute the pairs of two owned particles while the ghosts travel (on), or after (off, the default): "
           "the same trajectories, for measurements",
           [&c](const std::string& v) { c.stepper.overlapGhosts = CommandLine::toBool("overlap-ghosts", v); });
    cl.add("lane-form", "scalar|avx2|avx512",
           "run the vector passes in this lane form instead of the best one the processor runs: the bits of a run "
           "on another processor (Installing.md, lane forms)",
           [](const std::string& v) { setLaneForm(laneFormNamed(v, "--lane-form")); });
    cl.add("vtu", "on|off", "write ParaView .vtu frames",
           [&c](const std::string& v) { c.writeVtu = CommandLine::toBool("vtu", v); });
    cl.add("fstat", "on|off",
           "write the .fstat file of every contact (off: output steps keep only the contacts' number and elastic "
           "energy for .ene, not 120 bytes per contact)",
           [&c](const std::string& v) { c.writeFstat = CommandLine::toBool("fstat", v); });
    cl.add("files", "on|off", "write any output files at all",
           [&c](const std::string& v) { c.setFileOutput(CommandLine::toBool("files", v)); });
    cl.add("id-ordered-sums", "on|off",
           "sum each particle's contact forces in the order of its partners' ids: the same result to the bit on "
           "any number of ranks, for a second pass over the pairs (no maser; kept by a restart)",
           [&c](const std::string& v) { c.idOrderedSums = CommandLine::toBool("id-ordered-sums", v); });
    cl.add("rebalance-interval", "T",
           "under mpirun: place the rank boundaries for equal particle counts every T of simulated time "
           "(0: at the start, at saves and on request only)",
           [this](const std::string& v) {
               ranks_->setRebalanceInterval(CommandLine::toDouble("rebalance-interval", v));
           });
    cl.add("rank-grid", "GXxGYxGZ",
           "under mpirun: the ranks along x, y and z, e.g. 2x2x1 (their product is the number of ranks; default: "
           "all along x)",
           [this](const std::string& v) { ranks_->setGrid(CommandLine::toGrid("rank-grid", v)); });
    cl.add("max-overlap", "F",
           "largest overlap during the run, as a fraction of the smaller radius, before the run stops as a "
           "blow-up (default 0.25)",
           [&c](const std::string& v) { c.maxOverlapFraction = CommandLine::toDouble("max-overlap", v); });
    cl.add("progress-interval", "S", "wall seconds between progress lines",
           [&c](const std::string& v) { c.progressInterval = CommandLine::toDouble("progress-interval", v); });
}

}  // namespace talus
