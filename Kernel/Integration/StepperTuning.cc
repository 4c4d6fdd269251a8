#include "Integration/StepperTuning.h"

namespace talus {

const char* wavesName(StepperTuning::Waves waves) {
    using W = StepperTuning::Waves;
    return waves == W::on ? "on" : waves == W::off ? "off" : "auto";
}

StepperTuning::Waves wavesNamed(const std::string& name, const std::string& flag) {
    using W = StepperTuning::Waves;
    for (const W w : {W::automatic, W::on, W::off})
        if (name == wavesName(w)) return w;
    throw Error(flag + " must be auto, on or off, got '" + name + "'");
}

SweepForm sweepFormNamed(const std::string& name, const std::string& flag) {
    if (name == "auto") return SweepForm::undecided;
    for (const SweepForm f : {SweepForm::scalar, SweepForm::lanes, SweepForm::gathers})
        if (name == sweepFormName(f)) return f;
    throw Error(flag + " must be auto, scalar, lanes or gathers, got '" + name + "'");
}

}  // namespace talus
