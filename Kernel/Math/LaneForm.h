// The lane forms of the passes over the particles and of the force loop: the same code compiled
// once per instruction set (Kernel/CMakeLists.txt, talusLaneSources), and the one this process
// runs, chosen once from the processor (Documentation/UserGuide/Installing.md "Lane forms").
//   scalar  baseline x86-64 (SSE2): the loops as the compiler vectorises them, no fused multiply-add;
//   avx2    x86-64-v3 (AVX2, FMA, BMI2): four particles at a time (Lanes<4>, Math/FourLanes.h);
//   avx512  x86-64-v4 (AVX-512 F, BW, DQ, VL) with BMI2: eight at a time (Lanes<8>, Math/EightLanes.h).
// Each lane loop is written once, a template over the lanes (Math/Lanes.h).
// The results of a form are the same to the bit whatever processor runs it; those of two forms
// differ in rounding (a fused multiply-add rounds once).
#pragma once

#include <string>
#include <vector>

namespace talus {

enum class LaneForm { scalar, avx2, avx512 };

const char* laneFormName(LaneForm form);
// The form of a name ("scalar", "avx2", "avx512"); talus::Error naming `what` for another.
LaneForm laneFormNamed(const std::string& name, const std::string& what);
// The forms of this build that this processor runs, scalar first.
std::vector<LaneForm> laneFormsOfThisProcessor();
// The form in use: the last of laneFormsOfThisProcessor() unless setLaneForm chose another.
LaneForm laneForm();
// Runs the passes in `form` from now on (tests and measurements compare forms on one machine);
// talus::Error if this processor does not run it or the build lacks it.
void setLaneForm(LaneForm form);

}  // namespace talus
