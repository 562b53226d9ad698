// Import of MT Manager text exports (core/io/XsensTextReader.h): metadata variants, delimiters,
// counter wraps, lost packets, empty cells, ignored columns (FreeAcc), a file cut in the middle of a
// line, the errors a user sees (file:line:column: message), format detection, and every real IPOL
// MTw export in ../shared/datasets/xsens-mtw-ipol.

#include "io/LineReader.h"
#include "io/XsensTextReader.h"

#include "TestData.h"

#include <QtTest>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using footpath::AccUnit;
using footpath::GyrUnit;
using footpath::ImportOptions;
using footpath::ImportResult;

namespace {

const char* const kSource = "walk.txt";
const QByteArray kImuHeader = "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n";

/// One complete tab-separated row after kImuHeader.
QByteArray imuRow(qint64 counter)
{
    return QByteArray::number(counter) + "\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n";
}

QByteArray imuRows(std::initializer_list<qint64> counters)
{
    QByteArray rows;
    for (qint64 counter : counters)
        rows += imuRow(counter);
    return rows;
}

ImportResult read(const QByteArray& text, const ImportOptions& options = {})
{
    std::istringstream in(text.toStdString());
    return footpath::readXsensText(in, kSource, options, static_cast<std::size_t>(text.size()));
}

ImportResult readWithRate(const QByteArray& text, double rate_hz)
{
    ImportOptions options;
    options.rate_hz = rate_hz;
    return read(text, options);
}

QString errorText(const ImportResult& result)
{
    return result.error ? QString::fromStdString(result.error->text()) : QStringLiteral("<no error>");
}

QStringList warningsOf(const ImportResult& result)
{
    QStringList list;
    for (const std::string& warning : result.recording.warnings)
        list << QString::fromStdString(warning);
    return list;
}

QList<double> timesOf(const ImportResult& result)
{
    QList<double> times;
    for (const footpath::ImuSample& sample : result.recording.samples)
        times << sample.time_s;
    return times;
}

/// Times compared to 1e-12 s: exact enough to tell one tick of SampleTimeFine (1e-4 s) apart.
bool sameTimes(const QList<double>& actual, const QList<double>& expected)
{
    if (actual.size() != expected.size())
        return false;
    for (qsizetype i = 0; i < actual.size(); ++i)
        if (std::abs(actual[i] - expected[i]) > 1e-12)
            return false;
    return true;
}

QByteArray describe(const QList<double>& times)
{
    QByteArray out;
    for (double time : times)
        out += QByteArray::number(time, 'g', 15) + " ";
    return out;
}

/// Lost packets as the times show them: intervals longer than 1.5 periods, the samples missing in
/// them, and the longest one with the time it starts.
struct TimeGaps {
    int count = 0;
    int missing = 0;
    double longest_s = 0.0;
    double longestAt_s = 0.0;
};

TimeGaps gapsOf(const ImportResult& result, double period_s)
{
    TimeGaps gaps;
    const std::vector<footpath::ImuSample>& samples = result.recording.samples;
    for (std::size_t i = 1; i < samples.size(); ++i) {
        const double interval_s = samples[i].time_s - samples[i - 1].time_s;
        if (interval_s <= 1.5 * period_s)
            continue;
        ++gaps.count;
        gaps.missing += int(std::lround(interval_s / period_s)) - 1;
        if (interval_s > gaps.longest_s) {
            gaps.longest_s = interval_s;
            gaps.longestAt_s = samples[i - 1].time_s;
        }
    }
    return gaps;
}

bool equals(const Eigen::Vector3d& actual, double x, double y, double z)
{
    return actual.x() == x && actual.y() == y && actual.z() == z;
}

QByteArray describe(const Eigen::Vector3d& v)
{
    return QByteArray::number(v.x(), 'g', 17) + ", " + QByteArray::number(v.y(), 'g', 17) + ", "
           + QByteArray::number(v.z(), 'g', 17);
}

#define VERIFY_OK(result) QVERIFY2((result).ok(), qPrintable(errorText(result)))
#define VERIFY_TIMES(result, ...) \
    QVERIFY2(sameTimes(timesOf(result), QList<double>{__VA_ARGS__}), describe(timesOf(result)).constData())
#define VERIFY_VECTOR(actual, x, y, z) QVERIFY2(equals((actual), (x), (y), (z)), describe(actual).constData())

ImportResult readDatasetFile(const QString& path)
{
    std::ifstream in(path.toStdString(), std::ios::binary | std::ios::ate);
    const auto size = static_cast<std::size_t>(std::max<std::streamoff>(0, in.tellg()));
    in.seekg(0);
    return footpath::readXsensText(in, QFileInfo(path).fileName().toStdString(), {}, size);
}

}  // namespace

class TestXsensTextReader : public QObject {
    Q_OBJECT

private slots:
    void rateAndTimeSource_data();
    void rateAndTimeSource();
    void delimitersAndLineEnds_data();
    void delimitersAndLineEnds();
    void packetCounterWrapsAt65536();
    void sampleTimeFineWrapsAt2To32();
    void lostPacketsShowAsGapsInTime_data();
    void lostPacketsShowAsGapsInTime();
    void emptyCellsSkipRowsOrRepeatValues();
    void pressureIsConvertedToPascal_data();
    void pressureIsConvertedToPascal();
    void freeAccelerationIsNeverTakenAsAcc();
    void repeatedPacketIsSkipped();
    void truncatedLastLine_data();
    void truncatedLastLine();
    void errors_data();
    void errors();
    void progressReportsAndCancels();
    void looksLikeXsensText_data();
    void looksLikeXsensText();
    void realIpolExports_data();
    void realIpolExports();
    void realIpolExportValuesAndLongestGap();
};

void TestXsensTextReader::rateAndTimeSource_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<double>("rateOverride");
    QTest::addColumn<double>("expectedRate");
    QTest::addColumn<QString>("expectedTimeSource");
    QTest::addColumn<double>("expectedSecondTime");
    QTest::addColumn<int>("expectedWarnings");

    const QByteArray classic = "// Start Time: Unknown\n// Update Rate: 100.0Hz\n// Filter Profile: human (46.1)\n"
                               "// Option Flags: AHS Disabled ICC Disabled\n// Firmware Version: 4.0.2\n";
    QTest::newRow("classic // block, Update Rate: 100.0Hz")
        << classic + kImuHeader + imuRows({0, 1}) << 0.0 << 100.0 << "PacketCounter at 100 Hz" << 0.01 << 0;
    const QByteArray newStyle = "// General information:\n//  MT Manager version: 2022.2.0\n"
                                "//  XDA version: 2022.2.0 build 1234 rev 1\n// Device information:\n"
                                "//  DeviceId: 00B4D6D1\n//  ProductCode: MTW2-3A7G6\n//  Firmware Version: 4.6.0\n"
                                "// Device settings:\n//  Filter Profile: human(46.1)\n//  Option Flags: none\n"
                                "//  Update Rate: 60.0Hz\n// Coordinate system: ENU\n";
    QTest::newRow("2022 block, two-space keys, 60 Hz")
        << newStyle + kImuHeader + imuRows({0, 1}) << 0.0 << 60.0 << "PacketCounter at 60 Hz" << 1.0 / 60.0 << 0;
    QTest::newRow("IPOL first line: Acquisition frequency: 100 Hz")
        << "Acquisition frequency: 100 Hz\n" + kImuHeader + imuRows({0, 1}) << 0.0 << 100.0
        << "PacketCounter at 100 Hz" << 0.01 << 0;
    QTest::newRow("MTw manual's Counter column, rate given")
        << QByteArray("Counter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n") + imuRows({0, 1}) << 25.0 << 25.0
        << "PacketCounter at 25 Hz" << 0.04 << 0;
    QTest::newRow("override beats the stated rate, with a warning")
        << "// Update Rate: 100.0Hz\n" + kImuHeader + imuRows({0, 1}) << 50.0 << 50.0 << "PacketCounter at 50 Hz"
        << 0.02 << 1;
    QTest::newRow("unreadable stated rate warns; the override is used")
        << "// Update Rate: Unknown\n" + kImuHeader + imuRows({0, 1}) << 100.0 << 100.0 << "PacketCounter at 100 Hz"
        << 0.01 << 1;

    const QByteArray fineHeader = "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n";
    const QByteArray fineRows100 = "7\t1000000\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                                   "8\t1000100\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                                   "9\t1000200\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n";
    QTest::newRow("no stated rate: 100 Hz from SampleTimeFine steps")
        << fineHeader + fineRows100 << 0.0 << 100.0 << "SampleTimeFine (10 kHz)" << 0.01 << 0;
    QTest::newRow("stated rate is nominal only: time still from SampleTimeFine")
        << "// Update Rate: 200.0Hz\n" + fineHeader + fineRows100 << 0.0 << 200.0 << "SampleTimeFine (10 kHz)" << 0.01
        << 0;
    QTest::newRow("SampleTimeFine only, 400 Hz from its steps")
        << QByteArray("SampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                      "500\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n525\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                      "550\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n")
        << 0.0 << 400.0 << "SampleTimeFine (10 kHz)" << 0.0025 << 0;
}

void TestXsensTextReader::rateAndTimeSource()
{
    QFETCH(QByteArray, text);
    QFETCH(double, rateOverride);
    QFETCH(double, expectedRate);
    QFETCH(QString, expectedTimeSource);
    QFETCH(double, expectedSecondTime);
    QFETCH(int, expectedWarnings);

    const ImportResult result = readWithRate(text, rateOverride);
    VERIFY_OK(result);
    QCOMPARE(result.info.format, std::string("xsens-text"));
    QCOMPARE(result.info.rate_hz, expectedRate);
    QCOMPARE(QString::fromStdString(result.info.timeSource), expectedTimeSource);
    QVERIFY(result.recording.samples.size() >= 2);
    QCOMPARE(result.recording.samples[0].time_s, 0.0);
    QVERIFY2(std::abs(result.recording.samples[1].time_s - expectedSecondTime) < 1e-12,
             QByteArray::number(result.recording.samples[1].time_s, 'g', 17).constData());
    QCOMPARE(int(result.recording.warnings.size()), expectedWarnings);
    QCOMPARE(result.info.accUnitAsRead, AccUnit::MetresPerSecond2);
    QCOMPARE(result.info.gyrUnitAsRead, GyrUnit::RadiansPerSecond);
}

void TestXsensTextReader::delimitersAndLineEnds_data()
{
    QTest::addColumn<QByteArray>("text");

    QTest::newRow("tab .txt") << QByteArray("// Update Rate: 100.0Hz\n"
                                            "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z\n"
                                            "03583\t1.5\t-2.25\t9.75\t0.125\t-0.5\t2\t0.25\t-0.75\t1\n");
    QTest::newRow("comma .csv") << QByteArray("// Update Rate: 100.0Hz\n"
                                              "PacketCounter,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Mag_X,Mag_Y,Mag_Z\n"
                                              "3583,1.5,-2.25,9.75,0.125,-0.5,2,0.25,-0.75,1\n");
    QTest::newRow("quoted .csv header") << QByteArray("// Update Rate: 100.0Hz\n"
                                                      "\"PacketCounter\",\"Acc_X\",\"Acc_Y\",\"Acc_Z\",\"Gyr_X\",\"Gyr_Y\","
                                                      "\"Gyr_Z\",\"Mag_X\",\"Mag_Y\",\"Mag_Z\"\n"
                                                      "3583,1.5,-2.25,9.75,0.125,-0.5,2,0.25,-0.75,1\n");
    QTest::newRow("semicolon, decimal comma") << QByteArray("// Update Rate: 100.0Hz\n"
                                                            "PacketCounter;Acc_X;Acc_Y;Acc_Z;Gyr_X;Gyr_Y;Gyr_Z;Mag_X;Mag_Y;Mag_Z\n"
                                                            "3583;1,5;-2,25;9,75;0,125;-0,5;2;0,25;-0,75;1\n");
    QTest::newRow("CRLF, trailing tab, BOM") << QByteArray("\xEF\xBB\xBF// Update Rate: 100.0Hz\r\n"
                                                           "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z\t\r\n"
                                                           "3583\t1.5\t-2.25\t9.75\t0.125\t-0.5\t2\t0.25\t-0.75\t1\t\r\n");
    QTest::newRow("blank lines and a comment among the rows")
        << QByteArray("// Update Rate: 100.0Hz\n\n"
                      "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z\n\n"
                      "// a note\n3583\t+1.5\t-2.25\t9.75\t0.125\t-0.5\t2\t0.25\t-0.75\t1\n\n");
}

void TestXsensTextReader::delimitersAndLineEnds()
{
    QFETCH(QByteArray, text);

    const ImportResult result = read(text);
    VERIFY_OK(result);
    QCOMPARE(result.recording.samples.size(), std::size_t(1));
    const footpath::ImuSample& sample = result.recording.samples.front();
    VERIFY_VECTOR(sample.acc_mps2, 1.5, -2.25, 9.75);
    VERIFY_VECTOR(sample.gyr_radps, 0.125, -0.5, 2.0);
    VERIFY_VECTOR(sample.mag, 0.25, -0.75, 1.0);
    QVERIFY(std::isnan(sample.pressure_pa));
    QCOMPARE(sample.time_s, 0.0);
    QVERIFY2(result.recording.warnings.empty(), qPrintable(warningsOf(result).join('\n')));
    QCOMPARE(result.info.channels, (std::vector<std::string>{"acc", "gyr", "mag"}));
}

void TestXsensTextReader::packetCounterWrapsAt65536()
{
    const ImportResult result = readWithRate(kImuHeader + imuRows({65534, 65535, 0, 1}), 100.0);
    VERIFY_OK(result);
    VERIFY_TIMES(result, 0.0, 0.01, 0.02, 0.03);
}

void TestXsensTextReader::sampleTimeFineWrapsAt2To32()
{
    // 2^32 - 100, then +100 ticks (wrapped to 0), +100, +100: 0.01 s apart throughout.
    const QByteArray text = "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                            "10\t4294967196\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                            "11\t0\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                            "12\t100\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                            "13\t200\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n";
    const ImportResult result = read(text);
    VERIFY_OK(result);
    VERIFY_TIMES(result, 0.0, 0.01, 0.02, 0.03);
    QCOMPARE(result.info.rate_hz, 100.0);
}

void TestXsensTextReader::lostPacketsShowAsGapsInTime_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<double>("rateOverride");
    QTest::addColumn<QList<double>>("expectedTimes");

    QTest::newRow("PacketCounter 0 1 2 5 6 8")
        << kImuHeader + imuRows({0, 1, 2, 5, 6, 8}) << 100.0 << QList<double>{0.0, 0.01, 0.02, 0.05, 0.06, 0.08};
    QTest::newRow("PacketCounter loses packets across its wrap")
        << kImuHeader + imuRows({65534, 1, 2}) << 100.0 << QList<double>{0.0, 0.03, 0.04};
    QTest::newRow("SampleTimeFine decides, not the counter")
        << QByteArray("PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                      "0\t100\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n1\t200\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                      "2\t300\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n3\t700\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                      "4\t800\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n")
        << 0.0 << QList<double>{0.0, 0.01, 0.02, 0.06, 0.07};
}

void TestXsensTextReader::lostPacketsShowAsGapsInTime()
{
    QFETCH(QByteArray, text);
    QFETCH(double, rateOverride);
    QFETCH(QList<double>, expectedTimes);

    const ImportResult result = readWithRate(text, rateOverride);
    VERIFY_OK(result);
    QVERIFY2(sameTimes(timesOf(result), expectedTimes), describe(timesOf(result)).constData());
    QCOMPARE(result.info.rate_hz, 100.0);
}

void TestXsensTextReader::emptyCellsSkipRowsOrRepeatValues()
{
    const QByteArray text = "// Update Rate: 100.0Hz\n"
                            "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z\tPressure\n"
                            "0\t1\t2\t3\t4\t5\t6\t\t\t\t\n"                  // line 3: no mag, no pressure yet
                            "1\t1\t2\t3\t4\t5\t6\t0.5\t0.25\t-1\t1013.25\n"  // line 4
                            "2\t1\t\t3\t4\t5\t6\t0.6\t0.3\t-1\t1013.5\n"     // line 5: no Acc_Y -> skipped
                            "3\t1\t2\t3\t4\t5\t6\t\t\t\t\n"                  // line 6: repeats mag and pressure
                            "4\t1\t2\t3\t4\t5\t\t0.6\t0.3\t-1\t\n"           // line 7: no Gyr_Z -> skipped
                            "5\t1\t2\t3\t4\t5\t6\t0.75\t0.5\t-1\t1013\n"    // line 8
                            "6\t1\t2\t3\t4\t5\t6\t\t\t\t\n";                 // line 9: repeats line 8's
    const ImportResult result = read(text);
    VERIFY_OK(result);
    const std::vector<footpath::ImuSample>& samples = result.recording.samples;
    QCOMPARE(samples.size(), std::size_t(5));
    VERIFY_TIMES(result, 0.0, 0.01, 0.03, 0.05, 0.06);  // the skipped rows are missing samples, not shifted ones
    QVERIFY(std::isnan(samples[0].mag.x()) && std::isnan(samples[0].mag.z()));
    QVERIFY(std::isnan(samples[0].pressure_pa));
    VERIFY_VECTOR(samples[1].mag, 0.5, 0.25, -1.0);
    QCOMPARE(samples[1].pressure_pa, 101325.0);
    // Line 5 was skipped, but its mag and pressure are the latest known values at line 6.
    VERIFY_VECTOR(samples[2].mag, 0.6, 0.3, -1.0);
    QCOMPARE(samples[2].pressure_pa, 101350.0);
    VERIFY_VECTOR(samples[3].mag, 0.75, 0.5, -1.0);
    QCOMPARE(samples[3].pressure_pa, 101300.0);
    VERIFY_VECTOR(samples[4].mag, 0.75, 0.5, -1.0);
    QCOMPARE(samples[4].pressure_pa, 101300.0);
    const QStringList warnings = warningsOf(result);
    QCOMPARE(warnings.size(), 1);
    QVERIFY2(warnings[0].contains("skipped 2 row(s)") && warnings[0].contains("line 5"), qPrintable(warnings[0]));
    QCOMPARE(result.info.channels, (std::vector<std::string>{"acc", "gyr", "mag", "pressure"}));
}

void TestXsensTextReader::pressureIsConvertedToPascal_data()
{
    QTest::addColumn<QByteArray>("cell");
    QTest::addColumn<double>("expectedPa");
    QTest::addColumn<bool>("expectWarning");

    QTest::newRow("hPa (mbar, the MTw manual's unit)") << QByteArray("1013.25") << 101325.0 << false;
    QTest::newRow("Pa (the MTData2 unit)") << QByteArray("101325") << 101325.0 << false;
    QTest::newRow("high altitude hPa") << QByteArray("700") << 70000.0 << false;
    QTest::newRow("implausible in both") << QByteArray("5000") << 5000.0 << true;
}

void TestXsensTextReader::pressureIsConvertedToPascal()
{
    QFETCH(QByteArray, cell);
    QFETCH(double, expectedPa);
    QFETCH(bool, expectWarning);

    const QByteArray text = "// Update Rate: 100.0Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tPressure\n"
                            "0\t1\t2\t3\t4\t5\t6\t" + cell + "\n";
    const ImportResult result = read(text);
    VERIFY_OK(result);
    QCOMPARE(result.recording.samples.front().pressure_pa, expectedPa);
    QCOMPARE(!result.recording.warnings.empty(), expectWarning);
}

void TestXsensTextReader::freeAccelerationIsNeverTakenAsAcc()
{
    const QByteArray text =
        "// Update Rate: 100.0Hz\n"
        "PacketCounter\tSampleTimeFine\tUTC_Nano\tUTC_Year\tQuat_q0\tQuat_q1\tQuat_q2\tQuat_q3\tRoll\tPitch\tYaw\t"
        "FreeAcc_X\tFreeAcc_Y\tFreeAcc_Z\tFreeAcc_E\tFreeAcc_N\tFreeAcc_U\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\t"
        "VelInc_X\tStatusWord\n"
        "0\t100\t\t\t1\t0\t0\t0\t10\t20\t30\t0.5\t0.6\t0.7\t-0.5\t-0.6\t-0.7\t1.25\t2.5\t9.75\t0.1\t0.2\t0.3\t0.01\t3\n";
    const ImportResult result = read(text);
    VERIFY_OK(result);
    QCOMPARE(result.recording.samples.size(), std::size_t(1));
    VERIFY_VECTOR(result.recording.samples.front().acc_mps2, 1.25, 2.5, 9.75);
    VERIFY_VECTOR(result.recording.samples.front().gyr_radps, 0.1, 0.2, 0.3);
    QVERIFY(!result.recording.hasMag());
}

void TestXsensTextReader::repeatedPacketIsSkipped()
{
    const ImportResult result = readWithRate(kImuHeader + imuRows({0, 1, 1, 2}), 100.0);
    VERIFY_OK(result);
    VERIFY_TIMES(result, 0.0, 0.01, 0.02);
    const QStringList warnings = warningsOf(result);
    QCOMPARE(warnings.size(), 1);
    QVERIFY2(warnings[0].contains("repeating") && warnings[0].contains("line 4"), qPrintable(warnings[0]));
}

void TestXsensTextReader::truncatedLastLine_data()
{
    QTest::addColumn<QByteArray>("lastLine");
    QTest::addColumn<bool>("expectTruncated");
    QTest::addColumn<int>("expectedSamples");

    QTest::newRow("cut after a delimiter") << QByteArray("3\t1\t2\t3\t4\t") << true << 3;
    QTest::newRow("cut inside the gyro cells") << QByteArray("3\t1\t2\t3\t4\t0.") << true << 3;
    QTest::newRow("cut after a minus sign") << QByteArray("3\t1\t2\t3\t4\t5\t6\t0.5\t0.5\t-") << true << 3;
    QTest::newRow("complete last line without newline") << QByteArray("3\t1\t2\t3\t4\t5\t6\t0.5\t0.5\t0.5") << false << 4;
}

void TestXsensTextReader::truncatedLastLine()
{
    QFETCH(QByteArray, lastLine);
    QFETCH(bool, expectTruncated);
    QFETCH(int, expectedSamples);

    const QByteArray text = "Acquisition frequency: 100 Hz\n"
                            "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z\n"
                            "0\t1\t2\t3\t4\t5\t6\t0.5\t0.5\t0.5\n1\t1\t2\t3\t4\t5\t6\t0.5\t0.5\t0.5\n"
                            "2\t1\t2\t3\t4\t5\t6\t0.5\t0.5\t0.5\n" + lastLine;
    const ImportResult result = read(text);
    VERIFY_OK(result);
    QCOMPARE(result.info.truncated, expectTruncated);
    QCOMPARE(int(result.recording.samples.size()), expectedSamples);
    const QStringList warnings = warningsOf(result);
    QCOMPARE(warnings.size(), expectTruncated ? 1 : 0);
    if (expectTruncated)
        QVERIFY2(warnings[0].contains("line 6"), qPrintable(warnings[0]));
}

void TestXsensTextReader::errors_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<double>("rateOverride");
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("fragment");

    const QByteArray rate = "// Update Rate: 100.0Hz\n";
    QTest::newRow("not a number") << rate + kImuHeader + imuRow(0) + "1\t0.1\tabc\t9.8\t0.01\t0.02\t0.03\n" << 0.0 << 4
                                  << 3 << "expected a number in column 'Acc_Y', got 'abc'";
    QTest::newRow("not a number in a semicolon file")
        << rate + "PacketCounter;Acc_X;Acc_Y;Acc_Z;Gyr_X;Gyr_Y;Gyr_Z\n0;1;2;3;4;5;6,5,5\n" << 0.0 << 3 << 7
        << "column 'Gyr_Z', got '6,5,5'";
    QTest::newRow("Gyr columns missing")
        << rate + "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tMag_X\n0\t1\t2\t3\t4\n" << 0.0 << 2 << 0
        << "missing column(s) Gyr_X, Gyr_Y, Gyr_Z; the column line has: PacketCounter, Acc_X, Acc_Y, Acc_Z, Mag_X";
    {
        // A column line of 104 names: the message lists its first 300 characters.
        QByteArray columns = "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z";
        QString listed = QStringLiteral("PacketCounter, Acc_X, Acc_Y, Acc_Z");
        for (int k = 0; k < 100; ++k) {
            const QString name = QStringLiteral("N%1").arg(k, 3, 10, QLatin1Char('0'));
            columns += "\t" + name.toLatin1();
            listed += QStringLiteral(", ") + name;
        }
        QTest::newRow("long column line cut in the message")
            << rate + columns + "\n0\t1\t2\t3\n" << 0.0 << 2 << 0
            << QStringLiteral("missing column(s) Gyr_X, Gyr_Y, Gyr_Z; the column line has: ") + listed.left(300)
                   + QStringLiteral(" ...");
    }
    QTest::newRow("FreeAcc without Acc")
        << rate + "PacketCounter\tFreeAcc_X\tFreeAcc_Y\tFreeAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n0\t1\t2\t3\t4\t5\t6\n" << 0.0 << 2
        << 0 << "missing column(s) Acc_X, Acc_Y, Acc_Z";
    QTest::newRow("no time column")
        << rate + "Acc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n1\t2\t3\t4\t5\t6\n" << 0.0 << 2 << 0
        << "no time column: expected PacketCounter or SampleTimeFine";
    QTest::newRow("column twice") << rate + "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tacc_x\n" << 0.0 << 2
                                  << 8 << "column 'acc_x' appears twice (first in column 2)";
    QTest::newRow("Xsens DOT export") << QByteArray("PacketCounter,SampleTimeFine,Euler_X,Euler_Y,Euler_Z,Acc_X\n") << 0.0
                                      << 1 << 3 << "Xsens DOT";
    QTest::newRow("PacketCounter goes back")
        << rate + kImuHeader + imuRows({100, 101, 50}) << 0.0 << 5 << 1
        << "PacketCounter goes back from 101 to 50, which a wrap at 65536 does not explain";
    QTest::newRow("SampleTimeFine goes back")
        << rate + "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "0\t5000\t1\t2\t3\t4\t5\t6\n1\t4900\t1\t2\t3\t4\t5\t6\n"
        << 0.0 << 4 << 2 << "SampleTimeFine goes back from 5000 to 4900";
    QTest::newRow("counter not a whole number") << rate + kImuHeader + imuRows({0}) + "1.5\t1\t2\t3\t4\t5\t6\n" << 0.0
                                                << 4 << 1 << "expected a whole non-negative count in column 'PacketCounter'";
    QTest::newRow("negative counter") << rate + kImuHeader + "-1\t1\t2\t3\t4\t5\t6\n" << 0.0 << 3 << 1
                                      << "whole non-negative count";
    QTest::newRow("column line but no rows") << rate + rate + kImuHeader << 0.0 << 3 << 0
                                             << "no data rows after this column line";
    QTest::newRow("no row has Acc and Gyr") << rate + kImuHeader + "0\t\t\t\t4\t5\t6\n1\t1\t2\t3\t\t\t\n" << 0.0 << 2 << 0
                                            << "none of the 2 data rows";
    QTest::newRow("empty file") << QByteArray() << 0.0 << 0 << 0 << "the file is empty";
    QTest::newRow("only blank lines") << QByteArray("\n\n  \n") << 0.0 << 0 << 0 << "the file is empty";
    QTest::newRow("metadata only") << rate + "// Filter Profile: human\n" << 0.0 << 0 << 0
                                   << "no column line after 2 metadata line(s)";
    QTest::newRow("counter without any rate") << kImuHeader + imuRows({0, 1}) << 0.0 << 0 << 0 << "give the sample rate";
    QTest::newRow("a line without end") << QByteArray(int(footpath::kMaxTextLineLength_bytes) + 1, 'x') << 0.0 << 1 << 0
                                        << "the line is longer than 1 MiB (1048576 bytes)";
    QTest::newRow("binary bytes") << QByteArray("\xFA\xFF\x36\x10\x20\x02\x00\x01\xFA\xFF\x0D", 11) << 0.0 << 1 << 0
                                  << "missing column(s) Acc_X";
}

void TestXsensTextReader::errors()
{
    QFETCH(QByteArray, text);
    QFETCH(double, rateOverride);
    QFETCH(int, line);
    QFETCH(int, column);
    QFETCH(QString, fragment);

    const ImportResult result = readWithRate(text, rateOverride);
    QVERIFY2(!result.ok(), "read without error");
    QCOMPARE(QString::fromStdString(result.error->file), QString::fromLatin1(kSource));
    QCOMPARE(int(result.error->line), line);
    QCOMPARE(int(result.error->column), column);
    QVERIFY2(errorText(result).contains(fragment), qPrintable(errorText(result)));
}

void TestXsensTextReader::progressReportsAndCancels()
{
    QByteArray text = "// Update Rate: 100.0Hz\n" + kImuHeader;
    for (qint64 counter = 0; counter < 5000; ++counter)
        text += imuRow(counter % 65536);

    QList<double> fractions;
    ImportOptions options;
    options.progress = [&fractions](double fraction) {
        fractions << fraction;
        return true;
    };
    const ImportResult whole = read(text, options);
    VERIFY_OK(whole);
    QCOMPARE(whole.recording.samples.size(), std::size_t(5000));
    QVERIFY2(fractions.size() >= 4, QByteArray::number(fractions.size()).constData());
    QVERIFY(std::is_sorted(fractions.begin(), fractions.end()));
    QVERIFY(fractions.front() > 0.0 && fractions.back() <= 1.0);

    options.progress = [](double) { return false; };
    const ImportResult cancelled = read(text, options);
    QVERIFY(!cancelled.ok());
    QCOMPARE(QString::fromStdString(cancelled.error->message), QStringLiteral("reading cancelled"));
}

void TestXsensTextReader::looksLikeXsensText_data()
{
    QTest::addColumn<QByteArray>("start");
    QTest::addColumn<bool>("expected");

    QTest::newRow("classic export") << QByteArray("// Start Time: Unknown\n// Update Rate: 100.0Hz\n"
                                                  "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\n0\t100\t1\t2\n")
                                    << true;
    QTest::newRow("IPOL export") << QByteArray("Acquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\n")
                                 << true;
    QTest::newRow("csv export with BOM") << QByteArray("\xEF\xBB\xBF// Update Rate: 100.0Hz\nSampleTimeFine,Acc_X\n")
                                         << true;
    QTest::newRow("column line cut by the kilobyte limit") << QByteArray("// Update Rate: 100.0Hz\nPacketCounter\tAcc")
                                                           << true;
    QTest::newRow("pyshoe csv") << QByteArray("t_s, acc_x_mps2, acc_y_mps2, acc_z_mps2, gyr_x_radps\n0.005,1,2,3,4\n")
                                << false;
    QTest::newRow("plain numbers") << QByteArray("\n123,0.1,0.2,9.8,0.01,0.02,0.03,101325\n") << false;
    QTest::newRow("Acc_X without a counter") << QByteArray("time_s,Acc_X,Acc_Y,Acc_Z\n0,1,2,3\n") << false;
    QTest::newRow("metadata only") << QByteArray("// Update Rate: 100.0Hz\n") << false;
    QTest::newRow("empty") << QByteArray() << false;
    QTest::newRow("mtb bytes") << QByteArray("\xFA\xFF\x0D\x76\x03\x70\x03\xF8\x04\x80", 10) << false;
}

void TestXsensTextReader::looksLikeXsensText()
{
    QFETCH(QByteArray, start);
    QFETCH(bool, expected);
    QCOMPARE(footpath::looksLikeXsensText(start.toStdString()), expected);
}

void TestXsensTextReader::realIpolExports_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("rows");
    QTest::addColumn<int>("firstCounter");
    QTest::addColumn<int>("lastCounter");
    QTest::addColumn<int>("gaps");
    QTest::addColumn<int>("missing");

    // Verified by hand with awk over each file (skipping its two header lines): rows = data lines,
    // first/last PacketCounter, gaps = counter steps greater than 1, missing = sum of (step - 1).
    // Every file: tab-separated, 10 cells a row, LF line ends, counters written as "N.0", no step
    // <= 0. rows + missing = last - first + 1 in each. Note 3-2_lf has no gap (it only starts at
    // counter 1) while 3-2_rf has 25; 12-3_lf also starts at 1.
    QTest::newRow("1-1 left") << "1-1_lf.txt" << 2913 << 0 << 2998 << 57 << 86;
    QTest::newRow("1-1 right") << "1-1_rf.txt" << 2913 << 0 << 3044 << 80 << 132;
    QTest::newRow("1-4 left") << "1-4_lf.txt" << 2849 << 0 << 2848 << 0 << 0;
    QTest::newRow("1-4 right") << "1-4_rf.txt" << 2849 << 0 << 2848 << 0 << 0;
    QTest::newRow("10-1 left") << "10-1_lf.txt" << 2389 << 0 << 2388 << 0 << 0;
    QTest::newRow("10-1 right") << "10-1_rf.txt" << 2389 << 0 << 2388 << 0 << 0;
    QTest::newRow("12-3 left") << "12-3_lf.txt" << 2471 << 1 << 3116 << 406 << 645;
    QTest::newRow("12-3 right") << "12-3_rf.txt" << 2733 << 0 << 3118 << 250 << 386;
    QTest::newRow("14-1 left") << "14-1_lf.txt" << 2363 << 0 << 2362 << 0 << 0;
    QTest::newRow("14-1 right") << "14-1_rf.txt" << 2363 << 0 << 2362 << 0 << 0;
    QTest::newRow("3-2 left") << "3-2_lf.txt" << 3147 << 1 << 3147 << 0 << 0;
    QTest::newRow("3-2 right") << "3-2_rf.txt" << 3147 << 0 << 3181 << 25 << 35;
}

void TestXsensTextReader::realIpolExports()
{
    FOOTPATH_REQUIRE_DATASETS();
    QFETCH(QString, file);
    QFETCH(int, rows);
    QFETCH(int, firstCounter);
    QFETCH(int, lastCounter);
    QFETCH(int, gaps);
    QFETCH(int, missing);

    const QString path = datasetPath(QStringLiteral("xsens-mtw-ipol/") + file);
    QVERIFY2(QFileInfo::exists(path), qPrintable(path));
    const ImportResult result = readDatasetFile(path);
    VERIFY_OK(result);
    QVERIFY2(result.recording.warnings.empty(), qPrintable(warningsOf(result).join('\n')));
    QVERIFY(!result.info.truncated);
    QCOMPARE(int(result.recording.samples.size()), rows);
    QCOMPARE(result.info.rate_hz, 100.0);
    QCOMPARE(result.info.timeSource, std::string("PacketCounter at 100 Hz"));
    QCOMPARE(result.info.channels, (std::vector<std::string>{"acc", "gyr", "mag"}));
    QVERIFY(result.recording.hasMag() && !result.recording.hasPressure());
    QCOMPARE(result.recording.samples.front().time_s, 0.0);
    const double expectedDuration = (lastCounter - firstCounter) / 100.0;
    QVERIFY2(std::abs(result.recording.duration_s() - expectedDuration) < 1e-9,
             QByteArray::number(result.recording.duration_s(), 'g', 12).constData());
    const TimeGaps timeGaps = gapsOf(result, 0.01);
    QCOMPARE(timeGaps.count, gaps);
    QCOMPARE(timeGaps.missing, missing);
}

void TestXsensTextReader::realIpolExportValuesAndLongestGap()
{
    FOOTPATH_REQUIRE_DATASETS();
    // 1-4_lf.txt line 3: "0.0  5.422423 2.263487 8.542407  -0.008992 0.014272 -0.012537  -0.594727 -0.093018 -0.336426".
    const ImportResult gapFree = readDatasetFile(datasetPath(QStringLiteral("xsens-mtw-ipol/1-4_lf.txt")));
    VERIFY_OK(gapFree);
    const footpath::ImuSample& first = gapFree.recording.samples.front();
    VERIFY_VECTOR(first.acc_mps2, 5.422423, 2.263487, 8.542407);
    VERIFY_VECTOR(first.gyr_radps, -0.008992, 0.014272, -0.012537);
    VERIFY_VECTOR(first.mag, -0.594727, -0.093018, -0.336426);

    // 1-1_lf.txt: the longest jump is from counter 2813 to 2820 (6 packets lost), found with awk.
    const ImportResult gapped = readDatasetFile(datasetPath(QStringLiteral("xsens-mtw-ipol/1-1_lf.txt")));
    VERIFY_OK(gapped);
    const TimeGaps gaps = gapsOf(gapped, 0.01);
    QVERIFY2(std::abs(gaps.longest_s - 0.07) < 1e-9, QByteArray::number(gaps.longest_s).constData());
    QVERIFY2(std::abs(gaps.longestAt_s - 28.13) < 1e-9, QByteArray::number(gaps.longestAt_s).constData());
}

QTEST_APPLESS_MAIN(TestXsensTextReader)

#include "tst_xsenstextreader.moc"
