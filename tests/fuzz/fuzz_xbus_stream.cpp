// libFuzzer target: the Xbus stream decoder as a serial port feeds it (arbitrary chunks, a small
// buffer limit now and then), then every payload through the message parsers the live path and
// the .mtb reader use. Besides crashes it checks two promises of XbusFrameDecoder: every byte is
// accounted for exactly once, and a decoded message re-encodes to a frame that decodes to itself.

#include "xbus/LegacyMtData.h"
#include "xbus/MtData2.h"
#include "xbus/XbusControl.h"
#include "xbus/XbusFrame.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdlib>
#include <vector>

using namespace footpath;

namespace {

void parsePayload(const XbusMessage& message)
{
    const std::vector<std::uint8_t>& payload = message.payload;
    const XbusConfigurationParsed configuration = parseConfiguration(payload);
    if (configuration.ok())
        for (const XbusConfiguration::Device& device : configuration.configuration.devices)
            if (device.layout.validate().empty())
                (void)decodeLegacyMtData(payload, device.layout);
    (void)decodeMtData2(payload);
    (void)decodeLegacyMtData(payload, LegacyDataLayout{});
    (void)parseDeviceId(payload);
    (void)parseProductCode(payload);
    (void)parseFirmwareRevision(payload);
    (void)parseOutputConfiguration(payload);
    (void)parseBaudCode(payload);
    (void)xbusErrorText(payload);
    (void)xbusMidName(message.mid);
}

void checkRoundTrip(const XbusMessage& message)
{
    const std::vector<std::uint8_t> frame = encodeFrame(message);
    XbusFrameDecoder decoder;
    decoder.feed(frame.data(), frame.size());
    decoder.finish();
    XbusMessage again;
    if (!decoder.next(again) || again.mid != message.mid || again.busId != message.busId
        || again.payload != message.payload)
        std::abort();
}

/// The bytes of the frame next() just returned. Not from the payload's size: a frame may use the
/// extended length field for a payload that would fit the standard one (the fuzzer found one), and
/// its header is then two bytes longer.
std::uint64_t lastFrameSize(const XbusFrameDecoder& decoder)
{
    return decoder.pendingOffset() - decoder.lastFrameOffset();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    FuzzedDataProvider input(data, size);
    const bool smallBuffer = input.ConsumeBool();
    XbusFrameDecoder decoder(smallBuffer ? std::size_t{0} : XbusFrameDecoder::kDefaultBufferLimit);
    std::uint64_t fed = 0;
    std::uint64_t framed = 0;
    XbusMessage message;
    while (input.remaining_bytes() > 0) {
        const std::size_t chunk = input.ConsumeIntegralInRange<std::size_t>(1, 4096);
        const std::vector<std::uint8_t> bytes = input.ConsumeBytes<std::uint8_t>(chunk);
        decoder.feed(bytes.data(), bytes.size());
        fed += bytes.size();
        // With the small buffer, sometimes let bytes pile up so that the overflow path runs.
        if (smallBuffer && (bytes.empty() || bytes.front() % 3 == 0))
            continue;
        while (decoder.next(message)) {
            framed += lastFrameSize(decoder);
            parsePayload(message);
            checkRoundTrip(message);
        }
    }
    decoder.finish();
    while (decoder.next(message))
        framed += lastFrameSize(decoder);
    const XbusDecodeStats& stats = decoder.stats();
    if (framed + stats.bytesSkipped + stats.bytesDroppedOverflow + stats.bytesTruncated + decoder.pendingBytes() != fed)
        std::abort();
    // Damaged frames are a subset of the failed candidates, their bytes a subset of the skipped ones.
    if (stats.damagedFrames > stats.checksumFailures || stats.damagedFrameBytes > stats.bytesSkipped)
        std::abort();
    return 0;
}
