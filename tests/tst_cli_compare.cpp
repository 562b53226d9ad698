// footpath-cli compare run as a process (FOOTPATH_CLI) on simulated walks written into a
// QTemporaryDir and on the shared recordings: the sets in the order given with the figures the
// issue names, the best value marked, one table per input and the means per set for several
// inputs, the suggested sets without --sets, and exit code 2 naming the nearest method for an
// unknown one. Whether a method helps is the methods' own tests' business; here only the report.

#include "CliRunner.h"
#include "TestData.h"
#include "nav/MethodSets.h"
#include "sim/WalkSimulator.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

using namespace clitest;

const QString kEcgColumns = QStringLiteral("time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z");

bool writeImuCsv(const QString& path, const std::vector<footpath::ImuSample>& samples)
{
    const QByteArray text = imuCsv(samples);
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(text) == text.size();
}

QJsonObject parseObject(const QString& text)
{
    const QJsonDocument document = QJsonDocument::fromJson(text.toUtf8());
    return document.isObject() ? document.object() : QJsonObject();
}

QStringList namesOf(const QJsonArray& sets)
{
    QStringList names;
    for (const QJsonValue& set : sets)
        names << set.toObject().value(QStringLiteral("name")).toString();
    return names;
}

/// The contract for every set object: these keys, as numbers.
bool hasRequiredFigures(const QJsonObject& set)
{
    for (const char* key : {"end_to_start_m", "end_to_start_pct", "path_length_m"})
        if (!set.value(QLatin1String(key)).isDouble())
            return false;
    return set.value(QStringLiteral("name")).isString();
}

/// The name of the set with the smallest (largest when `largest`) value of key, among those with one.
QString bestByHand(const QJsonArray& sets, const QString& key, bool largest = false)
{
    QString best;
    double bestValue = 0.0;
    for (const QJsonValue& entry : sets) {
        const QJsonValue value = entry.toObject().value(key);
        if (!value.isDouble())
            continue;
        if (best.isEmpty() || (largest ? value.toDouble() > bestValue : value.toDouble() < bestValue)) {
            best = entry.toObject().value(QStringLiteral("name")).toString();
            bestValue = value.toDouble();
        }
    }
    return best;
}

/// Table rows of a text report: the lines starting with one of the set names, in printed order.
QStringList rowsFor(const QString& out, const QStringList& names)
{
    QStringList rows;
    for (const QString& line : out.split(QLatin1Char('\n')))
        for (const QString& name : names)
            if (line.startsWith(name + QLatin1Char(' ')))
                rows << line;
    return rows;
}

}  // namespace

class TestCliCompare : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void json_listsTheSetsInOrderWithTheirFigures();
    void text_printsOneRowPerSetAndMarksTheBest();
    void withoutSets_runsTheSuggestedSets();
    void severalInputs_giveATableEachAndTheMeans();
    void jobs_doNotChangeTheOutput();
    void unreadableFileInAFolder_isReportedInItsPlace();
    void unknownMethod_exitsTwoNamingTheNearest();
    void setsOutsideCompare_isRejected();
    void pyshoeTrial_givesArmsePerSet();
    void ecgRectangle_givesEndToStartPerSet();

private:
    QTemporaryDir dir_;
    QString loopCsv_;      ///< a closed rectangle
    QString straightCsv_;  ///< a straight line
    double loopLength_m_ = 0.0;
    double straightLength_m_ = 0.0;
};

void TestCliCompare::initTestCase()
{
    QVERIFY2(QFileInfo(QString::fromUtf8(FOOTPATH_CLI)).isExecutable(), FOOTPATH_CLI);
    QVERIFY(dir_.isValid());
    const footpath::SimulatedWalk loop = footpath::simulateWalk(footpath::closedRectanglePath(8.0, 5.0), {});
    const footpath::SimulatedWalk straight = footpath::simulateWalk(footpath::straightLinePath(12.0), {});
    loopLength_m_ = loop.truePathLength_m;
    straightLength_m_ = straight.truePathLength_m;
    QVERIFY(std::abs(loopLength_m_ - 26.0) < 1e-9);
    loopCsv_ = dir_.filePath(QStringLiteral("loop.csv"));
    straightCsv_ = dir_.filePath(QStringLiteral("straight.csv"));
    QVERIFY(writeImuCsv(loopCsv_, loop.recording.samples));
    QVERIFY(writeImuCsv(straightCsv_, straight.recording.samples));
}

void TestCliCompare::json_listsTheSetsInOrderWithTheirFigures()
{
    const QStringList order{QStringLiteral("zupt,zaru"), QStringLiteral("zupt"), QStringLiteral("zupt,15state")};
    const Run run = runCli({QStringLiteral("compare"), loopCsv_, QStringLiteral("--sets"),
                            QStringLiteral("zupt,zaru; ZUPT ;zupt,15state"), QStringLiteral("--json")});
    VERIFY_EXIT(run, 0);
    const QJsonObject root = parseObject(run.out);
    QCOMPARE(root.value(QStringLiteral("input")).toString(), loopCsv_);
    const QJsonArray sets = root.value(QStringLiteral("sets")).toArray();
    QCOMPARE(namesOf(sets), order);  // the order given, the tokens normalised
    for (const QJsonValue& entry : sets) {
        const QJsonObject set = entry.toObject();
        QVERIFY2(hasRequiredFigures(set), qPrintable(run.out));
        QVERIFY(set.value(QStringLiteral("height_change_m")).isDouble());
        QVERIFY(set.value(QStringLiteral("steps")).toInt() > 10);
        QVERIFY(set.value(QStringLiteral("warnings")).isArray());
        // The simulated file has no reference: no ARMSE, no F1.
        QVERIFY(!set.contains(QStringLiteral("armse_2d_m")) && !set.contains(QStringLiteral("stance_f1")));
        // The percentage is of the estimated path.
        const double pathLength = set.value(QStringLiteral("path_length_m")).toDouble();
        QVERIFY(std::abs(set.value(QStringLiteral("end_to_start_pct")).toDouble()
                         - 100.0 * set.value(QStringLiteral("end_to_start_m")).toDouble() / pathLength)
                < 1e-6);
    }
    // Plain ZUPT on a noiseless walk: the walked length, and back at the start.
    const QJsonObject zupt = sets[1].toObject();
    QVERIFY2(std::abs(zupt.value(QStringLiteral("path_length_m")).toDouble() - loopLength_m_) < 0.03 * loopLength_m_,
             qPrintable(run.out));
    QVERIFY2(zupt.value(QStringLiteral("end_to_start_pct")).toDouble() < 2.0, qPrintable(run.out));
    // "best" names the set with the smallest end-to-start, and nothing for figures no set has.
    const QJsonObject best = root.value(QStringLiteral("best")).toObject();
    QCOMPARE(best.value(QStringLiteral("end_to_start_m")).toString(),
             bestByHand(sets, QStringLiteral("end_to_start_m")));
    QVERIFY(!best.contains(QStringLiteral("armse_2d_m")));
}

void TestCliCompare::text_printsOneRowPerSetAndMarksTheBest()
{
    const QStringList names{QStringLiteral("zupt"), QStringLiteral("zupt,zaru"), QStringLiteral("feliz")};
    const Run run = runCli({QStringLiteral("compare"), loopCsv_, QStringLiteral("--sets"), names.join(';')});
    VERIFY_EXIT(run, 0);
    const Run json = runCli({QStringLiteral("compare"), loopCsv_, QStringLiteral("--sets"), names.join(';'),
                             QStringLiteral("--json")});
    VERIFY_EXIT(json, 0);
    QVERIFY2(run.out.contains(QStringLiteral("end-start m")) && !run.out.contains(QStringLiteral("ARMSE2D m")),
             qPrintable(run.out));
    const QStringList rows = rowsFor(run.out, names);
    QCOMPARE(int(rows.size()), names.size());
    const QString bestSet = bestByHand(parseObject(json.out).value(QStringLiteral("sets")).toArray(),
                                       QStringLiteral("end_to_start_m"));
    // The first figure of a row is its end-to-start; the best one carries the '*'.
    const QRegularExpression firstFigure(QStringLiteral("^\\S+\\s+([0-9.]+)(\\*?)"));
    int marked = 0;
    for (int i = 0; i < rows.size(); ++i) {
        const QRegularExpressionMatch match = firstFigure.match(rows[i]);
        QVERIFY2(match.hasMatch() && rows[i].startsWith(names[i] + QLatin1Char(' ')), qPrintable(run.out));
        const bool star = !match.captured(2).isEmpty();
        QCOMPARE(star, names[i] == bestSet);
        marked += star ? 1 : 0;
    }
    QCOMPARE(marked, 1);
}

void TestCliCompare::withoutSets_runsTheSuggestedSets()
{
    const Run run = runCli({QStringLiteral("compare"), straightCsv_, QStringLiteral("--json")});
    VERIFY_EXIT(run, 0);
    const QStringList suggested =
        QString::fromStdString(footpath::suggestedMethodSetsSpec()).split(QLatin1Char(';'), Qt::SkipEmptyParts);
    QVERIFY(suggested.size() >= 5);
    const QJsonArray sets = parseObject(run.out).value(QStringLiteral("sets")).toArray();
    QCOMPARE(namesOf(sets), suggested);
    for (const QJsonValue& set : sets)
        QVERIFY2(hasRequiredFigures(set.toObject()), qPrintable(run.out));
}

void TestCliCompare::severalInputs_giveATableEachAndTheMeans()
{
    const QStringList names{QStringLiteral("zupt"), QStringLiteral("zupt,zaru")};
    const QStringList args{QStringLiteral("compare"), loopCsv_, straightCsv_, QStringLiteral("--sets"),
                           names.join(';')};
    const Run text = runCli(args);
    VERIFY_EXIT(text, 0);
    // A table per input in the order given, then the means: each set has three rows.
    const qsizetype loopAt = text.out.indexOf(QStringLiteral("input       ") + loopCsv_);
    const qsizetype straightAt = text.out.indexOf(QStringLiteral("input       ") + straightCsv_);
    const qsizetype meanAt = text.out.indexOf(QStringLiteral("mean per set over 2 of 2 inputs"));
    QVERIFY2(loopAt >= 0 && loopAt < straightAt && straightAt < meanAt, qPrintable(text.out));
    QCOMPARE(int(rowsFor(text.out, names).size()), 3 * names.size());

    const Run json = runCli(args + QStringList{QStringLiteral("--json")});
    VERIFY_EXIT(json, 0);
    const QJsonObject root = parseObject(json.out);
    const QJsonArray inputs = root.value(QStringLiteral("inputs")).toArray();
    QCOMPARE(int(inputs.size()), 2);
    QCOMPARE(inputs[0].toObject().value(QStringLiteral("input")).toString(), loopCsv_);
    QCOMPARE(inputs[1].toObject().value(QStringLiteral("input")).toString(), straightCsv_);
    const QJsonArray means = root.value(QStringLiteral("sets")).toArray();
    QCOMPARE(root.value(QStringLiteral("summary")).toObject().value(QStringLiteral("sets")).toArray(), means);
    QCOMPARE(namesOf(means), names);
    for (int s = 0; s < names.size(); ++s) {
        const QJsonObject mean = means[s].toObject();
        QVERIFY2(hasRequiredFigures(mean), qPrintable(json.out));
        QCOMPARE(mean.value(QStringLiteral("count")).toInt(), 2);
        for (const char* key : {"end_to_start_m", "path_length_m", "steps"}) {
            double sum = 0.0;
            for (const QJsonValue& input : inputs) {
                const QJsonArray sets = input.toObject().value(QStringLiteral("sets")).toArray();
                QCOMPARE(namesOf(sets), names);
                sum += sets[s].toObject().value(QLatin1String(key)).toDouble();
            }
            QVERIFY2(std::abs(mean.value(QLatin1String(key)).toDouble() - sum / 2.0) < 1e-9, key);
        }
    }
    // Plain ZUPT's mean path is the mean walked length.
    QVERIFY(std::abs(means[0].toObject().value(QStringLiteral("path_length_m")).toDouble()
                     - (loopLength_m_ + straightLength_m_) / 2.0)
            < 0.03 * (loopLength_m_ + straightLength_m_) / 2.0);
}

void TestCliCompare::jobs_doNotChangeTheOutput()
{
    const QStringList args{QStringLiteral("compare"), loopCsv_, QStringLiteral("--sets"),
                           QStringLiteral("zupt;zupt,zaru;zupt,hdr;feliz"), QStringLiteral("--json")};
    const Run one = runCli(args + QStringList{QStringLiteral("--jobs"), QStringLiteral("1")});
    const Run two = runCli(args + QStringList{QStringLiteral("--jobs"), QStringLiteral("2")});
    VERIFY_EXIT(one, 0);
    VERIFY_EXIT(two, 0);
    QCOMPARE(two.out, one.out);
}

void TestCliCompare::unreadableFileInAFolder_isReportedInItsPlace()
{
    QTemporaryDir work;
    QVERIFY(work.isValid());
    QVERIFY(QFile::copy(straightCsv_, work.filePath(QStringLiteral("a.csv"))));
    const QString junk = work.filePath(QStringLiteral("b.csv"));
    QFile file(junk);
    QVERIFY(file.open(QIODevice::WriteOnly) && file.write(QByteArray("\x00\x01 not a recording\n", 19)) == 19);
    file.close();

    const Run run = runCli({QStringLiteral("compare"), work.path(), QStringLiteral("--sets"),
                            QStringLiteral("zupt;zupt,zaru"), QStringLiteral("--json")});
    VERIFY_EXIT(run, kExitBadInput);  // the others go on, the exit code says one failed
    QVERIFY2(run.err.contains(QStringLiteral("could not compare ")) && run.err.contains(junk), qPrintable(run.err));
    const QJsonObject root = parseObject(run.out);
    const QJsonArray inputs = root.value(QStringLiteral("inputs")).toArray();
    QCOMPARE(int(inputs.size()), 2);
    QCOMPARE(namesOf(inputs[0].toObject().value(QStringLiteral("sets")).toArray()),
             (QStringList{QStringLiteral("zupt"), QStringLiteral("zupt,zaru")}));
    QVERIFY(inputs[1].toObject().value(QStringLiteral("error")).toString().startsWith(junk));
    for (const QJsonValue& mean : root.value(QStringLiteral("sets")).toArray())
        QCOMPARE(mean.toObject().value(QStringLiteral("count")).toInt(), 1);
}

void TestCliCompare::unknownMethod_exitsTwoNamingTheNearest()
{
    const Run run = runCli({QStringLiteral("compare"), loopCsv_, QStringLiteral("--sets"),
                            QStringLiteral("zupt;zupt,hdrr")});
    VERIFY_EXIT(run, kExitBadInput);
    QVERIFY2(run.err.contains(QStringLiteral("unknown method 'hdrr'"))
                 && run.err.contains(QStringLiteral("did you mean 'hdr'")),
             qPrintable(run.err));
    QVERIFY2(run.out.isEmpty(), qPrintable(run.out));
}

void TestCliCompare::setsOutsideCompare_isRejected()
{
    const Run run = runCli({QStringLiteral("eval"), loopCsv_, QStringLiteral("--sets"), QStringLiteral("zupt")});
    VERIFY_EXIT(run, kExitBadInput);
    QVERIFY2(run.err.contains(QStringLiteral("--sets belongs to compare")), qPrintable(run.err));
}

void TestCliCompare::pyshoeTrial_givesArmsePerSet()
{
    FOOTPATH_REQUIRE_DATASETS();
    const QString trial = datasetPath(QStringLiteral("pyshoe-vicon/2017-11-22-11-22-03.csv"));
    const QStringList names{QStringLiteral("zupt"), QStringLiteral("zupt,zaru"), QStringLiteral("feliz")};
    const Run run = runCli({QStringLiteral("compare"), trial, QStringLiteral("--sets"), names.join(';'),
                            QStringLiteral("--json")});
    VERIFY_EXIT(run, 0);
    const QJsonObject root = parseObject(run.out);
    const QJsonArray sets = root.value(QStringLiteral("sets")).toArray();
    QCOMPARE(namesOf(sets), names);
    for (const QJsonValue& entry : sets) {
        const QJsonObject set = entry.toObject();
        QVERIFY2(hasRequiredFigures(set), qPrintable(run.out));
        // Against VICON: an ARMSE per set, a fraction of the ~27 m walk rather than metres.
        const double armse = set.value(QStringLiteral("armse_2d_m")).toDouble(-1.0);
        QVERIFY2(armse > 0.0 && armse < 1.0, qPrintable(run.out));
    }
    QCOMPARE(root.value(QStringLiteral("best")).toObject().value(QStringLiteral("armse_2d_m")).toString(),
             bestByHand(sets, QStringLiteral("armse_2d_m")));

    const Run text = runCli({QStringLiteral("compare"), trial, QStringLiteral("--sets"), names.join(';')});
    VERIFY_EXIT(text, 0);
    QVERIFY2(text.out.contains(QStringLiteral("ARMSE2D m")), qPrintable(text.out));
    QCOMPARE(int(rowsFor(text.out, names).size()), names.size());
}

void TestCliCompare::ecgRectangle_givesEndToStartPerSet()
{
    FOOTPATH_REQUIRE_DATASETS();
    const QString file = datasetPath(QStringLiteral("ecg-xmu/rectangle_72m.TXT"));
    const QStringList names{QStringLiteral("zupt"), QStringLiteral("zupt,hdr"), QStringLiteral("zupt,hdr,iper")};
    const QStringList args{QStringLiteral("compare"), file, QStringLiteral("--columns"), kEcgColumns,
                           QStringLiteral("--sets"), names.join(';')};
    const Run text = runCli(args);
    VERIFY_EXIT(text, 0);
    const QStringList rows = rowsFor(text.out, names);
    QCOMPARE(int(rows.size()), names.size());
    for (const QString& row : rows)
        QVERIFY2(QRegularExpression(QStringLiteral("^\\S+\\s+[0-9]+\\.[0-9]{3}\\*?\\s+[0-9]+\\.[0-9]{2}"))
                     .match(row)
                     .hasMatch(),
                 qPrintable(text.out));

    const Run json = runCli(args + QStringList{QStringLiteral("--json")});
    VERIFY_EXIT(json, 0);
    const QJsonArray sets = parseObject(json.out).value(QStringLiteral("sets")).toArray();
    QCOMPARE(namesOf(sets), names);
    for (const QJsonValue& entry : sets) {
        const QJsonObject set = entry.toObject();
        QVERIFY2(hasRequiredFigures(set), qPrintable(json.out));
        QVERIFY(!set.contains(QStringLiteral("armse_2d_m")));  // a known length only, no positions
        // Every set walks the 72 m rectangle, give or take the stride scale.
        QVERIFY2(std::abs(set.value(QStringLiteral("path_length_m")).toDouble() - 72.0) < 0.15 * 72.0,
                 qPrintable(json.out));
    }
}

QTEST_GUILESS_MAIN(TestCliCompare)
#include "tst_cli_compare.moc"
