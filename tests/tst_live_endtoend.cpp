// End to end over a real pseudo-terminal: footpath-mti-sim plays a simulated walk as a live MTi
// with seeded faults (dropped and damaged messages, junk between frames), `footpath-cli record`
// records 10 s of device time through DeviceSession and QSerialPort, and the emulator's sidecar
// log of what it sent is the truth: every message sent intact arrived exactly once with its
// values, the packets lost on the way were counted, and the .mtb and the CSV re-open with the
// same samples. A second run pulls the plug mid-stream and checks that nothing received before
// the disconnect is lost. Device time runs 10x faster than wall time to keep the run short.
#include "DeviceSession.h"
#include "LiveTestSupport.h"
#include "io/Import.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QElapsedTimer>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTimer>
#include <QTemporaryDir>
#include <QtTest>

#include <array>
#include <cmath>
#include <map>
#include <optional>

#include <csignal>
#include <sys/resource.h>

#ifndef FOOTPATH_CLI
#error "FOOTPATH_CLI must name the footpath-cli binary"
#endif

using namespace footpath;
using namespace livetest;

namespace {

constexpr int kProcessTimeout_ms = 30000;
const QStringList kFaults = {QStringLiteral("--seed"), QStringLiteral("11"), QStringLiteral("--drop-rate"),
                             QStringLiteral("0.01"), QStringLiteral("--corrupt-rate"), QStringLiteral("0.01"),
                             QStringLiteral("--junk-rate"), QStringLiteral("0.02"), QStringLiteral("--speed"),
                             QStringLiteral("10")};

/// One row of the recorded CSV.
struct Received {
    double time_s = 0.0;
    std::array<double, 6> values{};
    unsigned counter = 0;
};

std::vector<Received> readRecordedCsv(const QString& path)
{
    std::vector<Received> rows;
    for (const QByteArray& line : dataLines(path)) {
        const QList<QByteArray> cells = line.split(',');
        Received r;
        r.time_s = cells.at(0).toDouble();
        for (int i = 0; i < 6; ++i)
            r.values[std::size_t(i)] = cells.at(1 + i).toDouble();
        r.counter = cells.last().toUInt();
        rows.push_back(r);
    }
    return rows;
}

QString csvHeader(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromLatin1(file.readLine()).trimmed() : QString();
}

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

Run runCli(const QStringList& args)
{
    QProcess process;
    process.start(QString::fromUtf8(FOOTPATH_CLI), args);
    Run run;
    if (!process.waitForFinished(kProcessTimeout_ms))
        process.kill();
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = QString::fromLocal8Bit(process.readAllStandardOutput());
    run.err = QString::fromLocal8Bit(process.readAllStandardError());
    return run;
}

/// The last value of "label N" the CLI printed in its counter lines.
std::uint64_t lastCounter(const QString& out, const QString& label)
{
    const QRegularExpression pattern(label + QStringLiteral(" (\\d+)"));
    std::uint64_t value = 0;
    for (auto it = pattern.globalMatch(out); it.hasNext();)
        value = it.next().captured(1).toULongLong();
    return value;
}

/// Messages that did not arrive intact between the first and the last received one.
std::uint64_t lostBetween(const std::vector<Sent>& sent, unsigned firstCounter, unsigned lastCounter)
{
    std::uint64_t lost = 0;
    for (const Sent& s : sent)
        lost += s.counter > firstCounter && s.counter < lastCounter && !s.intact();
    return lost;
}

void compareWithSent(const std::vector<Received>& received, const std::vector<Sent>& expected)
{
    QCOMPARE(received.size(), expected.size());
    for (std::size_t k = 0; k < received.size(); ++k) {
        QCOMPARE(received[k].counter, expected[k].counter);  // in order, each exactly once
        QCOMPARE(received[k].time_s, double(expected[k].sampleTimeFine - expected.front().sampleTimeFine) / 10000.0);
        for (std::size_t i = 0; i < 6; ++i)
            QCOMPARE(received[k].values[i], expected[k].values[i]);  // bit for bit
    }
}

void compareRecordings(const ImportResult& mtb, const ImportResult& csv)
{
    QVERIFY2(mtb.ok(), mtb.ok() ? "" : mtb.error->message.c_str());
    QVERIFY2(csv.ok(), csv.ok() ? "" : csv.error->message.c_str());
    QCOMPARE(mtb.recording.samples.size(), csv.recording.samples.size());
    QCOMPARE(mtb.recording.hasMag(), csv.recording.hasMag());
    QCOMPARE(mtb.recording.hasPressure(), csv.recording.hasPressure());
    for (std::size_t k = 0; k < mtb.recording.samples.size(); ++k) {
        const ImuSample& a = mtb.recording.samples[k];
        const ImuSample& b = csv.recording.samples[k];
        QCOMPARE(a.time_s, b.time_s);
        QVERIFY(a.acc_mps2 == b.acc_mps2 && a.gyr_radps == b.gyr_radps);
        QVERIFY(!mtb.recording.hasMag() || a.mag == b.mag);
        QVERIFY(!mtb.recording.hasPressure() || a.pressure_pa == b.pressure_pa);
    }
}

/// The emulator's "injected: key=value ..." line: what it put into the stream.
std::map<QString, std::uint64_t> injectedSummary(const QString& emulatorOutput)
{
    std::map<QString, std::uint64_t> summary;
    const QRegularExpression line(QStringLiteral("injected:(.*)"));
    const QRegularExpressionMatch match = line.match(emulatorOutput);
    for (const QString& pair : match.captured(1).split(QLatin1Char(' '), Qt::SkipEmptyParts))
        summary[pair.section(QLatin1Char('='), 0, 0)] = pair.section(QLatin1Char('='), 1).toULongLong();
    return summary;
}

std::uint64_t countFate(const std::vector<Sent>& sent, const char* fate)
{
    const auto hasFate = [fate](const Sent& s) { return s.fate == QLatin1String(fate); };
    return std::uint64_t(std::count_if(sent.begin(), sent.end(), hasFate));
}

/// A recording re-opened through the importer holds the first samples the emulator sent intact,
/// in order, bit for bit, timed from the first of them.
void checkIsIntactPrefix(const ImportResult& read, const std::vector<Sent>& expected)
{
    QVERIFY2(read.ok(), read.ok() ? "" : read.error->message.c_str());
    const std::vector<ImuSample>& samples = read.recording.samples;
    QVERIFY(!samples.empty());
    QVERIFY(samples.size() <= expected.size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
        QCOMPARE(samples[k].time_s, double(expected[k].sampleTimeFine - expected.front().sampleTimeFine) / 10000.0);
        for (int axis = 0; axis < 3; ++axis) {
            QCOMPARE(samples[k].acc_mps2[axis], expected[k].values[std::size_t(axis)]);
            QCOMPARE(samples[k].gyr_radps[axis], expected[k].values[std::size_t(3 + axis)]);
        }
    }
}

/// Waits until the CSV at `path` has at least `rows` data rows.
bool waitForRows(const QString& path, int rows, int timeout_ms)
{
    return QTest::qWaitFor([&] { return dataLines(path).size() >= rows; }, timeout_ms);
}

}  // namespace

class TestLiveEndToEnd : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        if (!QFileInfo::exists(QStringLiteral("/dev/ptmx")))
            QSKIP("no pseudo-terminals on this system (/dev/ptmx)");
    }

    void recordsTenSecondsWithEverySampleExactlyOnce()
    {
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("ttyMTi0"));
        const QString log = dir.filePath(QStringLiteral("sent.csv"));
        const QString mtb = dir.filePath(QStringLiteral("walk.mtb"));
        const QString csv = dir.filePath(QStringLiteral("walk.csv"));
        Emulator emulator;
        if (const QString problem = emulator.start(link, log, kFaults); !problem.isEmpty())
            QSKIP(qPrintable(QStringLiteral("cannot run the emulator: ") + problem));

        const Run run = runCli({QStringLiteral("record"), QStringLiteral("--port"), link, QStringLiteral("--duration"),
                                QStringLiteral("10"), QStringLiteral("--out"), mtb, QStringLiteral("--csv"), csv});
        emulator.stop();
        QVERIFY2(run.exitCode == 0, qPrintable(run.out + run.err));
        QVERIFY2(run.out.contains(QStringLiteral("device      037003F8 MTi-300-2A8G4, firmware 1.8.2")), qPrintable(run.out));
        QVERIFY(run.out.contains(QStringLiteral("port        ") + link + QStringLiteral(" at 115200 baud")));

        const std::vector<Sent> sent = readSentLog(log);
        const std::vector<Received> received = readRecordedCsv(csv);
        QVERIFY(received.size() > 900);
        const auto first = std::find_if(sent.begin(), sent.end(),
                                        [&](const Sent& s) { return s.counter == received.front().counter; });
        QVERIFY(first != sent.end());
        QVERIFY(std::none_of(sent.begin(), first, [](const Sent& s) { return s.fate == QLatin1String("sent"); }));
        const std::vector<Sent> expected = expectedSamples(sent, first->sampleTimeFine, 10.0);
        compareWithSent(received, expected);

        const std::uint64_t lost = lostBetween(sent, received.front().counter, received.back().counter);
        QVERIFY2(lost >= 10, "the seed should drop and damage some messages in 10 s");
        QCOMPARE(lastCounter(run.out, QStringLiteral("lost")), lost);
        QVERIFY(lastCounter(run.out, QStringLiteral("checksum errors")) > 0);
        QCOMPARE(lastCounter(run.out, QStringLiteral("samples")), std::uint64_t(received.size()));

        QCOMPARE(csvHeader(csv), QStringLiteral("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z,"
                                                "pressure_pa,packet_counter"));
        const ImportResult fromMtb = importRecording(mtb.toStdString());
        const ImportResult fromCsv = importRecording(csv.toStdString());
        compareRecordings(fromMtb, fromCsv);
        QCOMPARE(fromMtb.recording.samples.size(), expected.size());
        QCOMPARE(fromMtb.info.gaps.missingSamples, std::size_t(lost));
        QVERIFY(!fromMtb.info.truncated);
    }

    void disconnectLosesNothingReceived()
    {
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("ttyMTi1"));
        const QString log = dir.filePath(QStringLiteral("sent.csv"));
        const QString mtb = dir.filePath(QStringLiteral("cut.mtb"));
        const QString csv = dir.filePath(QStringLiteral("cut.csv"));
        Emulator emulator;
        const QString problem =
            emulator.start(link, log, kFaults + QStringList{QStringLiteral("--disconnect-after"), QStringLiteral("4")});
        if (!problem.isEmpty())
            QSKIP(qPrintable(QStringLiteral("cannot run the emulator: ") + problem));

        const Run run = runCli({QStringLiteral("record"), QStringLiteral("--port"), link, QStringLiteral("--rate"),
                                QStringLiteral("200"), QStringLiteral("--duration"), QStringLiteral("10"),
                                QStringLiteral("--out"), mtb, QStringLiteral("--csv"), csv});
        QVERIFY(emulator.waitForExit());
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("the port ") + link + QStringLiteral(" vanished (device unplugged?)")),
                 qPrintable(run.err));
        QVERIFY(run.err.contains(QStringLiteral("everything received was kept")));

        const std::vector<Sent> sent = readSentLog(log);
        const std::vector<Received> received = readRecordedCsv(csv);
        QVERIFY(!received.empty());
        const std::vector<Sent> expected = expectedSamples(sent, sent.front().sampleTimeFine, 0.0);
        compareWithSent(received, expected);  // up to the very last message before the plug was pulled
        QVERIFY(std::abs(double(sent.back().sampleTimeFine) / 10000.0 - 4.0) < 0.01);  // 4 s at 200 Hz
        compareRecordings(importRecording(mtb.toStdString()), importRecording(csv.toStdString()));
    }

    void faultCountersEqualWhatTheEmulatorInjected()
    {
        // Corrupted, dropped and junk-preceded messages plus a burst at 10x the rate, until the
        // device vanishes after 6 s: the whole stream reaches the host, so every counter must
        // equal what the emulator says it injected, and every intact message must be recorded.
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("ttyMTi2"));
        const QString log = dir.filePath(QStringLiteral("sent.csv"));
        const QString mtb = dir.filePath(QStringLiteral("faults.mtb"));
        const QString csv = dir.filePath(QStringLiteral("faults.csv"));
        Emulator emulator;
        const QStringList faults{QStringLiteral("--seed"), QStringLiteral("5"), QStringLiteral("--drop-rate"),
                                 QStringLiteral("0.03"), QStringLiteral("--corrupt-rate"), QStringLiteral("0.03"),
                                 QStringLiteral("--junk-rate"), QStringLiteral("0.05"), QStringLiteral("--speed"),
                                 QStringLiteral("10"), QStringLiteral("--burst-at"), QStringLiteral("2"),
                                 QStringLiteral("--burst-for"), QStringLiteral("1"), QStringLiteral("--burst-factor"),
                                 QStringLiteral("10"), QStringLiteral("--disconnect-after"), QStringLiteral("6")};
        if (const QString problem = emulator.start(link, log, faults); !problem.isEmpty())
            QSKIP(qPrintable(QStringLiteral("cannot run the emulator: ") + problem));

        const Run run = runCli({QStringLiteral("record"), QStringLiteral("--port"), link, QStringLiteral("--out"), mtb,
                                QStringLiteral("--csv"), csv});
        QVERIFY(emulator.waitForExit());
        const QString emulatorOutput = emulator.output();
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("vanished")), qPrintable(run.err));
        std::map<QString, std::uint64_t> injected = injectedSummary(emulatorOutput);
        QVERIFY2(injected.count(QStringLiteral("data_messages")) == 1, qPrintable(emulatorOutput));
        qInfo("emulator: %s", qPrintable(emulatorOutput.section(QStringLiteral("injected:"), 1).trimmed()));
        qInfo("cli: %s", qPrintable(run.out.section(QLatin1Char('\n'), -5).trimmed()));

        const std::vector<Sent> sent = readSentLog(log);
        QCOMPARE(injected[QStringLiteral("data_messages")], std::uint64_t(600));  // 6 s at 100 Hz
        QCOMPARE(std::uint64_t(sent.size()), injected[QStringLiteral("data_messages")]);
        QCOMPARE(injected[QStringLiteral("burst_messages")], std::uint64_t(100));
        QCOMPARE(injected[QStringLiteral("unread_bytes")], std::uint64_t(0));
        QCOMPARE(countFate(sent, "dropped"), injected[QStringLiteral("dropped")]);
        QCOMPARE(countFate(sent, "corrupted"), injected[QStringLiteral("corrupted")]);
        QVERIFY(injected[QStringLiteral("dropped")] >= 5 && injected[QStringLiteral("corrupted")] >= 5);
        QVERIFY(injected[QStringLiteral("junk_bytes")] > 100);

        // Losses before the first or after the last intact message show as no counter gap.
        const auto firstIntact = std::find_if(sent.begin(), sent.end(), [](const Sent& s) { return s.intact(); });
        const auto lastIntact = std::find_if(sent.rbegin(), sent.rend(), [](const Sent& s) { return s.intact(); });
        const std::uint64_t lostAtTheEdges =
            std::uint64_t(firstIntact - sent.begin()) + std::uint64_t(lastIntact - sent.rbegin());
        QCOMPARE(lastCounter(run.out, QStringLiteral("checksum errors")), injected[QStringLiteral("corrupted")]);
        QCOMPARE(lastCounter(run.out, QStringLiteral("junk bytes")), injected[QStringLiteral("junk_bytes")]);
        QCOMPARE(lastCounter(run.out, QStringLiteral("lost")),
                 injected[QStringLiteral("dropped")] + injected[QStringLiteral("corrupted")] - lostAtTheEdges);

        const std::vector<Sent> expected = expectedSamples(sent, sent.front().sampleTimeFine, 0.0);
        QCOMPARE(lastCounter(run.out, QStringLiteral("samples")), std::uint64_t(expected.size()));
        compareWithSent(readRecordedCsv(csv), expected);
        const ImportResult fromMtb = importRecording(mtb.toStdString());
        checkIsIntactPrefix(fromMtb, expected);
        QCOMPARE(fromMtb.recording.samples.size(), expected.size());
        compareRecordings(fromMtb, importRecording(csv.toStdString()));
    }

    void slowConsumerStaysWithinTheQueueBound()
    {
        // A GUI that takes samples only every 300 ms while a burst delivers 400 samples in 80 ms:
        // it never gets more than the queue's bound at once, what it missed is counted as not
        // shown, and the recording has every sample.
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("ttyMTi3"));
        const QString log = dir.filePath(QStringLiteral("sent.csv"));
        Emulator emulator;
        const QString problem = emulator.start(
            link, log,
            {QStringLiteral("--speed"), QStringLiteral("5"), QStringLiteral("--burst-at"), QStringLiteral("2"),
             QStringLiteral("--burst-for"), QStringLiteral("4"), QStringLiteral("--burst-factor"),
             QStringLiteral("10")});
        if (!problem.isEmpty())
            QSKIP(qPrintable(QStringLiteral("cannot run the emulator: ") + problem));

        constexpr std::size_t kBound = 150;
        SessionSettings settings;
        settings.portName = link;
        settings.stopAfter_s = 8.0;
        settings.displayQueueSamples = kBound;
        settings.recording = {dir.filePath(QStringLiteral("slow.mtb")), dir.filePath(QStringLiteral("slow.csv"))};
        DeviceSession session;
        QSignalSpy ended(&session, &DeviceSession::ended);
        std::size_t shown = 0;
        std::size_t largestTake = 0;
        int lastCounterShown = -1;
        bool inOrder = true;
        const auto take = [&] {
            for (const LiveSample& sample : session.takeSamples()) {
                ++shown;
                inOrder = inOrder && int(*sample.packetCounter) > lastCounterShown;
                lastCounterShown = int(*sample.packetCounter);
            }
        };
        QTimer slowGui;
        QObject::connect(&slowGui, &QTimer::timeout, &session, [&] {
            const std::size_t before = shown;
            take();
            largestTake = std::max(largestTake, shown - before);
        });
        slowGui.start(300);
        session.start(settings);
        QVERIFY(ended.wait(20000));
        slowGui.stop();
        take();
        emulator.stop();

        const DeviceCounters counters = session.counters();
        QCOMPARE(ended.first().at(0).value<SessionEnd>(), SessionEnd::Stopped);
        QVERIFY2(largestTake <= kBound, qPrintable(QString::number(largestTake)));
        QVERIFY(inOrder);
        QVERIFY(counters.samplesNotShown > 0);
        QCOMPARE(shown + counters.samplesNotShown, std::size_t(counters.samplesReceived));
        QCOMPARE(counters.samplesReceived, std::uint64_t(800));  // 8 s at 100 Hz, no faults
        const std::vector<Sent> sent = readSentLog(log);
        const std::vector<Received> recorded = readRecordedCsv(settings.recording.csv);
        compareWithSent(recorded, expectedSamples(sent, sent.front().sampleTimeFine, 8.0));
        QCOMPARE(importRecording(settings.recording.mtb.toStdString()).recording.samples.size(), std::size_t(800));
    }

    void sigkillLosesAtMostTheLastSecond()
    {
        // The recording process dies without a chance to close its files: they re-open through
        // the importers with every sample received up to the kill (written at once, synced every
        // second), at most 1 s short of what the device had sent.
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("ttyMTi4"));
        const QString log = dir.filePath(QStringLiteral("sent.csv"));
        const QString mtb = dir.filePath(QStringLiteral("killed.mtb"));
        const QString csv = dir.filePath(QStringLiteral("killed.csv"));
        Emulator emulator;
        if (const QString problem = emulator.start(link, log, kFaults.mid(0, 8)); !problem.isEmpty())
            QSKIP(qPrintable(QStringLiteral("cannot run the emulator: ") + problem));  // faults at speed 1

        QProcess recorder;
        recorder.start(QString::fromUtf8(FOOTPATH_CLI),
                       {QStringLiteral("record"), QStringLiteral("--port"), link, QStringLiteral("--duration"),
                        QStringLiteral("60"), QStringLiteral("--out"), mtb, QStringLiteral("--csv"), csv});
        QVERIFY(recorder.waitForStarted(5000));
        QVERIFY2(waitForRows(csv, 150, 15000), qPrintable(QString::fromLocal8Bit(recorder.readAllStandardError())));
        QTest::qWait(250);  // mid-stream, between two syncs
        ::kill(pid_t(recorder.processId()), SIGKILL);
        QVERIFY(recorder.waitForFinished(5000));
        const std::vector<Sent> sentByTheKill = readSentLog(log);
        QCOMPARE(recorder.exitStatus(), QProcess::CrashExit);
        emulator.stop();

        const std::vector<Sent> expected = expectedSamples(sentByTheKill, sentByTheKill.front().sampleTimeFine, 0.0);
        const double sentUntil_s = double(expected.back().sampleTimeFine - expected.front().sampleTimeFine) / 10000.0;
        for (const QString& path : {mtb, csv}) {
            const ImportResult read = importRecording(path.toStdString());
            checkIsIntactPrefix(read, expected);
            const double lost_s = sentUntil_s - read.recording.samples.back().time_s;
            qInfo("%s: %zu samples, %.2f s short of what was sent", qPrintable(QFileInfo(path).fileName()),
                  read.recording.samples.size(), lost_s);
            QVERIFY2(lost_s <= 1.0, qPrintable(QString::number(lost_s)));
        }
    }

    void fileSizeLimitStopsTheRecordingAndKeepsTheData()
    {
        // A file size limit (as a full disk would) in the recording process: the failed write is
        // reported at once with the file's name, the recording stops, and both files end on a
        // whole message and row and re-open with the samples written so far.
        constexpr rlim_t kLimit = 48 * 1024;
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("ttyMTi5"));
        const QString log = dir.filePath(QStringLiteral("sent.csv"));
        const QString mtb = dir.filePath(QStringLiteral("full.mtb"));
        const QString csv = dir.filePath(QStringLiteral("full.csv"));
        Emulator emulator;
        if (const QString problem = emulator.start(link, log, kFaults); !problem.isEmpty())
            QSKIP(qPrintable(QStringLiteral("cannot run the emulator: ") + problem));

        QProcess recorder;
        recorder.setChildProcessModifier([] {
            const rlimit limit{kLimit, kLimit};
            ::setrlimit(RLIMIT_FSIZE, &limit);  // SIGXFSZ is left as it is: the product must ignore it
        });
        QElapsedTimer clock;
        clock.start();
        recorder.start(QString::fromUtf8(FOOTPATH_CLI),
                       {QStringLiteral("record"), QStringLiteral("--port"), link, QStringLiteral("--duration"),
                        QStringLiteral("600"), QStringLiteral("--out"), mtb, QStringLiteral("--csv"), csv});
        QVERIFY(recorder.waitForFinished(kProcessTimeout_ms));
        const qint64 elapsed_ms = clock.elapsed();
        emulator.stop();
        const QString err = QString::fromLocal8Bit(recorder.readAllStandardError());
        QCOMPARE(recorder.exitStatus(), QProcess::NormalExit);  // not killed by SIGXFSZ
        QCOMPARE(recorder.exitCode(), 2);
        QVERIFY2(err.contains(QStringLiteral("file size limit")) && err.contains(QStringLiteral("recording stopped")),
                 qPrintable(err));
        QVERIFY2(err.contains(csv) || err.contains(mtb), qPrintable(err));
        QVERIFY2(elapsed_ms < 10000, qPrintable(QString::number(elapsed_ms)));  // 600 s asked: it stopped at the error

        const std::vector<Sent> sent = readSentLog(log);
        const std::vector<Sent> expected = expectedSamples(sent, sent.front().sampleTimeFine, 0.0);
        for (const QString& path : {mtb, csv}) {
            QVERIFY(QFileInfo(path).size() <= qint64(kLimit));
            const ImportResult read = importRecording(path.toStdString());
            checkIsIntactPrefix(read, expected);
            QVERIFY(!read.info.truncated);
            qInfo("%s: %lld bytes, %zu samples kept", qPrintable(QFileInfo(path).fileName()), QFileInfo(path).size(),
                  read.recording.samples.size());
        }
        QFile rows(csv);
        QVERIFY(rows.open(QIODevice::ReadOnly));
        QVERIFY(rows.readAll().endsWith('\n'));  // whole rows only
    }

    void deviceProblemsExitWithCodeTwoAndWords()
    {
        QTemporaryDir dir;
        const Run missing = runCli({QStringLiteral("record"), QStringLiteral("--port"),
                                    dir.filePath(QStringLiteral("ttyNothing")), QStringLiteral("--out"),
                                    dir.filePath(QStringLiteral("x.mtb"))});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY2(missing.err.contains(QStringLiteral("cannot open ") + dir.filePath(QStringLiteral("ttyNothing"))),
                 qPrintable(missing.err));
        const Run noOut = runCli({QStringLiteral("record"), QStringLiteral("--port"), QStringLiteral("/dev/null")});
        QCOMPARE(noOut.exitCode, 2);
        QVERIFY(noOut.err.contains(QStringLiteral("record needs --out FILE.mtb")));
        const Run badRate = runCli({QStringLiteral("record"), QStringLiteral("--port"), QStringLiteral("x"),
                                    QStringLiteral("--out"), QStringLiteral("y.mtb"), QStringLiteral("--rate"),
                                    QStringLiteral("2.5")});
        QCOMPARE(badRate.exitCode, 2);
        QVERIFY(badRate.err.contains(QStringLiteral("whole number of Hz")));
    }
};

QTEST_GUILESS_MAIN(TestLiveEndToEnd)
#include "tst_live_endtoend.moc"
