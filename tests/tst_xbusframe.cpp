// The Xbus frame codec: every checksum-verified frame of docs/xbus.md section 8 decodes,
// encoding round-trips (standard and extended length), and the incremental decoder resynchronises
// after garbage and bad checksums the way section 1.4 describes, counting what it skipped.
#include "xbus/XbusFrame.h"

#include <QtTest>

#include <numeric>

using namespace footpath;

namespace {

std::vector<std::uint8_t> bytes(const QByteArray& hex)
{
    const QByteArray raw = QByteArray::fromHex(hex);  // spaces are skipped
    return {raw.begin(), raw.end()};
}

QByteArray hexOf(const std::vector<std::uint8_t>& data)
{
    return QByteArray(reinterpret_cast<const char*>(data.data()), static_cast<int>(data.size())).toHex(' ');
}

std::vector<XbusMessage> decodeAll(XbusFrameDecoder& decoder, const std::vector<std::uint8_t>& stream)
{
    decoder.feed(stream.data(), stream.size());
    std::vector<XbusMessage> messages;
    XbusMessage message;
    while (decoder.next(message))
        messages.push_back(message);
    return messages;
}

std::vector<std::uint8_t> concat(std::initializer_list<std::vector<std::uint8_t>> parts)
{
    std::vector<std::uint8_t> out;
    for (const auto& part : parts)
        out.insert(out.end(), part.begin(), part.end());
    return out;
}

/// Section 8.6: payload 0x00..0xFF then 44 zeros, 300 bytes.
std::vector<std::uint8_t> extendedExamplePayload()
{
    std::vector<std::uint8_t> payload(300, 0);
    std::iota(payload.begin(), payload.begin() + 256, std::uint8_t{0});
    return payload;
}

/// Section 8.8: SCOT's MTi-300 Configuration payload, 118 bytes.
std::vector<std::uint8_t> configurationExamplePayload()
{
    std::vector<std::uint8_t> payload = bytes("03 70 03 F8 04 80 00 00");
    payload.resize(payload.size() + 88, 0);
    const std::vector<std::uint8_t> tail = bytes("00 01 03 70 03 F8 00 00 00 00 00 00 00 01 00 27 01 08 02 49 05 01");
    payload.insert(payload.end(), tail.begin(), tail.end());
    return payload;
}

const std::vector<std::uint8_t> kGoToConfig = bytes("FA FF 30 00 D1");
const std::vector<std::uint8_t> kDeviceId = bytes("FA FF 01 04 03 70 03 F8 8E");
const std::vector<std::uint8_t> kErrorMessage = bytes("FA FF 42 01 04 BA");

}  // namespace

class TestXbusFrame : public QObject {
    Q_OBJECT
private slots:
    void verifiedExampleFrames_data()
    {
        QTest::addColumn<QByteArray>("frame");
        QTest::addColumn<int>("mid");
        QTest::addColumn<QByteArray>("payload");
        // 8.1 short commands
        QTest::newRow("GoToConfig") << QByteArray("FA FF 30 00 D1") << 0x30 << QByteArray();
        QTest::newRow("GoToConfigAck") << QByteArray("FA FF 31 00 D0") << 0x31 << QByteArray();
        QTest::newRow("GoToMeasurement") << QByteArray("FA FF 10 00 F1") << 0x10 << QByteArray();
        QTest::newRow("GoToMeasurementAck") << QByteArray("FA FF 11 00 F0") << 0x11 << QByteArray();
        QTest::newRow("WakeUp") << QByteArray("FA FF 3E 00 C3") << 0x3E << QByteArray();
        QTest::newRow("WakeUpAck") << QByteArray("FA FF 3F 00 C2") << 0x3F << QByteArray();
        QTest::newRow("Reset") << QByteArray("FA FF 40 00 C1") << 0x40 << QByteArray();
        QTest::newRow("ResetAck") << QByteArray("FA FF 41 00 C0") << 0x41 << QByteArray();
        QTest::newRow("ReqDID") << QByteArray("FA FF 00 00 01") << 0x00 << QByteArray();
        QTest::newRow("DeviceID") << QByteArray("FA FF 01 04 03 70 03 F8 8E") << 0x01 << QByteArray("037003F8");
        QTest::newRow("ReqProductCode") << QByteArray("FA FF 1C 00 E5") << 0x1C << QByteArray();
        QTest::newRow("ProductCode") << QByteArray("FA FF 1D 0D 4D 54 69 2D 33 30 30 2D 32 41 35 47 34 BD") << 0x1D
                                     << QByteArray("MTi-300-2A5G4").toHex();
        QTest::newRow("ReqHardwareVersion") << QByteArray("FA FF 1E 00 E3") << 0x1E << QByteArray();
        QTest::newRow("ReqFWRev") << QByteArray("FA FF 12 00 EF") << 0x12 << QByteArray();
        QTest::newRow("FirmwareRev") << QByteArray("FA FF 13 03 01 08 02 E0") << 0x13 << QByteArray("010802");
        QTest::newRow("ReqBaudrate") << QByteArray("FA FF 18 00 E9") << 0x18 << QByteArray();
        QTest::newRow("ReqBaudrateAck 115200") << QByteArray("FA FF 19 01 02 E5") << 0x19 << QByteArray("02");
        QTest::newRow("SetBaudrate 921600") << QByteArray("FA FF 18 01 80 68") << 0x18 << QByteArray("80");
        QTest::newRow("SetBaudrateAck") << QByteArray("FA FF 19 00 E8") << 0x19 << QByteArray();
        QTest::newRow("SetBaudrate 115200") << QByteArray("FA FF 18 01 02 E6") << 0x18 << QByteArray("02");
        QTest::newRow("ReqOutputConfiguration") << QByteArray("FA FF C0 00 41") << 0xC0 << QByteArray();
        QTest::newRow("empty output configuration") << QByteArray("FA FF C0 04 00 00 00 00 3D") << 0xC0
                                                    << QByteArray("00000000");
        QTest::newRow("ReqConfiguration") << QByteArray("FA FF 0C 00 F5") << 0x0C << QByteArray();
        QTest::newRow("RestoreFactoryDef") << QByteArray("FA FF 0E 00 F3") << 0x0E << QByteArray();
        QTest::newRow("ReqData") << QByteArray("FA FF 34 00 CD") << 0x34 << QByteArray();
        QTest::newRow("Error 4") << QByteArray("FA FF 42 01 04 BA") << 0x42 << QByteArray("04");
        QTest::newRow("ReqOutputMode") << QByteArray("FA FF D0 00 31") << 0xD0 << QByteArray();
        QTest::newRow("SetOutputModeAck") << QByteArray("FA FF D1 00 30") << 0xD1 << QByteArray();
        QTest::newRow("SetOutputMode orientation") << QByteArray("FA FF D0 02 00 04 2B") << 0xD0 << QByteArray("0004");
        QTest::newRow("SetOutputSettings") << QByteArray("FA FF D2 04 00 00 00 01 2A") << 0xD2 << QByteArray("00000001");
        QTest::newRow("SetPeriod 1152") << QByteArray("FA FF 04 02 04 80 77") << 0x04 << QByteArray("0480");
        QTest::newRow("RS485 padded GoToConfig") << QByteArray("FA FF 30 1E") + QByteArray(60, '0') + "B3" << 0x30
                                                 << QByteArray(60, '0');
        // 8.2 output configuration and its ack; the ARD examples
        const QByteArray outputConfiguration = "10 20 FF FF 10 60 FF FF 20 10 00 64 40 20 01 90 80 20 01 90 "
                                               "C0 20 00 64 E0 20 FF FF 50 42 00 64 50 22 00 64 D0 12 00 64";
        QTest::newRow("SetOutputConfiguration") << "FA FF C0 28 " + outputConfiguration + " 73" << 0xC0
                                                << outputConfiguration;
        QTest::newRow("OutputConfiguration ack") << "FA FF C1 28 " + outputConfiguration + " 72" << 0xC1
                                                 << outputConfiguration;
        QTest::newRow("ARD acc gyr mag") << QByteArray("FA FF C0 0C 40 20 00 64 80 20 00 64 C0 20 00 64 29") << 0xC0
                                         << QByteArray("40 20 00 64 80 20 00 64 C0 20 00 64");
        QTest::newRow("ARD euler") << QByteArray("FA FF C0 18 10 60 FF FF 20 30 00 64 40 20 00 64 80 20 00 64 C0 20 "
                                                 "00 64 E0 20 FF FF FD")
                                   << 0xC0
                                   << QByteArray("10 60 FF FF 20 30 00 64 40 20 00 64 80 20 00 64 C0 20 00 64 E0 20 FF FF");
        // 8.3-8.5 MTData2, 8.7 legacy MTData
        const QByteArray mti710 = "10 20 02 DF C5 10 60 04 00 45 9D A0 40 20 0C BE DC 9A FA 3F 54 9F 37 41 1C BB 70 "
                                  "80 20 0C BB AA 5C 80 3B 8C 55 01 BB 81 33 00 E0 20 04 00 00 00 81";
        QTest::newRow("8.3 MTi-G-710") << "FA FF 36 31 " + mti710 + " 45" << 0x36 << mti710;
        const QByteArray constructed = "10 20 02 04 D2 10 60 04 00 57 47 2E 40 20 0C 3E 80 00 00 BF 00 00 00 41 1D 00 "
                                       "00 80 20 0C 3C 80 00 00 BD 00 00 00 00 00 00 00 C0 20 0C 3F 00 00 00 BE 80 "
                                       "00 00 3F 80 00 00 E0 20 04 00 00 00 03";
        QTest::newRow("8.4 constructed") << "FA FF 36 40 " + constructed + " A8" << 0x36 << constructed;
        const QByteArray float64Quaternion = "10 20 02 04 D2 20 17 20 3F F0 00 00 00 00 00 00" + QByteArray(48, '0');
        QTest::newRow("8.4 float64 NED quaternion") << "FA FF 36 28 " + float64Quaternion + " 15" << 0x36
                                                    << float64Quaternion;
        const QByteArray mti300 = "10 20 02 46 82 10 60 04 01 C4 FC 3E 20 10 10 3F 71 CE 6C BE A5 6B CF 3C 61 3B D8 "
                                  "BD 69 1D 25 E0 20 04 00 40 00 03";
        QTest::newRow("8.5 MTi-300") << "FA FF 36 26 " + mti300 + " 12" << 0x36 << mti300;
        const QByteArray legacyQuaternion = "3F 80 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 2A";
        QTest::newRow("8.7 legacy quaternion") << "FA FF 32 12 " + legacyQuaternion + " D4" << 0x32 << legacyQuaternion;
        const QByteArray legacyCalibrated = "3E 80 00 00 BF 00 00 00 41 1D 00 00 3C 80 00 00 BD 00 00 00 00 00 00 00 "
                                            "3F 00 00 00 BE 80 00 00 3F 80 00 00 00 2A";
        QTest::newRow("8.7 legacy calibrated") << "FA FF 32 26 " + legacyCalibrated + " EF" << 0x32 << legacyCalibrated;
        // 8.6 extended length and 8.8 Configuration, rebuilt from their descriptions
        const QByteArray extended = hexOf(extendedExamplePayload());
        QTest::newRow("8.6 extended length") << "FA FF 36 FF 01 2C " + extended + " 1F" << 0x36 << extended;
        const QByteArray configuration = hexOf(configurationExamplePayload());
        QTest::newRow("8.8 Configuration") << "FA FF 0D 76 " + configuration + " 9B" << 0x0D << configuration;
    }
    void verifiedExampleFrames()
    {
        QFETCH(QByteArray, frame);
        QFETCH(int, mid);
        QFETCH(QByteArray, payload);
        const std::vector<std::uint8_t> stream = bytes(frame);
        XbusFrameDecoder decoder;
        const std::vector<XbusMessage> messages = decodeAll(decoder, stream);
        QCOMPARE(messages.size(), std::size_t(1));
        QCOMPARE(int(messages[0].busId), 0xFF);
        QCOMPARE(int(messages[0].mid), mid);
        QCOMPARE(hexOf(messages[0].payload), hexOf(bytes(payload)));
        QCOMPARE(decoder.stats().bytesSkipped, std::uint64_t(0));
        QCOMPARE(decoder.pendingBytes(), std::size_t(0));
        QCOMPARE(hexOf(encodeFrame(messages[0])), hexOf(stream));  // the encoder rebuilds it byte for byte
    }

    void encodeRoundTrip_data()
    {
        QTest::addColumn<int>("payloadSize");
        QTest::addColumn<int>("headerSize");
        QTest::newRow("empty") << 0 << 4;
        QTest::newRow("1 byte") << 1 << 4;
        QTest::newRow("254: longest standard") << 254 << 4;
        QTest::newRow("255: shortest extended") << 255 << 6;
        QTest::newRow("1320: EMTS size") << 1320 << 6;
        QTest::newRow("8185: maximum") << 8185 << 6;
    }
    void encodeRoundTrip()
    {
        QFETCH(int, payloadSize);
        QFETCH(int, headerSize);
        XbusMessage message;
        message.mid = 0x91;
        message.payload.resize(std::size_t(payloadSize));
        for (std::size_t i = 0; i < message.payload.size(); ++i)
            message.payload[i] = std::uint8_t(i * 7 + 3);
        const std::vector<std::uint8_t> frame = encodeFrame(message);
        QCOMPARE(int(frame.size()), payloadSize + headerSize + 1);
        QCOMPARE(int(frame[3]), headerSize == 4 ? payloadSize : 0xFF);
        if (headerSize == 6)
            QCOMPARE((frame[4] << 8) | frame[5], payloadSize);
        const int sum = std::accumulate(frame.begin() + 1, frame.end(), 0);
        QCOMPARE(sum & 0xFF, 0);
        XbusFrameDecoder decoder;
        const std::vector<XbusMessage> decoded = decodeAll(decoder, frame);
        QCOMPARE(decoded.size(), std::size_t(1));
        QCOMPARE(int(decoded[0].mid), 0x91);
        QVERIFY(decoded[0].payload == message.payload);
    }

    void encodeRefusesOversizedPayload()
    {
        XbusMessage message;
        message.payload.resize(kXbusMaxPayload + 1);
        QVERIFY(encodeFrame(message).empty());
    }

    void garbageBeforeAndBetweenFrames()
    {
        const std::vector<std::uint8_t> garbageA = bytes("00 11 22 33");
        const std::vector<std::uint8_t> garbageB = bytes("FF FF 01");
        const std::vector<std::uint8_t> stream = concat({garbageA, kGoToConfig, garbageB, kDeviceId});
        XbusFrameDecoder decoder;
        const std::vector<XbusMessage> messages = decodeAll(decoder, stream);
        QCOMPARE(messages.size(), std::size_t(2));
        QCOMPARE(int(messages[0].mid), 0x30);
        QCOMPARE(int(messages[1].mid), 0x01);
        QCOMPARE(decoder.lastFrameOffset(), std::uint64_t(garbageA.size() + kGoToConfig.size() + garbageB.size()));
        const XbusDecodeStats& stats = decoder.stats();
        QCOMPARE(stats.bytesSkipped, std::uint64_t(7));
        QCOMPARE(stats.skippedRuns, std::uint64_t(2));
        QCOMPARE(stats.checksumFailures, std::uint64_t(0));
        QCOMPARE(stats.firstProblems.size(), std::size_t(2));
        QCOMPARE(stats.firstProblems[0].offset, std::uint64_t(0));
        QCOMPARE(stats.firstProblems[0].size, std::uint64_t(4));
        QCOMPARE(stats.firstProblems[1].offset, std::uint64_t(9));
        QCOMPARE(stats.firstProblems[1].size, std::uint64_t(3));
    }

    void extendedLengthFieldForAShortPayload()
    {
        // LEN = 0xFF with an extended length of 3: legal framing for a payload that would fit the
        // standard field, two header bytes longer. The fuzzer found the byte accounting of such a
        // frame (tests/fuzz/corpus/fuzz_xbus_stream/extended-length-short-payload.bin).
        std::vector<std::uint8_t> frame = bytes("FA FF 36 FF 00 03 01 02 03");
        std::uint8_t sum = 0;
        for (std::size_t k = 1; k < frame.size(); ++k)
            sum = static_cast<std::uint8_t>(sum + frame[k]);
        frame.push_back(static_cast<std::uint8_t>(0x100 - sum));
        const std::vector<std::uint8_t> stream = concat({frame, kDeviceId});
        XbusFrameDecoder decoder;
        XbusMessage message;
        decoder.feed(stream.data(), stream.size());
        QVERIFY(decoder.next(message));
        QCOMPARE(int(message.mid), 0x36);
        QCOMPARE(message.payload, bytes("01 02 03"));
        QCOMPARE(decoder.pendingOffset() - decoder.lastFrameOffset(), std::uint64_t(frame.size()));
        QVERIFY(decoder.next(message));
        QCOMPARE(int(message.mid), 0x01);
        QCOMPARE(decoder.pendingOffset(), std::uint64_t(stream.size()));
        QCOMPARE(decoder.stats().bytesSkipped, std::uint64_t(0));
    }

    void badChecksumIsSkippedAndCounted()
    {
        std::vector<std::uint8_t> damaged = kDeviceId;
        damaged[5] ^= 0x10;  // one flipped bit in the payload
        const std::vector<std::uint8_t> stream = concat({kGoToConfig, damaged, kErrorMessage});
        XbusFrameDecoder decoder;
        const std::vector<XbusMessage> messages = decodeAll(decoder, stream);
        QCOMPARE(messages.size(), std::size_t(2));
        QCOMPARE(int(messages[0].mid), 0x30);
        QCOMPARE(int(messages[1].mid), 0x42);
        const XbusDecodeStats& stats = decoder.stats();
        QCOMPARE(stats.checksumFailures, std::uint64_t(1));
        QCOMPARE(stats.bytesSkipped, std::uint64_t(damaged.size()));
        QCOMPARE(stats.firstProblems.size(), std::size_t(2));
        QCOMPARE(stats.firstProblems[0].kind, XbusStreamProblem::Kind::BadChecksum);
        QCOMPARE(stats.firstProblems[0].offset, std::uint64_t(kGoToConfig.size()));
        QCOMPARE(stats.firstProblems[1].kind, XbusStreamProblem::Kind::SkippedBytes);
        QCOMPARE(stats.firstProblems[1].offset, std::uint64_t(kGoToConfig.size()));
        QCOMPARE(stats.firstProblems[1].size, std::uint64_t(damaged.size()));
    }

    void falsePreambleInsideGarbageIsSkipped_data()
    {
        QTest::addColumn<QByteArray>("garbage");
        QTest::addColumn<int>("checksumFailures");
        QTest::newRow("checksum does not add up") << QByteArray("FA 12 34 02 00 00 00") << 1;
        QTest::newRow("length above the maximum") << QByteArray("FA FF 36 FF 7F FF 00") << 0;
        QTest::newRow("BID 00 MID 00 in a zero run") << QByteArray("FA 00 00 00 00") << 0;
    }
    void falsePreambleInsideGarbageIsSkipped()
    {
        QFETCH(QByteArray, garbage);
        QFETCH(int, checksumFailures);
        const std::vector<std::uint8_t> junk = bytes(garbage);
        const std::vector<std::uint8_t> stream = concat({junk, kDeviceId});
        XbusFrameDecoder decoder;
        const std::vector<XbusMessage> messages = decodeAll(decoder, stream);
        QCOMPARE(messages.size(), std::size_t(1));
        QCOMPARE(int(messages[0].mid), 0x01);
        QCOMPARE(decoder.stats().bytesSkipped, std::uint64_t(junk.size()));
        QCOMPARE(decoder.stats().checksumFailures, std::uint64_t(checksumFailures));
    }

    void damagedFramesAreCountedOnceEachAndApartFromJunk()
    {
        // Each damaged frame holds a false preamble with a complete (failing) candidate inside.
        std::vector<std::uint8_t> damaged =
            encodeFrame({kXbusMasterBusId, 0x36, bytes("01 FA 12 34 02 00 00 00 05 06")});
        damaged[4] ^= 0x10;  // a payload byte: the length still says where the frame ends
        const std::vector<std::uint8_t> junk = bytes("01 02 03");
        const std::vector<std::uint8_t> stream = concat({kGoToConfig, damaged, damaged, junk, kDeviceId});
        XbusFrameDecoder decoder;
        QCOMPARE(decodeAll(decoder, stream).size(), std::size_t(2));
        const XbusDecodeStats& stats = decoder.stats();
        QCOMPARE(stats.checksumFailures, std::uint64_t(4));  // two frames, two false preambles
        QCOMPARE(stats.damagedFrames, std::uint64_t(2));
        QCOMPARE(stats.damagedFrameBytes, std::uint64_t(2 * damaged.size()));
        QCOMPARE(stats.bytesSkipped - stats.damagedFrameBytes, std::uint64_t(junk.size()));
    }

    void damagedLengthDoesNotHideTheNextFrame()
    {
        std::vector<std::uint8_t> damaged = kGoToConfig;
        damaged[3] = 0x03;  // claims three payload bytes: the next frame's first bytes
        XbusFrameDecoder decoder;
        const std::vector<XbusMessage> messages = decodeAll(decoder, concat({damaged, kDeviceId}));
        QCOMPARE(messages.size(), std::size_t(1));
        QCOMPARE(int(messages[0].mid), 0x01);
        QCOMPARE(decoder.stats().damagedFrames, std::uint64_t(1));
        QCOMPARE(decoder.stats().damagedFrameBytes, std::uint64_t(damaged.size()));  // not the frame after it
    }

    void frameSplitByteByByte()
    {
        XbusMessage extended{kXbusMasterBusId, 0x36, extendedExamplePayload()};
        const std::vector<std::uint8_t> stream = concat({kGoToConfig, encodeFrame(extended), kDeviceId});
        XbusFrameDecoder decoder;
        std::vector<XbusMessage> messages;
        XbusMessage message;
        for (std::uint8_t byte : stream) {
            decoder.feed(&byte, 1);
            while (decoder.next(message))
                messages.push_back(message);
        }
        QCOMPARE(messages.size(), std::size_t(3));
        QCOMPARE(int(messages[0].mid), 0x30);
        QVERIFY(messages[1].payload == extended.payload);
        QCOMPARE(hexOf(messages[2].payload), QByteArray("03 70 03 f8"));
        QCOMPARE(decoder.stats().bytesSkipped, std::uint64_t(0));
        QCOMPARE(decoder.stats().framesDecoded, std::uint64_t(3));
    }

    void truncatedFrameAtTheEndStaysPending()
    {
        const std::vector<std::uint8_t> head(kDeviceId.begin(), kDeviceId.begin() + 6);
        XbusFrameDecoder decoder;
        const std::vector<XbusMessage> messages = decodeAll(decoder, concat({kGoToConfig, head}));
        QCOMPARE(messages.size(), std::size_t(1));
        QCOMPARE(decoder.pendingBytes(), head.size());
        QCOMPARE(decoder.pendingOffset(), std::uint64_t(kGoToConfig.size()));
        QCOMPARE(decoder.stats().bytesSkipped, std::uint64_t(0));

        const std::vector<std::uint8_t> rest(kDeviceId.begin() + 6, kDeviceId.end());
        const std::vector<XbusMessage> completed = decodeAll(decoder, rest);  // the rest arrives: it completes
        QCOMPARE(completed.size(), std::size_t(1));
        QCOMPARE(int(completed[0].mid), 0x01);
        QCOMPARE(decoder.lastFrameOffset(), std::uint64_t(kGoToConfig.size()));
    }

    void finishReportsTheUnfinishedFrame()
    {
        const std::vector<std::uint8_t> head(kDeviceId.begin(), kDeviceId.begin() + 6);
        XbusFrameDecoder decoder;
        decodeAll(decoder, concat({kGoToConfig, head}));
        decoder.finish();
        XbusMessage message;
        QVERIFY(!decoder.next(message));
        QCOMPARE(decoder.pendingBytes(), std::size_t(0));
        const XbusDecodeStats& stats = decoder.stats();
        QCOMPARE(stats.bytesTruncated, std::uint64_t(head.size()));
        QCOMPARE(stats.bytesSkipped, std::uint64_t(0));
        QCOMPARE(stats.firstProblems.size(), std::size_t(1));
        QCOMPARE(stats.firstProblems[0].kind, XbusStreamProblem::Kind::Truncated);
        QCOMPARE(stats.firstProblems[0].offset, std::uint64_t(kGoToConfig.size()));
    }

    void finishLooksPastAFalsePreambleAtTheEnd()
    {
        // A garbage header claiming 256 bytes, then a complete frame: only the end of the stream
        // shows that the claim was false.
        const std::vector<std::uint8_t> falseHeader = bytes("FA FF 36 FF 01 00");
        XbusFrameDecoder decoder;
        QVERIFY(decodeAll(decoder, concat({falseHeader, kDeviceId})).empty());
        decoder.finish();
        XbusMessage message;
        QVERIFY(decoder.next(message));
        QCOMPARE(int(message.mid), 0x01);
        QVERIFY(!decoder.next(message));
        QCOMPARE(decoder.stats().bytesSkipped, std::uint64_t(falseHeader.size()));
        QCOMPARE(decoder.stats().bytesTruncated, std::uint64_t(0));
    }

    void bufferIsBounded()
    {
        XbusFrameDecoder decoder(0);  // raised to one maximal frame
        const std::vector<std::uint8_t> header = bytes("FA FF 36 FF 1F F9");  // claims the maximum, 8185 bytes
        decoder.feed(header.data(), header.size());
        const std::vector<std::uint8_t> filler(3 * kXbusMaxFrameSize, 0x11);
        decoder.feed(filler.data(), filler.size());
        QCOMPARE(decoder.pendingBytes(), kXbusMaxFrameSize);
        const XbusDecodeStats& stats = decoder.stats();
        QCOMPARE(stats.bytesDroppedOverflow, std::uint64_t(header.size() + filler.size() - kXbusMaxFrameSize));
        QCOMPARE(stats.firstProblems.size(), std::size_t(1));
        QCOMPARE(stats.firstProblems[0].kind, XbusStreamProblem::Kind::Overflow);
        QCOMPARE(stats.firstProblems[0].offset, std::uint64_t(0));
        decoder.feed(kDeviceId.data(), kDeviceId.size());  // still decodes what comes next
        XbusMessage message;
        QVERIFY(decoder.next(message));
        QCOMPARE(int(message.mid), 0x01);
        QCOMPARE(decoder.lastFrameOffset(), std::uint64_t(header.size() + filler.size()));
    }

    void problemListIsCappedButCountsAll()
    {
        std::vector<std::uint8_t> stream;
        for (int i = 0; i < 40; ++i)
            stream = concat({stream, bytes("01 02"), kGoToConfig});
        XbusFrameDecoder decoder;
        QCOMPARE(decodeAll(decoder, stream).size(), std::size_t(40));
        const XbusDecodeStats& stats = decoder.stats();
        QCOMPARE(stats.problemCount, std::uint64_t(40));
        QCOMPARE(stats.skippedRuns, std::uint64_t(40));
        QCOMPARE(stats.firstProblems.size(), XbusDecodeStats::kMaxRecordedProblems);
        QCOMPARE(stats.firstProblems.back().offset, std::uint64_t(7 * (XbusDecodeStats::kMaxRecordedProblems - 1)));
        QCOMPARE(stats.bytesSkipped, std::uint64_t(80));
    }

    void resetForgetsEverything()
    {
        XbusFrameDecoder decoder;
        decodeAll(decoder, concat({bytes("01 02 03"), kGoToConfig, bytes("FA FF")}));
        decoder.reset();
        QCOMPARE(decoder.pendingBytes(), std::size_t(0));
        QCOMPARE(decoder.stats().bytesSkipped, std::uint64_t(0));
        QCOMPARE(decoder.stats().framesDecoded, std::uint64_t(0));
        const std::vector<XbusMessage> messages = decodeAll(decoder, kDeviceId);
        QCOMPARE(messages.size(), std::size_t(1));
        QCOMPARE(decoder.lastFrameOffset(), std::uint64_t(0));
    }

    void payloadReaderNeverReadsPastTheEnd()
    {
        const std::vector<std::uint8_t> data = bytes("01 02 03");
        XbusPayloadReader reader(data.data(), data.size());
        std::uint32_t u32 = 0;
        std::uint16_t u16 = 0;
        std::uint8_t u8 = 0;
        QVERIFY(!reader.readU32(u32));
        QCOMPARE(reader.offset(), std::size_t(0));  // a failed read does not move
        QVERIFY(reader.readU16(u16));
        QCOMPARE(u16, std::uint16_t(0x0102));
        QVERIFY(!reader.readU16(u16));
        QVERIFY(!reader.skip(2));
        QVERIFY(reader.readU8(u8));
        QCOMPARE(u8, std::uint8_t(0x03));
        QCOMPARE(reader.remaining(), std::size_t(0));
        QVERIFY(!reader.readU8(u8));
    }
};

QTEST_APPLESS_MAIN(TestXbusFrame)
#include "tst_xbusframe.moc"
