// importRecording(): format detection, units, time base and reference data, on every shared
// recording and on crafted files. Expected counts and rates were read off the files with
// independent scripts (awk / Python: rows, median time step, median |a|), not with Footpath.
#include "TestData.h"
#include "io/ColumnMapGuess.h"
#include "io/ColumnNames.h"
#include "io/Import.h"
#include "io/ImportPresets.h"
#include "io/NearestNames.h"
#include "io/ParameterIo.h"
#include "io/ReferenceSidecar.h"
#include "nav/Pipeline.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace footpath;

namespace {

ImportResult importOrFail(const QString& path, const ImportOptions& options = {})
{
    ImportResult read = importRecording(path.toStdString(), options);
    if (!read.ok())
        qWarning("%s", read.error->text().c_str());
    return read;
}

bool hasWarning(const Recording& recording, const QString& part)
{
    for (const std::string& warning : recording.warnings)
        if (QString::fromStdString(warning).contains(part))
            return true;
    return false;
}

/// A walk-like synthetic text: 100 Hz, |a| about g, rates up to ~5 rad/s.
QByteArray syntheticText(const QByteArray& header, double accScale, double gyrScale, double timeScale,
                         int rows = 400, int dropEvery = 0)
{
    QByteArray text = header + "\n";
    int written = 0;
    for (int k = 0; k < rows; ++k) {
        if (dropEvery > 0 && k % dropEvery == dropEvery - 1)
            continue;  // a lost packet
        const double t = k * 0.01;
        const double swing = std::sin(2.0 * M_PI * t);
        text += QByteArray::number(t * timeScale, 'g', 12) + "," + QByteArray::number(0.5 * swing * accScale) + ","
                + QByteArray::number(0.2 * accScale) + "," + QByteArray::number(9.8 * accScale) + ","
                + QByteArray::number(0.1 * gyrScale) + "," + QByteArray::number(5.0 * swing * gyrScale) + ","
                + QByteArray::number(0.05 * gyrScale) + "\n";
        ++written;
    }
    return text;
}

/// The import feeds the pipeline: an estimate for every sample, finite throughout. Whether the
/// walk is plausible depends on the stance detector (the fixed C1/C2/C3 thresholds miss the
/// strides of several ecg-xmu walks); the figures are printed so a regression shows.
bool estimatesEverySample(const Recording& recording, const QString& name)
{
    const PipelineOutput output = runPipeline(recording, Parameters());
    if (!output.error.empty() || output.result.position_m.size() != recording.samples.size())
        return false;
    for (const Eigen::Vector3d& p : output.result.position_m)
        if (!p.allFinite())
            return false;
    const Summary& s = output.result.summary;
    qInfo("%-26s %6zu samples %7.1f s %5zu steps path %9.1f m end-to-start %9.1f m", qPrintable(name), s.samples,
          s.duration_s, s.steps, s.pathLength_m, s.endToStart_m);
    return true;
}

}  // namespace

class TestImport : public QObject {
    Q_OBJECT
private slots:
    // ---- the shared recordings ------------------------------------------------------------
    void pyshoeVicon_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("samples");
        QTest::addColumn<int>("gaps");
        // Gaps: steps longer than 1.5 sample periods (7.5 ms), counted with awk; two files have one
        // 8.6 ms step each.
        const std::tuple<const char*, int, int> files[] = {
            {"2017-11-22-11-22-03.csv", 6490, 0}, {"2017-11-22-11-22-46.csv", 6753, 0},
            {"2017-11-22-11-23-25.csv", 7117, 0}, {"2017-11-22-11-25-20.csv", 5323, 0},
            {"2017-11-22-11-26-05.csv", 7525, 1}, {"2017-11-22-11-26-46.csv", 6555, 0},
            {"2017-11-22-11-27-30.csv", 5684, 0}, {"2017-11-22-11-28-03.csv", 5204, 0},
            {"2017-11-27-11-11-24.csv", 4203, 0}, {"2017-11-27-11-17-28.csv", 5117, 1},
            {"2017-11-27-11-22-22.csv", 5203, 0}, {"2017-12-15-17-59-50.csv", 3402, 0}};
        for (const auto& [file, samples, gaps] : files)
            QTest::newRow(file) << QString(file) << samples << gaps;
    }
    void pyshoeVicon()
    {
        FOOTPATH_REQUIRE_DATASETS();
        QFETCH(QString, file);
        QFETCH(int, samples);
        QFETCH(int, gaps);
        const ImportResult read = importOrFail(datasetPath("pyshoe-vicon/" + file));
        QVERIFY(read.ok());
        QCOMPARE(read.info.format, std::string("pyshoe-vicon"));
        QCOMPARE(read.recording.samples.size(), std::size_t(samples));
        QVERIFY(std::abs(read.info.rate_hz - 200.0) < 0.5);
        QCOMPARE(read.info.accUnitAsRead, AccUnit::MetresPerSecond2);
        QCOMPARE(read.info.gyrUnitAsRead, GyrUnit::RadiansPerSecond);
        QCOMPARE(read.info.gaps.count, std::size_t(gaps));
        QCOMPARE(read.recording.reference.positions_m.size(), std::size_t(samples));
        QVERIFY(read.recording.reference.closedLoop);
        QVERIFY(estimatesEverySample(read.recording, file));
    }

    void ecgXmu_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("samples");
        QTest::addColumn<int>("columns");
        QTest::addColumn<double>("length");
        QTest::newRow("Height") << "Height.txt" << 15330 << 11 << 0.0;
        QTest::newRow("data") << "data.txt" << 20433 << 8 << 0.0;
        QTest::newRow("freewalking") << "freewalking_88.8m.txt" << 8561 << 8 << 88.8;
        QTest::newRow("juxing") << "mage_juxing_1.txt" << 2992 << 11 << 0.0;
        QTest::newRow("sanjiaoxing") << "mage_sanjiaoxing_1.txt" << 3044 << 11 << 0.0;
        QTest::newRow("yuan") << "mage_yuan_1.txt" << 2062 << 11 << 0.0;
        QTest::newRow("zhixian") << "mage_zhixian_1.txt" << 3213 << 11 << 0.0;
        QTest::newRow("rectangle") << "rectangle_72m.TXT" << 10051 << 7 << 72.0;
        QTest::newRow("shanglou") << "shanglou041601.TXT" << 13349 << 8 << 0.0;
        QTest::newRow("step_34") << "step_34.txt" << 4916 << 8 << 0.0;
        QTest::newRow("straight") << "straight_40.4m.txt" << 4141 << 8 << 40.4;
    }
    void ecgXmu()
    {
        FOOTPATH_REQUIRE_DATASETS();
        QFETCH(QString, file);
        QFETCH(int, samples);
        QFETCH(int, columns);
        QFETCH(double, length);
        const QString path = datasetPath("ecg-xmu/" + file);
        // Without a column map a headerless file is refused with a message that counts the columns.
        const ImportResult refused = importRecording(path.toStdString());
        QVERIFY(!refused.ok());
        QVERIFY(QString::fromStdString(refused.error->message)
                    .contains(QString("the first line has %1 numeric columns").arg(columns)));

        ImportOptions options;
        options.columnMap = {"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"};
        if (columns >= 8)
            options.columnMap.push_back("pressure_pa");
        while (static_cast<int>(options.columnMap.size()) < columns)
            options.columnMap.push_back("skip");
        const ImportResult read = importOrFail(path, options);
        QVERIFY(read.ok());
        QCOMPARE(read.info.format, std::string("delimited"));
        QCOMPARE(read.recording.samples.size(), std::size_t(samples));
        QVERIFY(std::abs(read.info.rate_hz - 100.0) < 0.5);
        QCOMPARE(read.info.accUnitAsRead, AccUnit::MetresPerSecond2);
        QCOMPARE(read.info.gyrUnitAsRead, GyrUnit::RadiansPerSecond);
        QCOMPARE(read.info.gaps.count, std::size_t(0));
        QCOMPARE(read.recording.hasPressure(), columns >= 8);
        QCOMPARE(read.recording.reference.knownLength_m, length);
        if (columns >= 8)
            QVERIFY(read.recording.samples.front().pressure_pa > 90000.0);
        QVERIFY(estimatesEverySample(read.recording, file));
    }

    // ---- units ------------------------------------------------------------------------------
    void unitsFromNamesOrData_data()
    {
        QTest::addColumn<QByteArray>("header");
        QTest::addColumn<double>("accScale");
        QTest::addColumn<double>("gyrScale");
        QTest::addColumn<double>("timeScale");
        QTest::addColumn<int>("acc");
        QTest::addColumn<int>("gyr");
        QTest::addColumn<int>("time");
        QTest::addColumn<QString>("warning");
        const QByteArray plain = "time,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z";
        const int mps2 = int(AccUnit::MetresPerSecond2), g = int(AccUnit::StandardGravity);
        const int rad = int(GyrUnit::RadiansPerSecond), deg = int(GyrUnit::DegreesPerSecond);
        const int s = int(TimeUnit::Seconds), ms = int(TimeUnit::Milliseconds), us = int(TimeUnit::Microseconds);
        QTest::newRow("SI stated") << QByteArray("t_s,acc_x_mps2,acc_y_mps2,acc_z_mps2,gyr_x_radps,gyr_y_radps,gyr_z_radps")
                                   << 1.0 << 1.0 << 1.0 << mps2 << rad << s << "";
        QTest::newRow("g and deg/s stated")
            << QByteArray("Time (ms),Acc X [g],Acc Y [g],Acc Z [g],Gyr X (deg/s),Gyr Y (deg/s),Gyr Z (deg/s)")
            << 1.0 / 9.80665 << 180.0 / M_PI << 1000.0 << g << deg << ms << "";
        QTest::newRow("g found from |a|, seconds from spacing") << plain << 1.0 / 9.80665 << 1.0 << 1.0 << g << rad << s
                                                                << "median step of 0.01 is read as s";
        QTest::newRow("deg/s found from the rates, ms from spacing")
            << plain << 1.0 << 180.0 / M_PI << 1000.0 << mps2 << deg << ms << "read as deg/s";
        QTest::newRow("microseconds from spacing") << plain << 1.0 << 1.0 << 1e6 << mps2 << rad << us << "read as us";
        QTest::newRow("stated m/s^2 that looks like g is warned")
            << QByteArray("time_s,acc_x_mps2,acc_y_mps2,acc_z_mps2,gyr_x,gyr_y,gyr_z") << 1.0 / 9.80665 << 1.0 << 1.0
            << mps2 << rad << s << "looks like g";
    }
    void unitsFromNamesOrData()
    {
        QFETCH(QByteArray, header);
        QFETCH(double, accScale);
        QFETCH(double, gyrScale);
        QFETCH(double, timeScale);
        QFETCH(int, acc);
        QFETCH(int, gyr);
        QFETCH(int, time);
        QFETCH(QString, warning);
        QTemporaryDir dir;
        const QString path = writeFileIn(dir, "walk.csv", syntheticText(header, accScale, gyrScale, timeScale));
        const ImportResult read = importOrFail(path);
        QVERIFY(read.ok());
        QCOMPARE(int(read.info.accUnitAsRead), acc);
        QCOMPARE(int(read.info.gyrUnitAsRead), gyr);
        QCOMPARE(int(read.info.timeUnitAsRead), time);
        // After conversion every file is the same walk in SI.
        const ImuSample& sample = read.recording.samples[25];  // t = 0.25 s: sin = 1
        QVERIFY(std::abs(sample.time_s - 0.25) < 1e-9);
        QVERIFY(std::abs(sample.acc_mps2.z() - 9.8 * accScale * (acc == int(AccUnit::StandardGravity) ? 9.80665 : 1.0))
                < 1e-3);
        QVERIFY(std::abs(sample.gyr_radps.y() - (gyr == int(GyrUnit::DegreesPerSecond) ? 5.0 : 5.0 * gyrScale)) < 1e-3);
        if (!warning.isEmpty())
            QVERIFY2(hasWarning(read.recording, warning), qPrintable(warning));
    }

    void overridesWin()
    {
        QTemporaryDir dir;
        const QString path = writeFileIn(dir, "walk.csv",
                                       syntheticText("time,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 1.0 / 9.80665, 1.0, 1.0));
        ImportOptions options;
        options.accUnit = AccUnit::MetresPerSecond2;  // wrong on purpose: it is g
        const ImportResult read = importOrFail(path, options);
        QCOMPARE(read.info.accUnitAsRead, AccUnit::MetresPerSecond2);
        QVERIFY(std::abs(read.recording.samples[0].acc_mps2.z() - 1.0) < 1e-3);  // not scaled
        QVERIFY(hasWarning(read.recording, "looks like g"));
    }

    // ---- time base ----------------------------------------------------------------------------
    void gapsAreCountedAndReported()
    {
        QTemporaryDir dir;
        // Every 50th packet lost: of 400 rows, samples 49, 99, ..., 399 are missing; the last one
        // ends the file, so 7 gaps of 20 ms show.
        const QString path = writeFileIn(dir, "gaps.csv", syntheticText("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 1.0,
                                                                      1.0, 1.0, 400, 50));
        const ImportResult read = importOrFail(path);
        QCOMPARE(read.info.gaps.count, std::size_t(7));
        QCOMPARE(read.info.gaps.missingSamples, std::size_t(7));
        QVERIFY(std::abs(read.info.gaps.longest_s - 0.02) < 1e-9);
        QVERIFY(std::abs(read.info.rate_hz - 100.0) < 0.01);
        QVERIFY(hasWarning(read.recording, "7 gap(s) in the time base, about 7 samples lost"));
    }

    void counterTimeBaseNeedsARate()
    {
        QTemporaryDir dir;
        QByteArray text = "counter,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";
        for (int k : {0, 1, 2, 4, 5})  // packet 3 lost
            text += QByteArray::number(k) + ",0,0,9.81,0,0,0\n";
        const QString path = writeFileIn(dir, "counter.csv", text);
        const ImportResult noRate = importRecording(path.toStdString());
        QVERIFY(!noRate.ok());
        // What to set, in words the GUI's import dialog also fits (it has no --rate).
        QVERIFY(QString::fromStdString(noRate.error->message).contains("give the sample rate"));
        QVERIFY(!QString::fromStdString(noRate.error->message).contains("--"));
        ImportOptions options;
        options.rate_hz = 50.0;
        const ImportResult read = importOrFail(path, options);
        QCOMPARE(read.recording.samples.back().time_s, 0.1);
        QCOMPARE(read.info.gaps.count, std::size_t(1));
    }

    void decimalCommaWithSemicolons()
    {
        QTemporaryDir dir;
        const QString path = writeFileIn(dir, "excel.csv",
                                       "time_s;acc_x;acc_y;acc_z;gyr_x;gyr_y;gyr_z\n0,00;0,1;0,2;9,81;0;0;0,5\n"
                                       "0,01;0,1;0,2;9,81;0;0;0,5\n");
        const ImportResult read = importOrFail(path);
        QVERIFY(read.ok());
        QCOMPARE(read.recording.samples[1].time_s, 0.01);
        QCOMPARE(read.recording.samples[1].acc_mps2.z(), 9.81);
    }

    // ---- reference data -----------------------------------------------------------------------
    void lengthFromFileNames_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("length");
        QTest::newRow("rectangle_72m.TXT") << "rectangle_72m.TXT" << 72.0;
        QTest::newRow("straight_40.4m.txt") << "straight_40.4m.txt" << 40.4;
        QTest::newRow("walk-12m_2.csv") << "walk-12m_2.csv" << 12.0;
        QTest::newRow("no length") << "mage_juxing_1.txt" << 0.0;
        QTest::newRow("mm is not m") << "walk_72mm.csv" << 0.0;
    }
    void lengthFromFileNames()
    {
        QFETCH(QString, name);
        QFETCH(double, length);
        QCOMPARE(lengthFromFileName(("/some/dir/" + name).toStdString()), length);
    }

    void sidecarGivesClosedLoopAndLength()
    {
        QTemporaryDir dir;
        const QString path = writeFileIn(dir, "loop.csv", syntheticText("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 1, 1, 1));
        writeFileIn(dir, "loop.csv.reference.json", R"({"closed_loop": true, "length_m": 25.8})");
        const ImportResult read = importOrFail(path);
        QVERIFY(read.recording.reference.closedLoop);
        QCOMPARE(read.recording.reference.knownLength_m, 25.8);
        QVERIFY(!read.recording.reference.notes.empty());

        writeFileIn(dir, "broken.csv.reference.json", "{closed_loop: yes");
        const QString broken = writeFileIn(dir, "broken.csv", syntheticText("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 1, 1, 1));
        const ImportResult withBrokenSidecar = importOrFail(broken);
        QVERIFY(withBrokenSidecar.ok());
        QVERIFY(hasWarning(withBrokenSidecar.recording, "reference sidecar ignored"));
    }

    // ---- presets ------------------------------------------------------------------------------
    void importPresetRoundTripAndApply()
    {
        QTemporaryDir dir;
        ImportPreset preset;
        preset.name = "ecg-xmu";
        preset.columnMap = {"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "pressure_pa"};
        preset.accUnit = AccUnit::MetresPerSecond2;
        preset.gyrUnit = GyrUnit::RadiansPerSecond;
        QCOMPARE(saveImportPreset(preset, dir.path().toStdString()), std::string());
        ImportPreset loaded;
        QCOMPARE(loadImportPreset("ecg-xmu", loaded, dir.path().toStdString()), std::string());
        QCOMPARE(loaded.columnMap, preset.columnMap);
        QCOMPARE(loaded.accUnit, preset.accUnit);
        QCOMPARE(listImportPresets(dir.path().toStdString()).size(), std::size_t(1));

        ImportOptions options;
        options.gyrUnit = GyrUnit::DegreesPerSecond;  // the user's own setting wins
        applyImportPreset(loaded, options);
        QCOMPARE(options.columnMap, preset.columnMap);
        QCOMPARE(options.gyrUnit, GyrUnit::DegreesPerSecond);

        ImportPreset missing;
        const std::string problem = loadImportPreset("nope", missing, dir.path().toStdString());
        QVERIFY(QString::fromStdString(problem).contains("saved presets: ecg-xmu"));
        QVERIFY(!saveImportPreset(ImportPreset{"../evil", {}, {}, {}, {}, {}, 0.0}, dir.path().toStdString()).empty());
    }

    void importPresetRate_isRefusedOutsideZeroTo10kHz_data()
    {
        QTest::addColumn<QString>("rate");
        QTest::addColumn<QString>("problem");  // empty: read
        QTest::newRow("200 Hz") << "200" << "";
        QTest::newRow("0: from the file") << "0" << "";
        QTest::newRow("10 kHz") << "10000" << "";
        QTest::newRow("negative") << "-100" << "got -100";
        QTest::newRow("huge") << "1e12" << "got 1e+12";
        QTest::newRow("text") << "\"fast\"" << "got \"fast\"";
        QTest::newRow("null") << "null" << "got null";
    }

    void importPresetRate_isRefusedOutsideZeroTo10kHz()
    {
        QFETCH(QString, rate);
        QFETCH(QString, problem);
        const std::string json = R"({"format": "footpath-import-preset", "version": 1, "name": "x", "rate_hz": )"
                                 + rate.toStdString() + "}";
        ImportPreset preset;
        preset.rate_hz = 55.0;
        const QString error = QString::fromStdString(importPresetFromJson(json, "presets/x.json", preset));
        if (problem.isEmpty()) {
            QVERIFY2(error.isEmpty(), qPrintable(error));
            QCOMPARE(preset.rate_hz, rate.toDouble());
            return;
        }
        QCOMPARE(error, "presets/x.json: \"rate_hz\" must be a number of Hz from 0 (the rate comes from the file) to "
                        "10000, " + problem);
        QCOMPARE(preset.rate_hz, 55.0);  // left as it was
    }

    // ---- header names -------------------------------------------------------------------------
    void headerNames_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("role");
        QTest::addColumn<int>("acc");
        QTest::addColumn<int>("gyr");
        QTest::addColumn<int>("time");
        const int none = 0;
        const auto r = [](ColumnRole role) { return int(role); };
        QTest::newRow("acc_x") << "acc_x" << r(ColumnRole::AccX) << none << none << none;
        QTest::newRow("AccY") << "AccY" << r(ColumnRole::AccY) << none << none << none;
        QTest::newRow("az") << "az" << r(ColumnRole::AccZ) << none << none << none;
        QTest::newRow("accel_x_g") << "accel_x_g" << r(ColumnRole::AccX) << int(AccUnit::StandardGravity) << none << none;
        QTest::newRow("Accelerometer X (m/s^2)") << "Accelerometer X (m/s^2)" << r(ColumnRole::AccX)
                                                 << int(AccUnit::MetresPerSecond2) << none << none;
        QTest::newRow("gyro_z_dps") << "gyro_z_dps" << r(ColumnRole::GyrZ) << none << int(GyrUnit::DegreesPerSecond) << none;
        QTest::newRow("wx") << "wx" << r(ColumnRole::GyrX) << none << none << none;
        QTest::newRow("gy") << "gy" << r(ColumnRole::GyrY) << none << none << none;
        QTest::newRow("Gyr_Z [rad/s]") << "Gyr_Z [rad/s]" << r(ColumnRole::GyrZ) << none << int(GyrUnit::RadiansPerSecond) << none;
        QTest::newRow("mag_y") << "mag_y" << r(ColumnRole::MagY) << none << none << none;
        QTest::newRow("timestamp") << "timestamp" << r(ColumnRole::Time) << none << none << none;
        QTest::newRow("t_s") << "t_s" << r(ColumnRole::Time) << none << none << int(TimeUnit::Seconds);
        QTest::newRow("Time (us)") << "Time (us)" << r(ColumnRole::Time) << none << none << int(TimeUnit::Microseconds);
        QTest::newRow("baro") << "baro" << r(ColumnRole::Pressure) << none << none << none;
        QTest::newRow("PacketCounter") << "PacketCounter" << r(ColumnRole::Counter) << none << none << none;
        QTest::newRow("FreeAcc_X is not acc") << "FreeAcc_X" << -1 << none << none << none;
        QTest::newRow("temperature is not time") << "temperature" << -1 << none << none << none;
        QTest::newRow("vicon_x_m is not data") << "vicon_x_m" << -1 << none << none << none;
        QTest::newRow("accuracy is not acc") << "accuracy" << -1 << none << none << none;
    }
    void headerNames()
    {
        QFETCH(QString, name);
        QFETCH(int, role);
        QFETCH(int, acc);
        QFETCH(int, gyr);
        QFETCH(int, time);
        const std::optional<ColumnMeaning> meaning = recogniseHeaderName(name.toStdString());
        QCOMPARE(meaning.has_value(), role >= 0);
        if (!meaning)
            return;
        QCOMPARE(int(meaning->role), role);
        QCOMPARE(int(meaning->accUnit), acc);
        QCOMPARE(int(meaning->gyrUnit), gyr);
        QCOMPARE(int(meaning->timeUnit), time);
    }

    void pressureUnitsConvertToPascal()
    {
        QTemporaryDir dir;
        const QString path = writeFileIn(dir, "baro.csv",
                                       "time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,pressure_hpa\n"
                                       "0,0,0,9.81,0,0,0,1013.25\n0.01,0,0,9.81,0,0,0,1013.2\n");
        const ImportResult read = importOrFail(path);
        QVERIFY(read.recording.hasPressure());
        QCOMPARE(read.recording.samples[0].pressure_pa, 101325.0);
    }

    void headerlessGuess_isConfidentOnlyWhenTheDataAgree()
    {
        // 2 s of a foot at rest at 100 Hz: time in ms, acc in m/s^2, gyr, then pressure.
        QByteArray usual;
        QByteArray swapped;  // gyroscope first: read as the usual layout, |a| is no gravity
        for (int k = 0; k < 200; ++k) {
            const QByteArray time = QByteArray::number(1000 + 10 * k);
            usual += time + ",0.3,-0.2,9.79,0.01,-0.02,0.005,101325\n";
            swapped += time + ",0.01,-0.02,0.005,0.3,-0.2,9.79,101325\n";
        }
        QTemporaryDir dir;
        const ColumnMapGuess good = guessColumnMap(writeFileIn(dir, "usual.txt", usual).toStdString(), {});
        QCOMPARE(good.columnMap, (std::vector<std::string>{"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y",
                                                           "gyr_z", "pressure_pa"}));
        QVERIFY2(good.confident, good.doubt.c_str());
        const ColumnMapGuess bad = guessColumnMap(writeFileIn(dir, "swapped.txt", swapped).toStdString(), {});
        QVERIFY(!bad.confident);
        QVERIFY2(QString::fromStdString(bad.doubt).contains("not gravity"), bad.doubt.c_str());
        const ColumnMapGuess prose = guessColumnMap(writeFileIn(dir, "prose.txt", "Hello there.\nNo data.\n").toStdString(), {});
        QVERIFY(!prose.confident);
        QVERIFY2(QString::fromStdString(prose.doubt).contains("does not look like sensor data"), prose.doubt.c_str());
    }

    void columnGuess_readsTheHeaderAndChecksRolesAgainstTheValues()
    {
        // A logger's export whose gyroscope names are not known: the dialog used to propose the
        // usual headerless layout, time in ms (a 200 kHz rate for this seconds column) and the
        // magnetometer's x as a pressure in Pa. Now the names give the roles they can, the values
        // the time unit, and the magnetometer stays a magnetometer.
        QByteArray text = "Time,AX,AY,AZ,Roll rate,Pitch rate,Yaw rate,MX,MY,MZ\n";
        for (int k = 0; k < 400; ++k)
            text += QByteArray::number(0.005 * k, 'f', 3) + ",0.01,0.02,-1.0,0.01,0.0,0.02,0.21,0.05,-0.43\n";
        QTemporaryDir dir;
        const std::string path = writeFileIn(dir, "export.csv", text).toStdString();
        const ColumnMapGuess guess = guessColumnMap(path, {});
        QCOMPARE(guess.headerLine, std::size_t(1));
        QCOMPARE(guess.headerNames.size(), std::size_t(10));
        QCOMPARE(QString::fromStdString(guess.headerNames[4]), QStringLiteral("Roll rate"));
        QCOMPARE(guess.columnMap, (std::vector<std::string>{"time_s", "acc_x", "acc_y", "acc_z", "skip", "skip", "skip",
                                                            "mag_x", "mag_y", "mag_z"}));
        QVERIFY(!guess.confident);  // no gyroscope: the user says which columns hold it
        QVERIFY2(QString::fromStdString(guess.doubt).contains("gyr"), guess.doubt.c_str());
        QString notes;
        for (const std::string& note : guess.notes)
            notes += QString::fromStdString(note) + "\n";
        QVERIFY2(notes.contains("time in seconds, 200 Hz"), qPrintable(notes));
        QVERIFY2(notes.contains("Roll rate"), qPrintable(notes));

        // With the gyroscope named by the user, the file reads right; the header row is said to be
        // replaced by the map, not reported as a damaged row.
        ImportOptions options;
        options.columnMap = {"time_s", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "mag_x", "mag_y", "mag_z"};
        const ColumnMapCheck fine = checkColumnMap(headOfFile(path, kColumnGuessBytes), path, options);
        QVERIFY2(fine.refusals.empty(), fine.refusals.empty() ? "" : fine.refusals.front().c_str());
        QVERIFY2(fine.doubts.empty(), fine.doubts.empty() ? "" : fine.doubts.front().c_str());
        const ImportResult read = importOrFail(QString::fromStdString(path), options);
        QCOMPARE(read.recording.samples.size(), std::size_t(400));
        QVERIFY(!read.recording.warnings.empty());
        QVERIFY2(QString::fromStdString(read.recording.warnings.front()).startsWith("line 1 is a header row (Time, AX"),
                 read.recording.warnings.front().c_str());
        for (const std::string& warning : read.recording.warnings)
            QVERIFY2(warning.find("skipped") == std::string::npos, warning.c_str());

        // What the old guess proposed is refused before Open, saying why.
        options.columnMap[0] = "time_ms";
        const ColumnMapCheck tooFast = checkColumnMap(headOfFile(path, kColumnGuessBytes), path, options);
        QVERIFY(!tooFast.refusals.empty());
        QVERIFY2(QString::fromStdString(tooFast.refusals.front()).contains("rate is 2e+05 Hz"), tooFast.refusals.front().c_str());
        options.columnMap[0] = "time_s";
        options.columnMap[7] = "pressure_pa";
        const ColumnMapCheck noBarometer = checkColumnMap(headOfFile(path, kColumnGuessBytes), path, options);
        QVERIFY(!noBarometer.refusals.empty());
        QVERIFY2(QString::fromStdString(noBarometer.refusals.front()).contains("no barometer"),
                 noBarometer.refusals.front().c_str());
    }

    void columnGuess_skipsAColumnThatHoldsNoPressure()
    {
        // Headerless: time in ms, acc in m/s^2, gyr, then three unit-norm floats (a magnetometer):
        // read as the usual layout, column 8 was a pressure and the barometric height +-3000 m.
        QByteArray text;
        for (int k = 0; k < 300; ++k)
            text += QByteArray::number(1000 + 10 * k) + ",0.3,-0.2,9.79,0.01,-0.02,0.005,0.5512,0.1021,-0.8277\n";
        QTemporaryDir dir;
        const ColumnMapGuess guess = guessColumnMap(writeFileIn(dir, "log.txt", text).toStdString(), {});
        QVERIFY(guess.headerNames.empty());
        QCOMPARE(QString::fromStdString(guess.columnMap[0]), QStringLiteral("time_ms"));
        QCOMPARE(QString::fromStdString(guess.columnMap[7]), QStringLiteral("skip"));
        QVERIFY2(guess.confident, guess.doubt.c_str());
        QVERIFY(std::any_of(guess.notes.begin(), guess.notes.end(),
                            [](const std::string& note) { return note.find("no air pressure") != std::string::npos; }));
        // A pressure in hPa is taken as one.
        QByteArray hpa;
        for (int k = 0; k < 300; ++k)
            hpa += QByteArray::number(0.01 * k, 'f', 2) + ",0.3,-0.2,9.79,0.01,-0.02,0.005,1013.2\n";
        const ColumnMapGuess inHpa = guessColumnMap(writeFileIn(dir, "hpa.txt", hpa).toStdString(), {});
        QCOMPARE(QString::fromStdString(inHpa.columnMap[0]), QStringLiteral("time_s"));  // the values' steps, not the usual ms
        QCOMPARE(QString::fromStdString(inHpa.columnMap[7]), QStringLiteral("pressure_hpa"));
        QVERIFY2(inHpa.confident, inHpa.doubt.c_str());
    }

    void nearestNames_suggestCloseNamesOnly()
    {
        const std::vector<std::string> names = {"acc_std_max_mps2", "acc_min_mps2", "gyr_max_radps", "window_s"};
        QCOMPARE(nearestNames("gyr_max", names), std::vector<std::string>{"gyr_max_radps"});
        QCOMPARE(nearestNames("acc_std_max_mps", names).front(), std::string("acc_std_max_mps2"));
        QCOMPARE(nearestNames("windwo_s", names), std::vector<std::string>{"window_s"});  // a swap is one edit
        QVERIFY(nearestNames("zzzzzzzz", names).empty());
        QVERIFY(nearestNames("acc", names, 3).size() <= 3);
        QCOMPARE(editDistance("kitten", "sitting"), std::size_t(3));
        QCOMPARE(didYouMean("--closed-lop", {"--closed-loop", "--json"}), std::string("; did you mean --closed-loop?"));
        QVERIFY(didYouMean("--xyz", {"--closed-loop", "--json"}).empty());
    }

    void unknownPresetKey_suggestsTheNearestParameter()
    {
        Parameters params;
        const std::string problem = parametersFromJson(
            R"({"format": "footpath-parameters", "version": 1, "parameters": {"gyr_max_radp": 1.0}})", "p.json", params);
        QVERIFY2(QString::fromStdString(problem).contains("unknown parameter 'gyr_max_radp'; did you mean gyr_max_radps"),
                 problem.c_str());
        QVERIFY2(QString::fromStdString(setParameterByName(params, "gyr_max", "1")).contains("did you mean gyr_max_radps"),
                 "setParameterByName");
    }
};

QTEST_GUILESS_MAIN(TestImport)
#include "tst_import.moc"
