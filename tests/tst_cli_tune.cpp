// footpath-cli tune run as a process (FOOTPATH_CLI) on simulated closed walks written into a
// QTemporaryDir: the criterion per file before and after, the changed parameters, a preset that
// eval reads back with the figure tune printed, and the option checks. Whether tuning finds the
// best setting is tst_autotune's business.

#include "CliRunner.h"
#include "io/ParameterIo.h"
#include "sim/WalkSimulator.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace clitest;

class TestCliTune : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        for (std::uint32_t seed = 1; seed <= 2; ++seed) {
            footpath::WalkSimulatorConfig sensor = footpath::mtiClassSensor(100.0, seed);
            sensor.accNoiseStd_mps2 *= 3.0;
            const auto walk = footpath::simulateWalk(footpath::closedRectanglePath(8.0, 5.0), sensor);
            const QString path = dir_.filePath(QStringLiteral("walk%1.csv").arg(seed));
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(imuCsv(walk.recording.samples));
            walks_ << path;
        }
    }

    void tuneSavesAPresetThatEvalReproduces()
    {
        const QString preset = dir_.filePath(QStringLiteral("tuned.json"));
        const Run run = runCli(QStringList{QStringLiteral("tune")} + walks_
                               + QStringList{QStringLiteral("--closed-loop"), QStringLiteral("--criterion"),
                                             QStringLiteral("closed-loop"), QStringLiteral("--evaluations"),
                                             QStringLiteral("24"), QStringLiteral("--json"), QStringLiteral("--out"),
                                             preset});
        VERIFY_EXIT(run, 0);
        const QJsonObject json = QJsonDocument::fromJson(run.out.toUtf8()).object();
        QCOMPARE(json.value(QStringLiteral("evaluations")).toInt(), 24);
        QCOMPARE(json.value(QStringLiteral("unit")).toString(), QStringLiteral("%"));
        const double before = json.value(QStringLiteral("before")).toDouble();
        const double after = json.value(QStringLiteral("after")).toDouble();
        QVERIFY2(after <= before, qPrintable(run.out));
        const QJsonArray rows = json.value(QStringLiteral("recordings")).toArray();
        QCOMPARE(rows.size(), 2);

        // The preset holds what tune printed: eval with it gives the same closure per walk.
        footpath::Parameters tuned;
        QVERIFY(footpath::loadParameters(preset.toStdString(), tuned).empty());
        QCOMPARE(json.value(QStringLiteral("changed")).toObject().isEmpty(), tuned == footpath::Parameters());
        for (int i = 0; i < 2; ++i) {
            const Run eval = runCli({QStringLiteral("eval"), walks_[i], QStringLiteral("--closed-loop"),
                                     QStringLiteral("--json"), QStringLiteral("--params"), preset});
            VERIFY_EXIT(eval, 0);
            const double closure =
                QJsonDocument::fromJson(eval.out.toUtf8()).object().value(QStringLiteral("dbse_pct")).toDouble();
            QVERIFY2(std::abs(closure - rows[i].toObject().value(QStringLiteral("after")).toDouble()) < 1e-6,
                     qPrintable(eval.out));
        }
    }

    void textNamesEachFileAndTheMean()
    {
        const Run run = runCli(QStringList{QStringLiteral("tune")} + walks_
                               + QStringList{QStringLiteral("--closed-loop"), QStringLiteral("--criterion"),
                                             QStringLiteral("closed-loop"), QStringLiteral("--evaluations"),
                                             QStringLiteral("9"), QStringLiteral("--out"),
                                             dir_.filePath(QStringLiteral("t2.json"))});
        VERIFY_EXIT(run, 0);
        QVERIFY2(run.out.contains(QStringLiteral("walk1.csv")) && run.out.contains(QStringLiteral("walk2.csv"))
                     && run.out.contains(QStringLiteral("mean")) && run.out.contains(QStringLiteral("saved")),
                 qPrintable(run.out));
    }

    void badOptionsExitTwoSayingWhy_data()
    {
        QTest::addColumn<QStringList>("extra");
        QTest::addColumn<QString>("message");
        QTest::newRow("no criterion") << QStringList{QStringLiteral("--out"), QStringLiteral("x.json")}
                                      << QStringLiteral("--criterion");
        QTest::newRow("unknown criterion") << QStringList{QStringLiteral("--criterion"), QStringLiteral("loop"),
                                                          QStringLiteral("--out"), QStringLiteral("x.json")}
                                           << QStringLiteral("closed-loop, length or reference");
        QTest::newRow("no output") << QStringList{QStringLiteral("--criterion"), QStringLiteral("length")}
                                   << QStringLiteral("--out");
        QTest::newRow("nothing to score") << QStringList{QStringLiteral("--criterion"), QStringLiteral("length"),
                                                         QStringLiteral("--out"), QStringLiteral("x.json")}
                                          << QStringLiteral("known length");
    }

    void badOptionsExitTwoSayingWhy()
    {
        QFETCH(QStringList, extra);
        QFETCH(QString, message);
        const Run run = runCli(QStringList{QStringLiteral("tune"), walks_.front()} + extra, dir_.path());
        VERIFY_EXIT(run, kExitBadInput);
        QVERIFY2(run.err.contains(message), qPrintable(run.err));
    }

private:
    QTemporaryDir dir_;
    QStringList walks_;
};

QTEST_GUILESS_MAIN(TestCliTune)
#include "tst_cli_tune.moc"
