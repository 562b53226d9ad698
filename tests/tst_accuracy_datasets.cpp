// Accuracy of the default pipeline on the real recordings in ../shared/datasets, measured the way a
// user measures it: `footpath-cli eval --json` over the recordings (the metrics of docs/accuracy.md). Every
// table is printed, however bad; the bounds are the figures the defaults reach today, so a change
// that makes any dataset worse fails here. The targets are printed beside them.
#include "TestData.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>

#ifndef FOOTPATH_CLI
#error "FOOTPATH_CLI must name the footpath-cli binary"
#endif

namespace {

/// Runs footpath-cli eval --json with the arguments; fails the test on a non-zero exit.
QJsonObject evalJson(const QStringList& arguments)
{
    QProcess process;
    process.start(QString::fromUtf8(FOOTPATH_CLI), QStringList{"eval", "--json"} + arguments);
    if (!process.waitForFinished(300000) || process.exitCode() != 0)
        qFatal("footpath-cli eval %s failed: %s", qPrintable(arguments.join(' ')),
               process.readAllStandardError().constData());
    return QJsonDocument::fromJson(process.readAllStandardOutput()).object();
}

QJsonObject summaryOf(const QJsonObject& batch, const char* metric)
{
    return batch.value("summary").toObject().value(metric).toObject();
}

/// One line per recording with the metrics named.
void printTable(const QJsonObject& batch, const QStringList& metrics)
{
    qInfo("%s", qPrintable(QStringLiteral("parameters %1, methods %2")
                               .arg(batch.value("parameters").toString(), batch.value("methods").toString())));
    for (const QJsonValue& row : batch.value("recordings").toArray()) {
        const QJsonObject recording = row.toObject();
        QString line = QFileInfo(recording.value("recording").toString()).fileName().leftJustified(26);
        for (const QString& metric : metrics)
            line += QStringLiteral(" %1=%2").arg(metric).arg(recording.value(metric).toDouble(), 0, 'f', 4);
        line += QStringLiteral(" warnings=%1").arg(recording.value("warning_count").toInt());
        qInfo("%s", qPrintable(line));
    }
    for (const QString& metric : metrics) {
        const QJsonObject s = summaryOf(batch, metric.toUtf8().constData());
        qInfo("  %-22s mean %.4f  median %.4f  worst %.4f  (%d)", qPrintable(metric), s.value("mean").toDouble(),
              s.value("median").toDouble(), s.value("worst").toDouble(), s.value("count").toInt());
    }
}

QStringList warningKinds(const QJsonObject& recording)
{
    QStringList kinds;
    for (const QJsonValue& warning : recording.value("warnings").toArray())
        kinds << warning.toObject().value("kind").toString();
    return kinds;
}

const QString kEcgColumns11 = "time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,pressure_pa,skip,skip,skip";
const QString kEcgColumns8 = "time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,pressure_pa";
const QString kEcgColumns7 = "time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z";

}  // namespace

class TestAccuracyDatasets : public QObject {
    Q_OBJECT
private slots:
    void init() { FOOTPATH_REQUIRE_DATASETS(); }

    void pyshoeViconAllTwelveTrials()
    {
        const QJsonObject batch = evalJson({datasetPath("pyshoe-vicon")});
        printTable(batch, {"armse_2d_m", "dbse_m"});
        const QJsonObject armse = summaryOf(batch, "armse_2d_m");
        QCOMPARE(armse.value("count").toInt(), 12);
        qInfo("pyshoe-vicon mean 2D ARMSE %.4f m, worst %.4f m (paper detector 4.39 m; issue target <= 0.055 m, "
              "none above 0.15 m; pyshoe's per-trial oracle threshold 0.057 m)",
              armse.value("mean").toDouble(), armse.value("worst").toDouble());
        // The smoother's figures (0.0492 / 0.1210 m); the filter alone (--set estimator=ekf) scores
        // 0.0535 / 0.1324 m with the same noise.
        QVERIFY2(armse.value("mean").toDouble() <= 0.055, "mean 2D ARMSE over the 12 trials (the issue's target)");
        QVERIFY2(armse.value("worst").toDouble() <= 0.150, "worst 2D ARMSE (the issue's bound)");
    }

    void ecgXmuClosedWalks()
    {
        const QJsonObject rectangle =
            evalJson({"--columns", kEcgColumns7, "--closed-loop", datasetPath("ecg-xmu/rectangle_72m.TXT")});
        const QJsonObject shapes = evalJson({"--columns", kEcgColumns11, "--closed-loop",
                                             datasetPath("ecg-xmu/mage_juxing_1.txt"),
                                             datasetPath("ecg-xmu/mage_sanjiaoxing_1.txt"),
                                             datasetPath("ecg-xmu/mage_yuan_1.txt")});
        printTable(shapes, {"dbse_pct", "dbse_m"});
        std::vector<double> closures{rectangle.value("dbse_pct").toDouble()};
        for (const QJsonValue& row : shapes.value("recordings").toArray())
            closures.push_back(row.toObject().value("dbse_pct").toDouble());
        qInfo("rectangle_72m.TXT dbse_pct=%.4f (of 72 m)", closures.front());
        std::sort(closures.begin(), closures.end());
        const double median = (closures[1] + closures[2]) / 2.0;
        qInfo("ecg-xmu closed walks: median closure %.2f %%, worst %.2f %% (paper detector 15.1 %% median, one "
              "diverging; issue target <= 2 %%, none above 5 %%)",
              median, closures.back());
        QVERIFY2(median <= 2.0, "median closure of the four closed ecg-xmu walks");
        QVERIFY2(closures.back() <= 5.0, "worst closure of the four closed ecg-xmu walks");
    }

    void ecgXmuKnownLengths()
    {
        const QJsonObject batch = evalJson({"--columns", kEcgColumns8, datasetPath("ecg-xmu/straight_40.4m.txt"),
                                            datasetPath("ecg-xmu/freewalking_88.8m.txt")});
        printTable(batch, {"distance_error_pct"});
        // These two walks are short by 8-15 % with the defaults: their sensor never comes to rest
        // (|w| stays near 1 rad/s at mid-stance, as on a shank), so every ZUPT removes real motion.
        // The bound guards against it getting worse; docs/method.md explains the trade.
        QVERIFY2(summaryOf(batch, "distance_error_pct").value("worst").toDouble() <= 16.0,
                 "distance error of the ecg-xmu walks of known length");
    }

    void xsensMtwIpolStanceAgainstGaitEvents()
    {
        const QJsonObject batch = evalJson({datasetPath("xsens-mtw-ipol/1-4_lf.txt"), datasetPath("xsens-mtw-ipol/1-4_rf.txt"),
                                            datasetPath("xsens-mtw-ipol/10-1_lf.txt"), datasetPath("xsens-mtw-ipol/10-1_rf.txt"),
                                            datasetPath("xsens-mtw-ipol/14-1_lf.txt"), datasetPath("xsens-mtw-ipol/14-1_rf.txt")});
        printTable(batch, {"stance_precision", "stance_recall", "stance_f1"});
        const double f1 = summaryOf(batch, "stance_f1").value("mean").toDouble();
        qInfo("xsens-mtw-ipol gap-free trials: mean stance F1 %.3f (paper detector 0.26; a ZUPT flag is shorter "
              "than a gait lab's stance, the gait-event issue targets 0.95)",
              f1);
        // The ZUPT flag marks the foot at rest, a part of the gait lab's stance (0.52 with the defaults,
        // whose threshold sits close to the quietest moment); the gait-event detector's stance is the
        // one compared with the lab's (gait stance F1 0.98, tst_gaitevents). This guards the flag's
        // precision-heavy agreement against collapsing.
        QVERIFY2(f1 >= 0.50, "stance F1 on the gap-free IPOL trials");
    }

    void xsensMtwIpolOutAndBack()
    {
        // All six trials, both feet: 10 m out, a U-turn, 10 m back to the start (closed, 20 m; the
        // gait-event JSON marks the U-turn). The closure is the heading's figure: both legs bend the
        // same way, so the walk ends about a metre from its start (the heading issue's subject).
        QStringList files;
        for (const char* trial : {"1-1", "1-4", "10-1", "12-3", "14-1", "3-2"})
            for (const char* foot : {"_lf.txt", "_rf.txt"})
                files << datasetPath(QStringLiteral("xsens-mtw-ipol/%1%2").arg(trial, foot));
        const QJsonObject batch = evalJson(files);
        printTable(batch, {"dbse_pct", "dbse_m", "distance_error_pct", "stride_count_error", "gait_stance_f1"});
        const QJsonObject closure = summaryOf(batch, "dbse_pct");
        QCOMPARE(closure.value("count").toInt(), 12);
        // Today: median 5.92 %, worst 9.79 %; distance error median 4.03 %, worst 12.68 % (12-3,
        // whose 406 lost packets leave gaps the filter bridges).
        QVERIFY2(closure.value("median").toDouble() <= 6.0, "median out-and-back closure (% of 20 m)");
        QVERIFY2(closure.value("worst").toDouble() <= 10.0, "worst out-and-back closure (% of 20 m)");
        QVERIFY2(summaryOf(batch, "distance_error_pct").value("worst").toDouble() <= 13.0, "distance error of 20 m");
        // A stride needs a swing: weight shifts while standing are no strides (counted as strides,
        // 5 of the 12 files had 1 to 4 more than labelled swings). The gap-free trials match the labelled swings exactly; with lost packets the
        // labels' sample indices drift from the rows, so one stride either way is allowed there.
        for (const QJsonValue& row : batch.value("recordings").toArray()) {
            const QJsonObject recording = row.toObject();
            const QString name = QFileInfo(recording.value("recording").toString()).fileName();
            const int error = recording.value("stride_count_error").toInt();
            const bool hasGaps = name.startsWith("1-1") || name.startsWith("12-3") || name.startsWith("3-2");
            QVERIFY2(hasGaps ? std::abs(error) <= 1 : error == 0, qPrintable(QStringLiteral("%1: %2").arg(name).arg(error)));
        }
    }

    void paperDetectorOnTheRunningTrialIsFlagged()
    {
        // The example: the paper's detector finds 2 stances in 26 s of running. The result
        // is nonsense and must say so; the default detector's result on the same trial is sound.
        const QString running = datasetPath("pyshoe-vicon/2017-11-27-11-22-22.csv");
        const QJsonObject paper = evalJson({"--set", "detector=c1c2c3", running});
        const QStringList kinds = warningKinds(paper);
        qInfo("paper detector on the running trial: ARMSE %.2f m, warnings: %s",
              paper.value("armse_2d_m").toDouble(), qPrintable(kinds.join(", ")));
        QVERIFY(kinds.contains("long_swing"));
        QVERIFY(kinds.contains("stride_length"));
        QVERIFY(kinds.contains("implausible_speed"));
        const QJsonObject defaults = evalJson({running});
        QVERIFY(defaults.value("armse_2d_m").toDouble() < 0.5);
        QVERIFY(!warningKinds(defaults).contains("long_swing"));
        QVERIFY(!warningKinds(defaults).contains("implausible_speed"));
    }
};

QTEST_GUILESS_MAIN(TestAccuracyDatasets)
#include "tst_accuracy_datasets.moc"
