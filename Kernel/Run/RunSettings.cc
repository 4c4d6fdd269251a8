#include "Run/RunSettings.h"

#include <cmath>

#include "Error.h"

namespace talus {

namespace {

// "settings().timeStep (--dt) must be positive, got -1"
std::string named(const std::string& setting, const std::string& flag) {
    return "settings()." + setting + (flag.empty() ? std::string() : " (--" + flag + ")");
}

void requirePositive(double x, const std::string& setting, const std::string& flag) {
    require(std::isfinite(x) && x > 0, named(setting, flag) + " must be positive, got " + str(x));
}

void requireNotNegative(double x, const std::string& setting, const std::string& flag) {
    require(std::isfinite(x) && x >= 0, named(setting, flag) + " must not be negative, got " + str(x));
}

}  // namespace

void RunSettings::validate(bool started) const {
    require(!started || timeStep != 0, "no time step: set settings().timeStep or pass --dt");
    requireWord(name, named("name", "name"));
    if (timeStep != 0 && timeStep != automaticTimeStep) requirePositive(timeStep, "timeStep", "dt");  // (0: not set yet)
    require(std::isfinite(largestStepFraction) && largestStepFraction > 0 && largestStepFraction <= 1,
            named("largestStepFraction", "largest-step-fraction") + " must be in (0, 1], got " +
                str(largestStepFraction));
    require(std::isfinite(stepsPerCollision) && stepsPerCollision * largestStepFraction >= 1,
            named("stepsPerCollision", "steps-per-collision") + " must be at least " + str(1 / largestStepFraction) +
                " (1 / --largest-step-fraction: the largest step a run accepts), got " + str(stepsPerCollision));
    requireNotNegative(impactSpeed, "impactSpeed", "impact-speed");
    require(std::isfinite(shapeTolerance) && shapeTolerance >= 1e-15 && shapeTolerance <= 1e-3,
            named("shapeTolerance", "shape-tolerance") + " must be in [1e-15, 1e-3] (relative to the bounding radius), got " +
                str(shapeTolerance));
    requireNotNegative(endTime, "endTime", "end-time");
    requireNotNegative(outputInterval, "outputInterval", "output-interval");
    if (skin != automaticSkin) requireNotNegative(skin, "skin", "skin");
    require(std::isfinite(cellSizeRatio) && cellSizeRatio > 1,
            named("cellSizeRatio", "cell-size-ratio") + " must be greater than 1, got " + str(cellSizeRatio));
    requirePositive(progressInterval, "progressInterval", "progress-interval");
    requirePositive(maxOverlapFraction, "maxOverlapFraction", "max-overlap");
    requirePositive(maxInitialOverlapFraction, "maxInitialOverlapFraction", "");
    require(stepper.waveSteps >= 1 && stepper.waveSteps <= 255,
            named("stepper.waveSteps", "wave-steps") + " must be 1 to 255, got " + std::to_string(stepper.waveSteps));
    require(stepper.waveStripColumns >= 0, named("stepper.waveStripColumns", "wave-strip") +
                                               " must not be negative, got " + std::to_string(stepper.waveStripColumns));
    require(stepper.waves != StepperTuning::Waves::on || stepper.waveSteps >= 2,
            named("stepper.waves", "waves") + " on needs waves of 2 steps or more (" +
                named("stepper.waveSteps", "wave-steps") + " is 1)");
    require(std::isfinite(stepper.nearSkinFraction) && stepper.nearSkinFraction >= 0 && stepper.nearSkinFraction < 1,
            named("stepper.nearSkinFraction", "near-skin-fraction") + " must be in [0, 1), got " +
                str(stepper.nearSkinFraction));
}

}  // namespace talus
