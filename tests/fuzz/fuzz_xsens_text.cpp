// libFuzzer target: the MT Manager text export reader, through the import entry point with the
// format forced (as `--format xsens-text` does); what it reads must be estimable.

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    footpath::fuzz::importAs(data, size, "xsens-text", "fuzz.txt");
    return 0;
}
