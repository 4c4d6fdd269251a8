// Time smoothing of coarse-grained fields (issue 5; Documentation/CoarseGraining.md "Time
// smoothing"): the sums of the frames at times t_j, weighted by a temporal kernel of width wt
// centred at each output time T,
//
//   F~(T) = sum_j f(|t_j - T| / wt) F(t_j) / sum_j f(|t_j - T| / wt),
//
// with f the shape of a 1-D coarse-graining function (KernelProfile.h without its normalisation:
// Lucy with cut-off wt, Gauss with standard deviation wt cut at 3 wt, Heaviside of half-width wt).
// Dividing by the sum of the weights of the frames present makes the weights sum to 1 at every
// output time, near the first and last frames too (a one-sided kernel there). Since every frame
// conserves mass and the weights sum to 1, so does every smoothed field. Limits, exactly: a
// Heaviside wider than the window gives every frame the weight 1, i.e. the plain time average
// (the same sums in the same order as --time-average); a kernel whose support is below the frame
// spacing leaves one frame with weight f(0) = 1, i.e. the snapshot.
//
// Frames arrive one by one (the .data file is read once); a frame is kept only while an output
// time within the support may still need it, so the memory is the frames within 2 R wt.
#pragma once

#include <deque>
#include <optional>
#include <vector>

#include "Kernels/KernelProfile.h"

namespace talus::cg {

struct SmoothedFields {
    double time = 0;                  // the output time T
    double firstTime = 0, lastTime = 0;  // first and last frame with a positive weight
    int frames = 0;                   // frames with a positive weight
    std::vector<double> sums;         // FieldSums rows of all points, smoothed
};

class TimeSmoother {
public:
    // Output times: `outputTimes` (any order) if not empty, else every `step` from the first
    // frame's time up to the last one if given, else the times of the frames. Throws InputError
    // for a non-positive width or step.
    TimeSmoother(KernelShape shape, double width, std::vector<double> outputTimes, std::optional<double> step);

    // f(|dt| / wt): 1 at dt = 0, 0 beyond the support.
    double weight(double dt) const;
    // R wt: frames farther than this from T have weight 0.
    double support() const { return profile_.cutoff() * width_; }

    // Adds the sums of the frame at `time` (times must increase; throws InputError otherwise) and
    // appends to `ready` the output times no later frame can change.
    void addFrame(double time, const std::vector<double>& sums, std::vector<SmoothedFields>& ready);
    // After the last frame: the remaining output times up to the last frame (listed ones beyond it
    // too, if a frame is within their support); throws InputError naming --output-times for a
    // listed time with no frame within the support.
    void finish(std::vector<SmoothedFields>& ready);

private:
    SmoothedFields smoothAt(double time) const;
    void queueOutputTimesUpTo(double time);

    KernelProfile profile_;
    double width_;
    std::vector<double> listed_;  // sorted
    std::size_t nextListed_ = 0;
    std::optional<double> step_;
    long nextStep_ = 0;
    double firstFrameTime_ = 0;
    struct Frame {
        double time;
        std::vector<double> sums;
    };
    std::deque<Frame> frames_;
    std::deque<double> pending_;  // output times waiting for later frames, increasing
    bool anyFrame_ = false;
    double lastFrameTime_ = 0;
};

}  // namespace talus::cg
