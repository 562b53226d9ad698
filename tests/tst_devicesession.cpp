// DeviceSession against an in-memory serial line (MockSerialLine) whose device side is the
// emulator's protocol logic, bent by a script where a test needs a deaf, slow, booting or
// refusing device. Covers the init sequence and its wake-up handling, retries, the baud probe,
// every failure in words, streaming counters (lost packets, checksum errors, resyncs), the
// duration cut, stop(), a vanishing port that keeps everything, and the bounded display queue.
#include "DeviceSession.h"
#include "MockSerialLine.h"
#include "MtiEmulator.h"

#include "io/Import.h"
#include "xbus/MtData2.h"
#include "xbus/XbusControl.h"

#include <QElapsedTimer>
#include <QFile>
#include <QMutex>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <map>
#include <memory>
#include <set>

using namespace footpath;

namespace {

const QString kPort = QStringLiteral("MOCK0");

/// How the scripted device departs from a well-behaved one.
struct Script {
    int goToConfigsToIgnore = 0;
    bool wakeUpInsteadOfFirstAnswer = false;  ///< it was booting when the host first spoke
    std::optional<quint32> onlyAtBaud;
    std::map<std::uint8_t, std::uint8_t> errorFor;  ///< request MID -> Error code
    std::set<std::uint8_t> silentFor;               ///< request MIDs never answered
    bool deaf = false;
};

QByteArray toBytes(const std::vector<std::uint8_t>& bytes)
{
    return QByteArray(reinterpret_cast<const char*>(bytes.data()), static_cast<int>(bytes.size()));
}

Recording playback()
{
    Recording recording;
    for (int k = 0; k < 10; ++k) {
        ImuSample s;
        s.time_s = 0.01 * k;
        s.mag = Eigen::Vector3d(0.5, 0.0, -0.75);
        s.pressure_pa = 101325.0;
        recording.samples.push_back(s);
    }
    return recording;
}

/// The device side of the line: the emulator (woken and in Config) behind the script. Called in
/// the worker thread only, so its state needs no lock.
MockSerialLine::Responder scriptedDevice(const MockSerialLine& line, Script script)
{
    auto device = std::make_shared<MtiEmulator>(playback(), MtiEmulatorConfig{});
    device->powerOn(0.0);
    device->receive(encodeFrame(wakeUpAckMessage()), 0.0);
    auto decoder = std::make_shared<XbusFrameDecoder>();
    auto ignored = std::make_shared<int>(0);
    return [&line, script, device, decoder, ignored](const QByteArray& written) {
        if (script.deaf || (script.onlyAtBaud && line.baudRates().value(line.baudRates().size() - 1) != *script.onlyAtBaud))
            return QByteArray();
        decoder->feed(reinterpret_cast<const std::uint8_t*>(written.constData()), std::size_t(written.size()));
        QByteArray reply;
        XbusMessage message;
        while (decoder->next(message)) {
            const bool goToConfig = message.mid == XbusMid::GoToConfig;
            if (goToConfig && script.wakeUpInsteadOfFirstAnswer && *ignored == 0) {
                ++*ignored;
                reply += toBytes(encodeFrame(wakeUpMessage()));
            } else if (goToConfig && *ignored < script.goToConfigsToIgnore) {
                ++*ignored;
            } else if (script.errorFor.count(message.mid) > 0) {
                reply += toBytes(encodeFrame(errorMessage(script.errorFor.at(message.mid))));
            } else if (script.silentFor.count(message.mid) == 0) {
                reply += toBytes(device->receive(encodeFrame(message), 0.0));
            }
        }
        return reply;
    };
}

SessionSettings fastSettings()
{
    SessionSettings settings;
    settings.portName = kPort;
    settings.probeBaudRates = false;
    settings.timeouts.reply_ms = 100;
    settings.timeouts.goToConfig_ms = 100;
    settings.timeouts.probe_ms = 30;
    settings.timeouts.tries = 3;
    settings.timeouts.stop_ms = 100;
    return settings;
}

/// MTData2 frames as the device streams them at 100 Hz: counter c has SampleTimeFine 100 c.
QByteArray dataFrame(std::uint16_t counter)
{
    MtData2Sample s;
    s.packetCounter = counter;
    s.sampleTimeFine = 100u * counter;
    s.acceleration = Eigen::Vector3d(0.5 * counter, 0.25, 9.75);
    s.rateOfTurn = Eigen::Vector3d(0.125, -0.5, 0.0);
    return toBytes(encodeFrame(xbusMessage(XbusMid::MtData2, encodeMtData2(s))));
}

/// Feeds in random chunks, each a separate readyRead, so frames arrive split anywhere.
void feedInChunks(MockSerialLine& line, const QByteArray& bytes)
{
    QRandomGenerator random(42);
    for (int at = 0; at < bytes.size();) {
        const int size = std::min(int(bytes.size()) - at, 1 + int(random.bounded(60)));
        line.feedReceived(bytes.mid(at, size));
        at += size;
    }
}

std::vector<std::uint8_t> writtenMids(const MockSerialLine& line)
{
    const QByteArray written = line.written();
    XbusFrameDecoder decoder;
    decoder.feed(reinterpret_cast<const std::uint8_t*>(written.constData()), std::size_t(written.size()));
    std::vector<std::uint8_t> mids;
    XbusMessage message;
    while (decoder.next(message))
        mids.push_back(message.mid);
    return mids;
}

std::size_t countOf(const std::vector<std::uint8_t>& mids, std::uint8_t mid)
{
    return std::size_t(std::count(mids.begin(), mids.end(), mid));
}

/// A session on a scripted line, with spies on what the tests look at.
struct Rig {
    explicit Rig(const Script& script = {})
    {
        line.setResponder(scriptedDevice(line, script));
    }

    bool start(const SessionSettings& settings = fastSettings())
    {
        session.start(settings);
        const bool settled = QTest::qWaitFor(
            [this] { return session.state() == SessionState::Streaming || ended.count() > 0; }, 10000);
        return settled && session.state() == SessionState::Streaming;
    }
    QString endMessage()
    {
        if (ended.isEmpty() && !ended.wait(10000))
            return QStringLiteral("(no end)");
        return ended.first().at(1).toString();
    }
    SessionEnd endKind() const { return ended.first().at(0).value<SessionEnd>(); }
    QStringList warningTexts() const
    {
        QStringList texts;
        for (const QList<QVariant>& args : warnings)
            texts << args.at(0).toString();
        return texts;
    }

    MockSerialLine line;
    DeviceSession session{line.factory()};
    QSignalSpy ended{&session, &DeviceSession::ended};
    QSignalSpy warnings{&session, &DeviceSession::warning};
    QSignalSpy identified{&session, &DeviceSession::deviceIdentified};
};

}  // namespace

class TestDeviceSession : public QObject {
    Q_OBJECT
private slots:
    void runsTheInitSequence()
    {
        Rig rig;
        QVERIFY(rig.start());
        const std::vector<std::uint8_t> expected = {XbusMid::GoToConfig, XbusMid::ReqDid, XbusMid::ReqProductCode,
                                                    XbusMid::ReqFwRev, XbusMid::SetOutputConfiguration,
                                                    XbusMid::GoToMeasurement};
        QVERIFY(writtenMids(rig.line) == expected);
        QCOMPARE(rig.identified.count(), 1);
        const DeviceInfo& info = rig.session.deviceInfo();
        QCOMPARE(info.deviceId, std::uint64_t(0x037003F8));
        QCOMPARE(info.deviceIdText(), QStringLiteral("037003F8"));
        QCOMPARE(info.productCode, QStringLiteral("MTi-300-2A8G4"));
        QCOMPARE(info.firmware.toString(), std::string("1.8.2 build 37 rev 70964"));
        QCOMPARE(info.baud, std::uint32_t(115200));
        QCOMPARE(info.rate_hz, std::uint16_t(100));
        QVERIFY(info.requestedOutput == footpathOutputConfiguration(100));
        QCOMPARE(findOutputEntry(info.appliedOutput, MtData2Id::BaroPressure)->rate_hz, std::uint16_t(50));
        QVERIFY(rig.warningTexts().contains(QStringLiteral("the device outputs BaroPressure at 50 Hz instead of 100 Hz")));
        QCOMPARE(rig.line.baudRates(), QList<quint32>{115200});
    }

    void acknowledgesAWakeUpAndAsksAgainAtOnce()
    {
        Script script;
        script.wakeUpInsteadOfFirstAnswer = true;
        Rig rig(script);
        SessionSettings settings = fastSettings();
        settings.timeouts.goToConfig_ms = 3000;  // waiting out the timeout would show
        QElapsedTimer clock;
        clock.start();
        QVERIFY(rig.start(settings));
        QVERIFY2(clock.elapsed() < 2000, "GoToConfig was not resent right after the WakeUp");
        const std::vector<std::uint8_t> mids = writtenMids(rig.line);
        QCOMPARE(mids.at(0), XbusMid::GoToConfig);
        QCOMPARE(mids.at(1), XbusMid::WakeUpAck);
        QCOMPARE(mids.at(2), XbusMid::GoToConfig);
    }

    void retriesLikeRealDrivers()
    {
        Script script;
        script.goToConfigsToIgnore = 2;
        Rig rig(script);
        QVERIFY(rig.start());
        QCOMPARE(countOf(writtenMids(rig.line), XbusMid::GoToConfig), std::size_t(3));
    }

    void silentDeviceIsReportedInWords()
    {
        Script script;
        script.deaf = true;
        Rig rig(script);
        QElapsedTimer clock;
        clock.start();
        QVERIFY(!rig.start());
        QCOMPARE(rig.endMessage(), QStringLiteral("no answer to GoToConfig at 115200 baud on MOCK0: is the device "
                                                  "powered and is the baud right?"));
        QCOMPARE(rig.endKind(), SessionEnd::Failed);
        QVERIFY(clock.elapsed() >= 300);  // three tries of 100 ms
        QCOMPARE(countOf(writtenMids(rig.line), XbusMid::GoToConfig), std::size_t(3));
        QVERIFY(!rig.line.isOpen());
    }

    void probeTriesTheCommonRatesInOrder()
    {
        Script script;
        script.deaf = true;
        Rig rig(script);
        SessionSettings settings = fastSettings();
        settings.probeBaudRates = true;
        QVERIFY(!rig.start(settings));
        QCOMPARE(rig.endMessage(), QStringLiteral("no answer to GoToConfig at 115200 baud on MOCK0, nor at 2000000, "
                                                  "921600, 460800, 230400, 57600, 38400, 19200, 9600 baud: is the "
                                                  "device powered, and is this its port?"));
        const QList<quint32> expected = {115200, 2000000, 921600, 460800, 230400, 57600, 38400, 19200, 9600};
        QCOMPARE(rig.line.baudRates(), expected);
    }

    void probeFindsTheDevicesBaud()
    {
        Script script;
        script.onlyAtBaud = 460800;
        Rig rig(script);
        SessionSettings settings = fastSettings();
        settings.probeBaudRates = true;
        QVERIFY(rig.start(settings));
        QCOMPARE(rig.session.deviceInfo().baud, std::uint32_t(460800));
        QCOMPARE(rig.line.baudRates(), (QList<quint32>{115200, 2000000, 921600, 460800}));
    }

    void silenceAfterTheFirstAnswerIsWorded()
    {
        Script script;
        script.silentFor = {XbusMid::ReqFwRev};
        Rig rig(script);
        QVERIFY(!rig.start());
        QCOMPARE(rig.endMessage(), QStringLiteral("no answer to ReqFWRev at 115200 baud on MOCK0 after 3 tries of "
                                                  "100 ms: the device answered before, so it may have been unplugged "
                                                  "or reset"));
    }

    void deviceRefusalIsWorded()
    {
        Script script;
        script.errorFor[XbusMid::SetOutputConfiguration] = XbusErrorCode::InvalidParameter;
        Rig rig(script);
        QVERIFY(!rig.start());
        QCOMPARE(rig.endMessage(),
                 QStringLiteral("the device refused SetOutputConfiguration: invalid parameter (error 33)"));
        QCOMPARE(rig.identified.count(), 0);
    }

    void unsupportedRateIsRefusedInWords()
    {
        Rig rig;
        SessionSettings settings = fastSettings();
        settings.rate_hz = 3;  // does not divide the emulated sensor clock
        QVERIFY(!rig.start(settings));
        QVERIFY2(rig.endMessage().startsWith(QStringLiteral("the device refused SetOutputConfiguration: invalid "
                                                            "parameter")),
                 qPrintable(rig.endMessage()));
    }

    void openFailureIsWorded()
    {
        Rig rig;
        rig.line.setOpenError(QStringLiteral("Permission denied"));
        QVERIFY(!rig.start());
        QCOMPARE(rig.endMessage(), QStringLiteral("cannot open MOCK0: Permission denied (is your user allowed to use "
                                                  "serial ports, e.g. in the dialout group?)"));
    }

    void countsLostPacketsChecksumErrorsAndResyncs()
    {
        Rig rig;
        QVERIFY(rig.start());
        QByteArray stream;
        for (std::uint16_t c = 0; c < 200; ++c) {
            if (c == 10 || c == 50 || c == 51)
                continue;  // dropped on the way
            QByteArray frame = dataFrame(c);
            if (c == 100)
                frame[7] = char(frame[7] ^ 0x20);  // damaged: the checksum fails
            if (c == 150)
                stream += QByteArray("\x01\x02junk\x03", 7);
            stream += frame;
        }
        feedInChunks(rig.line, stream);
        QTRY_COMPARE(rig.session.counters().samplesReceived, std::uint64_t(196));
        const DeviceCounters counters = rig.session.counters();
        QCOMPARE(counters.packetsLost, std::uint64_t(4));
        QCOMPARE(counters.checksumErrors, std::uint64_t(1));
        QVERIFY(counters.resyncs >= 2);
        QCOMPARE(counters.deviceTime_s, 1.99);
        const std::vector<LiveSample> samples = rig.session.takeSamples();
        QCOMPARE(samples.size(), std::size_t(196));
        for (const LiveSample& s : samples)
            QCOMPARE(s.imu.time_s, double(*s.packetCounter) * 100.0 / 10000.0);  // lost packets leave gaps
        QVERIFY(rig.session.takeSamples().empty());
    }

    void aDeviceErrorDuringMeasurementIsAWarning()
    {
        Rig rig;
        QVERIFY(rig.start());
        rig.line.feedReceived(toBytes(encodeFrame(errorMessage(XbusErrorCode::DataOverflow))));
        QTRY_VERIFY(rig.warningTexts().contains(
            QStringLiteral("the device reported during measurement: data overflow: more data than the link can carry "
                           "(baud rate too low) (error 41)")));
        QCOMPARE(rig.session.state(), SessionState::Streaming);
    }

    void aFloodOfDeviceErrorsIsCountedButWarnedOnce()
    {
        // Queued warnings for a busy GUI must not grow with the device's error rate.
        Rig rig;
        QVERIFY(rig.start());
        QByteArray flood;
        for (int k = 0; k < 500; ++k)
            flood += toBytes(encodeFrame(errorMessage(XbusErrorCode::DataOverflow)));
        flood += dataFrame(0);
        feedInChunks(rig.line, flood);
        QTRY_COMPARE(rig.session.counters().deviceErrors, std::uint64_t(500));
        QCOMPARE(rig.warningTexts().filter(QStringLiteral("data overflow")).size(), 1);
    }

    void stopAsksTheDeviceToStop()
    {
        Rig rig;
        QVERIFY(rig.start());
        rig.session.stop();
        QVERIFY(rig.ended.wait(5000));
        QCOMPARE(rig.endKind(), SessionEnd::Stopped);
        QCOMPARE(writtenMids(rig.line).back(), XbusMid::GoToConfig);
        QVERIFY(!rig.line.isOpen());
    }

    void stopsAfterTheRequestedDeviceTime()
    {
        QTemporaryDir dir;
        Rig rig;
        SessionSettings settings = fastSettings();
        settings.stopAfter_s = 0.5;
        settings.recording = {dir.filePath(QStringLiteral("cut.mtb")), dir.filePath(QStringLiteral("cut.csv"))};
        QVERIFY(rig.start(settings));
        QByteArray stream;
        for (std::uint16_t c = 0; c < 100; ++c)
            stream += dataFrame(c);
        feedInChunks(rig.line, stream);
        QVERIFY(rig.ended.wait(5000));
        QCOMPARE(rig.endKind(), SessionEnd::Stopped);
        QCOMPARE(rig.session.takeSamples().size(), std::size_t(50));
        QCOMPARE(rig.session.counters().samplesReceived, std::uint64_t(50));
        const ImportResult mtb = importRecording(settings.recording.mtb.toStdString());
        const ImportResult csv = importRecording(settings.recording.csv.toStdString());
        QVERIFY(mtb.ok() && csv.ok());
        QCOMPARE(mtb.recording.samples.size(), std::size_t(50));
        QCOMPARE(csv.recording.samples.size(), std::size_t(50));
        QVERIFY(!mtb.info.truncated);  // cut at a frame boundary
        QCOMPARE(writtenMids(rig.line).back(), XbusMid::GoToConfig);
    }

    void vanishingPortKeepsEverythingReceived()
    {
        QTemporaryDir dir;
        Rig rig;
        SessionSettings settings = fastSettings();
        settings.recording = {dir.filePath(QStringLiteral("gone.mtb")), dir.filePath(QStringLiteral("gone.csv"))};
        QVERIFY(rig.start(settings));
        QByteArray stream;
        for (std::uint16_t c = 0; c < 100; ++c)
            stream += dataFrame(c);
        stream += dataFrame(100).left(9);  // the cable is pulled inside a frame
        feedInChunks(rig.line, stream);
        // Posted after the bytes, so it reaches the port after all of them, as a real unplug would.
        rig.line.injectFailure(DevicePort::Failure::Vanished, QStringLiteral("No such device"));
        QCOMPARE(rig.endMessage(), QStringLiteral("the port MOCK0 vanished (device unplugged?) after 1.0 s of "
                                                  "measurement; everything received was kept: 100 samples, 0 lost "
                                                  "packets, 0 checksum errors, 0 resyncs"));
        QCOMPARE(rig.endKind(), SessionEnd::Vanished);
        QCOMPARE(rig.session.takeSamples().size(), std::size_t(100));
        const ImportResult mtb = importRecording(settings.recording.mtb.toStdString());
        const ImportResult csv = importRecording(settings.recording.csv.toStdString());
        QVERIFY(mtb.ok() && csv.ok());
        QCOMPARE(mtb.recording.samples.size(), std::size_t(100));
        QCOMPARE(csv.recording.samples.size(), std::size_t(100));
        QVERIFY(mtb.info.truncated);  // the unfinished frame's bytes were kept too
        QCOMPARE(QFile(settings.recording.mtb).size(), qint64(5 + 118) + stream.size());
    }

    void vanishingDuringInitIsWorded()
    {
        Script script;
        script.deaf = true;
        Rig rig(script);
        SessionSettings settings = fastSettings();
        settings.timeouts.goToConfig_ms = 5000;
        rig.session.start(settings);
        QTRY_VERIFY(rig.line.isOpen());
        rig.line.injectFailure(DevicePort::Failure::Vanished, QStringLiteral("No such device"));
        QCOMPARE(rig.endMessage(), QStringLiteral("MOCK0 failed during initialisation: No such device"));
    }

    void unwritableRecordingFailsBeforeTouchingThePort()
    {
        QTemporaryDir dir;
        const QString plainFile = dir.filePath(QStringLiteral("plain"));
        QVERIFY(QFile(plainFile).open(QIODevice::WriteOnly));
        Rig rig;
        SessionSettings settings = fastSettings();
        settings.recording.mtb = plainFile + QStringLiteral("/walk.mtb");
        QVERIFY(!rig.start(settings));
        QVERIFY2(rig.endMessage().startsWith(QStringLiteral("cannot record to ") + settings.recording.mtb),
                 qPrintable(rig.endMessage()));
        QVERIFY(rig.line.baudRates().isEmpty());  // the port was never opened
    }

    void failedInitLeavesNoRecordingBehind()
    {
        QTemporaryDir dir;
        Script script;
        script.deaf = true;
        Rig rig(script);
        SessionSettings settings = fastSettings();
        settings.recording = {dir.filePath(QStringLiteral("never.mtb")), dir.filePath(QStringLiteral("never.csv"))};
        QVERIFY(!rig.start(settings));
        QVERIFY(!QFile::exists(settings.recording.mtb));
        QVERIFY(!QFile::exists(settings.recording.csv));
    }

    void displayQueueIsBounded()
    {
        Rig rig;
        SessionSettings settings = fastSettings();
        settings.displayQueueSamples = 10;
        QVERIFY(rig.start(settings));
        QSignalSpy available(&rig.session, &DeviceSession::samplesAvailable);
        QByteArray stream;
        for (std::uint16_t c = 0; c < 50; ++c)
            stream += dataFrame(c);
        feedInChunks(rig.line, stream);
        QTRY_COMPARE(rig.session.counters().samplesNotShown, std::uint64_t(40));
        const std::vector<LiveSample> kept = rig.session.takeSamples();
        QCOMPARE(kept.size(), std::size_t(10));
        QCOMPARE(*kept.front().packetCounter, std::uint16_t(40));  // the newest are kept
        QCOMPARE(available.count(), 1);  // one notification until the queue is drained
    }

    void displayOverflowNeverTouchesTheRecording()
    {
        // A consumer that never takes its samples (a frozen GUI): the queue holds its bound, the
        // rest is counted as not shown, and the recording has every sample all the same.
        QTemporaryDir dir;
        Rig rig;
        SessionSettings settings = fastSettings();
        settings.displayQueueSamples = 25;
        settings.recording = {dir.filePath(QStringLiteral("slow.mtb")), dir.filePath(QStringLiteral("slow.csv"))};
        QVERIFY(rig.start(settings));
        QByteArray stream;
        for (std::uint16_t c = 0; c < 400; ++c)
            stream += dataFrame(c);
        feedInChunks(rig.line, stream);
        QTRY_COMPARE(rig.session.counters().samplesReceived, std::uint64_t(400));
        QTRY_COMPARE(rig.session.counters().samplesNotShown, std::uint64_t(375));
        rig.session.stop();
        QVERIFY(rig.ended.wait(5000) || !rig.ended.isEmpty());
        QCOMPARE(rig.session.takeSamples().size(), std::size_t(25));
        const ImportResult csv = importRecording(settings.recording.csv.toStdString());
        const ImportResult mtb = importRecording(settings.recording.mtb.toStdString());
        QVERIFY(csv.ok() && mtb.ok());
        QCOMPARE(csv.recording.samples.size(), std::size_t(400));
        QCOMPARE(mtb.recording.samples.size(), std::size_t(400));
        QCOMPARE(csv.recording.samples.back().acc_mps2.x(), 0.5 * 399);
    }

    void stoppedRecordingEndsOnAWholeMessage()
    {
        // Stopped while the decoder still waits on a false preamble inside a damaged message: the
        // .mtb ends with the last whole message, so it re-opens without a truncated tail.
        QTemporaryDir dir;
        Rig rig;
        SessionSettings settings = fastSettings();
        settings.recording = {dir.filePath(QStringLiteral("cut.mtb")), {}};
        QVERIFY(rig.start(settings));
        QByteArray stream;
        for (std::uint16_t c = 0; c < 20; ++c)
            stream += dataFrame(c);
        QByteArray damaged = toBytes(encodeFrame(
            xbusMessage(XbusMid::MtData2, {0x10, 0x20, 0x02, 0x00, 0x14, 0xFA, 0xFF, 0x36, 0x40, 0x01})));
        damaged[4] = char(damaged[4] ^ 0x01);  // the checksum fails; FA FF 36 40 inside claims 64 more bytes
        rig.line.feedReceived(stream + QByteArray("\x01\x02\x03", 3) + damaged);
        QTRY_COMPARE(rig.session.counters().checksumErrors, std::uint64_t(1));
        rig.session.stop();
        QVERIFY(rig.ended.wait(5000) || !rig.ended.isEmpty());
        const ImportResult mtb = importRecording(settings.recording.mtb.toStdString());
        QVERIFY(mtb.ok());
        QCOMPARE(mtb.recording.samples.size(), std::size_t(20));
        QVERIFY(!mtb.info.truncated);
        for (const std::string& warning : mtb.recording.warnings)
            QVERIFY2(warning.find("ends inside") == std::string::npos, warning.c_str());
    }

    void recordingCanStartAndStopMidStream()
    {
        QTemporaryDir dir;
        Rig rig;
        QVERIFY(rig.start());
        QSignalSpy stopped(&rig.session, &DeviceSession::recordingStopped);
        QByteArray before;
        for (std::uint16_t c = 0; c < 30; ++c)
            before += dataFrame(c);
        rig.line.feedReceived(before);
        QTRY_COMPARE(rig.session.counters().samplesReceived, std::uint64_t(30));
        const RecordingPaths paths{dir.filePath(QStringLiteral("mid.mtb")), dir.filePath(QStringLiteral("mid.csv"))};
        rig.session.startRecording(paths);
        QByteArray during;
        for (std::uint16_t c = 30; c < 70; ++c)
            during += dataFrame(c);
        feedInChunks(rig.line, during);
        QTRY_COMPARE(rig.session.counters().samplesReceived, std::uint64_t(70));
        rig.session.stopRecording();
        QVERIFY(stopped.wait(5000));
        QCOMPARE(stopped.first().at(1).toString(), QString());
        const ImportResult csv = importRecording(paths.csv.toStdString());
        const ImportResult mtb = importRecording(paths.mtb.toStdString());
        QVERIFY(csv.ok() && mtb.ok());
        QCOMPARE(csv.recording.samples.size(), std::size_t(40));
        QCOMPARE(mtb.recording.samples.size(), std::size_t(40));
        QCOMPARE(csv.recording.samples.front().time_s, 0.0);
        QCOMPARE(csv.recording.samples.front().acc_mps2.x(), 15.0);  // counter 30
    }
};

QTEST_MAIN(TestDeviceSession)
#include "tst_devicesession.moc"
