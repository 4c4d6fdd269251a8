// What a run takes from outside the scene (Documentation/Architecture.md "The driver contract"):
// the command line (the flags every driver has, Simulation's, and the driver's own), the values
// of the driver's that a restart file keeps, and the restart file the run continues, if any.
// A driver reaches it through Simulation::run().
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace talus {

class CommandLine;
struct SimulationState;

class Run {
public:
    Run();
    ~Run();

    // A driver's own flag --name VALUE, listed by --help, parsed before setupInitialConditions.
    void addFlag(const std::string& name, const std::string& help, double& value);
    void addFlag(const std::string& name, const std::string& help, int& value);
    void addTextFlag(const std::string& name, const std::string& help, std::string& value);
    // A number of the driver's (or of a boundary it owns) that the restart file keeps: saved with
    // every restart file and put back when the run restarts, before the command line is read
    // again. Number flags (addFlag) are kept this way too, as "flag.NAME". Names are one word
    // and unique.
    void keepInRestart(const std::string& name, double& value);
    void keepInRestart(const std::string& name, int& value);
    // A list of numbers kept the same way (a detector's recent samples, running sums): `save`
    // gives it at every save (on every rank at once, so it may sum over ranks), `restore` takes
    // it back when the run restarts (on every rank: what is summed over ranks must be put back
    // on one of them only). Saved as NAME.size and NAME.0, NAME.1, ...
    void keepInRestart(const std::string& name, std::function<std::vector<double>()> save,
                       std::function<void(const std::vector<double>&)> restore);

    // The restart file the run continues (--restart FILE); empty for a run from its set-up.
    const std::string& restartFile() const { return restartFile_; }
    // Ends the run after one more step, which saves the output as a run's last step does, before
    // the end time: for a driver that has decided what it measures (a flow steady or at rest).
    // Every rank calls it alike, from a hook.
    void finishAfterNextStep() { finishing_ = true; }

private:
    friend class Simulation;
    // The command line: Simulation registers the flags every driver has (--restart among them).
    CommandLine& commandLine() { return *commandLine_; }
    // Into state.keptValues at a save; back from them after a restart file was read (every kept
    // value must be there: a file of another driver would otherwise go on with values never saved).
    void saveKeptValues(SimulationState& state) const;
    void restoreKeptValues(const SimulationState& state) const;

    struct KeptValue {
        std::string name;
        double* real = nullptr;
        int* integer = nullptr;
        std::function<std::vector<double>()> saveList;  // a list, when set
        std::function<void(const std::vector<double>&)> restoreList;
    };
    void addKept(KeptValue value);

    std::unique_ptr<CommandLine> commandLine_;
    std::vector<KeptValue> kept_;
    std::string restartFile_;
    bool finishing_ = false;  // finishAfterNextStep was called (Simulation's time loop reads it)
};

}  // namespace talus
