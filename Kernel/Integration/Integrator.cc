#include "Integration/Integrator.h"

#include <ostream>

#include "Integration/StepWorkspace.h"
#include "Math/LaneForm.h"
#include "SimulationState.h"

namespace talus {

std::uint64_t Integrator::stepsNext(StepHost& host, std::uint64_t stepsLeft, std::uint64_t saveEvery) {
    const std::uint64_t wave = waves_.stepsNext(host, stepsLeft, saveEvery);
    chosen_ = wave > 0 ? &waves_ : nullptr;
    return wave > 0 ? wave : 1;
}

void Integrator::advance(StepHost& host, bool recordContacts) {
    if (chosen_ == &waves_) return waves_.advance(host, recordContacts);
    if (driftPass_.whyNot(host).empty()) {
        ++driftPassSteps_;
        return driftPass_.advance(host, recordContacts);
    }
    ++plainSteps_;
    plain_.advance(host, recordContacts);
}

void Integrator::afterListBuild(StepHost& host) {
    host.workspace().lastDisplacement = 0;  // (the positions are the new reference)
    if (host.state().settings.stepper.waveSteps > 1) waves_.makeSchedule(host);
}

void Integrator::tune(StepHost& host, bool restarted) {
    SimulationState& s = host.state();
    const StepperTuning& tuning = s.settings.stepper;
    s.pairList.nearSkinFraction = tuning.nearSkinFraction;
    s.pairList.sweepInFlowFrame = tuning.sweepInFlowFrame;
    requestedSweepForm() = tuning.sweepForm;
    waves_.choose(host, restarted);
}

void Integrator::afterRestart(StepHost& host) { waves_.continueAfterRestart(host); }

void Integrator::startRun() {
    plainSteps_ = driftPassSteps_ = 0;
    waves_.resetStatistics();
    chosen_ = nullptr;
}

void Integrator::describeChoice(const StepHost& host, std::ostream& out, const std::string& name) const {
    const Stepper* chosen = &plain_;
    std::string declined;
    for (const Stepper* s : {static_cast<const Stepper*>(&waves_), static_cast<const Stepper*>(&driftPass_)}) {
        const std::string_view why = s->whyNot(host);
        if (why.empty()) {
            chosen = s;
            break;
        }
        declined += "; " + std::string(s->name()) + " declined: " + std::string(why);
    }
    out << name << ": stepper " << chosen->name();
    if (chosen == &waves_)
        out << " of " << host.state().settings.stepper.waveSteps << " steps, " << waves_.choice() << " (single steps between waves by the "
            << driftPass_.name() << ")";
    out << declined << "; lanes " << laneFormName(laneForm()) << std::endl;
}

}  // namespace talus
