// The lane forms (Kernel/Math/LaneForm.h): the forms this processor runs, their choice, and the
// registration of every TALUS_LANE_TEST case (UnitTests/LaneFormTest.h) once per form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "Error.h"
#include "Math/LaneForm.h"
#include "LaneFormTest.h"

using namespace talus;

// The cases the lane sources left in their section (the linker names its ends).
extern "C" const test::LaneTestCase* const __start_talus_lane_tests[];
extern "C" const test::LaneTestCase* const __stop_talus_lane_tests[];

namespace {

// One case in one form: skipped where the processor does not run the form, run with the
// kernel's entry points in that form otherwise.
class InLaneForm : public ::testing::Test {
public:
    explicit InLaneForm(const test::LaneTestCase& c) : case_(c) {}

protected:
    void SetUp() override {
        const std::vector<LaneForm> forms = laneFormsOfThisProcessor();
        if (std::find(forms.begin(), forms.end(), case_.form) == forms.end())
            GTEST_SKIP() << "this processor does not run the " << laneFormName(case_.form) << " lanes";
        before_ = laneForm();
        setLaneForm(case_.form);
    }
    void TearDown() override { setLaneForm(before_); }
    void TestBody() override { case_.run(); }

private:
    const test::LaneTestCase& case_;
    LaneForm before_ = LaneForm::scalar;
};

const bool registered = [] {
    for (const test::LaneTestCase* const* entry = __start_talus_lane_tests; entry != __stop_talus_lane_tests; ++entry) {
        const test::LaneTestCase* c = *entry;
        ::testing::RegisterTest(c->suite, (std::string(c->name) + "/" + laneFormName(c->form)).c_str(), nullptr,
                                nullptr, c->file, c->line, [c]() -> ::testing::Test* { return new InLaneForm(*c); });
    }
    return true;
}();

// The forms this processor runs by the flags the operating system reports in /proc/cpuinfo
// (what it has enabled), read independently of the library's own test: the x86-64-v3 and v4
// levels of the forms' -march (Kernel/CMakeLists.txt; LZCNT left out: some virtual machines do
// not report it as "abm" though they run it), and BMI2 for the AVX-512 lanes.
std::set<LaneForm> formsByCpuinfo() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    std::set<std::string> flags;
    while (std::getline(in, line))
        if (line.rfind("flags", 0) == 0) {
            std::istringstream words(line.substr(line.find(':') + 1));
            for (std::string w; words >> w;) flags.insert(w);
            break;
        }
    const auto has = [&](std::initializer_list<const char*> names) {
        for (const char* n : names)
            if (!flags.count(n)) return false;
        return true;
    };
    std::set<LaneForm> forms{LaneForm::scalar};
    const bool v3 = has({"avx", "avx2", "bmi1", "bmi2", "f16c", "fma", "movbe", "xsave"});
    if (v3) forms.insert(LaneForm::avx2);
    if (v3 && has({"avx512f", "avx512bw", "avx512cd", "avx512dq", "avx512vl"})) forms.insert(LaneForm::avx512);
    return forms;
}

}  // namespace

// Every form the processor runs is run: the library finds the same forms as /proc/cpuinfo, the
// form in use is the best of them, and every lane case is there in each of them (the vector
// forms at least: the scalar form has no lanes to compare with its loops). Without this a build
// or a dispatch that lost a form would skip its tests and pass.
TEST(LaneForms, EveryFormThisProcessorRunsIsTested) {
    const std::vector<LaneForm> found = laneFormsOfThisProcessor();
    const std::set<LaneForm> expected = formsByCpuinfo();
    EXPECT_EQ(std::set<LaneForm>(found.begin(), found.end()), expected);
    EXPECT_EQ(laneForm(), *expected.rbegin());
    std::map<std::string, std::set<LaneForm>> casesByName;
    for (const test::LaneTestCase* const* c = __start_talus_lane_tests; c != __stop_talus_lane_tests; ++c)
        casesByName[std::string((*c)->suite) + "." + (*c)->name].insert((*c)->form);
    // Every case in every form the processor runs (the scalar form has no lane-against-loop
    // comparisons), and some cases in the vector forms alone: those comparisons are there.
    std::size_t vectorOnly = 0;
    for (const auto& [name, forms] : casesByName) {
        for (LaneForm form : expected)
            if (form != LaneForm::scalar) {
                EXPECT_TRUE(forms.count(form)) << name << " not in " << laneFormName(form);
            }
        vectorOnly += !forms.count(LaneForm::scalar);
    }
    EXPECT_GE(casesByName.size(), 13u);  // (the cases of UnitTests/CMakeLists.txt's laneTestSources)
    EXPECT_GE(vectorOnly, 2u);           // (VelocityVerlet's lanes against the loop)
    std::printf("[ measured ] lane forms of this processor:");
    for (LaneForm form : found) std::printf(" %s", laneFormName(form));
    std::printf("; %zu lane cases\n", casesByName.size());
}

TEST(LaneForms, NamesAreReadAndABadOneIsRefused) {
    EXPECT_EQ(laneFormNamed("avx2", "--lane-form"), LaneForm::avx2);
    try {
        laneFormNamed("avx3", "--lane-form");
        FAIL() << "avx3 accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--lane-form: 'avx3' is not a lane form"), std::string::npos) << e.what();
    }
}
