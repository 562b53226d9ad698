// The comparison mode as a user drives it: tick sets, run them off the GUI thread, read the table,
// see the paths over the main one, pick a set for the workspace, find the table in the PDF.
#include "AnalysisSession.h"
#include "AppSettings.h"
#include "ComparisonPanel.h"
#include "ComparisonTable.h"
#include "MainWindow.h"
#include "TrajectoryView2D.h"
#include "TrajectoryView3D.h"
#include "nav/MethodSets.h"
#include "sim/WalkSimulator.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QHeaderView>
#include <QLabel>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

using namespace footpath;

namespace {

const QString kSets = QStringLiteral("zupt;zupt,zaru;feliz");

SimulatedWalk simulatedRectangle()
{
    return simulateWalk(closedRectanglePath(10.0, 5.0), WalkSimulatorConfig());
}

QString writeWalkCsv(const QTemporaryDir& dir, const Recording& recording)
{
    const QString path = dir.filePath("walk.csv");
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n");
    for (const ImuSample& s : recording.samples)
        file.write(QString::asprintf("%.4f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", s.time_s, s.acc_mps2.x(), s.acc_mps2.y(),
                                     s.acc_mps2.z(), s.gyr_radps.x(), s.gyr_radps.y(), s.gyr_radps.z())
                       .toUtf8());
    return path;
}

int columnTitled(const QTableWidget& table, const QString& title)
{
    for (int c = 0; c < table.columnCount(); ++c)
        if (table.horizontalHeaderItem(c)->text() == title)
            return c;
    return -1;
}

/// A cell's text without the best marker.
QString figureText(const QTableWidget& table, int row, int column)
{
    QString text = table.item(row, column)->text();
    if (text.endsWith(bestMarker()))
        text.chop(bestMarker().size());
    return text;
}

/// Exactly the best row of the column is bold, marked and says "best".
void verifyBestMarking(const QTableWidget& table, int column, int best)
{
    for (int r = 0; r < table.rowCount(); ++r) {
        const QTableWidgetItem* item = table.item(r, column);
        QCOMPARE(item->font().bold(), r == best);
        QCOMPARE(item->text().endsWith(bestMarker()), r == best);
        QCOMPARE(item->toolTip() == QStringLiteral("best"), r == best);
    }
}

QString pdfText(const QString& pdf)
{
    QProcess process;
    process.start(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
    process.waitForFinished(60000);
    return QString::fromUtf8(process.readAllStandardOutput()).simplified();
}

void clickRow(QTableWidget& table, int row)
{
    const QRect cell = table.visualItemRect(table.item(row, 0));
    QTest::mouseClick(table.viewport(), Qt::LeftButton, {}, cell.center());
}

}  // namespace

class TestComparisonView : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        qRegisterMetaType<std::shared_ptr<const Result>>();
        QVERIFY(dir_.isValid());
        walk_ = simulatedRectangle();
        path_ = writeWalkCsv(dir_, walk_.recording);
        QVERIFY(!path_.isEmpty());
    }

    void comparisonInTheWindowMatchesRunComparison()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_comparisonview"));
        MainWindow window(settings);
        window.resize(1280, 800);
        window.show();
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(60000));
        ComparisonPanel* panel = window.comparisonPanel();
        QSignalSpy finished(panel, &ComparisonPanel::finished);
        QVERIFY(window.showComparison(kSets).isEmpty());
        // Off the GUI thread: the runs report through the event loop, after the call returned.
        // (Not isRunning(): the runs may already have ended on the other threads.)
        QCOMPARE(finished.count(), 0);
        QVERIFY(finished.wait(120000));

        std::string error;
        const std::vector<MethodSet> sets =
            parseMethodSets(kSets.toStdString(), window.session()->parameters(), error);
        const std::vector<ComparisonRow> direct = runComparison(*window.session()->recording(), sets, 1);
        QTableWidget& table = *panel->table();
        QCOMPARE(table.rowCount(), 3);
        const int endToStart = columnTitled(table, QStringLiteral("End to start\n(m)"));
        const int endToStartPct = columnTitled(table, QStringLiteral("End to start\n(%)"));
        const int pathLength = columnTitled(table, QStringLiteral("Path length\n(m)"));
        const int steps = columnTitled(table, QStringLiteral("Steps"));
        QVERIFY(endToStart > 0 && endToStartPct > 0 && pathLength > 0 && steps > 0);
        QCOMPARE(columnTitled(table, QStringLiteral("ARMSE 2D\n(m)")), -1);  // the CSV has no reference
        for (int r = 0; r < 3; ++r) {
            const ComparisonRow& row = direct[static_cast<std::size_t>(r)];
            QVERIFY2(row.output.error.empty(), row.output.error.c_str());
            QCOMPARE(table.item(r, 0)->text(), methodSetText(row.set.name));
            QCOMPARE(figureText(table, r, endToStart), QString::number(row.endToStart_m, 'f', 2));
            QCOMPARE(figureText(table, r, endToStartPct), QString::number(row.endToStartPct, 'f', 2));
            QCOMPARE(figureText(table, r, pathLength), QString::number(row.pathLength_m, 'f', 2));
            QCOMPARE(figureText(table, r, steps), QString::number(row.output.result.summary.steps));
        }
        verifyBestMarking(table, endToStart, bestComparisonRow(direct, "end_to_start_m"));
        verifyBestMarking(table, pathLength, -1);  // no "best" path length

        // Every set's path over the main one, with a legend entry each, in both views.
        auto* view2D = window.findChild<TrajectoryView2D*>(QStringLiteral("trajectory2D"));
        auto* view3D = window.findChild<TrajectoryView3D*>(QStringLiteral("trajectory3D"));
        QCOMPARE(view2D->overlayCurves().size(), std::size_t(3));
        QCOMPARE(view2D->overlayLegend()->itemCount(), 3);
        QVERIFY(view2D->overlayLegend()->visible());
        for (std::size_t i = 0; i < 3; ++i) {
            QCPCurve* curve = view2D->overlayCurves()[i];
            QVERIFY(view2D->overlayLegend()->hasItemWithPlottable(curve));
            QCOMPARE(curve->name(), methodSetText(direct[i].set.name));
            QCOMPARE(std::size_t(curve->dataCount()), direct[i].output.result.position_m.size());
        }
        QCOMPARE(view3D->overlays().size(), std::size_t(3));
        QCOMPARE(panel->heightPlot()->graphCount(), 3);

        // The PDF has the table.
        if (!QStandardPaths::findExecutable(QStringLiteral("pdftotext")).isEmpty()) {
            const QString pdf = dir_.filePath("report.pdf");
            QVERIFY(window.writeReport(pdf).isEmpty());
            const QString text = pdfText(pdf);
            QVERIFY(text.contains(QStringLiteral("Method comparison")));
            QVERIFY(text.contains(QStringLiteral("ZUPT+ZARU")));
            QVERIFY(text.contains(QString::number(direct[2].pathLength_m, 'f', 2)));
        }

        // Clicking a row makes its methods the workspace's; undo goes back.
        const Parameters before = window.session()->parameters();
        QSignalSpy reestimated(&window, &MainWindow::resultShown);
        clickRow(table, 1);
        QVERIFY(window.session()->parameters() == direct[1].set.params);
        QVERIFY(window.session()->parameters() != before);
        QVERIFY(window.findChild<QCheckBox*>(QStringLiteral("check_use_zaru"))->isChecked());
        QVERIFY(reestimated.wait(60000));
        QVERIFY(!panel->isStale());  // a row's own set is no reason to rerun
        window.session()->undoStack()->undo();
        QVERIFY(window.session()->parameters() == before);

        // Parameters changed (as "Use the tuned parameters" changes them): the window marks the
        // comparison stale, and the PDF says so too (it passed the rows off as current).
        Parameters tuned = window.session()->parameters();
        tuned.r_zupt_mps *= 2.0;
        window.session()->setParameters(tuned, QStringLiteral("Tuned parameters"));
        QVERIFY(panel->isStale());
        if (!QStandardPaths::findExecutable(QStringLiteral("pdftotext")).isEmpty()) {
            const QString pdf = dir_.filePath("stale.pdf");
            QVERIFY(window.writeReport(pdf).isEmpty());
            const QString text = pdfText(pdf).simplified();
            QVERIFY2(text.contains(QStringLiteral("Method comparison (stale)")), qPrintable(text.left(400)));
            QVERIFY(text.contains(QStringLiteral("Run the comparison again to update it")));
        }
        window.session()->undoStack()->undo();

        // Closing the panel takes the paths away; no comparison in the report then.
        window.findChild<QDockWidget*>(QStringLiteral("comparisonDock"))->close();
        QVERIFY(view2D->overlayCurves().empty());
        QCOMPARE(view2D->overlayLegend()->itemCount(), 0);
        QVERIFY(!view2D->overlayLegend()->visible());
        QVERIFY(view3D->overlays().empty());
    }

    void referenceColumnsBestMarksAndStaleness()
    {
        ComparisonPanel panel;
        Recording recording = walk_.recording;
        recording.reference.positions_m = walk_.truePosition_m;
        auto shared = std::make_shared<const Recording>(recording);
        panel.setRecording(shared);
        QVERIFY(panel.setCheckedSets(kSets).isEmpty());
        QCOMPARE(panel.checkedSets(), kSets);
        QSignalSpy finished(&panel, &ComparisonPanel::finished);
        panel.run();
        QVERIFY(finished.wait(120000));

        std::string error;
        const std::vector<ComparisonRow> direct =
            runComparison(recording, parseMethodSets(kSets.toStdString(), Parameters(), error), 1);
        const int armse = columnTitled(*panel.table(), QStringLiteral("ARMSE 2D\n(m)"));
        QVERIFY(armse > 0);
        for (int r = 0; r < 3; ++r)
            QCOMPARE(figureText(*panel.table(), r, armse),
                     QString::number(direct[static_cast<std::size_t>(r)].armse2d_m, 'f', 3));
        const int best = bestComparisonRow(direct, "armse_2d_m");
        QVERIFY(best >= 0);
        verifyBestMarking(*panel.table(), armse, best);

        // Parameters changed: the rows stay, marked stale, until run again.
        Parameters changed;
        changed.gravity_mps2 = 9.80;
        panel.setBaseParameters(changed);
        QVERIFY(panel.isStale());
        QVERIFY(panel.findChild<QLabel*>(QStringLiteral("comparisonHint"))->text().startsWith(QStringLiteral("Stale")));
        QCOMPARE(panel.rows().size(), std::size_t(3));

        // A new recording drops the rows (and with them the overlays).
        QSignalSpy rowsChanged(&panel, &ComparisonPanel::rowsChanged);
        panel.setRecording(shared);
        QCOMPARE(rowsChanged.count(), 1);
        QVERIFY(panel.rows().empty());
        QVERIFY(panel.overlays().empty());
        QCOMPARE(panel.table()->rowCount(), 0);
    }

    void aBadCustomSetIsExplainedInline()
    {
        ComparisonPanel panel;
        panel.show();
        const QString before = panel.checkedSets();
        const QString error = panel.addCustomSet(QStringLiteral("zupt,hdx"));
        QVERIFY(error.contains(QStringLiteral("hdx")));
        auto* label = panel.findChild<QLabel*>(QStringLiteral("customSetError"));
        QVERIFY(label->isVisible());
        QCOMPARE(label->text(), error);
        QCOMPARE(panel.checkedSets(), before);
        QVERIFY(panel.addCustomSet(QStringLiteral("zupt, HDR ,mag")).isEmpty());
        QVERIFY(!label->isVisible());
        QVERIFY(panel.checkedSets().endsWith(QStringLiteral(";zupt,hdr,mag")));
        QVERIFY(!panel.setCheckedSets(QStringLiteral("zupt;nonsense")).isEmpty());
        QVERIFY(panel.checkedSets().endsWith(QStringLiteral(";zupt,hdr,mag")));  // unchanged by the bad spec
    }

private:
    QTemporaryDir dir_;
    SimulatedWalk walk_;
    QString path_;
};

QTEST_MAIN(TestComparisonView)
#include "tst_comparisonview.moc"
