// The namespace of the lane form a source is being compiled for (Math/LaneKernels.h):
// TALUS_LANES is lanes_scalar, lanes_avx2 or lanes_avx512, set by Kernel/CMakeLists.txt for the
// sources it compiles once per form (talusLaneSources). The passes inside it may use that
// form's instructions; anything they share with the rest of the kernel lives outside it.
#pragma once

#include <string_view>

#include "Math/LaneForm.h"

#ifndef TALUS_LANES
#error "lane-form code: only the sources compiled once per lane form (talusLaneSources) include it"
#endif

namespace talus::TALUS_LANES {

#define TALUS_LANES_NAME_(lanes) #lanes
#define TALUS_LANES_NAME(lanes) TALUS_LANES_NAME_(lanes)
// The form this source is being compiled for.
inline constexpr LaneForm compiledLaneForm = [] {
    constexpr std::string_view name = TALUS_LANES_NAME(TALUS_LANES);
    return name == "lanes_avx512" ? LaneForm::avx512 : name == "lanes_avx2" ? LaneForm::avx2 : LaneForm::scalar;
}();

}  // namespace talus::TALUS_LANES
