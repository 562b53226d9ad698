// libFuzzer target: the Xsens .mtb reader, through the import entry point with the format forced
// (as `--format xsens-mtb` does), so the unit and gap handling after the read runs too; what it
// reads must be estimable (finite, in time order).

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    footpath::fuzz::importAs(data, size, "xsens-mtb", "fuzz.mtb");
    return 0;
}
