// libFuzzer target: fuzz::measureRegionVolumes (fuzz/fuzz_targets.h). Built and run by scripts/fuzz.
#include "fuzz_targets.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    veridem::fuzz::measureRegionVolumes(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
