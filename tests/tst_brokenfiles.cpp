// A corpus of broken files: each must give its own clear message (file, line or byte, what was
// expected) or keep what came before the damage, and never crash or hang.
#include "io/Import.h"

#include <QTemporaryDir>
#include <QtTest>

#include <random>

using namespace footpath;

namespace {

const QByteArray kHeader = "time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";

QByteArray goodRows(int count, double t0 = 0.0)
{
    QByteArray rows;
    for (int k = 0; k < count; ++k)
        rows += QByteArray::number(t0 + k * 0.01, 'f', 2) + ",0.1,0.2,9.81,0.01,0.02,0.5\n";
    return rows;
}

QByteArray randomBytes(int count, std::uint32_t seed, char first)
{
    std::mt19937 random(seed);
    QByteArray bytes(count, '\0');
    for (char& byte : bytes)
        byte = static_cast<char>(random() & 0xFF);
    bytes[0] = first;
    return bytes;
}

}  // namespace

class TestBrokenFiles : public QObject {
    Q_OBJECT
private slots:
    void refusedWithAClearMessage_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("format");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("expected");
        QTest::newRow("empty") << QByteArray() << "" << 0 << "the file is empty";
        QTest::newRow("blank lines only") << QByteArray("\n \n\t\n") << "" << 0 << "the file is empty";
        QTest::newRow("binary junk") << randomBytes(4096, 1, 'x') << "" << 0
                                     << "binary content of no format Footpath knows";
        // A container is named for what it is (a .mat was called "not an Xsens .mtb log").
        QByteArray mat("MATLAB 5.0 MAT-file, Platform: GLNXA64, Created on: Mon Nov 30 10:00:00 2026");
        mat.append(QByteArray(128 - mat.size(), ' ') + randomBytes(1024, 3, '\x0e'));
        QTest::newRow("MATLAB v5") << mat << "" << 0 << "a MATLAB .mat file (v5), a format Footpath does not read";
        QTest::newRow("HDF5") << QByteArray("\x89HDF\r\n\x1a\n", 8) + randomBytes(512, 4, '\0') << "" << 0
                              << "an HDF5 file";
        QTest::newRow("SQLite") << QByteArray("SQLite format 3\0", 16) + randomBytes(512, 5, '\x10') << "" << 0
                                << "an SQLite database";
        QTest::newRow("UTF-16") << QByteArray("\xFF\xFEt\0i\0m\0e\0", 10) << "" << 0 << "UTF-16 text";
        QTest::newRow("wrong delimiter") << QByteArray("time_s|acc_x|acc_y|acc_z|gyr_x|gyr_y|gyr_z\n0|0|0|9.8|0|0|0\n")
                                         << "" << 1 << "one column only";
        QTest::newRow("missing column") << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y\n0,0,0,9.8,0,0\n") << ""
                                        << 1 << "missing column(s): gyr_z; the header has: time_s, acc_x";
        QTest::newRow("NaN in the first row") << kHeader + "0,0.1,nan,9.8,0,0,0\n" << "" << 2
                                              << "expected a number in column 'acc_y', got 'nan'";
        QTest::newRow("inf in the first row") << kHeader + "0,0.1,0,inf,0,0,0\n" << "" << 2
                                              << "expected a number in column 'acc_z', got 'inf'";
        QTest::newRow("time going backwards") << kHeader + goodRows(5) + "0.02,0,0,9.8,0,0,0\n" << "" << 7
                                              << "time goes backwards";
        QTest::newRow("header only") << kHeader << "" << 1 << "no samples after the header";
        QTest::newRow("no header") << goodRows(3) << "" << 0 << "no header row: the first line has 7 numeric columns";
        QTest::newRow("one endless line") << QByteArray(2 * 1024 * 1024, 'a') << "" << 0
                                          << "does not look like sensor data: no numeric rows";
        QTest::newRow("plain words") << QByteArray("# Notes\n\nThe walk was recorded on the 3rd floor.\nSee the "
                                                   "README for 2 more walks.\n")
                                     << "" << 0 << "does not look like sensor data: no numeric rows";
        QTest::newRow("most rows damaged") << kHeader + "0.00,0,0,9.8,0,0,0\n0.01,x,0,9.8,0,0,0\n0.02,0,y,9.8,0,0,0\n"
                                           << "" << 3 << "2 of 3 data rows could not be read";
        QTest::newRow("unknown --format") << kHeader + goodRows(3) << "excel" << 0 << "unknown format 'excel'";
        QTest::newRow("CSV read as .mtb") << kHeader + goodRows(3) << "xsens-mtb" << 0 << "";
        QTest::newRow("random bytes after an Xbus preamble") << randomBytes(8192, 2, '\xFA') << "" << 0 << "";
    }
    void refusedWithAClearMessage()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, format);
        QFETCH(int, line);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = dir.filePath("broken.csv");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(content);
        file.close();
        ImportOptions options;
        options.format = format.toStdString();
        const ImportResult read = importRecording(path.toStdString(), options);
        QVERIFY(!read.ok());
        const QString message = QString::fromStdString(read.error->text());
        QVERIFY2(message.startsWith(path), qPrintable(message));  // names the file
        QVERIFY2(message.contains(expected), qPrintable(message));
        if (line > 0)
            QCOMPARE(int(read.error->line), line);
    }

    void damageAfterGoodRowsKeepsWhatCameBefore_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<int>("kept");
        QTest::addColumn<QStringList>("warnings");  // each must be in one warning
        QTest::addColumn<bool>("truncated");
        const QByteArray good = kHeader + goodRows(50);
        QTest::newRow("cut off mid-line") << good + "0.50,0.1,0.2" << 50
                                          << QStringList{"the file ends in the middle of line 52, column 4 (expected 7 "
                                                         "columns, found 3); the 50 samples before it were kept"}
                                          << true;
        QTest::newRow("cut off mid-number") << good + "0.50,0.1,0.2,9.8,0.01,0.02,0.4" << 51 << QStringList{} << false;
        QTest::newRow("corrupted block")
            << good + "\x01\x02garbage\x03\n" + goodRows(10, 0.6) << 60
            << QStringList{"line 52, column 2 (expected 7 columns, found 1): the row was skipped"} << false;
        QTest::newRow("text in a cell")
            << good + "0.50,0.1,abc,9.8,0,0,0\n" + goodRows(10, 0.6) << 60
            << QStringList{"line 52, column 3 (expected a number in column 'acc_y', got 'abc'): the row was skipped"}
            << false;
        QByteArray sprinkled = kHeader;
        for (int block = 0; block < 10; ++block)
            sprinkled += goodRows(5, block * 0.05) + "oops\n";
        QTest::newRow("many bad rows: the first three, then a count")
            << sprinkled << 50
            << QStringList{"line 7, column 2 (expected 7 columns, found 1): the row was skipped", "line 19, column 2",
                           "7 more damaged row(s) were skipped"}
            << false;
    }
    void damageAfterGoodRowsKeepsWhatCameBefore()
    {
        QFETCH(QByteArray, content);
        QFETCH(int, kept);
        QFETCH(QStringList, warnings);
        QFETCH(bool, truncated);
        QTemporaryDir dir;
        const QString path = dir.filePath("broken.csv");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(content);
        file.close();
        const ImportResult read = importRecording(path.toStdString());
        QVERIFY2(read.ok(), read.ok() ? "" : read.error->text().c_str());
        QCOMPARE(read.recording.samples.size(), std::size_t(kept));
        QCOMPARE(read.info.truncated, truncated);
        std::size_t rowWarnings = 0;
        for (const std::string& warning : read.recording.warnings)
            rowWarnings += QString::fromStdString(warning).contains(QStringLiteral("row")) ? 1 : 0;
        QVERIFY(rowWarnings <= 4);  // never a warning per damaged row
        for (const QString& expected : warnings) {
            bool warned = false;
            for (const std::string& warning : read.recording.warnings)
                warned = warned || QString::fromStdString(warning).contains(expected);
            QVERIFY2(warned, qPrintable(expected));
        }
    }

    void xsensTextSkipsADamagedRow()
    {
        QByteArray text = "// Update Rate: 100.0Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n";
        for (int k = 0; k < 40; ++k)
            text += QByteArray::number(k) + (k == 20 ? "\t0.1\tabc\t9.8\t0.01\t0.02\t0.03\n" : "\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n");
        QTemporaryDir dir;
        const QString path = dir.filePath("export.txt");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(text);
        file.close();
        const ImportResult read = importRecording(path.toStdString());
        QVERIFY2(read.ok(), read.ok() ? "" : read.error->text().c_str());
        QCOMPARE(read.info.format, std::string("xsens-text"));
        QCOMPARE(read.recording.samples.size(), std::size_t(39));
        bool warned = false;
        for (const std::string& warning : read.recording.warnings)
            warned = warned || QString::fromStdString(warning).contains(
                                   "line 23, column 3 (expected a number in column 'Acc_Y', got 'abc'): the row was skipped");
        QVERIFY(warned);
    }

    void missingFileIsAnError()
    {
        const ImportResult read = importRecording("/nonexistent/walk.csv");
        QVERIFY(!read.ok());
        QCOMPARE(read.error->text(), std::string("/nonexistent/walk.csv: cannot open the file for reading"));
    }
};

QTEST_GUILESS_MAIN(TestBrokenFiles)
#include "tst_brokenfiles.moc"
