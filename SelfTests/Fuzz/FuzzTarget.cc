// The libFuzzer entry of one fuzz target: compiled once per target with TALUS_FUZZ_ENTRY naming
// its entry function (FuzzEntries.h).
#include "FuzzEntries.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    talus::fuzz::TALUS_FUZZ_ENTRY(data, size);  // (accepted or refused alike: no finding)
    return 0;
}
