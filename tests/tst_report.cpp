// The PDF report and the CSV exports: the PDF opens, holds the figures the summary computed as
// real text, comes in A4 and Letter; the CSV files read back to the numbers they were written from.
// Set FOOTPATH_REPORT_KEEP=dir to keep the generated PDFs for looking at them.
#include "ReportWriter.h"
#include "SummaryPanel.h"
#include "TestData.h"
#include "io/ResultWriters.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QRegularExpression>
#include <QtTest>

#include <sstream>

using namespace footpath;

namespace {

ReportContent contentFor(const QString& path, const ImportOptions& options = {}, const Parameters& params = {})
{
    ImportResult read = importRecording(path.toStdString(), options);
    ReportContent content;
    if (!read.ok())
        return content;
    content.recordingPath = path;
    content.info = read.info;
    content.parameters = params;
    content.recording = std::make_shared<const Recording>(std::move(read.recording));
    content.result = std::make_shared<const Result>(runPipeline(*content.recording, content.parameters).result);
    return content;
}

QString run(const QString& program, const QStringList& arguments)
{
    QProcess process;
    process.start(program, arguments);
    process.waitForFinished(60000);
    return QString::fromUtf8(process.readAllStandardOutput());
}

/// The PDF's words on one line, with the typesetter's fi and fl ligatures spelled out.
QString pdfWords(const QString& pdf)
{
    return run("pdftotext", {pdf, "-"})
        .replace(QChar(0xFB01), QStringLiteral("fi"))
        .replace(QChar(0xFB02), QStringLiteral("fl"))
        .simplified();
}

/// A report of a simulated 10 x 5 m rectangle estimated with params.
ReportContent simulatedWalkContent(const Parameters& params)
{
    const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), WalkSimulatorConfig());
    ReportContent content;
    content.recordingPath = "simulated.csv";
    content.recording = std::make_shared<const Recording>(walk.recording);
    content.parameters = params;
    content.result = std::make_shared<const Result>(runPipeline(*content.recording, params).result);
    return content;
}

QString outputDir(const QTemporaryDir& temporary)
{
    const QByteArray keep = qgetenv("FOOTPATH_REPORT_KEEP");
    return keep.isEmpty() ? temporary.path() : QString::fromLocal8Bit(keep);
}

}  // namespace

class TestReport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        if (QStandardPaths::findExecutable("pdftotext").isEmpty() || QStandardPaths::findExecutable("pdfinfo").isEmpty())
            QSKIP("pdftotext/pdfinfo (Debian: poppler-utils) are not installed");
    }

    void pdfHoldsTheSummaryFiguresAsText()
    {
        FOOTPATH_REQUIRE_DATASETS();
        QTemporaryDir dir;
        const ReportContent content = contentFor(datasetPath("pyshoe-vicon/2017-11-22-11-22-03.csv"));
        QVERIFY(content.result);
        const QString pdf = outputDir(dir) + "/pyshoe-report.pdf";
        QCOMPARE(writePdfReport(content, pdf), QString());
        const QString info = run("pdfinfo", {pdf});
        QVERIFY2(info.contains("A4"), qPrintable(info));
        const int pages = info.section("Pages:", 1).trimmed().section('\n', 0, 0).toInt();
        QVERIFY2(pages >= 5, qPrintable(info));
        const QString text = run("pdftotext", {"-layout", pdf, "-"});
        const GaitStatistics g = computeGaitStatistics(*content.result, content.recording.get());
        QVERIFY(g.armse.has_value());
        for (const QString& figure : {QString::number(g.pathLength_m, 'f', 2) + " m",
                                      QString::number(g.armse->armse2d_m, 'f', 3) + " m",
                                      QString::number(content.result->summary.steps),
                                      QStringLiteral("2017-11-22-11-22-03.csv"), methodSetName(content.parameters),
                                      QStringLiteral("acc_std_max_mps2"), QStringLiteral("Figure 5")})
            QVERIFY2(text.contains(figure), qPrintable(figure));
        // Every step is in the table, paged as needed: the last step's number appears.
        QVERIFY(text.contains(QString::number(content.result->steps.size() - 1)));
    }

    void changedParametersAreMarkedAndLetterWorks()
    {
        QTemporaryDir dir;
        Parameters params;
        params.acc_std_max_mps2 = 0.7;
        params.use_zaru = false;
        const ReportContent content = simulatedWalkContent(params);
        const QString pdf = outputDir(dir) + "/letter-report.pdf";
        QCOMPARE(writePdfReport(content, pdf, QPageSize::Letter), QString());
        QVERIFY(run("pdfinfo", {pdf}).contains("letter"));
        const QString text = run("pdftotext", {"-layout", pdf, "-"});
        QVERIFY(text.contains("0.7"));
        QVERIFY(text.contains("ZUPT"));
        QVERIFY(!text.contains("ZUPT+ZARU"));
        // The mark the heading explains stands before the changed parameters, and only there.
        QVERIFY(text.contains("(* and bold: di"));  // pdftotext gives "ff" as a ligature
        QVERIFY2(text.contains(QRegularExpression("\\* acc_std_max_mps2\\s+0\\.7")), "acc_std_max_mps2 is not marked");
        QVERIFY(!text.contains(QRegularExpression("\\* gyr_max_radps")));
        // Long descriptions wrap instead of being cut with an ellipsis.
        QVERIFY(!text.contains(QChar(0x2026)));
        // Units as everywhere else (m/s², not the presets' m/s^2); no figure or tick reads "-0.000".
        QVERIFY(text.contains(QStringLiteral("m/s²")));
        QVERIFY(!text.contains(QStringLiteral("m/s^2")));
        const QRegularExpressionMatch negativeZero = QRegularExpression(QStringLiteral("-0(\\.0+)?(?![.0-9])")).match(text);
        QVERIFY2(!negativeZero.hasMatch(), qPrintable(negativeZero.captured()));
    }

    void valuesStayWholeAndTablesStartWithTheirRows()
    {
        // A tuned value was printed "0.\n000958747" (wrapped after its point), and the Parameters
        // table started with its heading and two rows at a page's foot.
        QTemporaryDir dir;
        Parameters params;
        params.q_vel_mps = 0.000958747;
        params.zv_min_stance_s = 0.0412345;
        const ReportContent content = simulatedWalkContent(params);
        const QString pdf = outputDir(dir) + "/wide-values-report.pdf";
        QCOMPARE(writePdfReport(content, pdf), QString());
        const QString text = run("pdftotext", {"-layout", pdf, "-"});
        QVERIFY(text.contains(QRegularExpression("\\* q_vel_mps\\s+0\\.000958747\\s")));
        QVERIFY(text.contains(QRegularExpression("\\* zv_min_stance_s\\s+0\\.0412345\\s")));
        // The page that holds a table's heading holds its first rows too.
        const QStringList pages = text.split(QLatin1Char('\f'));
        for (const auto& [heading, firstRows] :
             {std::pair{QStringLiteral("Parameters ("), QStringList{"alignment_s", "gravity_mps2", "declination_rad", "detector"}},
              std::pair{QStringLiteral("Steps\n"), QStringList{"Stance from", "\n1 ", "\n2 ", "\n3 "}}}) {
            const QString& title = heading;  // a lambda may not capture a structured binding (C++17)
            const auto page = std::find_if(pages.begin(), pages.end(), [&title](const QString& p) { return p.contains(title); });
            QVERIFY2(page != pages.end(), qPrintable(heading));
            for (const QString& row : firstRows)
                QVERIFY2(QString(*page).replace(QRegularExpression("\n[ \t]+"), "\n").contains(row),
                         qPrintable(heading + " without " + row));
        }
    }

    void aLongWalksPathFigureLeavesOutItsStanceMarkers()
    {
        // 600 m straight on: strides of 1.4 m are about 2 px apart on the page's path figures, so
        // the stances are not drawn and the captions do not promise them; a short walk keeps both.
        const auto captionOf = [](const std::vector<Eigen::Vector3d>& path, const QString& name) {
            const SimulatedWalk walk = simulateWalk(path, WalkSimulatorConfig());
            ReportContent content;
            content.recordingPath = name;
            content.recording = std::make_shared<const Recording>(walk.recording);
            content.result = std::make_shared<const Result>(runPipeline(*content.recording, content.parameters).result);
            QTemporaryDir dir;
            const QString pdf = outputDir(dir) + "/" + name + ".pdf";
            const QString error = writePdfReport(content, pdf);
            return error.isEmpty() ? pdfWords(pdf) : error;
        };
        const QString longWalk = captionOf(straightLinePath(600.0), QStringLiteral("long"));
        // Both path figures, from above and in 3D, say so.
        QCOMPARE(longWalk.count("too close together at this scale to be marked"), 2);
        QVERIFY(!longWalk.contains("stance positions as dots"));
        const QString shortWalk = captionOf(closedRectanglePath(10.0, 5.0), QStringLiteral("short"));
        QCOMPARE(shortWalk.count("stance positions as dots"), 2);
        QVERIFY(shortWalk.contains("Figure 3. The path in 3D (stance positions as dots"));
    }

    // The step table counts stance phases from 1, as the window's table does: the first row is
    // step 1 and the last the number of stance phases.
    void stepTableNumbersFromOne()
    {
        QTemporaryDir dir;
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), WalkSimulatorConfig());
        ReportContent content;
        content.recordingPath = "simulated.csv";
        content.recording = std::make_shared<const Recording>(walk.recording);
        content.result = std::make_shared<const Result>(runPipeline(*content.recording, content.parameters).result);
        const QString pdf = outputDir(dir) + "/steps-report.pdf";
        QCOMPARE(writePdfReport(content, pdf), QString());
        const QString text = run("pdftotext", {"-layout", pdf, "-"});
        const QString table = text.section(QStringLiteral("Stance from"), 1).section(QStringLiteral("Import notes"), 0, 0);
        QList<int> numbers;
        static const QRegularExpression row("^\\s*(\\d+)\\s+\\d+\\.\\d\\d\\s+\\d+\\.\\d\\d\\s");
        for (const QString& line : table.split('\n'))
            if (const QRegularExpressionMatch match = row.match(line); match.hasMatch())
                numbers << match.captured(1).toInt();
        QVERIFY2(!numbers.isEmpty(), qPrintable(table.left(500)));
        QCOMPARE(numbers.first(), 1);
        QCOMPARE(numbers.last(), int(content.result->steps.size()));
        QCOMPARE(numbers.size(), int(content.result->steps.size()));
        // The first stance ends no stride: dashes, as in the window's table, where a stride of 0 would mislead.
        static const QRegularExpression first("^\\s*1\\s+\\d+\\.\\d\\d\\s+\\d+\\.\\d\\d\\s+(\\S+)\\s+(\\S+)\\s", QRegularExpression::MultilineOption);
        const QRegularExpressionMatch firstRow = first.match(table);
        QVERIFY2(firstRow.hasMatch(), qPrintable(table.left(500)));
        QCOMPARE(firstRow.captured(1), QStringLiteral("\u2013"));
        QCOMPARE(firstRow.captured(2), QStringLiteral("\u2013"));

        std::ostringstream csv;
        writeStepsCsv(csv, *content.result);
        const QStringList rows = QString::fromStdString(csv.str()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(rows.size(), int(content.result->steps.size()) + 1);
        QVERIFY2(rows[1].startsWith("1,"), qPrintable(rows[1]));
        QVERIFY2(rows.last().startsWith(QString::number(content.result->steps.size()) + ","), qPrintable(rows.last()));
    }

    void warningsHaveTheirOwnSectionWithTheirSpans()
    {
        // The shared running trial with the paper's detector: its fixed C2 bound misses the
        // running stances (docs/method.md, "Saying when a result is wrong").
        FOOTPATH_REQUIRE_DATASETS();
        QTemporaryDir dir;
        Parameters params;
        params.detector = static_cast<int>(DetectorKind::PaperC1C2C3);
        const ReportContent content = contentFor(datasetPath("pyshoe-vicon/2017-11-27-11-22-22.csv"), {}, params);
        QVERIFY(content.result);
        QVERIFY(!content.result->warnings.empty());
        const QString pdf = outputDir(dir) + "/running-c1c2c3-report.pdf";
        QCOMPARE(writePdfReport(content, pdf), QString());
        const QString text = pdfWords(pdf);
        QVERIFY(text.contains(QStringLiteral("Plausibility warnings")));
        for (const PlausibilityWarning& w : content.result->warnings) {
            const QString opening = QString::fromStdString(w.message).section(QLatin1Char(' '), 0, 5);
            QVERIFY2(text.contains(opening), qPrintable(opening));
            QVERIFY2(text.contains(QString::number(w.start_s, 'f', 2)), qPrintable(QString::number(w.start_s, 'f', 2)));
        }
        QVERIFY(text.contains(QStringLiteral("blocked by C2")));  // what kept the detector from the stance
        // Before the figures, after the summary; the import's own notes are a section apart.
        QVERIFY(text.indexOf(QStringLiteral("Plausibility warnings")) < text.indexOf(QStringLiteral("Figure 1")));
        QVERIFY(text.indexOf(QStringLiteral("Summary")) < text.indexOf(QStringLiteral("Plausibility warnings")));
        QVERIFY(text.contains(QStringLiteral("Import notes (reading the file)")));
        QVERIFY(text.contains(QStringLiteral("Reading the file raised no warnings.")));
        QVERIFY(text.contains(QStringLiteral("Stance detector C1/C2/C3")));
    }

    void aResultWithoutWarningsSaysSo()
    {
        QTemporaryDir dir;
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), WalkSimulatorConfig());
        ReportContent content;
        content.recordingPath = "simulated.csv";
        content.recording = std::make_shared<const Recording>(walk.recording);
        content.result = std::make_shared<const Result>(runPipeline(*content.recording, content.parameters).result);
        QVERIFY(content.result->warnings.empty());
        const QString pdf = outputDir(dir) + "/no-warnings-report.pdf";
        QCOMPARE(writePdfReport(content, pdf), QString());
        const QString text = pdfWords(pdf);
        QVERIFY(text.contains(QStringLiteral("Plausibility warnings")));
        QVERIFY(text.contains(QStringLiteral("The plausibility checks found nothing")));
        QVERIFY(text.contains(QStringLiteral("detector SHOE")));  // Figure 5 names the chosen detector
        QVERIFY(text.contains(QStringLiteral("detector shoe")));  // the parameter table spells the choice
    }

    void nothingToReportIsAnErrorNotACrash()
    {
        QTemporaryDir dir;
        QVERIFY(!writePdfReport(ReportContent(), dir.filePath("empty.pdf")).isEmpty());
    }

    void trajectoryCsvRoundTrips()
    {
        const SimulatedWalk walk = simulateWalk(straightLinePath(5.0), WalkSimulatorConfig());
        const Result result = runPipeline(walk.recording, Parameters()).result;
        std::ostringstream out;
        writeTrajectoryCsv(out, result);
        std::istringstream in(out.str());
        std::string line;
        std::getline(in, line);
        QVERIFY(QString::fromStdString(line).startsWith("time_s,x_m,y_m,z_m,"));
        QVERIFY(QString::fromStdString(line).endsWith("acc_bias_z_mps2"));
        for (std::size_t k = 0; std::getline(in, line); ++k) {
            const QStringList cells = QString::fromStdString(line).split(',');
            QCOMPARE(cells.size(), 21);
            // 10 significant digits: sub-micrometre here.
            QVERIFY(std::abs(cells[1].toDouble() - result.position_m[k].x()) <= 1e-9 * (1 + std::abs(result.position_m[k].x())));
            QVERIFY(std::abs(cells[17].toDouble() - result.gyroBias_radps[k].z()) <= 1e-12 + 1e-9 * std::abs(result.gyroBias_radps[k].z()));
        }
    }

    void csvUsesADotWhateverTheLocale()
    {
        // Qt sets the C locale from the environment; a German one writes "9,81" with printf.
        const char* previous = std::setlocale(LC_ALL, nullptr);
        const std::string saved = previous ? previous : "C";
        if (!std::setlocale(LC_ALL, "de_DE.UTF-8"))
            std::setlocale(LC_NUMERIC, "de_DE");
        Parameters params;
        params.acc_std_max_mps2 = 0.25;
        std::ostringstream out;
        writeParametersCsv(out, params);
        std::setlocale(LC_ALL, saved.c_str());
        QVERIFY(QString::fromStdString(out.str()).contains("acc_std_max_mps2,0.25,m/s^2,0.5,1,"));
    }

    void summaryCsvHasUnitsInItsHeader()
    {
        Result result;
        result.summary.samples = 10;
        result.summary.pathLength_m = 12.5;
        std::ostringstream out;
        writeSummaryCsv(out, result);
        QVERIFY(QString::fromStdString(out.str())
                    .startsWith("samples,duration_s,stance_phases,steps,path_length_m,end_to_start_m,"
                                "end_to_start_pct,runtime_s,stair_steps_up,stair_steps_down,elevator_rides,"
                                "stairs_climb_m,stairs_descent_m,gait_strides,gait_stride_time_s,"
                                "gait_stride_length_m,gait_cadence_spm,gait_stance_pct,gait_swing_pct,"
                                "gait_clearance_m,merged_movements,warnings\n10,0,0,0,12.5,"));
        // No stride to average: empty gait cells, not zeros.
        QVERIFY2(QString::fromStdString(out.str()).endsWith(",0,,,,,,,0,0\n"), out.str().c_str());

        // The gait figures and the counts the window shows are there (they were missing).
        result.gait.strides = 5;
        result.gait.straightStrides = 4;
        result.gait.cadence_spm = 104.5;
        result.mergedMovements.push_back({1.0, 1.5, 0.004, 0.6});
        result.warnings.push_back({PlausibilityWarning::Kind::LongSwing, 2.0, 5.0, "a missed stance"});
        std::ostringstream filled;
        writeSummaryCsv(filled, result);
        QVERIFY2(QString::fromStdString(filled.str()).endsWith(",5,0,0,104.5,0,0,0,1,1\n"), filled.str().c_str());
    }

    void exportsCarryMotionClassesAndMethodNotes()
    {
        Result result;
        result.steps.resize(2);
        result.steps[1].strideLength_m = 1.25;
        result.steps[1].strideDuration_s = 1.1;
        result.steps[1].motion = MotionClass::StairsUp;
        result.steps[1].baroHeight_m = 0.25;
        result.summary.stairStepsUp = 1;
        result.summary.stairsClimb_m = 0.25;
        result.methodNotes.push_back({"iper", 1.5, 9.0, "not applied: no \"straight\" stretch"});
        std::ostringstream steps;
        writeStepsCsv(steps, result);
        const QStringList rows = QString::fromStdString(steps.str()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(rows.size(), 3);
        QVERIFY(rows[0].contains(",stride_duration_s,motion,baro_height_m,heel_strike_s,"));
        QVERIFY2(rows[1].contains(",unknown,,"), qPrintable(rows[1]));  // no barometer: an empty cell
        // The first step has no stride before it: empty cells, as the window shows "-" (it wrote 0,0).
        QVERIFY2(rows[1].startsWith("1,0,0,0,0,0,,,unknown,"), qPrintable(rows[1]));
        QVERIFY2(rows[2].contains(",1.25,1.1,"), qPrintable(rows[2]));
        QVERIFY2(rows[1].startsWith("1,") && rows[2].startsWith("2,"), "steps are numbered from 1");
        QVERIFY2(rows[2].contains(",stairs_up,0.25,"), qPrintable(rows[2]));

        const QJsonObject json =
            QJsonDocument::fromJson(QByteArray::fromStdString(summaryToJson(result)))
                .object();
        const QJsonObject motion = json.value("motion").toObject();
        QCOMPARE(motion.value("stair_steps_up").toInt(), 1);
        QCOMPARE(motion.value("stairs_climb_m").toDouble(), 0.25);
        QCOMPARE(motion.value("elevator_rides").toInt(), 0);
        QVERIFY(json.value("gait").toObject().contains("cadence_spm"));
        QCOMPARE(json.value("merged_movements").toArray().size(), 0);
        const QJsonArray notes = json.value("method_notes").toArray();
        QCOMPARE(notes.size(), 1);
        QCOMPARE(notes[0].toObject().value("method").toString(), QStringLiteral("iper"));
        QCOMPARE(notes[0].toObject().value("end_s").toDouble(), 9.0);
        QCOMPARE(notes[0].toObject().value("message").toString(),
                 QStringLiteral("not applied: no \"straight\" stretch"));
    }
};

QTEST_MAIN(TestReport)
#include "tst_report.moc"
