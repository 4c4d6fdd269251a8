// The decision of a calibration point (FlowDecision.h) on synthetic series sampled once per time
// unit, whose arrest and plateau times follow from the criteria by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "Error.h"
#include "FlowDecision.h"

using namespace talus;

namespace {

// Feeds samples t = 1, 2, ... of (energy, flux) until the state is decided or t reaches `last`;
// returns the time of the deciding sample (-1 if none).
double decide(FlowDecision& d, const std::function<double(double)>& energy, const std::function<double(double)>& flux,
              double last = 1000) {
    for (double t = 1; t <= last; ++t)
        if (d.add(t, energy(t), flux(t)) != FlowState::undecided) return t;
    return -1;
}

}  // namespace

// A flow that dies out as E = 0.5 exp(-t/5) drops below the arrest energy 1e-5 after
// t* = 5 ln(0.5 / 1e-5) = 54.1, so the first sample below it is t = 55, and with an arrest time of
// 10 the sample at t = 65 decides. Its kinetic energy is never on a plateau (it halves every 3.5
// time units), so nothing decides before.
TEST(FlowDecision, ArrestAfterTheArrestTimeBelowTheThreshold) {
    FlowDecision d({.arrestEnergy = 1e-5, .arrestTime = 10, .window = 20, .tolerance = 0.02});
    const double t = decide(d, [](double t) { return 0.5 * std::exp(-t / 5); }, [](double t) { return std::exp(-t / 10); });
    EXPECT_EQ(t, 65);
    EXPECT_EQ(d.state(), FlowState::arrested);
    EXPECT_EQ(d.decidedAt(), 65);
    EXPECT_STREQ(flowStateName(d.state()), "arrested");
}

// A pause shorter than the arrest time is not an arrest: 9 samples below the threshold, then a
// flow again, then 10 below: arrested at the tenth sample of the second pause (t = 40 + 10). (The
// flux grows as t^2, so that no plateau decides first.)
TEST(FlowDecision, APauseShorterThanTheArrestTimeIsNotAnArrest) {
    FlowDecision d({.arrestEnergy = 1e-5, .arrestTime = 10, .window = 20, .tolerance = 0.02});
    auto energy = [](double t) { return (t >= 21 && t <= 29) || t >= 40 ? 1e-6 : 0.1 * (1 + std::sin(t)); };
    EXPECT_EQ(decide(d, energy, [](double t) { return t * t; }), 50);
    EXPECT_EQ(d.state(), FlowState::arrested);
}

// A steady flow: energy and flux each the ramp c + r t. Over a window of W samples the
// least-squares line changes by r (W - 1), the window's mean is c + r (n - (W - 1)/2) for the
// window ending at sample n, so the plateau test r (W - 1) <= tol mean first holds at
// n = (W - 1)/tol - c/r + (W - 1)/2: with W = 20, tol = 0.02, c = 10 and r = 0.01 (energy) that is
// 950 - 1000 + 9.5 = -40.5, so the first full window (n = 20) passes; the flux ramps faster,
// r = 0.5 with c = 100: n = 950 - 200 + 9.5 = 759.5, so sample 760 decides.
TEST(FlowDecision, SteadyWhenBothSeriesAreOnAPlateau) {
    FlowDecision d({.arrestEnergy = 1e-5, .arrestTime = 10, .window = 20, .tolerance = 0.02});
    EXPECT_EQ(decide(d, [](double t) { return 10 + 0.01 * t; }, [](double t) { return 100 + 0.5 * t; }), 760);
    EXPECT_EQ(d.state(), FlowState::steady);
    EXPECT_STREQ(flowStateName(d.state()), "flowing");

    FlowDecision flat({.arrestEnergy = 1e-5, .arrestTime = 10, .window = 20, .tolerance = 0.02});
    EXPECT_EQ(decide(flat, [](double t) { return 10 + 0.01 * t; }, [](double) { return 3.0; }), 20);
}

// A steady flow that then stops is arrested (the arrest is checked at every sample); once
// arrested it stays so when it flows again.
TEST(FlowDecision, ASteadyFlowThatStopsIsArrested) {
    FlowDecision d({.arrestEnergy = 1e-5, .arrestTime = 5, .window = 10, .tolerance = 0.02});
    auto energy = [](double t) { return t < 30 ? 1.0 : 0.0; };
    EXPECT_EQ(decide(d, energy, [](double) { return 2.0; }, 29), 10);
    for (double t = 30; t <= 34; ++t) EXPECT_EQ(d.add(t, energy(t), 2.0), FlowState::steady) << t;
    EXPECT_EQ(d.add(35, 0.0, 2.0), FlowState::arrested);  // 5 time units after the first sample at rest
    EXPECT_EQ(d.add(36, 1.0, 2.0), FlowState::arrested);
    EXPECT_EQ(d.decidedAt(), 35);
}

// Bad criteria name the driver's flag.
TEST(FlowDecision, BadCriteriaNameTheirFlag) {
    auto message = [](const FlowCriteria& c) {
        try {
            FlowDecision d(c);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message({.arrestEnergy = 0}).find("--arrest-energy"), std::string::npos);
    EXPECT_NE(message({.arrestTime = -1}).find("--arrest-time"), std::string::npos);
    EXPECT_NE(message({.window = 3}).find("--window"), std::string::npos);
    EXPECT_NE(message({.tolerance = 0}).find("--tolerance"), std::string::npos);
}
