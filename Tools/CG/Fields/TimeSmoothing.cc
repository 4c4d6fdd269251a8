#include "Fields/TimeSmoothing.h"

#include <algorithm>
#include <cmath>

#include "IO/InputError.h"

namespace talus::cg {

TimeSmoother::TimeSmoother(KernelShape shape, double width, std::vector<double> outputTimes, std::optional<double> step)
    : profile_(shape, 1), width_(width), listed_(std::move(outputTimes)), step_(step) {
    if (!(width_ > 0)) throw InputError("--time-smoothing: the width must be positive, found " + str(width_));
    if (step_ && !(*step_ > 0)) throw InputError("--output-step: the step must be positive, found " + str(*step_));
    std::sort(listed_.begin(), listed_.end());
    listed_.erase(std::unique(listed_.begin(), listed_.end()), listed_.end());
}

double TimeSmoother::weight(double dt) const {
    const double q = dt / width_;
    // The unnormalised shape: the normalisation cancels in the ratio, and f(0) = c/c = 1 exactly.
    return profile_.value(q * q) / profile_.normalisation();
}

void TimeSmoother::queueOutputTimesUpTo(double time) {
    if (!listed_.empty()) {
        while (nextListed_ < listed_.size() && listed_[nextListed_] <= time) pending_.push_back(listed_[nextListed_++]);
    } else if (step_) {
        // A relative tolerance keeps a step time that lands on a frame (up to rounding) on it.
        while (true) {
            const double t = firstFrameTime_ + double(nextStep_) * *step_;
            if (t > time + 1e-9 * *step_) break;
            pending_.push_back(t);
            ++nextStep_;
        }
    } else {
        pending_.push_back(time);
    }
}

SmoothedFields TimeSmoother::smoothAt(double time) const {
    SmoothedFields out;
    out.time = time;
    double norm = 0;
    for (const Frame& frame : frames_) {
        const double w = weight(frame.time - time);
        if (!(w > 0)) continue;
        if (out.sums.empty()) {
            out.sums.assign(frame.sums.size(), 0.0);
            out.firstTime = frame.time;
        }
        for (std::size_t k = 0; k < frame.sums.size(); ++k) out.sums[k] += w * frame.sums[k];
        norm += w;
        out.lastTime = frame.time;
        ++out.frames;
    }
    if (!(norm > 0)) {
        throw InputError("--output-times: no frame within " + str(support()) + " (the support of --time-smoothing " + str(width_) +
                         ") of the output time " + str(time));
    }
    for (double& v : out.sums) v /= norm;
    return out;
}

void TimeSmoother::addFrame(double time, const std::vector<double>& sums, std::vector<SmoothedFields>& ready) {
    if (anyFrame_ && !(time > lastFrameTime_)) {
        throw InputError("--time-smoothing: frame times must increase, found t = " + str(time) + " after t = " + str(lastFrameTime_));
    }
    if (!anyFrame_) firstFrameTime_ = time;
    // Output times that this and every later frame leave unchanged (weight 0 at |dt| >= R wt).
    while (!pending_.empty() && time >= pending_.front() + support()) {
        ready.push_back(smoothAt(pending_.front()));
        pending_.pop_front();
    }
    frames_.push_back({time, sums});
    anyFrame_ = true;
    lastFrameTime_ = time;
    queueOutputTimesUpTo(time);
    // Every later output time is after `time`: frames at or before (earliest needed) - R wt have
    // weight 0 for all of them.
    const double earliest = pending_.empty() ? time : std::min(pending_.front(), time);
    while (!frames_.empty() && frames_.front().time <= earliest - support()) frames_.pop_front();
}

void TimeSmoother::finish(std::vector<SmoothedFields>& ready) {
    if (!anyFrame_) return;
    if (!listed_.empty()) {
        while (nextListed_ < listed_.size()) pending_.push_back(listed_[nextListed_++]);
    } else if (step_) {
        queueOutputTimesUpTo(lastFrameTime_);
    }
    for (double t : pending_) ready.push_back(smoothAt(t));
    pending_.clear();
    frames_.clear();
}

}  // namespace talus::cg
