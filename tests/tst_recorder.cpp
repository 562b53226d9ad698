// The Recorder: what it writes is in the file before it is closed (unbuffered writes, sync), the
// .mtb and the CSV re-open with importRecording and give the same samples bit for bit, the CSV's
// columns follow the first sample, a recording started mid-stream is timed from its own first
// sample, and a missing or unwritable folder or a full disk is reported at once in words.
#include "Recorder.h"

#include "io/Import.h"
#include "xbus/MtData2.h"
#include "xbus/XbusControl.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace footpath;

namespace {

DeviceInfo testDevice(std::uint16_t rate_hz = 100)
{
    DeviceInfo info;
    info.portName = QStringLiteral("/dev/ttyTEST");
    info.deviceId = 0x037003F8;
    info.productCode = QStringLiteral("MTi-300-2A8G4");
    info.firmware = {1, 8, 2, std::nullopt, std::nullopt};
    info.rate_hz = rate_hz;
    return info;
}

/// Data messages as a device sends them at 100 Hz: values that float32 cannot represent exactly,
/// pressure every second message (50 Hz), and `skip` counters lost on the way.
std::vector<MtData2Sample> messages(std::size_t count, std::uint16_t firstCounter = 0, std::size_t skipEvery = 0)
{
    std::vector<MtData2Sample> out;
    for (std::size_t k = 0; k < count; ++k) {
        if (skipEvery > 0 && k % skipEvery == skipEvery - 1)
            continue;
        MtData2Sample s;
        s.packetCounter = static_cast<std::uint16_t>(firstCounter + k);
        s.sampleTimeFine = static_cast<std::uint32_t>(123456 + 100 * k);
        s.acceleration = Eigen::Vector3d(0.1 * double(k), -1.2345678, 9.80665);
        s.rateOfTurn = Eigen::Vector3d(0.001, -0.5, 3.14159);
        s.magneticField = Eigen::Vector3d(0.45, -0.12, 0.87);
        if (k % 2 == 0)
            s.pressure_pa = 101325.0 + double(k);
        // Through float32, as they come off the wire.
        out.push_back(decodeMtData2(encodeMtData2(s)).sample);
    }
    return out;
}

QByteArray rawFramesOf(const std::vector<MtData2Sample>& samples)
{
    QByteArray raw;
    for (const MtData2Sample& s : samples) {
        const std::vector<std::uint8_t> frame = encodeFrame(xbusMessage(XbusMid::MtData2, encodeMtData2(s)));
        raw.append(reinterpret_cast<const char*>(frame.data()), static_cast<int>(frame.size()));
    }
    return raw;
}

/// Records like a session does: raw bytes and the decoded messages of the same frames.
bool record(Recorder& recorder, const std::vector<MtData2Sample>& samples)
{
    return recorder.writeRaw(rawFramesOf(samples)) && recorder.writeData(samples);
}

/// The same samples, bit for bit, in every channel the recordings have (a channel a recording's
/// first sample lacks is absent for its users, whatever later samples hold).
void compareSamples(const Recording& a, const Recording& b)
{
    QCOMPARE(a.samples.size(), b.samples.size());
    QCOMPARE(a.hasMag(), b.hasMag());
    QCOMPARE(a.hasPressure(), b.hasPressure());
    for (std::size_t k = 0; k < a.samples.size(); ++k) {
        const ImuSample& x = a.samples[k];
        const ImuSample& y = b.samples[k];
        QCOMPARE(x.time_s, y.time_s);
        QVERIFY(x.acc_mps2 == y.acc_mps2);
        QVERIFY(x.gyr_radps == y.gyr_radps);
        if (a.hasMag())
            QVERIFY(x.mag == y.mag);
        if (a.hasPressure())
            QCOMPARE(x.pressure_pa, y.pressure_pa);
    }
}

QByteArray fileContent(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

}  // namespace

class TestRecorder : public QObject {
    Q_OBJECT
private slots:
    void reopensWithTheImporterSampleForSample()
    {
        QTemporaryDir dir;
        const RecordingPaths paths{dir.filePath(QStringLiteral("walk.mtb")), dir.filePath(QStringLiteral("walk.csv"))};
        const std::vector<MtData2Sample> sent = messages(500, 65400, 7);  // the counter wraps, some are lost
        {
            Recorder recorder;
            QVERIFY2(recorder.open(paths), qPrintable(recorder.error()));
            QVERIFY(recorder.writeHeader(testDevice()));
            QVERIFY(record(recorder, {sent.begin(), sent.begin() + 200}));
            QVERIFY(record(recorder, {sent.begin() + 200, sent.end()}));
            QCOMPARE(recorder.rowsWritten(), std::uint64_t(sent.size()));
            QCOMPARE(recorder.packetsLost(), std::uint64_t(71));
        }
        const ImportResult mtb = importRecording(paths.mtb.toStdString());
        const ImportResult csv = importRecording(paths.csv.toStdString());
        QVERIFY2(mtb.ok(), mtb.ok() ? "" : mtb.error->message.c_str());
        QVERIFY2(csv.ok(), csv.ok() ? "" : csv.error->message.c_str());
        QCOMPARE(mtb.info.format, std::string("xsens-mtb"));
        QCOMPARE(csv.info.format, std::string("delimited"));
        QCOMPARE(mtb.info.rate_hz, 100.0);  // from the Configuration message the recorder wrote first
        QCOMPARE(mtb.recording.samples.size(), sent.size());
        compareSamples(mtb.recording, csv.recording);
        QCOMPARE(csv.recording.samples.back().time_s, 49900.0 / 10000.0);
        QVERIFY(csv.recording.hasMag() && csv.recording.hasPressure());
    }

    void csvHasTheCanonicalColumns()
    {
        QTemporaryDir dir;
        const RecordingPaths paths{dir.filePath(QStringLiteral("a.mtb")), dir.filePath(QStringLiteral("a.csv"))};
        Recorder recorder;
        QVERIFY(recorder.open(paths) && recorder.writeHeader(testDevice()));
        QVERIFY(record(recorder, messages(3, 41)));
        const QList<QByteArray> lines = fileContent(paths.csv).split('\n');
        QCOMPARE(lines.at(0), QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z,pressure_pa,"
                                         "packet_counter"));
        QVERIFY(lines.at(1).startsWith("0,0,-1.2345677614212036,9.806650161743164,"));
        QVERIFY(lines.at(1).endsWith(",101325,41"));
        QVERIFY(lines.at(2).startsWith("0.01,"));
        QVERIFY(lines.at(2).endsWith(",101325,42"));  // pressure holds its last value between readings
    }

    void columnsFollowTheFirstSample()
    {
        QTemporaryDir dir;
        const RecordingPaths paths{dir.filePath(QStringLiteral("b.mtb")), dir.filePath(QStringLiteral("b.csv"))};
        std::vector<MtData2Sample> sent = messages(4);
        for (MtData2Sample& s : sent) {
            s.magneticField.reset();
            s.pressure_pa.reset();
        }
        Recorder recorder;
        QVERIFY(recorder.open(paths) && recorder.writeHeader(testDevice()));
        QVERIFY(record(recorder, sent));
        QVERIFY(fileContent(paths.csv).startsWith("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,packet_counter\n"));
    }

    void everyWriteIsInTheFileBeforeClosing()
    {
        QTemporaryDir dir;
        const RecordingPaths paths{dir.filePath(QStringLiteral("c.mtb")), dir.filePath(QStringLiteral("c.csv"))};
        Recorder recorder;
        QVERIFY(recorder.open(paths) && recorder.writeHeader(testDevice()));
        const std::vector<MtData2Sample> sent = messages(10);
        QVERIFY(record(recorder, sent));
        // Read through another handle while the recorder is still open: a crash now loses nothing.
        QCOMPARE(fileContent(paths.csv).count('\n'), 11);
        const QByteArray mtb = fileContent(paths.mtb);
        QVERIFY(mtb.startsWith(QByteArray::fromHex("FAFF0D76")));  // the Configuration, 118 bytes
        QVERIFY(mtb.endsWith(rawFramesOf(sent)));
        QCOMPARE(recorder.rawBytesWritten(), std::uint64_t(rawFramesOf(sent).size()));
        QVERIFY(recorder.sync());
        QVERIFY(recorder.sync());  // nothing new: nothing to do
        const ImportResult whileOpen = importRecording(paths.mtb.toStdString());
        QVERIFY(whileOpen.ok());
        QCOMPARE(whileOpen.recording.samples.size(), std::size_t(10));
    }

    void startedMidStreamTimesFromItsFirstSample()
    {
        QTemporaryDir dir;
        const RecordingPaths paths{dir.filePath(QStringLiteral("d.mtb")), dir.filePath(QStringLiteral("d.csv"))};
        const std::vector<MtData2Sample> stream = messages(300);
        Recorder recorder;
        QVERIFY(recorder.open(paths) && recorder.writeHeader(testDevice()));
        QVERIFY(record(recorder, {stream.begin() + 117, stream.end()}));
        recorder.close();
        const ImportResult mtb = importRecording(paths.mtb.toStdString());
        const ImportResult csv = importRecording(paths.csv.toStdString());
        QVERIFY(mtb.ok() && csv.ok());
        QCOMPARE(csv.recording.samples.front().time_s, 0.0);
        compareSamples(mtb.recording, csv.recording);
    }

    void missingFolderIsReportedAtOnce()
    {
        QTemporaryDir dir;
        Recorder recorder;
        const QString missing = dir.filePath(QStringLiteral("no/such/folder/walk.mtb"));
        QVERIFY(!recorder.open({missing, {}}));
        QVERIFY2(recorder.error().contains(QStringLiteral("does not exist")), qPrintable(recorder.error()));
        QVERIFY(recorder.error().contains(missing));
        QVERIFY(!recorder.isOpen());
    }

    void unwritableFolderIsReportedAtOnce()
    {
        QTemporaryDir dir;
        // A regular file where a folder should be: unwritable for every user, root included.
        const QString notAFolder = dir.filePath(QStringLiteral("plain-file"));
        QVERIFY(QFile(notAFolder).open(QIODevice::WriteOnly));
        Recorder recorder;
        QVERIFY(!recorder.open({notAFolder + QStringLiteral("/walk.mtb"), {}}));
        QVERIFY2(recorder.error().contains(QStringLiteral("cannot record")), qPrintable(recorder.error()));
        // The CSV is checked before anything is recorded, too.
        Recorder second;
        QVERIFY(!second.open({dir.filePath(QStringLiteral("ok.mtb")), notAFolder + QStringLiteral("/walk.csv")}));
        QVERIFY(second.error().contains(QStringLiteral("walk.csv")));
        QVERIFY(!second.isOpen());
    }

    void fullDiskIsReportedByTheWriteThatHitsIt()
    {
        if (!QFile::exists(QStringLiteral("/dev/full")))
            QSKIP("no /dev/full on this system");
        QTemporaryDir dir;
        Recorder recorder;
        QVERIFY(recorder.open({QStringLiteral("/dev/full"), dir.filePath(QStringLiteral("e.csv"))}));
        QVERIFY(!recorder.writeHeader(testDevice()));
        QVERIFY2(recorder.error().contains(QStringLiteral("disk full")), qPrintable(recorder.error()));
        QVERIFY(recorder.error().contains(QStringLiteral("/dev/full")));
        QVERIFY(!recorder.isOpen());  // stopped, keeping what was written
        QVERIFY(!recorder.writeData(messages(2)));
    }

    void discardLeavesNoFiles()
    {
        QTemporaryDir dir;
        const RecordingPaths paths{dir.filePath(QStringLiteral("f.mtb")), dir.filePath(QStringLiteral("f.csv"))};
        Recorder recorder;
        QVERIFY(recorder.open(paths));
        recorder.discard();
        QVERIFY(!QFile::exists(paths.mtb));
        QVERIFY(!QFile::exists(paths.csv));
    }
};

QTEST_APPLESS_MAIN(TestRecorder)
#include "tst_recorder.moc"
