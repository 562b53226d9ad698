// libFuzzer target: the delimited-text reader with and without a header row. The first byte picks
// how the file is read: detected, forced "delimited", forced "pyshoe-vicon", or headerless with one
// of the column maps people use (time in s/ms/us or a counter with a rate, skipped columns, mag and
// pressure); the rest is the file.

#include "io/Import.h"

#include "FuzzInput.h"

#include <sstream>
#include <string>
#include <vector>

using footpath::ImportOptions;

namespace {

ImportOptions optionsFor(std::uint8_t selector)
{
    static const std::vector<std::vector<std::string>> columnMaps = {
        {"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "pressure"},
        {"time_s", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"},
        {"skip", "time_us", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "mag_x", "mag_y", "mag_z"},
        {"counter", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"},
    };
    ImportOptions options;
    switch (selector % 8) {
    case 0: break;  // detect
    case 1: options.format = "delimited"; break;
    case 2: options.format = "pyshoe-vicon"; break;
    case 3: options.format = "delimited"; options.referenceColumns = {"x", "-y", "z"}; break;
    default:
        options.format = "delimited";
        options.columnMap = columnMaps[selector % 8 - 4];
        options.rate_hz = selector & 0x80 ? 100.0 : 0.0;
        break;
    }
    return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0)
        return 0;
    const ImportOptions options = optionsFor(data[0]);
    std::istringstream in(footpath::fuzz::asText(data + 1, size - 1));
    footpath::fuzz::checkImported(footpath::importStream(in, size - 1, "fuzz.csv", options));
    (void)footpath::startsWithHeaderRow(footpath::fuzz::asText(data + 1, size - 1));
    return 0;
}
