// libFuzzer target: the MT Manager text export reader, through the import entry point with the
// format forced (as `--format xsens-text` does).

#include "io/Import.h"

#include "FuzzInput.h"

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::istringstream in(footpath::fuzz::asText(data, size));
    footpath::ImportOptions options;
    options.format = "xsens-text";
    footpath::fuzz::checkImported(footpath::importStream(in, size, "fuzz.txt", options));
    return 0;
}
