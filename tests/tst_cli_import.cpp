// footpath-cli info and the import options, run as a user would run them.
#include "TestData.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

namespace {

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

Run runCli(const QStringList& arguments, const QString& presetDir = {})
{
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    if (!presetDir.isEmpty())
        environment.insert("FOOTPATH_IMPORT_PRESETS", presetDir);
    process.setProcessEnvironment(environment);
    process.start(QString::fromUtf8(FOOTPATH_CLI), arguments);
    if (!process.waitForFinished(60000))
        return {};
    return {process.exitCode(), QString::fromUtf8(process.readAllStandardOutput()),
            QString::fromUtf8(process.readAllStandardError())};
}

QJsonObject infoJson(const QStringList& arguments, const QString& presetDir = {})
{
    const Run run = runCli(QStringList{"info"} + arguments + QStringList{"--json"}, presetDir);
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes)
{
    QFile file(dir.filePath(name));
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size() ? file.fileName() : QString();
}

const QStringList kEcgColumns{"--columns", "time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,pressure_pa"};

}  // namespace

class TestCliImport : public QObject {
    Q_OBJECT
private slots:
    void infoJsonHasTheDocumentedKeys()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const QJsonObject info = infoJson({datasetPath("pyshoe-vicon/2017-11-22-11-22-03.csv")});
        for (const char* key : {"format", "samples", "rate_hz", "duration_s", "channels", "gaps", "warnings"})
            QVERIFY2(info.contains(key), key);
        QCOMPARE(info.value("format").toString(), QString("pyshoe-vicon"));
        QCOMPARE(info.value("samples").toInt(), 6490);
        QVERIFY(std::abs(info.value("rate_hz").toDouble() - 200.0) < 0.5);
        QVERIFY(info.value("channels").toArray().contains("reference-position"));
        QCOMPARE(info.value("gaps").toObject().value("count").toInt(), 0);
    }

    void infoTableForAHeaderlessFileWithColumns()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const Run run = runCli(QStringList{"info", datasetPath("ecg-xmu/straight_40.4m.txt")} + kEcgColumns);
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains("format      delimited"));
        QVERIFY(run.out.contains("samples     4141"));
        QVERIFY(run.out.contains("known length 40.4 m from the file name"));
    }

    void headerlessFileWithoutColumnsIsRefusedWithAHint()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const Run run = runCli({"info", datasetPath("ecg-xmu/straight_40.4m.txt")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("no header row: the first line has 8 numeric columns"));
        // The reader says what to give; the CLI adds its option.
        QVERIFY2(run.err.contains("give the column map (--columns)"), qPrintable(run.err));
    }

    void readerMessagesGetTheCliOptionThatAnswersThem()
    {
        // A counter for time and no rate: the reader asks for the rate, the CLI names --rate.
        QTemporaryDir dir;
        QFile file(dir.filePath("counter.csv"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("counter,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n0,0,0,9.81,0,0,0\n1,0,0,9.81,0,0,0\n");
        file.close();
        const Run run = runCli({"info", file.fileName()});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("give the sample rate (--rate HZ)"), qPrintable(run.err));
    }

    void importPresetSavedAndReused()
    {
        FOOTPATH_REQUIRE_DATASETS();
        QTemporaryDir presets;
        const QString file = datasetPath("ecg-xmu/straight_40.4m.txt");
        const Run save = runCli(QStringList{"info", file} + kEcgColumns + QStringList{"--save-import-preset", "ecg"},
                                presets.path());
        QCOMPARE(save.exitCode, 0);
        QVERIFY(QFile::exists(presets.filePath("ecg.json")));
        const QJsonObject info = infoJson({file, "--import-preset", "ecg"}, presets.path());
        QCOMPARE(info.value("samples").toInt(), 4141);
        const Run unknown = runCli({"info", file, "--import-preset", "nope"}, presets.path());
        QCOMPARE(unknown.exitCode, 2);
        QVERIFY(unknown.err.contains("saved presets: ecg"));
    }

    void aLineOverTheBoundAndARateOutOfRangeAreRefused()
    {
        QTemporaryDir dir;
        // A line just over 1 MiB, as a 100 MB one would be.
        const QString path = writeFile(dir, "long-line.csv", "time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n"
                                                             "0,0.1,0.2,9.81,0,0,0\n" + QByteArray(1100 * 1024, '7'));
        QVERIFY(!path.isEmpty());
        const Run longLine = runCli({"info", path});
        QCOMPARE(longLine.exitCode, 2);
        QVERIFY2(longLine.err.contains(path + ":3: the line is longer than 1 MiB (1048576 bytes), the most a line of "
                                              "text may hold; expected one sample a line"),
                 qPrintable(longLine.err));

        const Run hugeRate = runCli({"info", path, "--rate", "1e9"});
        QCOMPARE(hugeRate.exitCode, 2);
        QVERIFY2(hugeRate.err.contains("--rate expects a rate in Hz > 0 and up to 10000, got '1e9'"), qPrintable(hugeRate.err));

        const QString preset = writeFile(
            dir, "negative.json", R"({"format": "footpath-import-preset", "version": 1, "name": "negative", "rate_hz": -100})");
        QVERIFY(!preset.isEmpty());
        const Run negative = runCli({"info", path, "--import-preset", preset});
        QCOMPARE(negative.exitCode, 2);
        QVERIFY2(negative.err.contains(preset + ": \"rate_hz\" must be a number of Hz from 0 (the rate comes from "
                                                "the file) to 10000, got -100"),
                 qPrintable(negative.err));
    }

    void unitOverridesAndFormatOverride()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("walk.csv");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("time,ax,ay,az,wx,wy,wz\n");
        for (int k = 0; k < 300; ++k)
            file.write(QByteArray::number(k * 10) + ",0.01,0.02,1.0," + QByteArray::number(100.0 * std::sin(k * 0.05))
                       + ",0,0\n");
        file.close();
        const QJsonObject detected = infoJson({path});
        QCOMPARE(detected.value("units").toObject().value("acc").toString(), QString("g"));
        QCOMPARE(detected.value("units").toObject().value("gyr").toString(), QString("deg/s"));
        QCOMPARE(detected.value("units").toObject().value("time").toString(), QString("ms"));
        const QJsonObject overridden = infoJson({path, "--acc-unit", "mps2", "--time-unit", "s"});
        QCOMPARE(overridden.value("units").toObject().value("acc").toString(), QString("m/s^2"));
        bool warned = false;
        for (const QJsonValue& warning : overridden.value("warnings").toArray())
            warned = warned || warning.toString().contains("looks like g");
        QVERIFY(warned);
        const Run badUnit = runCli({"info", path, "--gyr-unit", "rpm"});
        QCOMPARE(badUnit.exitCode, 2);
        QVERIFY(badUnit.err.contains("--gyr-unit expects radps or degps"));
        const Run wrongFormat = runCli({"info", path, "--format", "xsens-mtb"});
        QCOMPARE(wrongFormat.exitCode, 2);
    }

    void reportAndCsvExportsFromTheCommandLine()
    {
        FOOTPATH_REQUIRE_DATASETS();
        if (QStandardPaths::findExecutable("pdfinfo").isEmpty())
            QSKIP("pdfinfo (Debian: poppler-utils) is not installed");
        QTemporaryDir dir;
        const QString input = datasetPath("pyshoe-vicon/2017-11-22-11-27-30.csv");
        const QString pdf = dir.filePath("walk.pdf");
        const Run report = runCli({"report", input, "--pdf", pdf, "--set", "acc_std_max_mps2=0.6"});
        QCOMPARE(report.exitCode, 0);
        QProcess info;
        info.start("pdfinfo", {pdf});
        QVERIFY(info.waitForFinished(30000));
        QVERIFY(QString::fromUtf8(info.readAllStandardOutput()).contains("A4"));
        const Run missingPdf = runCli({"report", input});
        QCOMPARE(missingPdf.exitCode, 2);
        QVERIFY(missingPdf.err.contains("report needs --pdf"));

        const QString summary = dir.filePath("summary.csv"), parameters = dir.filePath("parameters.csv");
        const Run process = runCli({"process", input, "--summary-csv", summary, "--parameters-csv", parameters,
                                    "--set", "acc_std_max_mps2=0.6"});
        QCOMPARE(process.exitCode, 0);
        QFile params(parameters);
        QVERIFY(params.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(params.readAll());
        QVERIFY(text.startsWith("name,value,unit,default,differs_from_default"));
        QVERIFY(text.contains("acc_std_max_mps2,0.6,m/s^2,0.5,1,"));
        QFile sums(summary);
        QVERIFY(sums.open(QIODevice::ReadOnly));
        QVERIFY(QString::fromUtf8(sums.readAll()).startsWith("samples,duration_s,"));
    }

    void evalUsesTheReferenceTheFileCarries()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const Run run = runCli({"eval", datasetPath("pyshoe-vicon/2017-11-22-11-22-03.csv"), "--json"});
        QCOMPARE(run.exitCode, 0);
        const QJsonObject metrics = QJsonDocument::fromJson(run.out.toUtf8()).object();
        QVERIFY(metrics.contains("armse_2d_m"));
        QVERIFY(metrics.value("armse_2d_m").toDouble() < 0.1);
        QVERIFY(metrics.contains("dbse_m"));  // pyshoe trials are closed loops
        const Run rectangle = runCli(QStringList{"eval", datasetPath("ecg-xmu/rectangle_72m.TXT"), "--columns",
                                                 "time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", "--closed-loop",
                                                 "--json"});
        const QJsonObject closure = QJsonDocument::fromJson(rectangle.out.toUtf8()).object();
        QCOMPARE(closure.value("reference_length_m").toDouble(), 72.0);  // from the file name
        QVERIFY(closure.value("dbse_pct").toDouble() < 2.0);
    }
};

QTEST_GUILESS_MAIN(TestCliImport)
#include "tst_cli_import.moc"
