// Unit tests of the lane forms' own code (Kernel/Math/LaneKernels.h). A source that includes this
// header is compiled once per lane form, as the kernel's lane sources are (UnitTests/CMakeLists.txt,
// laneTestSources), and each TALUS_LANE_TEST(Suite, Name) case in it runs once per form, as
// Suite.Name/scalar, Suite.Name/avx2 and Suite.Name/avx512, with the kernel's entry points set to
// that form (setLaneForm); a form this processor does not run is skipped. The cases are handed to
// GoogleTest by code compiled for the baseline (LaneFormTest.cc), so that a form's instructions
// run only where the processor has them: each case leaves a pointer to its form, suite, name and
// function in a section of its own, which LaneFormTest.cc reads.
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

// (The section holds pointers to the cases: eight bytes each, so that the linker lays them out
// as an array; a larger object may be aligned beyond its size, with gaps between.)
#define TALUS_LANE_TEST(suite, name)                                                                          \
    static void suite##_##name();                                                                             \
    static constexpr talus::test::LaneTestCase suite##_##name##_case{                                         \
        talus::TALUS_LANES::compiledLaneForm, #suite, #name, __FILE__, __LINE__, suite##_##name};             \
    [[gnu::used, gnu::section("talus_lane_tests")]] static const talus::test::LaneTestCase* const             \
        suite##_##name##_entry = &suite##_##name##_case;                                                      \
    static void suite##_##name()

// TALUS_LANE_FORM_HAS_LANES (set by talus_lane_form, Kernel/CMakeLists.txt, for the avx2 and
// avx512 forms): this form has lanes of its own to compare with its loops (the scalar form's
// "lanes" are its loops: a comparison there would compare a loop with itself).
