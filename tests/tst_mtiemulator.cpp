// The emulated MTi, bytes in and bytes out with the clock passed in: it wakes up and waits 500 ms
// for WakeUpAck, answers the init sequence like a device (ids, output configuration echo with the
// rates it can deliver, Error for what it does not know), streams MTData2 at the configured rate
// with packet counter and SampleTimeFine, plays the recording's values, stops on GoToConfig,
// reboots on Reset, and injects repeatable faults from its seed.
#include "MtiEmulator.h"

#include "xbus/XbusControl.h"

#include <QtTest>

#include <cmath>

using namespace footpath;

namespace {

using Bytes = MtiEmulator::Bytes;

/// A 1 s recording at 100 Hz whose acceleration x is the sample index, so played values show
/// which recorded sample was sent.
Recording rampRecording(bool withMag, bool withPressure)
{
    Recording recording;
    for (int k = 0; k < 100; ++k) {
        ImuSample s;
        s.time_s = 0.01 * k;
        s.acc_mps2 = Eigen::Vector3d(k, 0.5, 9.75);
        s.gyr_radps = Eigen::Vector3d(0.25, -0.125, 0.0);
        if (withMag)
            s.mag = Eigen::Vector3d(0.5, 0.0, -0.75);
        if (withPressure)
            s.pressure_pa = 101325.0;
        recording.samples.push_back(s);
    }
    return recording;
}

std::vector<XbusMessage> decode(const Bytes& bytes, XbusDecodeStats* stats = nullptr)
{
    XbusFrameDecoder decoder;
    decoder.feed(bytes.data(), bytes.size());
    std::vector<XbusMessage> messages;
    XbusMessage message;
    while (decoder.next(message))
        messages.push_back(message);
    if (stats != nullptr)
        *stats = decoder.stats();
    return messages;
}

Bytes frame(const XbusMessage& message)
{
    return encodeFrame(message);
}

std::vector<MtData2Sample> dataOf(const std::vector<XbusMessage>& messages)
{
    std::vector<MtData2Sample> samples;
    for (const XbusMessage& message : messages)
        if (message.mid == XbusMid::MtData2)
            samples.push_back(decodeMtData2(message.payload).sample);
    return samples;
}

/// A device the host has woken up and taken to Config at t = 0.
MtiEmulator configDevice(MtiEmulatorConfig config = {}, bool withMag = true, bool withPressure = true)
{
    MtiEmulator device(rampRecording(withMag, withPressure), config);
    device.powerOn(0.0);
    device.receive(frame(wakeUpAckMessage()), 0.01);
    return device;
}

XbusMessage onlyReply(MtiEmulator& device, const XbusMessage& request, double now_s = 0.02)
{
    const std::vector<XbusMessage> replies = decode(device.receive(frame(request), now_s));
    return replies.size() == 1 ? replies.front() : XbusMessage{0, 0xEE, {}};
}

}  // namespace

class TestMtiEmulator : public QObject {
    Q_OBJECT
private slots:
    void wakesUpAndStaysInConfigWhenAcknowledged()
    {
        MtiEmulator device(rampRecording(true, true), {});
        const std::vector<XbusMessage> first = decode(device.powerOn(0.0));
        QCOMPARE(first.size(), std::size_t(1));
        QCOMPARE(first.front().mid, XbusMid::WakeUp);
        QCOMPARE(device.state(), MtiEmulator::State::WakingUp);
        QVERIFY(device.receive(frame(wakeUpAckMessage()), 0.3).empty());
        QCOMPARE(device.state(), MtiEmulator::State::Config);
        QVERIFY(device.advance(5.0).empty());  // nothing streams in Config
    }

    void measuresAfterAnUnansweredWakeUp()
    {
        MtiEmulator device(rampRecording(true, true), {});
        device.powerOn(0.0);
        QVERIFY(device.advance(0.49).empty());
        QCOMPARE(device.nextEventAt(), 0.5);
        const std::vector<XbusMessage> messages = decode(device.advance(0.5));
        QVERIFY(messages.size() >= 2);
        QCOMPARE(messages.front().mid, XbusMid::Configuration);  // as MTi-10/100 do (§4.1)
        const auto configuration = parseConfiguration(messages.front().payload);
        QVERIFY2(configuration.ok(), configuration.error.c_str());
        QCOMPARE(configuration.configuration.masterDeviceId, std::uint32_t(0x037003F8));
        QCOMPARE(messages[1].mid, XbusMid::MtData2);
        QCOMPARE(device.state(), MtiEmulator::State::Measurement);
    }

    void goToConfigInsideTheWakeUpWindowIsAcknowledged()
    {
        MtiEmulator device(rampRecording(true, true), {});
        device.powerOn(0.0);
        QCOMPARE(onlyReply(device, goToConfigMessage(), 0.1).mid, XbusMid::GoToConfigAck);
        QCOMPARE(device.state(), MtiEmulator::State::Config);
    }

    void answersTheInitSequence()
    {
        MtiEmulator device = configDevice();
        QCOMPARE(onlyReply(device, goToConfigMessage()).mid, XbusMid::GoToConfigAck);
        QCOMPARE(parseDeviceId(onlyReply(device, reqDeviceIdMessage()).payload).value, std::uint64_t(0x037003F8));
        QCOMPARE(parseProductCode(onlyReply(device, reqProductCodeMessage()).payload).value,
                 std::string("MTi-300-2A8G4"));
        QCOMPARE(parseFirmwareRevision(onlyReply(device, reqFirmwareRevMessage()).payload).value.toString(),
                 std::string("1.8.2 build 37 rev 70964"));
        QCOMPARE(onlyReply(device, xbusMessage(XbusMid::ReqHardwareVersion)).mid, XbusMid::HardwareVersion);
        QCOMPARE(onlyReply(device, xbusMessage(XbusMid::ReqConfiguration)).mid, XbusMid::Configuration);
        QCOMPARE(parseBaudCode(onlyReply(device, reqBaudrateMessage()).payload).value, std::uint8_t(0x02));
        QCOMPARE(onlyReply(device, setBaudrateMessage(0x80)).mid, XbusMid::BaudrateAck);
        QCOMPARE(device.baudCode(), std::uint8_t(0x80));
        QCOMPARE(onlyReply(device, goToMeasurementMessage()).mid, XbusMid::GoToMeasurementAck);
        QCOMPARE(device.state(), MtiEmulator::State::Measurement);
    }

    void echoesTheOutputConfigurationItApplies()
    {
        MtiEmulator device = configDevice();
        const XbusMessage echo = onlyReply(device, *setOutputConfigurationMessage(footpathOutputConfiguration(200)));
        QCOMPARE(echo.mid, XbusMid::OutputConfiguration);
        const auto applied = parseOutputConfiguration(echo.payload).value;
        using namespace MtData2Id;
        QCOMPARE(findOutputEntry(applied, PacketCounter)->rate_hz, OutputConfigEntry::kEveryMessage);
        QCOMPARE(findOutputEntry(applied, Acceleration)->rate_hz, std::uint16_t(200));
        QCOMPARE(findOutputEntry(applied, MagneticField)->rate_hz, std::uint16_t(100));  // magnetometer limit
        QCOMPARE(findOutputEntry(applied, BaroPressure)->rate_hz, std::uint16_t(50));    // barometer limit
        QVERIFY(applied == device.outputConfiguration());
        // Asking without a payload returns the same list.
        QCOMPARE(onlyReply(device, reqOutputConfigurationMessage()).payload, echo.payload);
    }

    void leavesOutSensorsTheRecordingLacks()
    {
        MtiEmulator device = configDevice({}, false, false);
        const auto applied = parseOutputConfiguration(
            onlyReply(device, *setOutputConfigurationMessage(footpathOutputConfiguration(100))).payload);
        QCOMPARE(applied.value.size(), std::size_t(4));
        QVERIFY(!findOutputEntry(applied.value, MtData2Id::MagneticField));
        QVERIFY(!findOutputEntry(applied.value, MtData2Id::BaroPressure));
    }

    void refusesWhatNoMtiAccepts_data()
    {
        QTest::addColumn<QByteArray>("request");
        QTest::addColumn<int>("error");
        QTest::newRow("unknown MID") << QByteArray("FA FF 5A 00 A7") << int(XbusErrorCode::InvalidMessage);
        QTest::newRow("rate not dividing 2000 Hz")
            << QByteArray("FA FF C0 04 40 20 00 78 65") << int(XbusErrorCode::InvalidParameter);
        QTest::newRow("unsupported data id")
            << QByteArray("FA FF C0 04 70 10 00 04 B9") << int(XbusErrorCode::InvalidParameter);
        QTest::newRow("payload not in entries") << QByteArray("FA FF C0 03 40 20 00 DE") << int(XbusErrorCode::InvalidParameter);
        QTest::newRow("unknown baud code") << QByteArray("FA FF 18 01 0F D9") << int(XbusErrorCode::BaudRateInvalid);
    }
    void refusesWhatNoMtiAccepts()
    {
        QFETCH(QByteArray, request);
        QFETCH(int, error);
        MtiEmulator device = configDevice();
        const QByteArray raw = QByteArray::fromHex(request);
        const std::vector<XbusMessage> replies =
            decode(device.receive(reinterpret_cast<const std::uint8_t*>(raw.constData()), std::size_t(raw.size()), 0.1));
        QCOMPARE(replies.size(), std::size_t(1));
        QCOMPARE(replies.front().mid, XbusMid::Error);
        QCOMPARE(int(replies.front().payload.at(0)), error);
    }

    void ignoresFramesWithABadChecksum()
    {
        MtiEmulator device = configDevice();
        Bytes damaged = frame(reqDeviceIdMessage());
        damaged.back() ^= 0x55;
        QVERIFY(device.receive(damaged, 0.1).empty());  // no NAK exists: the host resends
        QCOMPARE(onlyReply(device, reqDeviceIdMessage()).mid, XbusMid::DeviceId);
    }

    void streamsAtTheConfiguredRate()
    {
        MtiEmulator device = configDevice();
        device.receive(frame(*setOutputConfigurationMessage(footpathOutputConfiguration(100))), 0.0);
        device.receive(frame(goToMeasurementMessage()), 1.0);
        const std::vector<MtData2Sample> samples = dataOf(decode(device.advance(1.995)));
        QCOMPARE(samples.size(), std::size_t(100));  // t = 1.00, 1.01, ..., 1.99
        for (std::size_t k = 0; k < samples.size(); ++k) {
            QCOMPARE(*samples[k].packetCounter, std::uint16_t(k));
            QCOMPARE(*samples[k].sampleTimeFine, std::uint32_t(100 * k));  // 10 kHz ticks
            QCOMPARE(samples[k].acceleration->x(), double(k));  // the recording's k-th sample
            QVERIFY(samples[k].magneticField.has_value());
            QCOMPARE(samples[k].pressure_pa.has_value(), k % 2 == 0);  // barometer at 50 Hz
        }
        QCOMPARE(device.nextEventAt(), 2.0);
    }

    void loopsTheRecordingWithTimeRunningOn()
    {
        MtiEmulator device = configDevice();
        device.receive(frame(goToMeasurementMessage()), 0.0);
        const std::vector<MtData2Sample> samples = dataOf(decode(device.advance(1.505)));
        QCOMPARE(samples.size(), std::size_t(151));
        QCOMPARE(samples[100].acceleration->x(), 0.0);  // back at the start of the recording
        QCOMPARE(*samples[150].sampleTimeFine, std::uint32_t(15000));
    }

    void speedMakesDeviceTimeRunFaster()
    {
        MtiEmulatorConfig config;
        config.speed = 10.0;
        MtiEmulator device = configDevice(config);
        device.receive(frame(goToMeasurementMessage()), 0.0);
        const std::vector<MtData2Sample> samples = dataOf(decode(device.advance(0.0995)));
        QCOMPARE(samples.size(), std::size_t(100));  // one device second in a tenth of a wall second
        QCOMPARE(*samples.back().sampleTimeFine, std::uint32_t(9900));
    }

    void goToConfigStopsTheStream()
    {
        MtiEmulator device = configDevice();
        device.receive(frame(goToMeasurementMessage()), 0.0);
        device.advance(0.5);
        QCOMPARE(onlyReply(device, goToConfigMessage(), 0.5).mid, XbusMid::GoToConfigAck);
        QCOMPARE(device.state(), MtiEmulator::State::Config);
        QVERIFY(dataOf(decode(device.advance(3.0))).empty());
        QCOMPARE(onlyReply(device, reqDeviceIdMessage(), 3.0).mid, XbusMid::DeviceId);
    }

    void configRequestsInMeasurementAreErrors()
    {
        MtiEmulator device = configDevice();
        device.receive(frame(goToMeasurementMessage()), 0.0);
        const std::vector<XbusMessage> replies = decode(device.receive(frame(reqDeviceIdMessage()), 0.0));
        QCOMPARE(replies.back().mid, XbusMid::Error);
        QCOMPARE(int(replies.back().payload.at(0)), int(XbusErrorCode::InvalidMessage));
    }

    void resetRebootsWithAWakeUp()
    {
        MtiEmulator device = configDevice();
        QCOMPARE(onlyReply(device, resetMessage(), 1.0).mid, XbusMid::ResetAck);
        QCOMPARE(device.state(), MtiEmulator::State::Booting);
        QVERIFY(device.receive(frame(reqDeviceIdMessage()), 1.01).empty());  // nobody listens while booting
        const std::vector<XbusMessage> wake = decode(device.advance(1.05));
        QCOMPARE(wake.size(), std::size_t(1));
        QCOMPARE(wake.front().mid, XbusMid::WakeUp);
    }

    void emptyConfigurationCannotMeasure()
    {
        MtiEmulator device = configDevice();
        QCOMPARE(onlyReply(device, *setOutputConfigurationMessage({{0, 0}})).mid, XbusMid::OutputConfiguration);
        const XbusMessage refused = onlyReply(device, goToMeasurementMessage());
        QCOMPARE(refused.mid, XbusMid::Error);
        QCOMPARE(int(refused.payload.at(0)), int(XbusErrorCode::OutputConfigurationError));
    }

    void faultsAreRepeatableFromTheSeed()
    {
        const auto run = [](std::uint32_t seed) {
            MtiEmulatorConfig config;
            config.faults.corruptRate = config.faults.dropRate = config.faults.junkRate = 0.1;
            config.faults.seed = seed;
            MtiEmulator device = configDevice(config);
            device.receive(frame(goToMeasurementMessage()), 0.0);
            return device.advance(5.0);
        };
        QVERIFY(run(7) == run(7));
        QVERIFY(run(7) != run(8));
    }

    void faultsAreWhatTheObserverSays()
    {
        MtiEmulatorConfig config;
        config.faults.corruptRate = config.faults.dropRate = config.faults.junkRate = 0.05;
        config.faults.seed = 3;
        MtiEmulator device = configDevice(config);
        std::vector<MtiEmulator::DataRecord> records;
        device.setDataObserver([&records](const MtiEmulator::DataRecord& r) { records.push_back(r); });
        device.receive(frame(goToMeasurementMessage()), 0.0);
        const Bytes stream = device.advance(20.0);
        XbusFrameDecoder decoder;
        decoder.feed(stream.data(), stream.size());
        decoder.finish();
        std::vector<XbusMessage> messages;
        for (XbusMessage message; decoder.next(message);)
            messages.push_back(message);
        const XbusDecodeStats& stats = decoder.stats();
        const std::vector<MtData2Sample> received = dataOf(messages);

        std::vector<std::uint16_t> sentIntact;
        std::size_t corrupted = 0;
        std::size_t dropped = 0;
        for (const MtiEmulator::DataRecord& r : records) {
            if (r.fate == MtiEmulator::DataRecord::Fate::Sent)
                sentIntact.push_back(*r.sample.packetCounter);
            corrupted += r.fate == MtiEmulator::DataRecord::Fate::Corrupted;
            dropped += r.fate == MtiEmulator::DataRecord::Fate::Dropped;
        }
        QCOMPARE(records.size(), std::size_t(2001));
        QVERIFY(corrupted > 50 && dropped > 50);
        std::vector<std::uint16_t> receivedCounters;
        for (const MtData2Sample& s : received)
            receivedCounters.push_back(*s.packetCounter);
        QVERIFY(receivedCounters == sentIntact);  // every intact message arrives, nothing else does
        // What the emulator says it injected is what a receiver finds, exactly.
        const MtiInjected& injected = device.injected();
        QCOMPARE(injected.dataMessages, std::uint64_t(records.size()));
        QCOMPARE(injected.corrupted, std::uint64_t(corrupted));
        QCOMPARE(injected.dropped, std::uint64_t(dropped));
        QCOMPARE(stats.damagedFrames, injected.corrupted);
        QVERIFY(stats.checksumFailures > stats.damagedFrames);  // false preambles inside damaged frames
        QCOMPARE(stats.damagedFrameBytes, injected.corruptedBytes);
        QCOMPARE(stats.bytesSkipped - stats.damagedFrameBytes, injected.junkBytes);
        QVERIFY(injected.junkBytes > 0);
        QCOMPARE(stats.bytesTruncated, std::uint64_t(0));
    }

    void burstSendsFasterWithTheRatesTimeStamps()
    {
        MtiEmulatorConfig config;
        config.faults.burstAt_s = 1.0;
        config.faults.burstLength_s = 0.5;
        config.faults.burstFactor = 10.0;
        MtiEmulator device = configDevice(config);
        device.receive(frame(goToMeasurementMessage()), 0.0);
        // 100 messages in the first wall second, then 50 in 50 ms, then 100 Hz again.
        std::vector<MtData2Sample> samples = dataOf(decode(device.advance(1.0495)));
        QCOMPARE(samples.size(), std::size_t(150));
        QCOMPARE(*samples.back().sampleTimeFine, std::uint32_t(14900));  // stamped at the rate
        QCOMPARE(device.injected().burstMessages, std::uint64_t(50));
        QVERIFY(std::abs(device.nextEventAt() - 1.05) < 1e-9);
        samples = dataOf(decode(device.advance(1.1495)));
        QCOMPARE(samples.size(), std::size_t(10));  // 1.05, 1.06, ..., 1.14
        QCOMPARE(*samples.front().packetCounter, std::uint16_t(150));
        QCOMPARE(device.injected().burstMessages, std::uint64_t(50));
    }

    void junkNeverContainsThePreamble()
    {
        MtiEmulatorConfig config;
        config.faults.junkRate = 1.0;
        MtiEmulator device = configDevice(config);
        device.receive(frame(goToMeasurementMessage()), 0.0);
        const Bytes stream = device.advance(2.0);
        XbusDecodeStats stats;
        QCOMPARE(dataOf(decode(stream, &stats)).size(), std::size_t(201));
        QCOMPARE(stats.checksumFailures, std::uint64_t(0));  // junk is skipped without false frames
        QCOMPARE(stats.skippedRuns, std::uint64_t(201));
    }

    void disconnectsAfterTheStreamedTime()
    {
        MtiEmulatorConfig config;
        config.faults.disconnectAfter_s = 0.5;
        MtiEmulator device = configDevice(config);
        device.receive(frame(goToMeasurementMessage()), 0.0);
        QCOMPARE(dataOf(decode(device.advance(10.0))).size(), std::size_t(50));
        QCOMPARE(device.state(), MtiEmulator::State::Disconnected);
        QVERIFY(device.receive(frame(goToConfigMessage()), 10.0).empty());
    }

    void playsOnceWhenAsked()
    {
        MtiEmulatorConfig config;
        config.loop = false;
        MtiEmulator device = configDevice(config);
        device.receive(frame(goToMeasurementMessage()), 0.0);
        QCOMPARE(dataOf(decode(device.advance(10.0))).size(), std::size_t(100));
        QCOMPARE(device.state(), MtiEmulator::State::Disconnected);
    }
};

QTEST_APPLESS_MAIN(TestMtiEmulator)
#include "tst_mtiemulator.moc"
