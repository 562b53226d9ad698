// End to end over a real pseudo-terminal: footpath-mti-sim plays a simulated walk as a live MTi
// with seeded faults (dropped and damaged messages, junk between frames), `footpath-cli record`
// records 10 s of device time through DeviceSession and QSerialPort, and the emulator's sidecar
// log of what it sent is the truth: every message sent intact arrived exactly once with its
// values, the packets lost on the way were counted, and the .mtb and the CSV re-open with the
// same samples. A second run pulls the plug mid-stream and checks that nothing received before
// the disconnect is lost. Device time runs 10x faster than wall time to keep the run short.
#include "LiveTestSupport.h"
#include "io/Import.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <array>
#include <cmath>
#include <optional>

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
