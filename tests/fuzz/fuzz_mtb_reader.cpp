// libFuzzer target: the Xsens .mtb reader, through the import entry point with the format forced
// (as `--format xsens-mtb` does), so the unit and gap handling after the read runs too; what it
// reads must be estimable (finite, in time order).

#include "io/Import.h"

#include "FuzzInput.h"

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::istringstream in(footpath::fuzz::asText(data, size));
    footpath::ImportOptions options;
    options.format = "xsens-mtb";
    footpath::fuzz::checkImported(footpath::importStream(in, size, "fuzz.mtb", options));
    return 0;
}
