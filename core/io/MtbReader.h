#pragma once

#include "io/Import.h"

#include <cstddef>
#include <istream>
#include <string>

namespace footpath {

/// Reads an Xsens .mtb log (docs/xbus.md section 7.1): a plain stream of Xbus messages,
/// normally a Configuration (0x0D), the encrypted EMTS blob (0x91), then one data message per
/// sample. Samples come from MTData2 (0x36) or, on legacy devices, from MTData (0x32) laid out as
/// the Configuration's OutputMode/OutputSettings say; messages without both acceleration and rate
/// of turn are skipped (one warning), other messages are ignored.
///
/// Time comes from SampleTimeFine (10 kHz, wraps at 2^32) when the first sample has it, else from
/// the packet (legacy: sample) counter (wraps at 65536) divided by the rate, and starts at 0; lost
/// packets show as gaps. The rate is options.rate_hz, else the Configuration's (unless the
/// SampleTimeFine steps contradict it), else the median SampleTimeFine step. Values are SI as the
/// device sends them; the magnetic field is in the device's arbitrary units; a missing magnetic
/// field or pressure repeats the last value (NaN before the first).
///
/// Reads in fixed-size chunks through the incremental frame decoder, so memory follows the number
/// of samples, not the file size. Damaged bytes are skipped and the decoder resynchronises (a
/// warning names the byte offsets); a file that ends inside a message keeps every sample before it
/// and sets info.truncated. A file without a usable data message is an error naming the byte
/// offset where reading stopped. `totalBytes` (0 if unknown) drives progress. Never throws for bad
/// input.
ImportResult readMtb(std::istream& in, const std::string& sourceName, const ImportOptions& options,
                     std::size_t totalBytes);

}  // namespace footpath
