// Import of delimited IMU text (core/io/DelimitedTextReader.h): header names and aliases, optional
// columns, reference columns, headerless files with a column map, delimiters, and the error
// messages a user sees (file:line:column: message).

#include "io/ColumnNames.h"
#include "io/DelimitedTextReader.h"
#include "io/Import.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using footpath::ImuSample;
using footpath::ReadError;
using footpath::ImportOptions;
using footpath::ImportResult;

namespace {

const char* const kSource = "walk.csv";

std::vector<std::string> toStd(const QStringList& list)
{
    std::vector<std::string> out;
    for (const QString& item : list)
        out.push_back(item.toStdString());
    return out;
}

ImportResult parse(const QByteArray& text, const ImportOptions& options = {})
{
    std::istringstream in(text.toStdString());
    return footpath::readDelimitedText(in, kSource, options, static_cast<std::size_t>(text.size()));
}

ImportResult parse(const QByteArray& text, const QStringList& columnMap, const QStringList& referenceColumns)
{
    ImportOptions options;
    options.columnMap = toStd(columnMap);
    options.referenceColumns = toStd(referenceColumns);
    return parse(text, options);
}

QString errorText(const ImportResult& result)
{
    return result.error ? QString::fromStdString(result.error->text()) : QStringLiteral("<no error>");
}

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& content)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size())
        return {};
    return path;
}

/// Exact comparison of a vector against three expected components.
bool equals(const Eigen::Vector3d& actual, double x, double y, double z)
{
    return actual.x() == x && actual.y() == y && actual.z() == z;
}

QByteArray describe(const Eigen::Vector3d& v)
{
    return QByteArray::number(v.x(), 'g', 17) + ", " + QByteArray::number(v.y(), 'g', 17) + ", "
           + QByteArray::number(v.z(), 'g', 17);
}

#define VERIFY_VECTOR(actual, x, y, z) \
    QVERIFY2(equals((actual), (x), (y), (z)), describe(actual).constData())

#define VERIFY_OK(result) QVERIFY2((result).ok(), qPrintable(errorText(result)))

const QByteArray kHeader = "time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";

}  // namespace

class TestDelimitedTextReader : public QObject {
    Q_OBJECT

private slots:
    void headerCsv_parsesEveryValueAndTheSampleCount_data();
    void headerCsv_parsesEveryValueAndTheSampleCount();
    void pyshoeNames_areAcceptedAndExtraColumnsAreIgnored();
    void optionalMagAndPressure_setHasMagAndHasPressure_data();
    void optionalMagAndPressure_setHasMagAndHasPressure();
    void referenceColumns_leadingMinusNegatesThatAxis_data();
    void referenceColumns_leadingMinusNegatesThatAxis();
    void headerlessFile_columnMapScalesTimeAndSkipsColumns_data();
    void headerlessFile_columnMapScalesTimeAndSkipsColumns();
    void headerlessFile_lineNumbersCountBlankLines();
    void errors_reportMessageLineAndColumn_data();
    void errors_reportMessageLineAndColumn();
    void missingFile_isReportedWithThePathAndNoLine();
    void readFromFile_sourceAndErrorsCarryThePath();
    void readErrorText_formatsFileLineColumnMessage_data();
    void readErrorText_formatsFileLineColumnMessage();
    void progress_returningFalseCancelsTheRead();
    void columnRoleNames_listsTheCanonicalRoles();
};

void TestDelimitedTextReader::headerCsv_parsesEveryValueAndTheSampleCount_data()
{
    QTest::addColumn<QByteArray>("text");

    QTest::newRow("comma") << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n"
                                         "0.00,0.1,-0.2,9.81,0.01,-0.02,0.03\n"
                                         "0.01,1.5,2.5,-3.5,4.5,5.5,6.5\n"
                                         "0.02,-1e-3,2E2,0,7,8,9\n");
    QTest::newRow("UTF-8 byte-order mark (spreadsheet export)")
        << QByteArray("\xEF\xBB\xBFtime_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n"
                      "0.00,0.1,-0.2,9.81,0.01,-0.02,0.03\n"
                      "0.01,1.5,2.5,-3.5,4.5,5.5,6.5\n"
                      "0.02,-1e-3,2E2,0,7,8,9\n");
    QTest::newRow("tab") << QByteArray("time_s\tacc_x\tacc_y\tacc_z\tgyr_x\tgyr_y\tgyr_z\n"
                                       "0.00\t0.1\t-0.2\t9.81\t0.01\t-0.02\t0.03\n"
                                       "0.01\t1.5\t2.5\t-3.5\t4.5\t5.5\t6.5\n"
                                       "0.02\t-1e-3\t2E2\t0\t7\t8\t9\n");
    QTest::newRow("semicolon") << QByteArray("time_s;acc_x;acc_y;acc_z;gyr_x;gyr_y;gyr_z\n"
                                             "0.00;0.1;-0.2;9.81;0.01;-0.02;0.03\n"
                                             "0.01;1.5;2.5;-3.5;4.5;5.5;6.5\n"
                                             "0.02;-1e-3;2E2;0;7;8;9\n");
    QTest::newRow("spaces, aligned") << QByteArray("time_s   acc_x  acc_y  acc_z  gyr_x  gyr_y  gyr_z\n"
                                                   "  0.00   0.1    -0.2   9.81   0.01   -0.02  0.03\n"
                                                   "  0.01   1.5    2.5    -3.5   4.5    5.5    6.5\n"
                                                   "  0.02   -1e-3  2E2    0      7      8      9\n");
    QTest::newRow("CRLF, quoted header, padded cells, blank line")
        << QByteArray("\"time_s\",\"acc_x\",\"acc_y\",\"acc_z\",\"gyr_x\",\"gyr_y\",\"gyr_z\"\r\n"
                      "0.00, 0.1, -0.2, 9.81, 0.01, -0.02, 0.03\r\n"
                      "0.01,1.5,2.5,-3.5,4.5,5.5,6.5\r\n"
                      "\r\n"
                      "0.02,-1e-3,2E2,0,7,8,9\r\n");
    QTest::newRow("columns in another order")
        << QByteArray("gyr_z,gyr_y,gyr_x,acc_z,acc_y,acc_x,time_s\n"
                      "0.03,-0.02,0.01,9.81,-0.2,0.1,0.00\n"
                      "6.5,5.5,4.5,-3.5,2.5,1.5,0.01\n"
                      "9,8,7,0,2E2,-1e-3,0.02\n");
    QTest::newRow("upper-case names") << QByteArray("TIME_S,ACC_X,ACC_Y,ACC_Z,GYR_X,GYR_Y,GYR_Z\n"
                                                    "0.00,0.1,-0.2,9.81,0.01,-0.02,0.03\n"
                                                    "0.01,1.5,2.5,-3.5,4.5,5.5,6.5\n"
                                                    "0.02,-1e-3,2E2,0,7,8,9\n");
}

void TestDelimitedTextReader::headerCsv_parsesEveryValueAndTheSampleCount()
{
    QFETCH(QByteArray, text);
    const ImportResult result = parse(text);
    VERIFY_OK(result);

    const std::vector<ImuSample>& s = result.recording.samples;
    QCOMPARE(s.size(), std::size_t(3));
    QCOMPARE(result.recording.source, std::string(kSource));

    QCOMPARE(s[0].time_s, 0.0);
    VERIFY_VECTOR(s[0].acc_mps2, 0.1, -0.2, 9.81);
    VERIFY_VECTOR(s[0].gyr_radps, 0.01, -0.02, 0.03);
    QCOMPARE(s[1].time_s, 0.01);
    VERIFY_VECTOR(s[1].acc_mps2, 1.5, 2.5, -3.5);
    VERIFY_VECTOR(s[1].gyr_radps, 4.5, 5.5, 6.5);
    QCOMPARE(s[2].time_s, 0.02);
    VERIFY_VECTOR(s[2].acc_mps2, -1e-3, 200.0, 0.0);
    VERIFY_VECTOR(s[2].gyr_radps, 7.0, 8.0, 9.0);

    // Nothing optional was in the file.
    QVERIFY(!result.recording.hasMag());
    QVERIFY(!result.recording.hasPressure());
    QVERIFY(!s[2].hasMag());
    QVERIFY(!s[2].hasPressure());
    QVERIFY(result.recording.reference.positions_m.empty());
    QCOMPARE(result.recording.duration_s(), 0.02);
}

void TestDelimitedTextReader::pyshoeNames_areAcceptedAndExtraColumnsAreIgnored()
{
    // pyshoe export names; "label" holds text and "vicon_x_m" a number, neither is an IMU role.
    const QByteArray text = "t_s,acc_x_mps2,acc_y_mps2,acc_z_mps2,gyr_x_radps,gyr_y_radps,gyr_z_radps,vicon_x_m,label\n"
                            "10.000,0.5,0.25,9.75,0.125,-0.5,1.5,123.0,walk\n"
                            "10.005,0.75,-0.25,9.5,0.25,0.5,-1.5,124.0,still running\n";
    const ImportResult result = parse(text);
    VERIFY_OK(result);
    const std::vector<ImuSample>& s = result.recording.samples;
    QCOMPARE(s.size(), std::size_t(2));
    QCOMPARE(s[0].time_s, 10.0);
    QCOMPARE(s[1].time_s, 10.005);
    VERIFY_VECTOR(s[0].acc_mps2, 0.5, 0.25, 9.75);
    VERIFY_VECTOR(s[0].gyr_radps, 0.125, -0.5, 1.5);
    VERIFY_VECTOR(s[1].acc_mps2, 0.75, -0.25, 9.5);
    VERIFY_VECTOR(s[1].gyr_radps, 0.25, 0.5, -1.5);
    // An extra column is not a reference unless it is named as one.
    QVERIFY(result.recording.reference.positions_m.empty());
}

void TestDelimitedTextReader::optionalMagAndPressure_setHasMagAndHasPressure_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<bool>("hasMag");
    QTest::addColumn<bool>("hasPressure");

    QTest::newRow("neither") << QByteArray(kHeader + "0,1,2,3,4,5,6\n0.01,1,2,3,4,5,6\n") << false << false;
    QTest::newRow("mag only") << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z\n"
                                            "0,1,2,3,4,5,6,20.5,-3.25,40\n0.01,1,2,3,4,5,6,21,-3,41\n")
                              << true << false;
    QTest::newRow("pressure only") << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,pressure_pa\n"
                                                 "0,1,2,3,4,5,6,101325\n0.01,1,2,3,4,5,6,101320.5\n")
                                   << false << true;
    QTest::newRow("both") << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z,pressure_pa\n"
                                        "0,1,2,3,4,5,6,20.5,-3.25,40,101325\n0.01,1,2,3,4,5,6,21,-3,41,101320.5\n")
                          << true << true;
    // A magnetometer needs all three axes; a lone mag_x (even with text in it) is ignored.
    QTest::newRow("incomplete mag is ignored") << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x\n"
                                                             "0,1,2,3,4,5,6,n/a\n0.01,1,2,3,4,5,6,n/a\n")
                                               << false << false;
}

void TestDelimitedTextReader::optionalMagAndPressure_setHasMagAndHasPressure()
{
    QFETCH(QByteArray, text);
    QFETCH(bool, hasMag);
    QFETCH(bool, hasPressure);

    const ImportResult result = parse(text);
    VERIFY_OK(result);
    const std::vector<ImuSample>& s = result.recording.samples;
    QCOMPARE(s.size(), std::size_t(2));
    QCOMPARE(result.recording.hasMag(), hasMag);
    QCOMPARE(result.recording.hasPressure(), hasPressure);
    for (const ImuSample& sample : s) {
        QCOMPARE(sample.hasMag(), hasMag);
        QCOMPARE(sample.hasPressure(), hasPressure);
        VERIFY_VECTOR(sample.acc_mps2, 1.0, 2.0, 3.0);
        VERIFY_VECTOR(sample.gyr_radps, 4.0, 5.0, 6.0);
    }
    if (hasMag) {
        VERIFY_VECTOR(s[0].mag, 20.5, -3.25, 40.0);
        VERIFY_VECTOR(s[1].mag, 21.0, -3.0, 41.0);
    } else {
        QVERIFY(std::isnan(s[0].mag.x()) && std::isnan(s[0].mag.y()) && std::isnan(s[0].mag.z()));
    }
    if (hasPressure) {
        QCOMPARE(s[0].pressure_pa, 101325.0);
        QCOMPARE(s[1].pressure_pa, 101320.5);
    } else {
        QVERIFY(std::isnan(s[1].pressure_pa));
    }
}

void TestDelimitedTextReader::referenceColumns_leadingMinusNegatesThatAxis_data()
{
    QTest::addColumn<QStringList>("referenceColumns");
    QTest::addColumn<double>("sx");
    QTest::addColumn<double>("sy");
    QTest::addColumn<double>("sz");

    // The file holds x=1.5, y=2.5, z=-0.5 in the first row and x=3, y=-4, z=0.25 in the second.
    QTest::newRow("none negated") << QStringList{"vicon_x_m", "vicon_y_m", "vicon_z_m"} << 1.0 << 1.0 << 1.0;
    QTest::newRow("pyshoe mirrored y") << QStringList{"vicon_x_m", "-vicon_y_m", "vicon_z_m"} << 1.0 << -1.0 << 1.0;
    QTest::newRow("x and z negated, padded") << QStringList{" -vicon_x_m", "vicon_y_m ", "-vicon_z_m"} << -1.0 << 1.0
                                             << -1.0;
}

void TestDelimitedTextReader::referenceColumns_leadingMinusNegatesThatAxis()
{
    QFETCH(QStringList, referenceColumns);
    QFETCH(double, sx);
    QFETCH(double, sy);
    QFETCH(double, sz);

    const QByteArray text = "t_s,vicon_z_m,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,vicon_x_m,vicon_y_m\n"
                            "0.0,-0.5,0.1,0.2,9.8,0.01,0.02,0.03,1.5,2.5\n"
                            "0.01,0.25,0.1,0.2,9.8,0.01,0.02,0.03,3,-4\n";
    const ImportResult result = parse(text, {}, referenceColumns);
    VERIFY_OK(result);
    const std::vector<Eigen::Vector3d>& reference = result.recording.reference.positions_m;
    QCOMPARE(result.recording.samples.size(), std::size_t(2));
    QCOMPARE(reference.size(), std::size_t(2));
    VERIFY_VECTOR(reference[0], sx * 1.5, sy * 2.5, sz * -0.5);
    VERIFY_VECTOR(reference[1], sx * 3.0, sy * -4.0, sz * 0.25);
    // The IMU columns are untouched by the reference mapping.
    VERIFY_VECTOR(result.recording.samples[1].acc_mps2, 0.1, 0.2, 9.8);
    VERIFY_VECTOR(result.recording.samples[1].gyr_radps, 0.01, 0.02, 0.03);
}

void TestDelimitedTextReader::headerlessFile_columnMapScalesTimeAndSkipsColumns_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QStringList>("columnMap");

    const QStringList msMap{"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "skip"};
    // Each file: 1500 ms then 1510 ms, with a last column that is not a number (skipped).
    QTest::newRow("comma, leading empty line") << QByteArray("\n1500,0.5,-1.5,9.75,0.25,-0.125,2,x\n"
                                                             "1510,1,2,3,4,5,6,ignored\n")
                                               << msMap;
    QTest::newRow("space runs, leading empty line")
        << QByteArray("   \n  1500   0.5  -1.5   9.75  0.25   -0.125 2     x\n"
                      "1510 1 2 3    4 5 6 ignored\n")
        << msMap;
    QTest::newRow("semicolon") << QByteArray("1500;0.5;-1.5;9.75;0.25;-0.125;2;x\n1510;1;2;3;4;5;6;ignored\n")
                               << msMap;
    QTest::newRow("tab") << QByteArray("1500\t0.5\t-1.5\t9.75\t0.25\t-0.125\t2\tx\n1510\t1\t2\t3\t4\t5\t6\tignored\n")
                         << msMap;
    QTest::newRow("roles are case- and space-insensitive")
        << QByteArray("1500,0.5,-1.5,9.75,0.25,-0.125,2,x\n1510,1,2,3,4,5,6,ignored\n")
        << QStringList{"TIME_MS", " acc_x", "acc_y ", "Acc_Z", "gyr_x", "gyr_y", "gyr_z", "SKIP"};
    QTest::newRow("time_us, skip first")
        << QByteArray("x,1500000,0.5,-1.5,9.75,0.25,-0.125,2\nignored,1510000,1,2,3,4,5,6\n")
        << QStringList{"skip", "time_us", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"};
}

void TestDelimitedTextReader::headerlessFile_columnMapScalesTimeAndSkipsColumns()
{
    QFETCH(QByteArray, text);
    QFETCH(QStringList, columnMap);

    const ImportResult result = parse(text, columnMap, {});
    VERIFY_OK(result);
    const std::vector<ImuSample>& s = result.recording.samples;
    // The first non-empty line is data, not a header.
    QCOMPARE(s.size(), std::size_t(2));
    QCOMPARE(s[0].time_s, 1.5);
    QCOMPARE(s[1].time_s, 1.51);
    VERIFY_VECTOR(s[0].acc_mps2, 0.5, -1.5, 9.75);
    VERIFY_VECTOR(s[0].gyr_radps, 0.25, -0.125, 2.0);
    VERIFY_VECTOR(s[1].acc_mps2, 1.0, 2.0, 3.0);
    VERIFY_VECTOR(s[1].gyr_radps, 4.0, 5.0, 6.0);
}

void TestDelimitedTextReader::headerlessFile_lineNumbersCountBlankLines()
{
    // Two blank lines, a good row on line 3, a bad cell on line 5 (after another blank line): with
    // half the rows damaged the file is refused, and the error names line 5.
    const QByteArray text = "\n\n0,1,2,3,4,5,6\n\n10,1,2,oops,4,5,6\n";
    const ImportResult result = parse(
        text, QStringList{"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"}, {});
    QVERIFY(!result.ok());
    QCOMPARE(result.error->line, std::size_t(5));
    QCOMPARE(result.error->column, std::size_t(4));
    QVERIFY(QString::fromStdString(result.error->message)
                .contains(QStringLiteral("expected a number in column 'acc_z', got 'oops'; 1 of 2 data rows")));
}

void TestDelimitedTextReader::errors_reportMessageLineAndColumn_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QStringList>("columnMap");
    QTest::addColumn<QStringList>("referenceColumns");
    QTest::addColumn<int>("line");  // -1: not checked
    QTest::addColumn<int>("column");
    QTest::addColumn<QStringList>("messageParts");

    const QStringList none;
    const QByteArray rows = "0.00,0,0,9.8,0,0,0\n0.01,0,0,9.8,0,0,0\n";

    QTest::newRow("missing column lists the header")
        << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,temperature\n0,0,0,9.8,0,0,20\n") << none << none << 1
        << 0
        << QStringList{"missing column", "gyr_z",
                       "the header has: time_s, acc_x, acc_y, acc_z, gyr_x, gyr_y, temperature"};
    {
        // A header of 100 names: the message lists the first 300 characters and the count.
        QByteArray header;
        QString listed;
        for (int k = 0; k < 100; ++k) {
            const QString name = QStringLiteral("n%1").arg(k, 3, 10, QLatin1Char('0'));
            header += (k == 0 ? "" : ",") + name.toLatin1();
            if (k < 50)
                listed += name + QStringLiteral(", ");
        }
        QTest::newRow("long header cut in the message")
            << header + "\n0\n" << none << none << 1 << 0
            << QStringList{"missing column", QStringLiteral("; the header has: ") + listed + QStringLiteral(" ... (100 columns)")};
    }
    QTest::newRow("missing time column")
        << QByteArray("acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n0,0,9.8,0,0,0\n") << none << none << 1 << 0
        << QStringList{"missing column", "time (or a counter, with the sample rate given)",
                       "the header has: acc_x, acc_y, acc_z, gyr_x, gyr_y, gyr_z"};
    QTest::newRow("two time columns") << QByteArray("time_s,time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n"
                                                    "0,0,0,0,9.8,0,0,0\n")
                                      << none << none << 1 << 0 << QStringList{"exactly one time column"};
    QTest::newRow("non-numeric cell names line, column and name")
        << QByteArray(kHeader + "0.02,0,0,9.8,abc,0,0\n") << none << none << 2 << 5
        << QStringList{"expected a number in column 'gyr_x', got 'abc'"};
    QTest::newRow("empty cell") << QByteArray(kHeader + "0.00,0,,9.8,0,0,0\n") << none << none << 2 << 3
                                << QStringList{"column 'acc_y', got ''"};
    QTest::newRow("number with trailing text") << QByteArray(kHeader + "0.00,0,0,9.8m,0,0,0\n") << none << none << 2
                                               << 4 << QStringList{"column 'acc_z', got '9.8m'"};
    QTest::newRow("short row") << QByteArray(kHeader + "0.02,0,0,9.8,0\n") << none << none << 2 << 6
                               << QStringList{"expected 7 columns, found 5"};
    QTest::newRow("time going backwards") << QByteArray(kHeader + rows + "0.02,0,0,9.8,0,0,0\n0.015,0,0,9.8,0,0,0\n")
                                          << none << none << 5 << 0
                                          << QStringList{"time goes backwards", "0.015 after 0.02"};
    QTest::newRow("empty file") << QByteArray() << none << none << 0 << 0 << QStringList{"the file is empty"};
    QTest::newRow("empty file with a column map")
        << QByteArray() << QStringList{"time_s", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"} << none << 0
        << 0 << QStringList{"the file is empty"};
    // The problem is found at the header, the last line read.
    QTest::newRow("header only") << QByteArray(kHeader) << none << none << 1 << 0
                                 << QStringList{"no samples after the header"};
    QTest::newRow("unknown role in the column map")
        << QByteArray("0,0,0,9.8,0,0,0\n")
        << QStringList{"time_s", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyro_z"} << none << 0 << 0
        << QStringList{"unknown column role 'gyro_z'", "expected one of time_s, time_ms, time_us, counter, acc_x",
                       "pressure_pa, pressure_hpa, pressure_kpa, skip"};
    // A column-map problem is not tied to a line of the file.
    QTest::newRow("column map missing a role")
        << QByteArray("0,0,0,9.8,0,0,0\n")
        << QStringList{"time_s", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "skip"} << none << 0 << 0
        << QStringList{"the column map lacks: gyr_z", "it has: time_s, acc_x"};
    QTest::newRow("reference columns with a column map")
        << QByteArray("0,0,0,9.8,0,0,0,1,2,3\n")
        << QStringList{"time_s", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "skip", "skip", "skip"}
        << QStringList{"a", "b", "c"} << 0 << 0 << QStringList{"reference columns are named by the header row"};
    QTest::newRow("only blank lines") << QByteArray("\n\n  \n") << none << none << 0 << 0
                                      << QStringList{"the file is empty"};
    QTest::newRow("reference column not in header")
        << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,vicon_x_m,vicon_y_m,vicon_z_m\n0,0,0,9.8,0,0,0,1,2,3\n")
        << none << QStringList{"vicon_x_m", "-vicon_q_m", "vicon_z_m"} << 1 << 0
        << QStringList{"reference column 'vicon_q_m' is not in the header"};
    QTest::newRow("two reference columns")
        << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,vicon_x_m,vicon_y_m\n0,0,0,9.8,0,0,0,1,2\n") << none
        << QStringList{"vicon_x_m", "vicon_y_m"} << 1 << 0
        << QStringList{"expected three reference columns x,y,z, got 2"};
    QTest::newRow("non-numeric reference cell")
        << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,vicon_x_m,vicon_y_m,vicon_z_m\n"
                      "0,0,0,9.8,0,0,0,1,-,3\n")
        << none << QStringList{"vicon_x_m", "-vicon_y_m", "vicon_z_m"} << 2 << 9
        << QStringList{"column 'vicon_y_m', got '-'"};
    QTest::newRow("NaN cell") << QByteArray(kHeader + "0.00,nan,0,9.8,0,0,0\n") << none << none << 2 << 2
                              << QStringList{"expected a number in column 'acc_x', got 'nan'"};
    QTest::newRow("upper-case NaN cell") << QByteArray(kHeader + "0.02,0,0,9.8,0,NaN,0\n") << none << none << 2
                                         << 6 << QStringList{"column 'gyr_y', got 'NaN'"};
    QTest::newRow("inf cell") << QByteArray(kHeader + "0.00,0,0,9.8,0,0,inf\n") << none << none << 2 << 7
                              << QStringList{"column 'gyr_z', got 'inf'"};
    QTest::newRow("-infinity time") << QByteArray(kHeader + "-infinity,0,0,9.8,0,0,0\n") << none << none << 2 << 1
                                    << QStringList{"column 'time_s', got '-infinity'"};
    QTest::newRow("overflowing number") << QByteArray(kHeader + "0,1e999,0,9.8,0,0,0\n") << none << none << 2 << 2
                                        << QStringList{"column 'acc_x', got '1e999'"};
}

void TestDelimitedTextReader::errors_reportMessageLineAndColumn()
{
    QFETCH(QByteArray, text);
    QFETCH(QStringList, columnMap);
    QFETCH(QStringList, referenceColumns);
    QFETCH(int, line);
    QFETCH(int, column);
    QFETCH(QStringList, messageParts);

    const ImportResult result = parse(text, columnMap, referenceColumns);
    QVERIFY2(!result.ok(), "the malformed input was accepted");
    const ReadError& error = *result.error;
    const QString message = QString::fromStdString(error.message);
    QCOMPARE(QString::fromStdString(error.file), QString::fromLatin1(kSource));
    if (line >= 0)
        QCOMPARE(int(error.line), line);
    QCOMPARE(int(error.column), column);
    for (const QString& part : messageParts)
        QVERIFY2(message.contains(part), qPrintable(QStringLiteral("'%1' not in '%2'").arg(part, message)));
}

void TestDelimitedTextReader::missingFile_isReportedWithThePathAndNoLine()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath(QStringLiteral("no-such-walk.csv")).toStdString();
    const ImportResult result = footpath::importRecording(path);
    QVERIFY(!result.ok());
    QCOMPARE(result.error->file, path);
    QCOMPARE(int(result.error->line), 0);
    QCOMPARE(int(result.error->column), 0);
    QCOMPARE(result.error->text(), path + ": cannot open the file for reading");
    QVERIFY(result.recording.samples.empty());
}

void TestDelimitedTextReader::readFromFile_sourceAndErrorsCarryThePath()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString good = writeFile(dir, QStringLiteral("good.csv"), kHeader + "0,1,2,3,4,5,6\n0.5,7,8,9,10,11,12\n");
    const QString bad = writeFile(dir, QStringLiteral("bad.csv"), kHeader + "0,1,2,3,4,5,6\n0.5,7,x8,9,10,11,12\n");
    QVERIFY(!good.isEmpty() && !bad.isEmpty());

    const ImportResult read = footpath::importRecording(good.toStdString());
    VERIFY_OK(read);
    QCOMPARE(read.recording.source, good.toStdString());
    QCOMPARE(read.recording.samples.size(), std::size_t(2));
    QCOMPARE(read.recording.samples[1].time_s, 0.5);
    VERIFY_VECTOR(read.recording.samples[1].acc_mps2, 7.0, 8.0, 9.0);
    VERIFY_VECTOR(read.recording.samples[1].gyr_radps, 10.0, 11.0, 12.0);

    // Damage in one of two rows: too much to trust the file, so it is refused naming the place.
    const ImportResult damaged = footpath::importRecording(bad.toStdString());
    QVERIFY(!damaged.ok());
    QCOMPARE(damaged.error->file, bad.toStdString());
    QCOMPARE(damaged.error->line, std::size_t(3));
    QVERIFY(QString::fromStdString(damaged.error->text())
                .contains(QStringLiteral(":3:3: expected a number in column 'acc_y', got 'x8'")));
}

void TestDelimitedTextReader::readErrorText_formatsFileLineColumnMessage_data()
{
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("expected");

    QTest::newRow("line and column") << 12 << 4 << QStringLiteral("walk.csv:12:4: expected a number");
    QTest::newRow("line only") << 12 << 0 << QStringLiteral("walk.csv:12: expected a number");
    QTest::newRow("neither") << 0 << 0 << QStringLiteral("walk.csv: expected a number");
}

void TestDelimitedTextReader::readErrorText_formatsFileLineColumnMessage()
{
    QFETCH(int, line);
    QFETCH(int, column);
    QFETCH(QString, expected);
    ReadError error;
    error.file = "walk.csv";
    error.line = static_cast<std::size_t>(line);
    error.column = static_cast<std::size_t>(column);
    error.message = "expected a number";
    QCOMPARE(QString::fromStdString(error.text()), expected);
}

void TestDelimitedTextReader::progress_returningFalseCancelsTheRead()
{
    QByteArray text = kHeader;
    for (int k = 0; k < 10000; ++k)
        text += QByteArray::number(k * 0.01, 'f', 2) + ",0,0,9.8,0,0,0\n";

    std::vector<double> fractions;
    ImportOptions keepGoing;
    keepGoing.progress = [&fractions](double fraction) {
        fractions.push_back(fraction);
        return true;
    };
    const ImportResult all = parse(text, keepGoing);
    VERIFY_OK(all);
    QCOMPARE(all.recording.samples.size(), std::size_t(10000));
    QVERIFY(!fractions.empty());
    for (std::size_t i = 0; i < fractions.size(); ++i) {
        QVERIFY(fractions[i] > 0.0 && fractions[i] <= 1.0);
        if (i > 0)
            QVERIFY(fractions[i] > fractions[i - 1]);
    }

    ImportOptions cancel;
    cancel.progress = [](double) { return false; };
    const ImportResult cancelled = parse(text, cancel);
    QVERIFY(!cancelled.ok());
    QCOMPARE(cancelled.error->message, std::string("reading cancelled"));
    QVERIFY(cancelled.recording.samples.size() < 10000);
}

void TestDelimitedTextReader::columnRoleNames_listsTheCanonicalRoles()
{
    const std::vector<std::string> expected{"time_s", "time_ms", "time_us", "counter", "acc_x",       "acc_y", "acc_z",
                                            "gyr_x",  "gyr_y",   "gyr_z",   "mag_x",   "mag_y", "mag_z", "pressure_pa",
                                            "pressure_hpa", "pressure_kpa", "skip"};
    QVERIFY(footpath::columnRoleNames() == expected);
}

QTEST_APPLESS_MAIN(TestDelimitedTextReader)
#include "tst_delimitedtextreader.moc"
