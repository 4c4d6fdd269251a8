// Time smoothing (Fields/TimeSmoothing.h; issue 5): the fields at output times T are the frames'
// sums weighted by f(|t_j - T| / wt) and divided by the sum of the weights. Expected values:
//  - a Heaviside wider than the window weighs every frame 1: the plain time average (the sums
//    added in frame order, divided by the frame count: what --time-average does), bitwise;
//  - a kernel whose support is below the frame spacing keeps one frame of weight f(0) = 1: the
//    snapshot, bitwise;
//  - fields linear in time, F(t) = A + B t, on evenly spaced frames: a symmetric kernel whose
//    support lies inside the window gives sum w_j (A + B t_j) / sum w_j = A + B T exactly (the
//    weights are symmetric about T), at frame times and between them; at the first frame the
//    one-sided weights give A + B t_bar with t_bar = sum w_j t_j / sum w_j, computed here from
//    the Lucy polynomial written out;
//  - every frame conserves mass and the weights sum to 1, so the smoothed density integrates to
//    the mass at every output time (nested Gauss-Legendre quadrature split at the kernels' edges).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "App/Options.h"
#include "CGTestHelpers.h"
#include "Fields/CoarseGrainer.h"
#include "Fields/TimeSmoothing.h"
#include "IO/InputError.h"

using namespace talus::cg;
using namespace talus::cg::test;

namespace {

// Frames t = 0, 0.1, ..., 2.0 of 5 particles; positions move (when `moving`) and velocities
// vary linearly in time, v(t) = a + b t.
struct Sequence {
    std::vector<double> times;
    std::vector<ParticleFrame> frames;
    double mass = 0;
};

const Vec3 velocityA{0.3, -0.2, 0.5}, velocityB{1.1, 0.4, -0.7};

ParticleFrame frameAt(double t, bool moving) {
    std::vector<Vec3> x, v;
    std::vector<double> r;
    for (int i = 0; i < 5; ++i) {
        const double shift = moving ? 0.8 * std::sin(1.3 * t + i) : 0.0;
        x.push_back({1.0 + 0.7 * i, 2.0 + 0.3 * i, 2.5 + 0.4 * i + shift});
        v.push_back({velocityA[0] + velocityB[0] * t, velocityA[1] + velocityB[1] * t, velocityA[2] + velocityB[2] * t});
        r.push_back(0.2 + 0.05 * i);
    }
    ParticleFrame f = makeFrame(x, r, {{0, 0, 0}, {5, 4, 6}}, v);
    f.time = t;
    return f;
}

Sequence sequence(bool moving) {
    Sequence s;
    for (int k = 0; k <= 20; ++k) {
        s.times.push_back(0.1 * k);
        s.frames.push_back(frameAt(0.1 * k, moving));
    }
    for (double r : s.frames[0].radius) s.mass += 1.5 * sphereVolume(r);
    return s;
}

CoarseGrainer grainer(const char* coordinates) {
    CoarseGrainingSetup setup;
    setup.coordinates = Coordinates::fromName(coordinates);
    setup.width = WidthMatrix::isotropic(0.9);
    setup.speciesDensity = {1.5};
    return CoarseGrainer(setup);
}

std::vector<SmoothedFields> smooth(TimeSmoother& smoother, CoarseGrainer& g, const Sequence& s, const std::vector<Vec3>& points,
                                   std::vector<std::vector<double>>* frameSums = nullptr) {
    std::vector<SmoothedFields> out;
    std::vector<double> sums;
    for (const ParticleFrame& frame : s.frames) {
        g.setFrame(frame, nullptr);
        g.evaluate(points, sums);
        if (frameSums) frameSums->push_back(sums);
        smoother.addFrame(frame.time, sums, out);
    }
    smoother.finish(out);
    return out;
}

const std::vector<Vec3> somePoints{{1.2, 2.1, 2.6}, {2.0, 2.5, 3.4}, {3.3, 3.0, 4.0}, {0.5, 0.5, 0.5}};

}  // namespace

TEST(TimeSmoothing, HeavisideWiderThanTheWindowIsThePlainAverage) {
    const Sequence s = sequence(true);
    CoarseGrainer g = grainer("XYZ");
    TimeSmoother smoother(KernelShape::Heaviside, 2.5, {}, std::nullopt);  // window 2.0 < wt
    std::vector<std::vector<double>> frameSums;
    const auto out = smooth(smoother, g, s, somePoints, &frameSums);
    std::vector<double> average(frameSums[0].size(), 0.0);
    for (const auto& sums : frameSums) {
        for (std::size_t k = 0; k < sums.size(); ++k) average[k] += sums[k];
    }
    for (double& v : average) v /= static_cast<int>(frameSums.size());
    ASSERT_EQ(out.size(), s.times.size());  // output times = the frames
    for (std::size_t o = 0; o < out.size(); ++o) {
        EXPECT_EQ(out[o].time, s.times[o]);
        EXPECT_EQ(out[o].frames, 21);
        for (std::size_t k = 0; k < average.size(); ++k) ASSERT_EQ(out[o].sums[k], average[k]) << "output " << o << " value " << k;
    }
}

TEST(TimeSmoothing, KernelBelowTheFrameSpacingIsTheSnapshot) {
    const Sequence s = sequence(true);
    // Supports below the spacing 0.1: Lucy and Heaviside wt = 0.099, Gauss 3 wt = 0.099.
    for (auto [shape, width] : {std::pair{KernelShape::Lucy, 0.099}, std::pair{KernelShape::Heaviside, 0.099},
                                std::pair{KernelShape::Gauss, 0.033}}) {
        CoarseGrainer g = grainer("XYZ");
        TimeSmoother smoother(shape, width, {}, std::nullopt);
        std::vector<std::vector<double>> frameSums;
        const auto out = smooth(smoother, g, s, somePoints, &frameSums);
        ASSERT_EQ(out.size(), frameSums.size());
        for (std::size_t o = 0; o < out.size(); ++o) {
            EXPECT_EQ(out[o].frames, 1);
            for (std::size_t k = 0; k < frameSums[o].size(); ++k) {
                ASSERT_EQ(out[o].sums[k], frameSums[o][k]) << kernelShapeName(shape) << " output " << o;
            }
        }
    }
}

TEST(TimeSmoothing, LinearInTimeIsReproducedInTheInteriorAndRenormalisedAtTheEdges) {
    const Sequence s = sequence(false);  // fixed positions: momentum = A + B t at every point
    // Heaviside wt = 0.33, not a multiple of the half spacing 0.05: with a frame exactly at
    // |t - T| = wt, rounding of the times would decide on which side it is inside the (jumping)
    // kernel, and the weights would not be symmetric.
    for (auto [shape, width] : {std::pair{KernelShape::Lucy, 0.35}, std::pair{KernelShape::Gauss, 0.12},
                                std::pair{KernelShape::Heaviside, 0.33}}) {
        CoarseGrainer g = grainer("XYZ");
        TimeSmoother smoother(shape, width, {}, 0.05);  // output at the frames and half-way between
        const auto out = smooth(smoother, g, s, somePoints);
        ASSERT_EQ(out.size(), 41u);
        const double support = smoother.support();
        int interior = 0;
        std::vector<double> expected;
        for (const SmoothedFields& o : out) {
            // The momentum of the snapshot with velocities a + b T (positions do not move).
            g.setFrame(frameAt(o.time, false), nullptr);
            g.evaluate(somePoints, expected);
            const bool inside = o.time >= support - 1e-12 && o.time <= 2.0 - support + 1e-12;
            if (!inside && !(shape == KernelShape::Lucy && o.time == 0)) continue;
            double tBar = o.time;
            if (!inside) {
                // One-sided Lucy weights at T = 0: frames t_j = 0.1 j with q = t_j / wt < 1.
                double sw = 0, swt = 0;
                for (double t : s.times) {
                    const double q = t / width;
                    if (q >= 1) continue;
                    const double w = 1 - 6 * q * q + 8 * q * q * q - 3 * q * q * q * q;
                    sw += w;
                    swt += w * t;
                }
                tBar = swt / sw;
                EXPECT_GT(tBar, 0.05);  // the edge pulls the smoothed time inwards
                g.setFrame(frameAt(tBar, false), nullptr);
                g.evaluate(somePoints, expected);
            } else {
                ++interior;
            }
            const int fields = g.layout().count();
            for (std::size_t p = 0; p < somePoints.size(); ++p) {
                const double scale = std::abs(expected[p * fields + FieldSums::density]) * 2 + 1e-300;
                for (int c = 0; c < 3; ++c) {
                    EXPECT_NEAR(o.sums[p * fields + FieldSums::momentum + c], expected[p * fields + FieldSums::momentum + c], 1e-13 * scale)
                        << kernelShapeName(shape) << " T " << o.time << " point " << p;
                }
                EXPECT_NEAR(o.sums[p * fields + FieldSums::density], expected[p * fields + FieldSums::density], 1e-13 * scale);
            }
        }
        EXPECT_GE(interior, 25) << kernelShapeName(shape);
    }
}

TEST(TimeSmoothing, MassIsConservedAtEveryOutputTime) {
    // A depth profile (Z) of moving particles, integrated over z with panels split at every
    // particle's z and z +- w in every frame (the smoothed field is smooth between them).
    const Sequence s = sequence(true);
    CoarseGrainer g = grainer("Z");
    std::vector<double> breaks;
    for (const ParticleFrame& f : s.frames) {
        for (const Vec3& x : f.position) {
            for (double d : {-0.9, 0.0, 0.9}) breaks.push_back(x[2] + d);
        }
    }
    const GaussLegendre rule(12);
    std::vector<double> z, w;
    rule.panels(0, 6, breaks, z, w);
    std::vector<Vec3> points;
    for (double zk : z) points.push_back({0, 0, zk});
    for (auto [shape, width] : {std::pair{KernelShape::Lucy, 0.45}, std::pair{KernelShape::Gauss, 0.2}}) {
        TimeSmoother smoother(shape, width, {0.0, 0.03, 0.77, 1.5, 2.0, 2.1}, std::nullopt);
        const auto out = smooth(smoother, g, s, points);
        ASSERT_EQ(out.size(), 6u);
        const int fields = g.layout().count();
        for (const SmoothedFields& o : out) {
            double integral = 0;
            for (std::size_t p = 0; p < points.size(); ++p) integral += w[p] * o.sums[p * fields + FieldSums::density];
            // Z divides by the box area 5 x 4: int rho dz = mass / area.
            EXPECT_NEAR(integral * 20, s.mass, 1e-10 * s.mass) << kernelShapeName(shape) << " T " << o.time;
        }
    }
}

TEST(TimeSmoothing, BadInputIsNamed) {
    auto error = [](const std::vector<const char*>& args) -> std::string {
        std::vector<const char*> argv{"talus-cg", "run"};
        argv.insert(argv.end(), args.begin(), args.end());
        try {
            parseOptions(static_cast<int>(argv.size()), argv.data());
        } catch (const InputError& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_EQ(error({"--time-smoothing", "0"}), "--time-smoothing: the width must be positive, found 0");
    EXPECT_EQ(error({"--time-smoothing", "1", "--time-average"}), "--time-smoothing and --time-average exclude each other: give one");
    EXPECT_EQ(error({"--output-step", "1"}), "--output-step: only used with --time-smoothing WT");
    EXPECT_EQ(error({"--time-smoothing", "1", "--output-times", "1,x"}), "--output-times: 'x' is not a time");
    EXPECT_EQ(error({"--time-smoothing", "1", "--time-function", "Cosine"}),
              "--time-function: unknown time-smoothing function 'Cosine' (Lucy, Gauss or Heaviside)");
    // A listed time with no frame within the support, and frames out of order.
    TimeSmoother listed(KernelShape::Lucy, 0.1, {5.0}, std::nullopt);
    std::vector<SmoothedFields> out;
    listed.addFrame(0.0, {1.0}, out);
    listed.addFrame(0.5, {1.0}, out);
    try {
        listed.finish(out);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "--output-times: no frame within 0.1 (the support of --time-smoothing 0.1) of the output time 5");
    }
    TimeSmoother ordered(KernelShape::Lucy, 0.1, {}, std::nullopt);
    ordered.addFrame(1.0, {1.0}, out);
    EXPECT_THROW(ordered.addFrame(1.0, {1.0}, out), InputError);
}
