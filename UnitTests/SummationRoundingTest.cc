// When two sums of the same positive terms count as equal (Kernel/Math/SummationRounding.h): a
// mass balance over many particles must accept the rounding of summing in two orders and still
// catch a single particle lost or doubled.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "Math/SummationRounding.h"

using namespace talus;

namespace {

// The two masses of the thesis-scale maser-fed chute (Documentation/Chutes/MaserFedChute.md), as
// its restart file holds them, a third of them small, in random order.
std::vector<double> chuteMasses(std::size_t n, unsigned seed) {
    const double large = 1.3863609114164082, small = 0.6930501622776956;
    std::mt19937_64 random(seed);
    std::vector<double> masses(n);
    for (double& m : masses) m = (random() % 3 == 0) ? small : large;
    return masses;
}

double runningSum(const std::vector<double>& terms) {
    double sum = 0;
    for (double t : terms) sum += t;
    return sum;
}

}  // namespace

TEST(SummationRounding, TheSameMassesSummedInTwoOrdersAgree) {
    for (std::size_t n : {10u, 1000u, 177677u, 2000000u}) {
        std::vector<double> masses = chuteMasses(n, 7);
        const double inOrder = runningSum(masses);
        // As the census does it: two ranks' partial sums of a shuffled order, then their sum.
        std::shuffle(masses.begin(), masses.end(), std::mt19937_64(11));
        const auto half = masses.begin() + static_cast<std::ptrdiff_t>(n / 2);
        const double byRanks = runningSum({masses.begin(), half}) + runningSum({half, masses.end()});
        std::sort(masses.begin(), masses.end());
        const double sorted = runningSum(masses);
        EXPECT_TRUE(equalUpToSummationRounding(inOrder, byRanks, static_cast<double>(n))) << n;
        EXPECT_TRUE(equalUpToSummationRounding(inOrder, sorted, static_cast<double>(n))) << n;
    }
}

TEST(SummationRounding, OneParticleMoreOrLessIsCaught) {
    for (std::size_t n : {10u, 1000u, 177677u, 2000000u}) {
        const std::vector<double> masses = chuteMasses(n, 5);
        const double sum = runningSum(masses), lightest = *std::min_element(masses.begin(), masses.end());
        EXPECT_FALSE(equalUpToSummationRounding(sum, sum - lightest, static_cast<double>(n))) << n;
        EXPECT_FALSE(equalUpToSummationRounding(sum, sum + lightest, static_cast<double>(n))) << n;
    }
}

// The worst case of recursive summation: one large term first, then many terms each too small to
// change the total alone. The bound still holds against the exactly rounded sum.
TEST(SummationRounding, HoldsForTermsOfVeryDifferentSize) {
    const std::size_t n = 100000;
    std::vector<double> terms(n, 1.1e-16);
    terms.front() = 1.0;
    const double runningFromLarge = runningSum(terms);           // the small terms are lost: 1.0
    const double exact = 1.0 + 1.1e-16 * static_cast<double>(n - 1);  // 1.000000000011 (to its rounding)
    EXPECT_NE(runningFromLarge, exact);
    EXPECT_TRUE(equalUpToSummationRounding(runningFromLarge, exact, static_cast<double>(n)));
}
