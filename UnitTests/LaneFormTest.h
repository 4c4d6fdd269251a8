// Unit tests of the lane forms' own code (Kernel/Math/LaneKernels.h). A source that includes this
// header is compiled once per lane form, as the kernel's lane sources are (UnitTests/CMakeLists.txt,
// laneTestSources), and each TALUS_LANE_TEST(Suite, Name) case in it runs once per form, as
// Suite.Name/scalar, Suite.Name/avx2 and Suite.Name/avx512, with the kernel's entry points set to
// that form (setLaneForm); a form this processor does not run is skipped. The cases are handed to
// GoogleTest by code compiled for the baseline (LaneFormTest.cc), so that a form's instructions
// run only where the processor has them: each case leaves its form, suite, name and function in a
// section of its own, which LaneFormTest.cc reads.
#pragma once

#include <gtest/gtest.h>

#include "Math/LaneForm.h"
#ifdef TALUS_LANES  // (a lane source; LaneFormTest.cc reads the cases)
#include "Math/LaneNamespace.h"
#endif

namespace talus::test {

struct LaneTestCase {
    LaneForm form;
    const char* suite;
    const char* name;
    const char* file;
    int line;
    void (*run)();
};

}  // namespace talus::test

#define TALUS_LANE_TEST(suite, name)                                                                          \
    static void suite##_##name();                                                                             \
    [[gnu::used, gnu::section("talus_lane_tests")]] static constexpr talus::test::LaneTestCase                \
        suite##_##name##_case{talus::TALUS_LANES::compiledLaneForm, #suite, #name, __FILE__, __LINE__,        \
                              suite##_##name};                                                                \
    static void suite##_##name()

// Whether this form has lanes of its own to compare with its loops (the scalar form's "lanes"
// are its loops: a comparison there would compare a loop with itself).
#if defined(TALUS_AVX512_LANES) || defined(TALUS_AVX2_LANES)
#define TALUS_LANE_FORM_HAS_LANES 1
#endif
