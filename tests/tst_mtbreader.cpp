// The .mtb reader on synthetic logs built with the Xbus encoders (time bases with counter wraps and
// lost packets, damage in the middle and at the end, files with nothing to read) and on the real
// MTi-3 log of the shared datasets.
#include "io/MtbReader.h"

#include "TestData.h"
#include "xbus/LegacyMtData.h"
#include "xbus/MtData2.h"
#include "xbus/XbusFrame.h"

#include <QtTest>

#include <fstream>
#include <random>
#include <sstream>

using namespace footpath;

namespace {

/// Builds an .mtb byte stream message by message and remembers where each frame starts.
class MtbBuilder {
public:
    void configuration(std::uint16_t period = 1152, LegacyDataLayout layout = {0, 0})
    {
        XbusConfiguration c;
        c.masterDeviceId = 0x0388044D;
        c.samplingPeriod = period;
        c.date = "20240620";
        c.time = "16343200";
        c.devices.resize(1);
        c.devices[0].deviceId = c.masterDeviceId;
        c.devices[0].layout = layout;
        add(XbusMid::Configuration, encodeConfiguration(c));
    }
    void emts()  // opaque like the real encrypted blob, extended length
    {
        std::vector<std::uint8_t> blob(1320);
        std::mt19937 random(7);
        for (std::uint8_t& byte : blob)
            byte = static_cast<std::uint8_t>(random() & 0xFF);
        add(XbusMid::EmtsData, blob);
    }
    void mtData2(const MtData2Sample& sample) { add(XbusMid::MtData2, encodeMtData2(sample)); }
    void legacy(const MtData2Sample& sample, const LegacyDataLayout& layout)
    {
        add(XbusMid::MtData, encodeLegacyMtData(sample, layout));
    }
    void add(std::uint8_t mid, const std::vector<std::uint8_t>& payload)
    {
        frameOffsets.push_back(data.size());
        const std::vector<std::uint8_t> frame = encodeFrame({kXbusMasterBusId, mid, payload});
        data.insert(data.end(), frame.begin(), frame.end());
    }
    void raw(const std::vector<std::uint8_t>& bytes) { data.insert(data.end(), bytes.begin(), bytes.end()); }

    std::vector<std::uint8_t> data;
    std::vector<std::size_t> frameOffsets;
};

MtData2Sample imuSample(std::size_t k)
{
    MtData2Sample s;
    const double x = static_cast<double>(k);
    s.acceleration = Eigen::Vector3d(0.25 * x, -0.5, 9.8125);
    s.rateOfTurn = Eigen::Vector3d(0.015625, -0.03125 * x, 0.0);
    return s;
}

ImportResult read(const std::vector<std::uint8_t>& bytes, const ImportOptions& options = {})
{
    std::istringstream in(std::string(bytes.begin(), bytes.end()), std::ios::binary);
    return readMtb(in, "synthetic.mtb", options, bytes.size());
}

bool anyWarningContains(const ImportResult& result, const QString& text)
{
    for (const std::string& warning : result.recording.warnings)
        if (QString::fromStdString(warning).contains(text))
            return true;
    return false;
}

QString allWarnings(const ImportResult& result)
{
    QStringList list;
    for (const std::string& warning : result.recording.warnings)
        list << QString::fromStdString(warning);
    return list.join(" | ");
}

QString errorText(const ImportResult& result)
{
    return result.error ? QString::fromStdString(result.error->text()) : QString();
}

/// A standard log: Configuration, EMTS, then `count` MTData2 at 100 Hz, the packet at `lost` missing.
MtbBuilder standardLog(std::size_t count, std::size_t lost = SIZE_MAX)
{
    MtbBuilder log;
    log.configuration();
    log.emts();
    for (std::size_t k = 0; k < count; ++k) {
        MtData2Sample s = imuSample(k);
        s.packetCounter = static_cast<std::uint16_t>(k);
        s.sampleTimeFine = static_cast<std::uint32_t>(5000 + 100 * k);
        if (k != lost)
            log.mtData2(s);
    }
    return log;
}

}  // namespace

class TestMtbReader : public QObject {
    Q_OBJECT
private slots:
    void timeBaseFollowsTheDeviceClock_data()
    {
        QTest::addColumn<bool>("sampleTimeFine");
        QTest::addColumn<bool>("legacy");
        QTest::addColumn<int>("period");         // legacy ticks of 1/115200 s in the Configuration
        QTest::addColumn<double>("optionRate");  // 0: none given
        QTest::addColumn<double>("rate");        // expected info.rate_hz
        QTest::addColumn<QString>("timeSource");
        QTest::newRow("SampleTimeFine wrapping at 2^32") << true << false << 1152 << 0.0 << 100.0
                                                         << "SampleTimeFine (10 kHz)";
        QTest::newRow("SampleTimeFine at 400 Hz") << true << false << 288 << 0.0 << 400.0 << "SampleTimeFine (10 kHz)";
        QTest::newRow("PacketCounter wrapping at 65536") << false << false << 1152 << 0.0 << 100.0
                                                         << "PacketCounter at 100 Hz";
        QTest::newRow("PacketCounter at the rate given") << false << false << 1152 << 200.0 << 200.0
                                                         << "PacketCounter at 200 Hz";
        QTest::newRow("legacy sample counter") << false << true << 576 << 0.0 << 200.0 << "sample counter at 200 Hz";
    }
    void timeBaseFollowsTheDeviceClock()
    {
        QFETCH(bool, sampleTimeFine);
        QFETCH(bool, legacy);
        QFETCH(int, period);
        QFETCH(double, optionRate);
        QFETCH(double, rate);
        QFETCH(QString, timeSource);
        const LegacyDataLayout layout{LegacyOutputMode::Calibrated, LegacyOutputSettings::TimestampSampleCounter};
        const double deviceRate = 115200.0 / period;
        const auto ticksPerSample = static_cast<std::uint32_t>(10000.0 / deviceRate);
        const std::size_t count = 20;
        const std::size_t lost = 8;  // after both wraps
        MtbBuilder log;
        log.configuration(std::uint16_t(period), legacy ? layout : LegacyDataLayout{0, 0});
        log.emts();
        for (std::size_t k = 0; k < count; ++k) {
            MtData2Sample s = imuSample(k);
            s.packetCounter = static_cast<std::uint16_t>(65530 + k);  // wraps after k = 5
            if (sampleTimeFine)
                s.sampleTimeFine = static_cast<std::uint32_t>(4294967295u - 3 * ticksPerSample + k * ticksPerSample);
            if (k == lost)
                continue;
            if (legacy)
                log.legacy(s, layout);
            else
                log.mtData2(s);
        }
        ImportOptions options;
        options.rate_hz = optionRate;
        const ImportResult r = read(log.data, options);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        QCOMPARE(r.recording.samples.size(), count - 1);
        QCOMPARE(r.info.rate_hz, rate);
        QCOMPARE(QString::fromStdString(r.info.timeSource), timeSource);
        QCOMPARE(r.info.format, std::string("xsens-mtb"));
        QCOMPARE(r.info.accUnitAsRead, AccUnit::MetresPerSecond2);
        QCOMPARE(r.info.gyrUnitAsRead, GyrUnit::RadiansPerSecond);
        QVERIFY(!r.info.truncated);
        const double period_s = 1.0 / (sampleTimeFine ? deviceRate : rate);
        for (std::size_t i = 0; i < r.recording.samples.size(); ++i) {
            const std::size_t k = i < lost ? i : i + 1;  // the time base keeps the lost packet's slot
            QCOMPARE(r.recording.samples[i].time_s, double(k) * period_s);
            QCOMPARE(r.recording.samples[i].acc_mps2, *imuSample(k).acceleration);
            QCOMPARE(r.recording.samples[i].gyr_radps, *imuSample(k).rateOfTurn);
        }
    }

    void magAndPressureAreHeldBetweenUpdates()
    {
        MtbBuilder log;
        log.configuration();
        for (std::size_t k = 0; k < 8; ++k) {
            MtData2Sample s = imuSample(k);
            s.sampleTimeFine = static_cast<std::uint32_t>(100 * k);
            if (k % 2 == 0)
                s.magneticField = Eigen::Vector3d(0.5, -0.25, double(k));
            if (k % 4 == 0)
                s.pressure_pa = 100000.0 + double(k);
            log.mtData2(s);
        }
        const ImportResult r = read(log.data);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        QCOMPARE(r.recording.samples.size(), std::size_t(8));
        QCOMPARE(r.recording.samples[3].mag, Eigen::Vector3d(0.5, -0.25, 2.0));
        QCOMPARE(r.recording.samples[7].pressure_pa, 100004.0);
        QCOMPARE(r.recording.samples[4].pressure_pa, 100004.0);
        QCOMPARE(r.info.channels, (std::vector<std::string>{"acc", "gyr", "mag", "pressure"}));
        QVERIFY2(r.recording.warnings.empty(), qPrintable(allWarnings(r)));
    }

    void messagesWithoutAccOrGyrAreSkippedWithOneWarning()
    {
        MtbBuilder log = standardLog(6);
        std::size_t firstSkipped = 0;
        for (int k = 0; k < 3; ++k) {
            MtData2Sample orientationOnly;
            orientationOnly.quaternion = Eigen::Quaterniond(1, 0, 0, 0);
            orientationOnly.sampleTimeFine = 99999u + std::uint32_t(k);
            if (k == 0)
                firstSkipped = log.data.size();
            log.mtData2(orientationOnly);
        }
        const ImportResult r = read(log.data);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        QCOMPARE(r.recording.samples.size(), std::size_t(6));
        QCOMPARE(r.recording.warnings.size(), std::size_t(1));
        QVERIFY2(anyWarningContains(r, QString("skipped 3 data message(s) without both acceleration and rate of turn "
                                               "(first at byte offset %1)").arg(firstSkipped)),
                 qPrintable(allWarnings(r)));
    }

    void fileCutInsideAFrameKeepsWhatCameBefore()
    {
        MtbBuilder log = standardLog(10);
        const std::size_t eighth = log.frameOffsets[2 + 7];
        std::vector<std::uint8_t> cut(log.data.begin(), log.data.begin() + std::ptrdiff_t(eighth + 20));
        const ImportResult r = read(cut);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        QCOMPARE(r.recording.samples.size(), std::size_t(7));
        QVERIFY(r.info.truncated);
        QVERIFY2(anyWarningContains(r, QString("the file ends inside a message that starts at byte offset %1 (20 bytes "
                                               "not decoded)").arg(eighth)),
                 qPrintable(allWarnings(r)));
        QCOMPARE(r.recording.samples.back().time_s, 0.06);
    }

    void junkInTheMiddleIsSkippedWithAWarning()
    {
        MtbBuilder log = standardLog(4);
        const std::size_t junkAt = log.data.size();
        log.raw({0x00, 0x13, 0xFA, 0x44, 0x10, 0xFA, 0xFF, 0x36, 0x05, 0x01, 0x02, 0x37});  // holds two false preambles
        for (std::size_t k = 4; k < 10; ++k) {
            MtData2Sample s = imuSample(k);
            s.sampleTimeFine = static_cast<std::uint32_t>(5000 + 100 * k);
            log.mtData2(s);
        }
        const ImportResult r = read(log.data);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        QCOMPARE(r.recording.samples.size(), std::size_t(10));
        QVERIFY(!r.info.truncated);  // nothing after the junk was lost
        QVERIFY2(anyWarningContains(r, QString("skipped 12 damaged byte(s) that form no valid Xbus message, at byte "
                                               "offset %1 (12 bytes)").arg(junkAt)),
                 qPrintable(allWarnings(r)));
    }

    void damagedFrameLeavesAGapInTime()
    {
        MtbBuilder log = standardLog(10);
        const std::size_t fifth = log.frameOffsets[2 + 4];
        log.data[fifth + 20] ^= 0x01;  // one bit in the acceleration of packet 4
        const ImportResult r = read(log.data);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        QCOMPARE(r.recording.samples.size(), std::size_t(9));
        QCOMPARE(r.recording.samples[3].time_s, 0.03);
        QCOMPARE(r.recording.samples[4].time_s, 0.05);  // packet 4 is lost, its slot stays
        QVERIFY2(anyWarningContains(r, QString("at byte offset %1 (").arg(fifth)), qPrintable(allWarnings(r)));
        QVERIFY2(anyWarningContains(r, "1 checksum failure(s)"), qPrintable(allWarnings(r)));
    }

    void rateIsEstimatedWithoutConfiguration()
    {
        MtbBuilder log;
        for (std::size_t k = 0; k < 50; ++k) {
            MtData2Sample s = imuSample(k);
            s.sampleTimeFine = static_cast<std::uint32_t>(25 * k);
            if (k != 10 && k != 11)
                log.mtData2(s);
        }
        const ImportResult r = read(log.data);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        QCOMPARE(r.info.rate_hz, 400.0);
        QCOMPARE(r.recording.samples[10].time_s, 0.03);
    }

    void configurationContradictedBySampleTimeFineIsNotTrusted()
    {
        MtbBuilder log;
        log.configuration(1152);  // states 100 Hz
        for (std::size_t k = 0; k < 50; ++k) {
            MtData2Sample s = imuSample(k);
            s.sampleTimeFine = static_cast<std::uint32_t>(25 * k);  // but the clock says 400 Hz
            log.mtData2(s);
        }
        const ImportResult r = read(log.data);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        QCOMPARE(r.info.rate_hz, 400.0);
        QVERIFY2(anyWarningContains(r, "states 100 Hz but SampleTimeFine steps give 400 Hz"), qPrintable(allWarnings(r)));
    }

    void clockJumpingBackIsWarned()
    {
        MtbBuilder log = standardLog(5);  // SampleTimeFine 5000..5400
        const std::size_t restartAt = log.data.size();
        for (std::size_t k = 0; k < 3; ++k) {  // the device restarted: its clock begins anew
            MtData2Sample s = imuSample(k);
            s.sampleTimeFine = static_cast<std::uint32_t>(100 * k);
            log.mtData2(s);
        }
        const ImportResult r = read(log.data);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        QCOMPARE(r.recording.samples.size(), std::size_t(8));
        QVERIFY(r.recording.samples[5].time_s > r.recording.samples[4].time_s);
        QVERIFY2(anyWarningContains(r, QString("the time stamp jumps back in 1 data message(s) (first at byte offset %1")
                                           .arg(restartAt)),
                 qPrintable(allWarnings(r)));
    }

    void counterWithoutAnyRateIsAnError()
    {
        MtbBuilder log;
        for (std::size_t k = 0; k < 5; ++k) {
            MtData2Sample s = imuSample(k);
            s.packetCounter = static_cast<std::uint16_t>(k);
            log.mtData2(s);
        }
        const ImportResult r = read(log.data);
        QVERIFY(!r.ok());
        QVERIFY2(errorText(r).contains("states no rate: give the sample rate"), qPrintable(errorText(r)));
    }

    void unreadableFilesGiveAClearError_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("expected");
        QTest::newRow("empty") << QByteArray() << "synthetic.mtb: the file is empty: expected an Xsens .mtb log";
        std::mt19937 random(11);
        QByteArray noise(100000, '\0');
        for (char& byte : noise)
            byte = static_cast<char>(random() & 0xFF);
        noise[0] = char(0xFA);
        QTest::newRow("random bytes") << noise << "(stopped at byte offset 100000)";
        QTest::newRow("text") << QByteArray("time_s,acc_x\n0,1\n") << "no valid Xbus message in 17 bytes";
        MtbBuilder header;
        header.configuration();
        header.emts();
        QTest::newRow("Configuration and EMTS only")
            << QByteArray(reinterpret_cast<const char*>(header.data.data()), int(header.data.size()))
            << QString("no data message among the Xbus messages found (MID 0x0D x1, 0x91 x1): expected MTData2 (0x36) "
                       "or legacy MTData (0x32) with acceleration and rate of turn (stopped at byte offset %1)")
                   .arg(header.data.size());
        MtbBuilder orientation;
        orientation.configuration();
        MtData2Sample q;
        q.quaternion = Eigen::Quaterniond(1, 0, 0, 0);
        orientation.mtData2(q);
        QTest::newRow("orientation only")
            << QByteArray(reinterpret_cast<const char*>(orientation.data.data()), int(orientation.data.size()))
            << QString("none of the 1 data message(s) carries both acceleration and rate of turn (first at byte offset %1)")
                   .arg(orientation.frameOffsets[1]);
        MtbBuilder legacy;
        legacy.legacy(imuSample(0), {LegacyOutputMode::Calibrated, 0});
        QTest::newRow("legacy without Configuration")
            << QByteArray(reinterpret_cast<const char*>(legacy.data.data()), int(legacy.data.size()))
            << "no Configuration message before it describes its layout";
    }
    void unreadableFilesGiveAClearError()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, expected);
        const std::vector<std::uint8_t> bytes(content.begin(), content.end());
        const ImportResult r = read(bytes);
        QVERIFY(!r.ok());
        QCOMPARE(r.error->file, std::string("synthetic.mtb"));
        QCOMPARE(r.error->line, std::size_t(0));
        QVERIFY2(errorText(r).contains(expected), qPrintable(errorText(r)));
        QVERIFY(r.recording.samples.empty());
    }

    void progressIsReportedAndCancelStops()
    {
        const MtbBuilder log = standardLog(5000);  // about 4 chunks
        std::vector<double> fractions;
        ImportOptions options;
        options.progress = [&](double fraction) {
            fractions.push_back(fraction);
            return true;
        };
        const ImportResult r = read(log.data, options);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        QCOMPARE(r.recording.samples.size(), std::size_t(5000));
        QVERIFY(fractions.size() >= 3);
        QVERIFY(std::is_sorted(fractions.begin(), fractions.end()));
        QCOMPARE(fractions.back(), 1.0);

        options.progress = [](double) { return false; };
        const ImportResult cancelled = read(log.data, options);
        QVERIFY(!cancelled.ok());
        QCOMPARE(cancelled.error->message, std::string("reading cancelled"));
    }

    void realMti3Log()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const std::string path = datasetPath("xsens-mtb/logfile.mtb").toStdString();
        std::ifstream in(path, std::ios::binary);
        QVERIFY2(in, path.c_str());
        const ImportResult r = readMtb(in, path, {}, 142356);
        QVERIFY2(r.ok(), qPrintable(errorText(r)));
        // Checked by hand (xxd + a python3 struct.unpack walk over every frame): the file is a
        // Configuration (FA FF 0D 76: device 0388044D = MTi-3, period 0x0480 = 1152 -> 100 Hz,
        // "20240620" "16343200"), an EMTS blob (FA FF 91 FF 05 28, 1320 bytes) and 2998 MTData2
        // frames of 42 bytes from offset 0x5AA, each 1020 PacketCounter, 1060 SampleTimeFine,
        // 4020 Acceleration and 8020 RateOfTurn in float32; the counter runs 0..2997 without a
        // gap and SampleTimeFine 24320528..24620228 in steps of exactly 100. The first packet
        // (offset 0x5AA) is near zero; the second (offset 0x5D9) is the first real one.
        QCOMPARE(r.recording.samples.size(), std::size_t(2998));
        QCOMPARE(r.info.rate_hz, 100.0);
        QCOMPARE(QString::fromStdString(r.info.timeSource), QString("SampleTimeFine (10 kHz)"));
        QCOMPARE(r.info.channels, (std::vector<std::string>{"acc", "gyr"}));
        QVERIFY(!r.info.truncated);
        QVERIFY2(r.recording.warnings.empty(), qPrintable(allWarnings(r)));
        const std::vector<ImuSample>& s = r.recording.samples;
        QCOMPARE(s[1].time_s, 0.01);
        QVERIFY(std::abs(s.back().time_s - 29.97) < 1e-9);
        QVERIFY(s[0].acc_mps2.norm() < 1e-4);
        auto near = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).norm() < 1e-6; };
        QVERIFY(near(s[1].acc_mps2, Eigen::Vector3d(0.737795115, -0.129801065, 10.5650043)));
        QVERIFY(near(s[1].gyr_radps, Eigen::Vector3d(0.000916235149, -0.0117942691, -0.0111211101)));
        QVERIFY(near(s[2].acc_mps2, Eigen::Vector3d(0.731548011, -0.139269173, 10.6036615)));
        QVERIFY(near(s.back().acc_mps2, Eigen::Vector3d(0.729671776, -0.148282602, 10.5859871)));
        QVERIFY(near(s.back().gyr_radps, Eigen::Vector3d(0.0023977831, -0.0102825481, -0.00794828031)));
        QVERIFY(!s[1].hasMag());
        QVERIFY(!s[1].hasPressure());
    }
};

QTEST_APPLESS_MAIN(TestMtbReader)
#include "tst_mtbreader.moc"
