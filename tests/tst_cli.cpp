// The real footpath-cli binary (FOOTPATH_CLI) run through QProcess on a simulated 10 m straight walk:
// output files and their formats, the summary's figures, eval's reports (one file, or several files
// and folders at once), presets and --set, and the exit code 2 with a precise message for every
// kind of bad input. Inputs and outputs live in a QTemporaryDir.

#include "CliRunner.h"
#include "TestData.h"
#include "io/ParameterIo.h"
#include "nav/MethodSets.h"
#include "nav/Parameters.h"
#include "sim/WalkSimulator.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace {

using namespace clitest;

// The foundation issue fixes these first columns; the bias estimates follow them.
const QString kTrajectoryHeader =
    QStringLiteral("time_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,roll_rad,pitch_rad,yaw_rad,c1,c2,c3,stance,gait_stance,"
                   "gyro_bias_x_radps,gyro_bias_y_radps,gyro_bias_z_radps,acc_bias_x_mps2,acc_bias_y_mps2,"
                   "acc_bias_z_mps2");
const QString kStepsHeader =
    QStringLiteral("step,stance_start_s,stance_end_s,x_m,y_m,z_m,stride_length_m,stride_duration_s,motion,"
                   "baro_height_m,heel_strike_s,toe_off_s,gait_stance_pct,swing_pct,clearance_m,turning");
const QByteArray kImuHeader = "time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";

bool writeFile(const QString& path, const QByteArray& content)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(content) == content.size();
}

QStringList readLines(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'));
    if (!lines.isEmpty() && lines.last().isEmpty())
        lines.removeLast();
    return lines;
}

QJsonObject readJsonObject(const QByteArray& text, QString* error)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(text, &parseError);
    if (document.isNull() || !document.isObject()) {
        *error = parseError.errorString() + QStringLiteral(" in: ") + QString::fromUtf8(text);
        return {};
    }
    return document.object();
}

/// Stance phases in a per-sample 0/1 sequence (runs of ones).
int countStancePhases(const std::vector<std::uint8_t>& stance)
{
    int phases = 0;
    for (std::size_t k = 0; k < stance.size(); ++k)
        phases += (stance[k] == 1 && (k == 0 || stance[k - 1] == 0)) ? 1 : 0;
    return phases;
}

/// Files in dir (names only), hidden ones included, so a stray temporary would show.
QStringList filesIn(const QString& dir)
{
    return QDir(dir).entryList(QDir::Files | QDir::Dirs | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

/// The first word of every table row that names a .csv file, in printed order.
QStringList rowNamesOf(const QString& out)
{
    QStringList names;
    const QRegularExpression row(QStringLiteral("^(\\S+\\.csv)\\s"));
    for (const QString& line : out.split(QLatin1Char('\n')))
        if (const QRegularExpressionMatch match = row.match(line); match.hasMatch())
            names << match.captured(1);
    return names;
}

/// The method set eval names for the given parameters (the defaults: ZUPT, smoothed).
QString methodSetOf(const footpath::Parameters& params = footpath::Parameters())
{
    return QString::fromStdString(footpath::methodSetLabel(footpath::methodSetSpec(params)));
}

QString defaultMethodSet()
{
    return methodSetOf();
}

QString substitute(QString text, const QString& dir, const QString& walk)
{
    return text.replace(QStringLiteral("{dir}"), dir).replace(QStringLiteral("{walk}"), walk);
}

}  // namespace

class TestCli : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void process_writesTrajectoryStepsAndSummary();
    void process_summaryFiguresArePlausible();
    void process_acceptsSetAndPresetFile_data();
    void process_acceptsSetAndPresetFile();
    void eval_setOverridesThePresetAndBothAreApplied();
    void eval_lengthJsonReportsDistanceError();
    void eval_closedLoopPrintsTableWithDbse();
    void eval_severalInputsGiveOneRowEachAndASummary();
    void eval_severalInputsJsonKeepsTheInputOrder();
    void eval_warningsGoToStderrAndJson();
    void eval_missingPathExitsTwoNamingIt();
    void eval_unreadableFileInAFolderIsAnErrorRow();
    void eval_jobsDoNotChangeTheOutput();
    void eval_datasetFolderSummarisesEveryTrial();
    void badInput_exitsTwoWithAPreciseMessage_data();
    void badInput_exitsTwoWithAPreciseMessage();
    void failedWrite_leavesNoPartialFile();
    void help_exitsZeroAndPrintsUsage_data();
    void help_exitsZeroAndPrintsUsage();
    void noArguments_printsUsageToStderrAndExitsTwo();
    void commandHelp_printsThatCommandsOptions_data();
    void commandHelp_printsThatCommandsOptions();
    void mistypedNames_suggestTheNearest_data();
    void mistypedNames_suggestTheNearest();
    void directoryOrProse_isRefusedSayingWhat_data();
    void directoryOrProse_isRefusedSayingWhat();
    void writeFailure_namesTheFileAndTheReason_data();
    void writeFailure_namesTheFileAndTheReason();
    void badRows_areSkippedWithAWarningOrRefused();
    void counts_printAsIntegers();
    void gait_pairsTheFeetByNameAndReportsDoubleSupport();
    void gait_refusesAnythingButOneWalksTwoFeet();
    void report_takesBothFeetOfOneWalk();
    void screenshotOfAHeaderlessFile_finishes();
    void screenshotOfAFolderWithoutAPair_endsWithTheReason();
    void guiUnknownView_namesTheNearest();
    void guiColumns_readTheFileAsTold();
    void guiHelpAndVersion_needNoDisplay_data();
    void guiHelpAndVersion_needNoDisplay();

private:
    /// A folder with copies of the walk under names, beside files eval must skip.
    bool makeWalkFolder(const QString& folder, const QStringList& names) const;

    QTemporaryDir dir_;
    QString walkCsv_;
    std::size_t sampleCount_ = 0;
    double firstTime_s_ = 0.0;
    double lastTime_s_ = 0.0;
    int trueStrides_ = 0;
    double truePathLength_m_ = 0.0;
};

void TestCli::initTestCase()
{
    QVERIFY2(QFileInfo(QString::fromUtf8(FOOTPATH_CLI)).isExecutable(), FOOTPATH_CLI);
    QVERIFY(dir_.isValid());

    const footpath::SimulatedWalk walk = footpath::simulateWalk(footpath::straightLinePath(10.0), {});
    const std::vector<footpath::ImuSample>& samples = walk.recording.samples;
    QVERIFY(samples.size() > 500);
    sampleCount_ = samples.size();
    firstTime_s_ = samples.front().time_s;
    lastTime_s_ = samples.back().time_s;
    trueStrides_ = countStancePhases(walk.trueStance) - 1;
    truePathLength_m_ = walk.truePathLength_m;
    QVERIFY(trueStrides_ >= 5);
    QVERIFY(std::abs(truePathLength_m_ - 10.0) < 1e-9);

    walkCsv_ = dir_.filePath(QStringLiteral("walk.csv"));
    QVERIFY(writeFile(walkCsv_, imuCsv(samples)));
}

void TestCli::process_writesTrajectoryStepsAndSummary()
{
    QTemporaryDir out;
    QVERIFY(out.isValid());
    const QString trajectory = out.filePath(QStringLiteral("t.csv"));
    const QString steps = out.filePath(QStringLiteral("s.csv"));
    const QString summary = out.filePath(QStringLiteral("j.json"));

    const Run run = runCli({QStringLiteral("process"), walkCsv_, QStringLiteral("--trajectory"), trajectory,
                            QStringLiteral("--steps"), steps, QStringLiteral("--summary"), summary});
    VERIFY_EXIT(run, 0);
    // Exactly the three outputs, no leftover temporaries.
    QCOMPARE(filesIn(out.path()), (QStringList{QStringLiteral("j.json"), QStringLiteral("s.csv"),
                                               QStringLiteral("t.csv")}));
    // The one-line report on stdout names the input and the sample count.
    QVERIFY2(run.out.contains(walkCsv_) && run.out.contains(QStringLiteral("%1 samples").arg(sampleCount_)),
             qPrintable(run.out));

    // Trajectory: the exact header, then one row of 21 numbers per input sample, in input time.
    const QStringList rows = readLines(trajectory);
    QVERIFY(!rows.isEmpty());
    QCOMPARE(rows.first(), kTrajectoryHeader);
    QCOMPARE(std::size_t(rows.size() - 1), sampleCount_);
    int stanceRows = 0;
    for (int r = 1; r < rows.size(); ++r) {
        const QStringList cells = rows[r].split(QLatin1Char(','));
        QVERIFY2(cells.size() == 21, qPrintable(QStringLiteral("row %1: %2").arg(r).arg(rows[r])));
        for (const QString& cell : cells) {
            bool ok = false;
            const double value = cell.toDouble(&ok);
            QVERIFY2(ok && std::isfinite(value), qPrintable(QStringLiteral("row %1: %2").arg(r).arg(rows[r])));
        }
        for (int flag = 10; flag < 15; ++flag)
            QVERIFY2(cells[flag] == QLatin1String("0") || cells[flag] == QLatin1String("1"), qPrintable(rows[r]));
        stanceRows += cells[13] == QLatin1String("1") ? 1 : 0;
    }
    QVERIFY(std::abs(rows[1].section(QLatin1Char(','), 0, 0).toDouble() - firstTime_s_) < 1e-6);
    QVERIFY(std::abs(rows.last().section(QLatin1Char(','), 0, 0).toDouble() - lastTime_s_) < 1e-6);
    // A walk has both stance and swing.
    QVERIFY(stanceRows > 0 && std::size_t(stanceRows) < sampleCount_);
    // The foot ends about 10 m along x.
    QVERIFY2(std::abs(rows.last().section(QLatin1Char(','), 1, 1).toDouble() - 10.0) < 0.5, qPrintable(rows.last()));

    // Steps: the exact header, one row per stance phase, numbered from 0.
    const QStringList stepRows = readLines(steps);
    QVERIFY(!stepRows.isEmpty());
    QCOMPARE(stepRows.first(), kStepsHeader);
    QCOMPARE(int(stepRows.size()) - 1, trueStrides_ + 1);
    double strideSum_m = 0.0;
    for (int r = 1; r < stepRows.size(); ++r) {
        const QStringList cells = stepRows[r].split(QLatin1Char(','));
        QCOMPARE(int(cells.size()), 16);
        // The simulated walk has no barometer: no motion class, an empty barometric height.
        QCOMPARE(cells[8], QStringLiteral("unknown"));
        QVERIFY2(cells[9].isEmpty(), qPrintable(stepRows[r]));
        QCOMPARE(cells[0], QString::number(r));  // steps are numbered from 1, as in the GUI and the PDF
        QVERIFY(cells[1].toDouble() <= cells[2].toDouble());
        strideSum_m += cells[6].toDouble();
    }

    // Summary: valid JSON whose path length is the sum of the stride lengths.
    QFile summaryFile(summary);
    QVERIFY(summaryFile.open(QIODevice::ReadOnly));
    QString error;
    const QJsonObject json = readJsonObject(summaryFile.readAll(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY(std::abs(json.value(QStringLiteral("path_length_m")).toDouble() - strideSum_m) < 1e-6);
    QCOMPARE(json.value(QStringLiteral("steps")).toInt(), int(stepRows.size()) - 2);
    // The motion classes count nothing without a barometer; the methods' notes are always a list.
    const QJsonObject motion = json.value(QStringLiteral("motion")).toObject();
    for (const char* key : {"stair_steps_up", "stair_steps_down", "elevator_rides", "stairs_climb_m",
                            "stairs_descent_m"})
        QVERIFY2(motion.contains(QLatin1String(key)) && motion.value(QLatin1String(key)).toDouble() == 0.0, key);
    QVERIFY(json.value(QStringLiteral("method_notes")).isArray());
}

void TestCli::process_summaryFiguresArePlausible()
{
    QTemporaryDir out;
    QVERIFY(out.isValid());
    const QString summary = out.filePath(QStringLiteral("summary.json"));
    const Run run = runCli({QStringLiteral("process"), walkCsv_, QStringLiteral("--summary"), summary});
    VERIFY_EXIT(run, 0);

    QFile file(summary);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QString error;
    const QJsonObject json = readJsonObject(file.readAll(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    for (const char* key : {"samples", "duration_s", "steps", "path_length_m", "end_to_start_m", "end_to_start_pct",
                            "runtime_s"})
        QVERIFY2(json.value(QLatin1String(key)).isDouble(), key);
    // The plausibility checks' findings: the list is there even when it is empty.
    QVERIFY(json.value(QStringLiteral("warnings")).isArray());

    QCOMPARE(json.value(QStringLiteral("samples")).toInteger(), qint64(sampleCount_));
    QVERIFY(std::abs(json.value(QStringLiteral("duration_s")).toDouble() - (lastTime_s_ - firstTime_s_)) < 1e-6);
    QCOMPARE(json.value(QStringLiteral("steps")).toInt(), trueStrides_);
    const double path_m = json.value(QStringLiteral("path_length_m")).toDouble();
    QVERIFY2(std::abs(path_m - truePathLength_m_) < 0.5, qPrintable(QString::number(path_m)));
    // A straight line ends about its own length from the start.
    const double endToStart_m = json.value(QStringLiteral("end_to_start_m")).toDouble();
    QVERIFY2(std::abs(endToStart_m - 10.0) < 0.5, qPrintable(QString::number(endToStart_m)));
    const double pct = json.value(QStringLiteral("end_to_start_pct")).toDouble();
    QVERIFY2(std::abs(pct - 100.0 * endToStart_m / path_m) < 1e-3, qPrintable(QString::number(pct)));
    const double runtime_s = json.value(QStringLiteral("runtime_s")).toDouble();
    QVERIFY2(runtime_s > 0.0 && runtime_s < 60.0, qPrintable(QString::number(runtime_s)));
}

void TestCli::process_acceptsSetAndPresetFile_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::newRow("--set") << QStringList{QStringLiteral("--set"), QStringLiteral("acc_std_max_mps2=0.3")};
    QTest::newRow("--params") << QStringList{QStringLiteral("--params"), QStringLiteral("{dir}/preset.json")};
    QTest::newRow("--params and two --set")
        << QStringList{QStringLiteral("--params"), QStringLiteral("{dir}/preset.json"), QStringLiteral("--set"),
                       QStringLiteral("acc_std_max_mps2=0.3"), QStringLiteral("--set"), QStringLiteral("use_zaru=off")};
}

void TestCli::process_acceptsSetAndPresetFile()
{
    QFETCH(QStringList, options);
    QTemporaryDir out;
    QVERIFY(out.isValid());
    footpath::Parameters preset;
    preset.acc_std_max_mps2 = 0.4;
    preset.gyr_max_radps = 1.2;
    const std::string saved = footpath::saveParameters(out.filePath(QStringLiteral("preset.json")).toStdString(), preset);
    QVERIFY2(saved.empty(), saved.c_str());

    const QString summary = out.filePath(QStringLiteral("summary.json"));
    QStringList args{QStringLiteral("process"), walkCsv_, QStringLiteral("--summary"), summary};
    for (const QString& option : options)
        args << substitute(option, out.path(), walkCsv_);
    const Run run = runCli(args);
    VERIFY_EXIT(run, 0);
    QVERIFY2(run.err.isEmpty(), qPrintable(run.err));

    QFile file(summary);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QString error;
    const QJsonObject json = readJsonObject(file.readAll(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(json.value(QStringLiteral("samples")).toInteger(), qint64(sampleCount_));
    QVERIFY(std::abs(json.value(QStringLiteral("path_length_m")).toDouble() - 10.0) < 0.5);
}

void TestCli::eval_setOverridesThePresetAndBothAreApplied()
{
    QTemporaryDir out;
    QVERIFY(out.isValid());
    const QString presetPath = out.filePath(QStringLiteral("no-zaru.json"));
    footpath::Parameters preset;
    preset.use_zaru = false;
    QVERIFY(footpath::saveParameters(presetPath.toStdString(), preset).empty());

    // The preset alone turns ZARU off ...
    const Run fromPreset = runCli({QStringLiteral("eval"), walkCsv_, QStringLiteral("--json"), QStringLiteral("--params"),
                                   presetPath});
    VERIFY_EXIT(fromPreset, 0);
    QString error;
    QJsonObject json = readJsonObject(fromPreset.out.toUtf8(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(json.value(QStringLiteral("methods")).toString(), methodSetOf(preset));
    QCOMPARE(json.value(QStringLiteral("parameters")).toString(), presetPath);

    // ... and --set, applied after the preset, turns it back on.
    const Run overridden = runCli({QStringLiteral("eval"), walkCsv_, QStringLiteral("--json"), QStringLiteral("--params"),
                                   presetPath, QStringLiteral("--set"), QStringLiteral("use_zaru=on")});
    VERIFY_EXIT(overridden, 0);
    json = readJsonObject(overridden.out.toUtf8(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    footpath::Parameters withZaru = preset;
    withZaru.use_zaru = true;
    QCOMPARE(json.value(QStringLiteral("methods")).toString(), methodSetOf(withZaru));
    QCOMPARE(json.value(QStringLiteral("parameters")).toString(), presetPath + QStringLiteral(" use_zaru=on"));

    // --set alone.
    const Run setOnly = runCli({QStringLiteral("eval"), walkCsv_, QStringLiteral("--json"), QStringLiteral("--set"),
                                QStringLiteral("use_zupt=false"), QStringLiteral("--set"),
                                QStringLiteral("use_zaru=true")});
    VERIFY_EXIT(setOnly, 0);
    json = readJsonObject(setOnly.out.toUtf8(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(json.value(QStringLiteral("methods")).toString(), QStringLiteral("ZARU+RTS smoother"));

    // The papers' methods are named, and Feliz's estimator replaces the filter's list.
    const std::pair<QStringList, QString> namedSets[] = {
        {{QStringLiteral("use_hdr=1"), QStringLiteral("use_baro=1")}, QStringLiteral("ZUPT+HDR+barometer+RTS smoother")},
        {{QStringLiteral("filter_states=15"), QStringLiteral("use_iper=1")}, QStringLiteral("ZUPT+IPER+15-state+RTS smoother")},
        {{QStringLiteral("estimator=ekf")}, QStringLiteral("ZUPT")},
        {{QStringLiteral("estimator=feliz")}, QStringLiteral("Feliz")},
    };
    for (const auto& [sets, expected] : namedSets) {
        QStringList args{QStringLiteral("eval"), walkCsv_, QStringLiteral("--json")};
        for (const QString& set : sets)
            args << QStringLiteral("--set") << set;
        const Run named = runCli(args);
        VERIFY_EXIT(named, 0);
        json = readJsonObject(named.out.toUtf8(), &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(json.value(QStringLiteral("methods")).toString(), expected);
    }
}

void TestCli::eval_lengthJsonReportsDistanceError()
{
    const Run run = runCli({QStringLiteral("eval"), walkCsv_, QStringLiteral("--length"), QStringLiteral("10"),
                            QStringLiteral("--json")});
    VERIFY_EXIT(run, 0);
    QString error;
    const QJsonObject json = readJsonObject(run.out.toUtf8(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));

    QCOMPARE(json.value(QStringLiteral("recording")).toString(), walkCsv_);
    QCOMPARE(json.value(QStringLiteral("parameters")).toString(), QStringLiteral("defaults"));
    QCOMPARE(json.value(QStringLiteral("methods")).toString(), defaultMethodSet());
    QVERIFY(json.contains(QStringLiteral("distance_error_m")));
    QCOMPARE(json.value(QStringLiteral("reference_length_m")).toDouble(), 10.0);
    const double path_m = json.value(QStringLiteral("path_length_m")).toDouble();
    const double error_m = json.value(QStringLiteral("distance_error_m")).toDouble();
    QVERIFY2(std::abs(path_m - 10.0) < 0.5, qPrintable(run.out));
    // |estimate - reference|, printed with 6 significant digits.
    QVERIFY2(std::abs(error_m - std::abs(path_m - 10.0)) < 1e-4, qPrintable(run.out));
    QVERIFY2(std::abs(json.value(QStringLiteral("distance_error_pct")).toDouble() - error_m * 10.0) < 1e-3,
             qPrintable(run.out));
    QCOMPARE(json.value(QStringLiteral("steps")).toInt(), trueStrides_);
    // No reference positions and no --closed-loop: no DBSE.
    QVERIFY(!json.contains(QStringLiteral("dbse_m")));
    const QJsonArray warnings = json.value(QStringLiteral("warnings")).toArray();
    QCOMPARE(json.value(QStringLiteral("warning_count")).toInt(), int(warnings.size()));
}

void TestCli::eval_closedLoopPrintsTableWithDbse()
{
    const Run run = runCli({QStringLiteral("eval"), walkCsv_, QStringLiteral("--closed-loop")});
    VERIFY_EXIT(run, 0);
    QVERIFY2(run.err.isEmpty(), qPrintable(run.err));
    QVERIFY2(run.out.contains(QStringLiteral("DBSE")), qPrintable(run.out));
    QVERIFY2(run.out.contains(QStringLiteral("recording   ") + walkCsv_), qPrintable(run.out));
    QVERIFY2(run.out.contains(QStringLiteral("methods     ") + defaultMethodSet()), qPrintable(run.out));

    // "end-to-start DBSE (m)   <value>": a straight 10 m walk does not close its loop.
    const QRegularExpression dbseRow(QStringLiteral("end-to-start DBSE \\(m\\)\\s+(-?[0-9.]+)\\s*$"),
                                     QRegularExpression::MultilineOption);
    const QRegularExpressionMatch match = dbseRow.match(run.out);
    QVERIFY2(match.hasMatch(), qPrintable(run.out));
    QVERIFY2(std::abs(match.captured(1).toDouble() - 10.0) < 0.5, qPrintable(run.out));
    QVERIFY2(QRegularExpression(QStringLiteral("^path length \\(m\\)\\s+[0-9.]+\\s*$"),
                                QRegularExpression::MultilineOption)
                 .match(run.out)
                 .hasMatch(),
             qPrintable(run.out));
}

bool TestCli::makeWalkFolder(const QString& folder, const QStringList& names) const
{
    if (!QDir().mkpath(folder) || !QDir(folder).mkdir(QStringLiteral("sub")))
        return false;
    QStringList copies = names;
    // Not recordings, or not to be read on their own: eval must pass over every one of these.
    copies << QStringLiteral(".hidden.csv") << QStringLiteral("sub/nested.csv");
    for (const QString& name : copies)
        if (!QFile::copy(walkCsv_, QDir(folder).filePath(name)))
            return false;
    return writeFile(QDir(folder).filePath(QStringLiteral("notes.md")), "# notes\n")
           && writeFile(QDir(folder).filePath(QStringLiteral("1-1.json")), "{}\n")
           && writeFile(QDir(folder).filePath(QStringLiteral("track.png")), "\x89PNG\r\n")
           && writeFile(QDir(folder).filePath(QStringLiteral("report.pdf")), "%PDF-1.4\n");
}

void TestCli::eval_severalInputsGiveOneRowEachAndASummary()
{
    QTemporaryDir work;
    QVERIFY(work.isValid());
    const QString folder = work.filePath(QStringLiteral("walks"));
    QVERIFY(makeWalkFolder(folder, {QStringLiteral("b.csv"), QStringLiteral("a.csv")}));

    const Run run =
        runCli({QStringLiteral("eval"), folder, walkCsv_, QStringLiteral("--length"), QStringLiteral("10")});
    VERIFY_EXIT(run, 0);
    // Every results table names its parameter set and method set.
    const QString header =
        QStringLiteral("parameters  defaults\nmethods     ") + defaultMethodSet() + QStringLiteral("\n\n");
    QVERIFY2(run.out.startsWith(header), qPrintable(run.out));
    // The folder's recordings by name, then the file; hidden, nested and metadata files skipped.
    QCOMPARE(rowNamesOf(run.out), (QStringList{QStringLiteral("a.csv"), QStringLiteral("b.csv"),
                                               QStringLiteral("walk.csv")}));
    const auto multiline = QRegularExpression::MultilineOption;
    QVERIFY2(QRegularExpression(QStringLiteral("^file\\s+dist err %\\s+steps\\s+warnings$"), multiline)
                 .match(run.out)
                 .hasMatch(),
             qPrintable(run.out));

    // The summary: known length only (no positions, no loop), the same walk three times.
    QVERIFY2(run.out.contains(QStringLiteral("\nknown length\n")), qPrintable(run.out));
    QVERIFY2(!run.out.contains(QStringLiteral("\npositions\n")) && !run.out.contains(QStringLiteral("\nclosed loop\n")),
             qPrintable(run.out));
    const QString number = QStringLiteral("\\s+([0-9.]+)");
    const QRegularExpressionMatch distance =
        QRegularExpression(QStringLiteral("^  distance error \\(%\\)") + number + number + number
                               + QStringLiteral("\\s+(\\d+)$"),
                           multiline)
            .match(run.out);
    QVERIFY2(distance.hasMatch(), qPrintable(run.out));
    QCOMPARE(distance.captured(4).toInt(), 3);
    QVERIFY2(distance.captured(1).toDouble() < 5.0, qPrintable(run.out));
    QCOMPARE(distance.captured(1), distance.captured(2));
    QCOMPARE(distance.captured(1), distance.captured(3));
    QVERIFY2(run.out.contains(QStringLiteral("3 recordings: 3 evaluated, 0 failed")), qPrintable(run.out));
}

void TestCli::eval_severalInputsJsonKeepsTheInputOrder()
{
    QTemporaryDir work;
    QVERIFY(work.isValid());
    const QString folder = work.filePath(QStringLiteral("walks"));
    QVERIFY(makeWalkFolder(folder, {QStringLiteral("d.csv"), QStringLiteral("c.csv")}));
    const QString b = work.filePath(QStringLiteral("b.csv"));
    const QString a = work.filePath(QStringLiteral("a.csv"));
    QVERIFY(QFile::copy(walkCsv_, b) && QFile::copy(walkCsv_, a));
    const QStringList options{QStringLiteral("--length"), QStringLiteral("10"), QStringLiteral("--closed-loop"),
                              QStringLiteral("--json")};

    const Run run = runCli(QStringList{QStringLiteral("eval"), b, a, folder} + options);
    VERIFY_EXIT(run, 0);
    QString error;
    const QJsonObject root = readJsonObject(run.out.toUtf8(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const Run alone = runCli(QStringList{QStringLiteral("eval"), walkCsv_} + options);
    VERIFY_EXIT(alone, 0);
    const QJsonObject single = readJsonObject(alone.out.toUtf8(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(root.value(QStringLiteral("parameters")).toString(), QStringLiteral("defaults"));
    QCOMPARE(root.value(QStringLiteral("methods")), single.value(QStringLiteral("methods")));

    // The input order, whichever thread finished first; each object as eval of that file alone prints it.
    const QJsonArray recordings = root.value(QStringLiteral("recordings")).toArray();
    const QStringList expected{b, a, folder + QStringLiteral("/c.csv"), folder + QStringLiteral("/d.csv")};
    QCOMPARE(int(recordings.size()), int(expected.size()));
    for (int i = 0; i < recordings.size(); ++i) {
        QJsonObject recording = recordings[i].toObject();
        QCOMPARE(recording.value(QStringLiteral("recording")).toString(), expected[i]);
        QVERIFY(!recording.contains(QStringLiteral("error")));
        QVERIFY(recording.value(QStringLiteral("warnings")).isArray());
        recording.insert(QStringLiteral("recording"), walkCsv_);
        QCOMPARE(recording, single);
    }

    // Summary: mean, median, worst and count of every metric; none for references these files lack.
    const QJsonObject summary = root.value(QStringLiteral("summary")).toObject();
    for (const char* key : {"dbse_m", "dbse_pct", "distance_error_pct", "warning_count"}) {
        const QJsonObject stats = summary.value(QLatin1String(key)).toObject();
        QVERIFY2(stats.value(QStringLiteral("count")).toInt() == 4, key);
        QVERIFY2(stats.value(QStringLiteral("mean")).isDouble() && stats.value(QStringLiteral("median")).isDouble()
                     && stats.value(QStringLiteral("worst")).isDouble(),
                 key);
    }
    QCOMPARE(summary.value(QStringLiteral("distance_error_pct")).toObject().value(QStringLiteral("worst")).toDouble(),
             single.value(QStringLiteral("distance_error_pct")).toDouble());
    QCOMPARE(summary.value(QStringLiteral("armse_2d_m")).toObject().value(QStringLiteral("count")).toInt(), 0);
    QCOMPARE(summary.value(QStringLiteral("stance_f1")).toObject().value(QStringLiteral("count")).toInt(), 0);
}

void TestCli::eval_warningsGoToStderrAndJson()
{
    // The bundled sample walk cut 10 s in, mid-walk: it no longer starts with the foot at rest, which
    // is one of the things the plausibility checks look for.
    const QStringList lines = readLines(QStringLiteral(FOOTPATH_SOURCE_DIR)
                                        + QStringLiteral("/resources/samples/pyshoe-vicon-2017-11-22-11-27-30.csv"));
    QVERIFY(lines.size() > 3000);
    QTemporaryDir work;
    QVERIFY(work.isValid());
    const QString sample = work.filePath(QStringLiteral("moving-start.csv"));
    QVERIFY(writeFile(sample, (QStringList{lines.first()} + lines.mid(1999)).join(QLatin1Char('\n')).toUtf8() + '\n'));
    const Run run = runCli({QStringLiteral("eval"), sample, QStringLiteral("--json")});
    VERIFY_EXIT(run, 0);
    QString error;
    const QJsonObject json = readJsonObject(run.out.toUtf8(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const QJsonArray warnings = json.value(QStringLiteral("warnings")).toArray();
    QVERIFY2(!warnings.isEmpty(), qPrintable(run.out));
    QCOMPARE(json.value(QStringLiteral("warning_count")).toInt(), int(warnings.size()));
    // One stderr line per warning, "FILE: warning: [t0-t1 s] message", in the JSON's order.
    const QString prefix = sample + QStringLiteral(": warning: [");
    const QStringList printed = run.err.split(QLatin1Char('\n')).filter(prefix);
    QCOMPARE(int(printed.size()), int(warnings.size()));
    for (int i = 0; i < warnings.size(); ++i) {
        const QJsonObject warning = warnings[i].toObject();
        QVERIFY(!warning.value(QStringLiteral("kind")).toString().isEmpty());
        const double start_s = warning.value(QStringLiteral("start_s")).toDouble();
        const double end_s = warning.value(QStringLiteral("end_s")).toDouble();
        QVERIFY(start_s <= end_s);
        const QString message = warning.value(QStringLiteral("message")).toString();
        QCOMPARE(printed[i], QString::asprintf("%s: warning: [%.2f-%.2f s] %s", qPrintable(sample), start_s, end_s,
                                               qPrintable(message)));
    }

    // process reports the same warnings on stderr and in its summary JSON.
    const QString summaryPath = work.filePath(QStringLiteral("summary.json"));
    const Run process = runCli({QStringLiteral("process"), sample, QStringLiteral("--summary"), summaryPath});
    VERIFY_EXIT(process, 0);
    QCOMPARE(process.err.split(QLatin1Char('\n')).filter(prefix), printed);
    QFile file(summaryPath);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonArray written = readJsonObject(file.readAll(), &error).value(QStringLiteral("warnings")).toArray();
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(int(written.size()), int(warnings.size()));
    for (int i = 0; i < warnings.size(); ++i) {
        const QJsonObject fromEval = warnings[i].toObject();
        const QJsonObject fromProcess = written[i].toObject();
        for (const char* key : {"kind", "message"})
            QCOMPARE(fromProcess.value(QLatin1String(key)), fromEval.value(QLatin1String(key)));
        for (const char* key : {"start_s", "end_s"})  // the summary keeps 10 significant digits
            QVERIFY(std::abs(fromProcess.value(QLatin1String(key)).toDouble()
                             - fromEval.value(QLatin1String(key)).toDouble())
                    < 1e-6);
    }
}

void TestCli::eval_missingPathExitsTwoNamingIt()
{
    QTemporaryDir work;
    QVERIFY(work.isValid());
    const QString absent = work.filePath(QStringLiteral("no-such-folder"));
    const Run run = runCli({QStringLiteral("eval"), walkCsv_, absent});
    VERIFY_EXIT(run, kExitBadInput);
    QVERIFY2(run.err.contains(absent + QStringLiteral(": no such file or folder")), qPrintable(run.err));
    QVERIFY2(run.out.isEmpty(), qPrintable(run.out));
}

void TestCli::eval_unreadableFileInAFolderIsAnErrorRow()
{
    QTemporaryDir work;
    QVERIFY(work.isValid());
    QVERIFY(QFile::copy(walkCsv_, work.filePath(QStringLiteral("good.csv"))));
    const QString junk = work.filePath(QStringLiteral("junk.csv"));
    QVERIFY(writeFile(junk, QByteArray("\x00\x01\x02 not a recording\n", 21)));

    const Run run = runCli({QStringLiteral("eval"), work.path()});
    VERIFY_EXIT(run, kExitBadInput);
    const auto multiline = QRegularExpression::MultilineOption;
    // A file with no reference: its steps and warning count.
    QVERIFY2(QRegularExpression(QStringLiteral("^good\\.csv\\s+[0-9]+\\s+[0-9]+$"), multiline)
                 .match(run.out)
                 .hasMatch(),
             qPrintable(run.out));
    QVERIFY2(QRegularExpression(QStringLiteral("^junk\\.csv\\s+error: ") + QRegularExpression::escape(junk), multiline)
                 .match(run.out)
                 .hasMatch(),
             qPrintable(run.out));
    QVERIFY2(run.out.contains(QStringLiteral("2 recordings: 1 evaluated, 1 failed")), qPrintable(run.out));
    QVERIFY2(run.err.contains(QStringLiteral("could not be evaluated: ") + junk), qPrintable(run.err));

    const Run json = runCli({QStringLiteral("eval"), work.path(), QStringLiteral("--json")});
    VERIFY_EXIT(json, kExitBadInput);
    QString error;
    const QJsonObject root = readJsonObject(json.out.toUtf8(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const QJsonArray recordings = root.value(QStringLiteral("recordings")).toArray();
    QCOMPARE(int(recordings.size()), 2);
    QVERIFY(recordings[0].toObject().value(QStringLiteral("path_length_m")).isDouble());
    QVERIFY(recordings[1].toObject().value(QStringLiteral("error")).toString().startsWith(junk));
}

void TestCli::eval_jobsDoNotChangeTheOutput()
{
    QTemporaryDir work;
    QVERIFY(work.isValid());
    QVERIFY(makeWalkFolder(work.path(), {QStringLiteral("w1.csv"), QStringLiteral("w2.csv"), QStringLiteral("w3.csv"),
                                         QStringLiteral("w4.csv")}));
    for (const QStringList& format : {QStringList{}, QStringList{QStringLiteral("--json")}}) {
        const QStringList args =
            QStringList{QStringLiteral("eval"), work.path(), QStringLiteral("--closed-loop")} + format;
        const Run one = runCli(args + QStringList{QStringLiteral("--jobs"), QStringLiteral("1")});
        const Run two = runCli(args + QStringList{QStringLiteral("--jobs"), QStringLiteral("2")});
        VERIFY_EXIT(one, 0);
        VERIFY_EXIT(two, 0);
        QCOMPARE(two.out, one.out);
        QCOMPARE(two.err, one.err);
        QVERIFY(one.out.contains(QStringLiteral("w4.csv")));
    }
}

void TestCli::eval_datasetFolderSummarisesEveryTrial()
{
    FOOTPATH_REQUIRE_DATASETS();
    const QString folder = datasetPath(QStringLiteral("pyshoe-vicon"));
    const QStringList trials = QDir(folder).entryList({QStringLiteral("*.csv")}, QDir::Files, QDir::Name);
    QVERIFY(!trials.isEmpty());

    const Run run = runCli({QStringLiteral("eval"), folder, QStringLiteral("--json")});
    VERIFY_EXIT(run, 0);
    QString error;
    const QJsonObject root = readJsonObject(run.out.toUtf8(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const QJsonArray recordings = root.value(QStringLiteral("recordings")).toArray();
    QCOMPARE(int(recordings.size()), int(trials.size()));
    for (int i = 0; i < recordings.size(); ++i) {
        const QString path = recordings[i].toObject().value(QStringLiteral("recording")).toString();
        QCOMPARE(QFileInfo(path).fileName(), trials[i]);
    }
    // Every VICON trial has a reference trajectory and is a closed loop.
    const QJsonObject summary = root.value(QStringLiteral("summary")).toObject();
    for (const char* key : {"armse_2d_m", "armse_3d_m", "dbse_m", "dbse_pct"})
        QVERIFY2(summary.value(QLatin1String(key)).toObject().value(QStringLiteral("count")).toInt() == trials.size(),
                 key);
}

void TestCli::badInput_exitsTwoWithAPreciseMessage_data()
{
    QTest::addColumn<QStringList>("args");      // {dir}: a fresh directory, {walk}: the valid walk
    QTest::addColumn<QByteArray>("input");      // written to {dir}/in.csv when not empty
    QTest::addColumn<QStringList>("expected");  // each must appear in stderr

    const QByteArray good = "0.00,0.1,0.2,9.8,0.01,0.02,0.03\n0.01,0.1,0.2,9.8,0.01,0.02,0.03\n"
                            "0.02,0.1,0.2,9.8,0.01,0.02,0.03\n";
    const QString in = QStringLiteral("{dir}/in.csv");
    const QString process = QStringLiteral("process");

    QTest::newRow("non-numeric cell") << QStringList{process, in} << QByteArray(kImuHeader + "0.03,0.1,abc,9.8,0,0,0\n")
                                      << QStringList{in + ":2:3: expected a number in column 'acc_y', got 'abc'"};
    QTest::newRow("missing column")
        << QStringList{process, in} << QByteArray("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y\n0,0,0,9.8,0,0\n")
        << QStringList{in + ":1: missing column(s): gyr_z"};
    QTest::newRow("time going backwards")
        << QStringList{process, in} << QByteArray(kImuHeader + good + "0.015,0.1,0.2,9.8,0,0,0\n")
        << QStringList{in + ":5: time goes backwards"};
    QTest::newRow("missing input file") << QStringList{process, QStringLiteral("{dir}/absent.csv")} << QByteArray()
                                        << QStringList{QStringLiteral("{dir}/absent.csv: cannot open the file")};
    QTest::newRow("unknown option") << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--frobnicate")}
                                    << QByteArray()
                                    << QStringList{QStringLiteral("unknown option '--frobnicate'"),
                                                   QStringLiteral("Usage:")};
    QTest::newRow("unknown command") << QStringList{QStringLiteral("walk"), QStringLiteral("{walk}")} << QByteArray()
                                     << QStringList{QStringLiteral("unknown command 'walk'")};
    QTest::newRow("no input") << QStringList{process} << QByteArray() << QStringList{QStringLiteral("missing INPUT")};
    QTest::newRow("unknown --set name")
        << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--set"), QStringLiteral("no_such_knob=1")}
        << QByteArray() << QStringList{QStringLiteral("--set: unknown parameter 'no_such_knob'")};
    QTest::newRow("--set without =") << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--set"),
                                                    QStringLiteral("acc_std_max_mps2")}
                                     << QByteArray() << QStringList{QStringLiteral("--set expects name=value")};
    QTest::newRow("--set bad number")
        << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--set"), QStringLiteral("gyr_max_radps=fast")}
        << QByteArray() << QStringList{QStringLiteral("parameter 'gyr_max_radps' expects a number, got 'fast'")};
    QTest::newRow("--set acc_min above acc_max")
        << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--set"), QStringLiteral("acc_min_mps2=20")}
        << QByteArray()
        << QStringList{QStringLiteral("invalid parameters"),
                       QStringLiteral("acc_min_mps2 (20) must be below acc_max_mps2 (11)")};
    QTest::newRow("--set out of range")
        << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--set"), QStringLiteral("gravity_mps2=1")}
        << QByteArray()
        << QStringList{QStringLiteral("invalid parameters"), QStringLiteral("gravity_mps2 (1) must be between")};
    QTest::newRow("missing preset") << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--params"),
                                                   QStringLiteral("{dir}/nope.json")}
                                    << QByteArray() << QStringList{QStringLiteral("{dir}/nope.json: cannot open the preset")};
    QTest::newRow("unwritable trajectory")
        << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--trajectory"),
                       QStringLiteral("{dir}/no-such-dir/t.csv")}
        << QByteArray() << QStringList{QStringLiteral("{dir}/no-such-dir/t.csv: cannot open for writing")};
    QTest::newRow("unwritable summary")
        << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--summary"),
                       QStringLiteral("{dir}/no-such-dir/s.json")}
        << QByteArray() << QStringList{QStringLiteral("{dir}/no-such-dir/s.json: cannot open for writing")};
    QTest::newRow("--length not a number")
        << QStringList{QStringLiteral("eval"), QStringLiteral("{walk}"), QStringLiteral("--length"), QStringLiteral("ten")}
        << QByteArray() << QStringList{QStringLiteral("--length expects metres > 0, got 'ten'")};
    QTest::newRow("--jobs 0") << QStringList{QStringLiteral("eval"), QStringLiteral("{walk}"), QStringLiteral("--jobs"),
                                             QStringLiteral("0")}
                              << QByteArray() << QStringList{QStringLiteral("--jobs expects a whole number")};
    QTest::newRow("--jobs with process")
        << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--jobs"), QStringLiteral("2")} << QByteArray()
        << QStringList{QStringLiteral("--jobs belongs to eval")};
    QTest::newRow("two inputs for process") << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("{walk}")}
                                            << QByteArray() << QStringList{QStringLiteral("unexpected argument")};
    QTest::newRow("eval of a missing file")
        << QStringList{QStringLiteral("eval"), QStringLiteral("{dir}/absent.csv")} << QByteArray()
        << QStringList{QStringLiteral("{dir}/absent.csv: no such file or folder")};
    QTest::newRow("process with an eval option")
        << QStringList{process, QStringLiteral("{walk}"), QStringLiteral("--closed-loop")} << QByteArray()
        << QStringList{QStringLiteral("belong to eval")};
}

void TestCli::badInput_exitsTwoWithAPreciseMessage()
{
    QFETCH(QStringList, args);
    QFETCH(QByteArray, input);
    QFETCH(QStringList, expected);

    QTemporaryDir work;
    QVERIFY(work.isValid());
    QStringList before;
    if (!input.isEmpty()) {
        QVERIFY(writeFile(work.filePath(QStringLiteral("in.csv")), input));
        before << QStringLiteral("in.csv");
    }
    QStringList resolved;
    for (const QString& arg : args)
        resolved << substitute(arg, work.path(), walkCsv_);

    const Run run = runCli(resolved, work.path());
    VERIFY_EXIT(run, kExitBadInput);
    QVERIFY2(run.err.startsWith(QStringLiteral("footpath-cli: ")), run.describe().constData());
    for (const QString& part : expected) {
        const QString text = substitute(part, work.path(), walkCsv_);
        QVERIFY2(run.err.contains(text), qPrintable(QStringLiteral("'%1' not in stderr:\n%2").arg(text, run.err)));
    }
    // A failed run reports nothing on stdout and leaves no file behind (not even a partial one).
    QVERIFY2(run.out.isEmpty(), qPrintable(run.out));
    QCOMPARE(filesIn(work.path()), before);
}

void TestCli::failedWrite_leavesNoPartialFile()
{
    QTemporaryDir work;
    QVERIFY(work.isValid());
    // The trajectory's target is a directory: the data can be written to a temporary file but not
    // renamed into place. The temporary must be removed and the directory left alone.
    QVERIFY(QDir(work.path()).mkdir(QStringLiteral("t.csv")));
    QVERIFY(writeFile(work.filePath(QStringLiteral("t.csv/keep.txt")), "keep"));
    const QString target = work.filePath(QStringLiteral("t.csv"));

    const Run run = runCli({QStringLiteral("process"), walkCsv_, QStringLiteral("--trajectory"), target});
    VERIFY_EXIT(run, kExitBadInput);
    QVERIFY2(run.err.contains(target + QStringLiteral(": ")), qPrintable(run.err));
    QCOMPARE(filesIn(work.path()), QStringList{QStringLiteral("t.csv")});
    QVERIFY(QFileInfo(target).isDir());
    QCOMPARE(filesIn(target), QStringList{QStringLiteral("keep.txt")});

    // An existing output survives a run that fails before writing.
    const QString existing = work.filePath(QStringLiteral("old.csv"));
    QVERIFY(writeFile(existing, "previous result\n"));
    const Run failed = runCli({QStringLiteral("process"), work.filePath(QStringLiteral("absent.csv")),
                               QStringLiteral("--trajectory"), existing});
    VERIFY_EXIT(failed, kExitBadInput);
    QCOMPARE(readLines(existing), QStringList{QStringLiteral("previous result")});
    QCOMPARE(filesIn(work.path()), (QStringList{QStringLiteral("old.csv"), QStringLiteral("t.csv")}));
}

void TestCli::help_exitsZeroAndPrintsUsage_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("help") << QStringList{QStringLiteral("help")};
    QTest::newRow("--help") << QStringList{QStringLiteral("--help")};
    QTest::newRow("-h") << QStringList{QStringLiteral("-h")};
}

void TestCli::help_exitsZeroAndPrintsUsage()
{
    QFETCH(QStringList, args);
    const Run run = runCli(args);
    VERIFY_EXIT(run, 0);
    QVERIFY2(run.out.startsWith(QStringLiteral("Usage:")), qPrintable(run.out));
    QVERIFY(run.out.contains(QStringLiteral("footpath-cli process INPUT")));
    QVERIFY(run.out.contains(QStringLiteral("footpath-cli eval INPUT")));
    QVERIFY2(run.err.isEmpty(), qPrintable(run.err));
}

void TestCli::noArguments_printsUsageToStderrAndExitsTwo()
{
    const Run run = runCli({});
    VERIFY_EXIT(run, kExitBadInput);
    QVERIFY2(run.out.isEmpty(), qPrintable(run.out));
    QVERIFY(run.err.contains(QStringLiteral("no command given")));
    QVERIFY(run.err.contains(QStringLiteral("process, eval, compare, tune, gait, info, report, record")));
}

void TestCli::commandHelp_printsThatCommandsOptions_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QStringList>("expected");  // in stdout
    QTest::addColumn<QString>("absent");        // another command's synopsis
    const QString eval = QStringLiteral("footpath-cli eval INPUT");
    QTest::newRow("process") << QStringList{"process", "--help"}
                             << QStringList{"footpath-cli process INPUT", "--trajectory out.csv", "--set name=value"}
                             << eval;
    QTest::newRow("process -h after other options")
        << QStringList{"process", "in.csv", "--set", "x=1", "-h"} << QStringList{"footpath-cli process INPUT"} << eval;
    QTest::newRow("eval") << QStringList{"eval", "--help"} << QStringList{eval, "--closed-loop", "--jobs N"}
                          << QStringLiteral("footpath-cli record");
    QTest::newRow("compare") << QStringList{"compare", "--help"}
                             << QStringList{"footpath-cli compare INPUT", "--sets", "zupt"} << eval;
    QTest::newRow("gait") << QStringList{"gait", "--help"}
                          << QStringList{"footpath-cli gait LEFT RIGHT", "double support", "one clock"} << eval;
    QTest::newRow("info") << QStringList{"info", "--help"} << QStringList{"footpath-cli info INPUT", "--columns"}
                          << eval;
    QTest::newRow("report") << QStringList{"report", "--help"}
                            << QStringList{"footpath-cli report INPUT [RIGHT] --pdf", "--page-size"} << eval;
    QTest::newRow("record without its required options")
        << QStringList{"record", "--help"} << QStringList{"footpath-cli record --port PATH", "--duration"} << eval;
    QTest::newRow("help COMMAND") << QStringList{"help", "info"} << QStringList{"footpath-cli info INPUT"} << eval;
}

void TestCli::commandHelp_printsThatCommandsOptions()
{
    QFETCH(QStringList, args);
    QFETCH(QStringList, expected);
    QFETCH(QString, absent);
    const Run run = runCli(args);
    VERIFY_EXIT(run, 0);
    QVERIFY2(run.out.startsWith(QStringLiteral("Usage:")), qPrintable(run.out));
    for (const QString& text : expected)
        QVERIFY2(run.out.contains(text), qPrintable(text));
    QVERIFY2(!run.out.contains(absent), qPrintable(absent));
    QVERIFY(run.out.contains(QStringLiteral("Exit codes")));
    QVERIFY2(run.err.isEmpty(), qPrintable(run.err));
}

void TestCli::mistypedNames_suggestTheNearest_data()
{
    QTest::addColumn<QStringList>("args");  // {walk}: the valid walk
    QTest::addColumn<QString>("expected");
    QTest::addColumn<QString>("notSuggested");
    QTest::newRow("option") << QStringList{"eval", "{walk}", "--closed-lop"}
                            << QStringLiteral("unknown option '--closed-lop'; did you mean --closed-loop?")
                            << QStringLiteral("--json");
    QTest::newRow("command") << QStringList{"proces", "{walk}"}
                             << QStringLiteral("unknown command 'proces'; did you mean process?")
                             << QStringLiteral("record?");
    QTest::newRow("--set name") << QStringList{"process", "{walk}", "--set", "gyr_max=1"}
                                << QStringLiteral("unknown parameter 'gyr_max'; did you mean gyr_max_radps")
                                << QStringLiteral("acc_std_max");
    QTest::newRow("--set name, a typo") << QStringList{"process", "{walk}", "--set", "acc_std_max_mps=0.5"}
                                        << QStringLiteral("did you mean acc_std_max_mps2")
                                        << QStringLiteral("gyr_max_radps");
    QTest::newRow("nothing near: no guess") << QStringList{"process", "{walk}", "--set", "zzzzzzzzzzzz=1"}
                                            << QStringLiteral("unknown parameter 'zzzzzzzzzzzz'")
                                            << QStringLiteral("did you mean");
}

void TestCli::mistypedNames_suggestTheNearest()
{
    QFETCH(QStringList, args);
    QFETCH(QString, expected);
    QFETCH(QString, notSuggested);
    for (QString& arg : args)
        arg = substitute(arg, dir_.path(), walkCsv_);
    const Run run = runCli(args);
    VERIFY_EXIT(run, kExitBadInput);
    QVERIFY2(run.err.contains(expected), qPrintable(run.err));
    const QString firstLine = run.err.section(QLatin1Char('\n'), 0, 0);
    QVERIFY2(!firstLine.contains(notSuggested), qPrintable(firstLine));
}

void TestCli::directoryOrProse_isRefusedSayingWhat_data()
{
    QTest::addColumn<QStringList>("args");  // {dir}: a folder holding a README.md of prose
    QTest::addColumn<QString>("expected");
    const QString directory = QStringLiteral("{dir}: is a directory, not a recording file");
    QTest::newRow("process") << QStringList{"process", "{dir}"} << directory;
    QTest::newRow("info") << QStringList{"info", "{dir}"} << directory;
    QTest::newRow("report") << QStringList{"report", "{dir}", "--pdf", "{dir}/out.pdf"} << directory;
    QTest::newRow("eval of an empty folder") << QStringList{"eval", "{dir}/empty"}
                                             << QStringLiteral("{dir}/empty holds no recording");
    QTest::newRow("compare of an empty folder") << QStringList{"compare", "{dir}/empty"}
                                                << QStringLiteral("{dir}/empty holds no recording");
    QTest::newRow("prose") << QStringList{"info", "{dir}/README.md"}
                           << QStringLiteral("{dir}/README.md: does not look like sensor data: no numeric rows");
}

void TestCli::directoryOrProse_isRefusedSayingWhat()
{
    QFETCH(QStringList, args);
    QFETCH(QString, expected);
    QTemporaryDir work;
    QVERIFY(QDir(work.path()).mkdir(QStringLiteral("empty")));
    QVERIFY(writeFile(QDir(work.path()).filePath(QStringLiteral("README.md")),
                      "# Walks\n\nThese walks were recorded on the 2nd and 3rd floor.\nOpen them in Footpath.\n"));
    for (QString& arg : args)
        arg = substitute(arg, work.path(), walkCsv_);
    const Run run = runCli(args);
    VERIFY_EXIT(run, kExitBadInput);
    QVERIFY2(run.err.contains(substitute(expected, work.path(), walkCsv_)), qPrintable(run.err));
    QVERIFY2(run.out.isEmpty(), qPrintable(run.out));
}

void TestCli::writeFailure_namesTheFileAndTheReason_data()
{
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("target");  // {dir}: a fresh folder
    QTest::addColumn<QString>("reason");
    QTest::newRow("missing folder") << "--trajectory" << "{dir}/absent/out.csv" << "No such file or directory";
    QTest::newRow("a folder as the file") << "--summary" << "{dir}" << "Is a directory";
}

void TestCli::writeFailure_namesTheFileAndTheReason()
{
    QFETCH(QString, option);
    QFETCH(QString, target);
    QFETCH(QString, reason);
    QTemporaryDir work;
    target = substitute(target, work.path(), walkCsv_);
    const Run run = runCli({QStringLiteral("process"), walkCsv_, option, target});
    QVERIFY2(run.finished && run.exitCode != 0, run.describe().constData());
    QVERIFY2(run.err.contains(target + QStringLiteral(": ")), qPrintable(run.err));
    QVERIFY2(run.err.contains(reason), qPrintable(run.err));
}

void TestCli::badRows_areSkippedWithAWarningOrRefused()
{
    QTemporaryDir work;
    QStringList lines = readLines(walkCsv_);
    QVERIFY(lines.size() > 500);
    // One bad cell in the middle: that row is skipped and named, the rest of the walk is read.
    QStringList oneBad = lines;
    QStringList cells = oneBad[300].split(QLatin1Char(','));
    cells[4] = QStringLiteral("abc");
    oneBad[300] = cells.join(QLatin1Char(','));
    const QString oneBadPath = work.filePath(QStringLiteral("one-bad.csv"));
    QVERIFY(writeFile(oneBadPath, oneBad.join(QLatin1Char('\n')).toUtf8() + "\n"));
    const Run info = runCli({QStringLiteral("info"), oneBadPath, QStringLiteral("--json")});
    VERIFY_EXIT(info, 0);
    const QJsonObject object = QJsonDocument::fromJson(info.out.toUtf8()).object();
    QCOMPARE(object.value(QStringLiteral("samples")).toInteger(), qint64(sampleCount_ - 1));
    QVERIFY2(info.out.contains(QStringLiteral("line 301, column 5 (expected a number in column 'gyr_x', got 'abc')")),
             qPrintable(info.out));
    const Run process = runCli({QStringLiteral("process"), oneBadPath});
    VERIFY_EXIT(process, 0);
    QVERIFY2(process.err.contains(QStringLiteral("line 301, column 5")), qPrintable(process.err));

    // Most rows damaged: refused with exit 2, naming the first bad place and the count.
    QStringList mostBad = lines;
    for (int i = 1; i < mostBad.size(); ++i)
        if (i % 4 != 0)
            mostBad[i].replace(0, 1, QStringLiteral("x"));
    const QString mostBadPath = work.filePath(QStringLiteral("most-bad.csv"));
    QVERIFY(writeFile(mostBadPath, mostBad.join(QLatin1Char('\n')).toUtf8() + "\n"));
    const Run refused = runCli({QStringLiteral("info"), mostBadPath});
    VERIFY_EXIT(refused, kExitBadInput);
    QVERIFY2(refused.err.contains(mostBadPath + QStringLiteral(":2:1: expected a number in column 'time_s'")),
             qPrintable(refused.err));
    QVERIFY2(refused.err.contains(QStringLiteral("data rows could not be read")), qPrintable(refused.err));

    // One good row after the header and the rest damaged: never a recording of one sample.
    QStringList oneGood = lines.mid(0, 2);
    oneGood << QStringLiteral("garbage") << QStringLiteral("more garbage");
    const QString oneGoodPath = work.filePath(QStringLiteral("one-good.csv"));
    QVERIFY(writeFile(oneGoodPath, oneGood.join(QLatin1Char('\n')).toUtf8() + "\n"));
    VERIFY_EXIT(runCli({QStringLiteral("info"), oneGoodPath}), kExitBadInput);
}

void TestCli::gait_pairsTheFeetByNameAndReportsDoubleSupport()
{
    FOOTPATH_REQUIRE_DATASETS();
    const QString left = datasetPath(QStringLiteral("xsens-mtw-ipol/1-4_lf.txt"));
    const QString right = datasetPath(QStringLiteral("xsens-mtw-ipol/1-4_rf.txt"));
    const Run run = runCli({QStringLiteral("gait"), right, left, QStringLiteral("--json")});  // right first
    VERIFY_EXIT(run, 0);
    QString error;
    const QJsonObject root = readJsonObject(run.out.toUtf8(), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(root.value(QStringLiteral("left")).toString(), left);
    QCOMPARE(root.value(QStringLiteral("right")).toString(), right);
    const QJsonObject support = root.value(QStringLiteral("double_support")).toObject();
    const double meanPct = support.value(QStringLiteral("mean_pct")).toDouble();
    QVERIFY2(meanPct > 15.0 && meanPct < 35.0, qPrintable(QString::number(meanPct)));
    QVERIFY(support.value(QStringLiteral("strides")).toInt() >= 20);
    for (const char* key : {"stride_time", "stride_length", "stance", "swing"})
        QVERIFY2(root.value(QStringLiteral("symmetry_index_pct")).toObject().value(QLatin1String(key)).isDouble(), key);
    // The IPOL labels travel with the files: both figures over the same strides.
    const QJsonObject labels = root.value(QStringLiteral("against_labels")).toObject();
    QVERIFY(labels.value(QStringLiteral("matched_strides")).toInt() >= 25);
    QVERIFY(std::abs(labels.value(QStringLiteral("matched_detected_pct")).toDouble()
                     - labels.value(QStringLiteral("matched_labelled_pct")).toDouble()) < 3.0);

    const Run table = runCli({QStringLiteral("gait"), left, right});
    VERIFY_EXIT(table, 0);
    QVERIFY2(table.out.contains(QStringLiteral("double support  %1 % of the gait cycle").arg(meanPct, 0, 'f', 1)),
             qPrintable(table.out));
    QVERIFY(table.out.contains(QStringLiteral("symmetry index  stride time")));
}

void TestCli::gait_refusesAnythingButOneWalksTwoFeet()
{
    const QString walk = walkCsv_;
    const Run one = runCli({QStringLiteral("gait"), walk});
    VERIFY_EXIT(one, kExitBadInput);
    QVERIFY2(one.err.contains(QStringLiteral("gait takes two files")), qPrintable(one.err));
    const Run twoLefts = runCli({QStringLiteral("gait"), QStringLiteral("a_lf.txt"), QStringLiteral("b_lf.txt")});
    VERIFY_EXIT(twoLefts, kExitBadInput);
    QVERIFY2(twoLefts.err.contains(QStringLiteral("both named as the left foot")), qPrintable(twoLefts.err));
    const Run output = runCli({QStringLiteral("gait"), QStringLiteral("a_lf.txt"), QStringLiteral("a_rf.txt"),
                               QStringLiteral("--trajectory"), QStringLiteral("t.csv")});
    VERIFY_EXIT(output, kExitBadInput);
    QVERIFY2(output.err.contains(QStringLiteral("gait takes the import options")), qPrintable(output.err));
}

void TestCli::report_takesBothFeetOfOneWalk()
{
    // footpath-cli report refused a second input, while the window's report had both feet.
    FOOTPATH_REQUIRE_DATASETS();
    if (QStandardPaths::findExecutable(QStringLiteral("pdftotext")).isEmpty())
        QSKIP("pdftotext (Debian: poppler-utils) is not installed");
    QTemporaryDir work;
    const QString pdf = work.filePath(QStringLiteral("both.pdf"));
    const Run run = runCli({QStringLiteral("report"), datasetPath(QStringLiteral("xsens-mtw-ipol/1-4_rf.txt")),
                            datasetPath(QStringLiteral("xsens-mtw-ipol/1-4_lf.txt")), QStringLiteral("--pdf"), pdf});
    VERIFY_EXIT(run, 0);
    QProcess text;
    text.start(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
    QVERIFY(text.waitForFinished(60000));
    const QString report = QString::fromUtf8(text.readAllStandardOutput()).simplified();
    for (const char* expected : {"1-4_lf.txt + 1-4_rf.txt", "Both feet", "Double support (both feet on the ground)",
                                 "Right foot", "Left foot"})
        QVERIFY2(report.contains(QLatin1String(expected)), expected);
    const Run three = runCli({QStringLiteral("report"), QStringLiteral("a_lf.txt"), QStringLiteral("a_rf.txt"),
                              QStringLiteral("c.txt"), QStringLiteral("--pdf"), pdf});
    VERIFY_EXIT(three, kExitBadInput);
    QVERIFY2(three.err.contains(QStringLiteral("unexpected argument 'c.txt'")), qPrintable(three.err));
}

void TestCli::counts_printAsIntegers()
{
    const Run text = runCli({QStringLiteral("eval"), walkCsv_, QStringLiteral("--length"), QStringLiteral("10")});
    VERIFY_EXIT(text, 0);
    const QRegularExpression stepsLine(QStringLiteral("^steps +(\\S+)$"), QRegularExpression::MultilineOption);
    const QRegularExpressionMatch steps = stepsLine.match(text.out);
    QVERIFY2(steps.hasMatch(), qPrintable(text.out));
    QVERIFY2(!steps.captured(1).contains(QLatin1Char('.')), qPrintable(steps.captured(0)));
    const QRegularExpression warningsLine(QStringLiteral("^plausibility warnings +(\\S+)$"),
                                          QRegularExpression::MultilineOption);
    QVERIFY2(!warningsLine.match(text.out).captured(1).contains(QLatin1Char('.')), qPrintable(text.out));

    const Run json = runCli({QStringLiteral("eval"), walkCsv_, QStringLiteral("--json")});
    VERIFY_EXIT(json, 0);
    QVERIFY2(QRegularExpression(QStringLiteral("\"steps\": ?\\d+[,}]")).match(json.out).hasMatch(), qPrintable(json.out));
    const Run process = runCli({QStringLiteral("process"), walkCsv_});
    VERIFY_EXIT(process, 0);
    QVERIFY2(QRegularExpression(QStringLiteral(": \\d+ samples, [0-9.]+ s, \\d+ steps,")).match(process.out).hasMatch(),
             qPrintable(process.out));
}

namespace {

/// The workspace run offscreen with the arguments, its own settings and presets; the exit code
/// (-1 when it had not ended after 60 s) and what it wrote to stderr.
std::pair<int, QString> runGui(const QString& gui, const QString& work, const QStringList& arguments)
{
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), QDir(work).filePath(QStringLiteral("config")));
    environment.insert(QStringLiteral("FOOTPATH_IMPORT_PRESETS"), QDir(work).filePath(QStringLiteral("presets")));
    process.setProcessEnvironment(environment);
    process.start(gui, arguments);
    const bool finished = process.waitForFinished(60000);
    if (!finished)
        process.kill();
    return {finished ? process.exitCode() : -1, QString::fromLocal8Bit(process.readAllStandardError())};
}

}  // namespace

void TestCli::screenshotOfAHeaderlessFile_finishes()
{
    // The workspace beside footpath-cli: a screenshot run needs no user even when the file needs
    // import settings (a confident guess is taken) and ends with exit 2 when it cannot guess.
    const QString gui = QFileInfo(QString::fromUtf8(FOOTPATH_CLI)).dir().filePath(QStringLiteral("footpath"));
    if (!QFileInfo(gui).isExecutable())
        QSKIP("the footpath binary is not built");
    QTemporaryDir work;
    QStringList lines = readLines(walkCsv_).mid(1);  // headerless, time in s: read as time_ms, so no
    for (QString& line : lines) {                     // rate of an IMU: make it milliseconds
        QStringList cells = line.split(QLatin1Char(','));
        cells[0] = QString::number(std::lround(cells[0].toDouble() * 1000.0));
        line = cells.join(QLatin1Char(','));
    }
    const QString headerless = work.filePath(QStringLiteral("headerless.txt"));
    QVERIFY(writeFile(headerless, lines.join(QLatin1Char('\n')).toUtf8() + "\n"));
    const QString prose = work.filePath(QStringLiteral("notes.txt"));
    QVERIFY(writeFile(prose, "A walk around the block.\nNothing else to say.\n"));
    const auto screenshot = [&](const QString& file, const QString& png) {
        return runGui(gui, work.path(), {file, QStringLiteral("--screenshot"), png});
    };
    const QString png = work.filePath(QStringLiteral("shot.png"));
    const auto [guessed, guessedErr] = screenshot(headerless, png);
    QVERIFY2(guessed == 0, qPrintable(guessedErr));
    QVERIFY(QFileInfo(png).size() > 0);
    const auto [refused, refusedErr] = screenshot(prose, work.filePath(QStringLiteral("prose.png")));
    QVERIFY2(refused == kExitBadInput, qPrintable(refusedErr));
    QVERIFY2(refusedErr.contains(QStringLiteral("does not look like sensor data")), qPrintable(refusedErr));
}

void TestCli::screenshotOfAFolderWithoutAPair_endsWithTheReason()
{
    // It waited forever for a result that a folder without a left/right pair never gives.
    const QString gui = QFileInfo(QString::fromUtf8(FOOTPATH_CLI)).dir().filePath(QStringLiteral("footpath"));
    if (!QFileInfo(gui).isExecutable())
        QSKIP("the footpath binary is not built");
    QTemporaryDir work;
    const QString folder = work.filePath(QStringLiteral("walks"));
    QVERIFY(QDir().mkpath(folder));
    QVERIFY(QFile::copy(walkCsv_, QDir(folder).filePath(QStringLiteral("only-one.csv"))));
    const QString png = work.filePath(QStringLiteral("shot.png"));
    const auto [code, err] = runGui(gui, work.path(), {folder, QStringLiteral("--screenshot"), png});
    QVERIFY2(code == kExitBadInput, qPrintable(QStringLiteral("exit %1: %2").arg(code).arg(err)));
    QVERIFY2(err.contains(QStringLiteral("footpath: ")) && err.size() > 20, qPrintable(err));
    QVERIFY(!QFileInfo::exists(png));
}

void TestCli::guiUnknownView_namesTheNearest()
{
    // "--view trajectory" exited 0 without a word.
    const QString gui = QFileInfo(QString::fromUtf8(FOOTPATH_CLI)).dir().filePath(QStringLiteral("footpath"));
    if (!QFileInfo(gui).isExecutable())
        QSKIP("the footpath binary is not built");
    QTemporaryDir work;
    const auto [code, err] = runGui(gui, work.path(), {walkCsv_, QStringLiteral("--view"), QStringLiteral("trajectory"),
                                                        QStringLiteral("--screenshot"), work.filePath("x.png")});
    QCOMPARE(code, kExitBadInput);
    QVERIFY2(err.contains(QStringLiteral("unknown view 'trajectory'; did you mean trajectory2d")), qPrintable(err));
    QVERIFY2(err.contains(QStringLiteral("summary, steps, gait")), qPrintable(err));
    // The summary's views exist now: a screenshot with the gait charts in front finishes.
    const QString png = work.filePath(QStringLiteral("gait.png"));
    const auto [shown, shownErr] = runGui(gui, work.path(), {walkCsv_, QStringLiteral("--view"), QStringLiteral("gait"),
                                                              QStringLiteral("--screenshot"), png});
    QVERIFY2(shown == 0, qPrintable(shownErr));
    QVERIFY(QFileInfo(png).size() > 0);
}

void TestCli::guiColumns_readTheFileAsTold()
{
    // The workspace had no --columns or --import-preset: a file its guess reads wrong could not be
    // opened from the command line.
    const QString gui = QFileInfo(QString::fromUtf8(FOOTPATH_CLI)).dir().filePath(QStringLiteral("footpath"));
    if (!QFileInfo(gui).isExecutable())
        QSKIP("the footpath binary is not built");
    QTemporaryDir work;
    QStringList lines = readLines(walkCsv_).mid(1);  // headerless, the gyroscope before the accelerometer
    for (QString& line : lines) {
        QStringList cells = line.split(QLatin1Char(','));
        const QStringList acc = cells.mid(1, 3), gyr = cells.mid(4, 3);
        cells = QStringList{cells[0]} + gyr + acc;
        line = cells.join(QLatin1Char(','));
    }
    const QString swapped = work.filePath(QStringLiteral("swapped.txt"));
    QVERIFY(writeFile(swapped, lines.join(QLatin1Char('\n')).toUtf8() + "\n"));
    const auto [guessed, guessedErr] = runGui(gui, work.path(), {swapped, QStringLiteral("--screenshot"), work.filePath("a.png")});
    QVERIFY2(guessed == kExitBadInput && guessedErr.contains(QStringLiteral("not gravity")), qPrintable(guessedErr));
    const QString map = QStringLiteral("time_s,gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z");
    const QString png = work.filePath(QStringLiteral("b.png"));
    const auto [told, toldErr] = runGui(gui, work.path(), {swapped, QStringLiteral("--columns"), map, QStringLiteral("--screenshot"), png});
    QVERIFY2(told == 0, qPrintable(toldErr));
    QVERIFY(QFileInfo(png).size() > 0);
    const auto [badPreset, badPresetErr] =
        runGui(gui, work.path(), {swapped, QStringLiteral("--import-preset"), QStringLiteral("no-such-preset"),
                                  QStringLiteral("--screenshot"), png});
    QCOMPARE(badPreset, kExitBadInput);
    QVERIFY2(badPresetErr.contains(QStringLiteral("no-such-preset")), qPrintable(badPresetErr));
}

void TestCli::guiHelpAndVersion_needNoDisplay_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("expected");
    QTest::newRow("--help") << QStringList{QStringLiteral("--help")} << QStringLiteral("--screenshot <file>");
    QTest::newRow("-h") << QStringList{QStringLiteral("-h")} << QStringLiteral("Recording to open");
    QTest::newRow("--version") << QStringList{QStringLiteral("--version")} << QStringLiteral("Footpath " FOOTPATH_VERSION);
}

void TestCli::guiHelpAndVersion_needNoDisplay()
{
    // On a server or over ssh: no X display, no Wayland, no platform chosen. A QApplication would
    // abort there ("could not connect to display"); the answer needs none.
    QFETCH(QStringList, args);
    QFETCH(QString, expected);
    const QString gui = QFileInfo(QString::fromUtf8(FOOTPATH_CLI)).dir().filePath(QStringLiteral("footpath"));
    if (!QFileInfo(gui).isExecutable())
        QSKIP("the footpath binary is not built");
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        environment.remove(QString::fromLatin1(name));
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(gui, args);
    const bool finished = process.waitForFinished(30000);
    if (!finished)
        process.kill();
    const QString out = QString::fromLocal8Bit(process.readAllStandardOutput());
    const QString err = QString::fromLocal8Bit(process.readAllStandardError());
    QVERIFY2(finished && process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0,
             qPrintable(QStringLiteral("exit %1\n%2\n%3").arg(process.exitCode()).arg(out, err)));
    QVERIFY2(out.contains(expected), qPrintable(out));
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
