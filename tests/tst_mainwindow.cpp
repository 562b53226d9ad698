// The workspace as a user drives it: open a file, tune a slider, toggle ZARU, undo, switch language.
#include "AnalysisSession.h"
#include "AppSettings.h"
#include "HelpDialog.h"
#include "LivePanel.h"
#include "LiveViews.h"
#include "MainWindow.h"
#include "ParameterPanel.h"
#include "RunHistory.h"
#include "SignalPlots.h"
#include "StanceFlagsPlot.h"
#include "SummaryPanel.h"
#include "TrajectoryView2D.h"
#include "TrajectoryView3D.h"
#include "nav/StreamingEstimator.h"
#include "sim/WalkSimulator.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QPushButton>
#include <QScreen>
#include <QStatusBar>
#include <QTableWidget>
#include <QTextBrowser>
#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QTableView>
#include <QFontDatabase>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QSlider>
#include <QTabWidget>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTranslator>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

using namespace footpath;

namespace {

QString writeSimulatedWalk(const QTemporaryDir& dir, std::size_t& samples)
{
    const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), WalkSimulatorConfig());
    const QString path = dir.filePath("walk.csv");
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n");
    for (const ImuSample& s : walk.recording.samples)
        file.write(QString::asprintf("%.4f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", s.time_s, s.acc_mps2.x(), s.acc_mps2.y(),
                                     s.acc_mps2.z(), s.gyr_radps.x(), s.gyr_radps.y(), s.gyr_radps.z())
                       .toUtf8());
    samples = walk.recording.samples.size();
    return path;
}

Parameters paperDetector()
{
    Parameters params;
    params.detector = static_cast<int>(DetectorKind::PaperC1C2C3);
    return params;
}

/// C1/C2/C3 with a median filter longer than any step's stance: only the rest at the start and the
/// end remain, so the checks find a missed stance (blocked by the median filter), a stride far too
/// long and too few stances.
Parameters missingEveryStance()
{
    Parameters params = paperDetector();
    params.median_window_s = 2.0;
    return params;
}

QString statisticAxisLabel(const MainWindow& window)
{
    const auto* flags = window.findChild<StanceFlagsPlot*>(QStringLiteral("stanceFlags"));
    return flags->statisticRect()->axis(QCPAxis::atLeft)->label();
}

}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        qRegisterMetaType<std::shared_ptr<const Result>>();
        QVERIFY(dir_.isValid());
        path_ = writeSimulatedWalk(dir_, samples_);
        QVERIFY(!path_.isEmpty());
    }

    void opensAFileAndThePlotsHoldItsSamples()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        QCOMPARE(window.session()->recording()->samples.size(), samples_);
        const auto* plots = window.findChild<SignalPlots*>(QStringLiteral("signalPlots"));
        QVERIFY(plots);
        QCOMPARE(std::size_t(plots->graph(SignalPlots::Channel::AccX)->dataCount()), samples_);
        QVERIFY(window.session()->result()->summary.steps > 10);
        QVERIFY(settings.recentFiles().contains(path_));
    }

    void movingASliderReRunsAndUndoRestores()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        window.session()->setParameters(paperDetector(), QStringLiteral("C1/C2/C3"));  // whose C2 the slider bounds
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        const std::shared_ptr<const Result> before = window.session()->result();

        auto* slider = window.findChild<QSlider*>(QStringLiteral("slider_acc_std_max_mps2"));
        QVERIFY(slider->isEnabled());
        QVERIFY(slider);
        slider->setValue(slider->minimum() + (slider->maximum() - slider->minimum()) / 100);  // 0.2 m/s²: a strict C2
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() != before && window.session()->result(), 30000);
        QVERIFY(window.session()->parameters().acc_std_max_mps2 < Parameters().acc_std_max_mps2);
        QVERIFY(window.session()->result()->flags.c2 != before->flags.c2);

        window.session()->undoStack()->undo();
        QCOMPARE(window.session()->parameters().acc_std_max_mps2, Parameters().acc_std_max_mps2);
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() && window.session()->result()->flags.c2 == before->flags.c2,
                                 30000);
    }

    void liveViewsSitBesideTheRecordedOnesAndFollowTheParameters()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        auto* live = window.findChild<LivePanel*>();
        QVERIFY(live);
        // The live views are tabs of the workspace's central tab widgets, not squeezed into the dock.
        for (QWidget* view : {static_cast<QWidget*>(live->views()->trajectory2D()),
                              static_cast<QWidget*>(live->views()->trajectory3D()),
                              static_cast<QWidget*>(live->views()->signalPlots()),
                              static_cast<QWidget*>(live->views()->stanceFlags())}) {
            QWidget* tabs = view->parentWidget() ? view->parentWidget()->parentWidget() : nullptr;
            QVERIFY(qobject_cast<QTabWidget*>(tabs));
            QVERIFY(!live->isAncestorOf(view));
        }
        const double before = live->latency_s();
        auto* slider = window.findChild<QSlider*>(QStringLiteral("slider_zv_window_s"));
        QVERIFY(slider);
        slider->setValue(slider->maximum());
        QVERIFY(live->latency_s() > before);  // the live estimator uses the workspace's parameters
        QCOMPARE(live->latency_s(), StreamingEstimator::latency_s(window.session()->parameters()));
    }

    void theStatusLineAndSummaryFollowWhatIsShownWithTheLivePanelRaised()
    {
        // Once the status line read "140230212493232 samples, 2913 steps, ... estimated in 21128 ms"
        // with the live panel raised: a MainWindow object built against an older Result (without
        // forwardSpeed_mps) read the summary 24 bytes off. Its figures must be the walk's own.
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        window.resize(1280, 800);
        window.show();
        auto* liveDock = window.findChild<QDockWidget*>(QStringLiteral("liveDock"));
        QVERIFY(liveDock);
        liveDock->raise();
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        const std::shared_ptr<const Result> result = window.session()->result();
        const auto* status = window.findChild<QLabel*>(QStringLiteral("status"));
        QVERIFY(status);
        if (result->warnings.empty()) {
            // Counted here from the recording and the step list, not read from the summary.
            const QString expected = QStringLiteral("%1 samples, %2 steps, path ")
                                         .arg(window.session()->recording()->samples.size())
                                         .arg(result->steps.size() - 1);
            QVERIFY2(status->text().startsWith(expected), qPrintable(status->text() + " / " + expected));
            const double runtime_ms = status->text().section(QStringLiteral("estimated in "), 1).section(' ', 0, 0).toDouble();
            QVERIFY2(runtime_ms >= 0.0 && runtime_ms < 60000.0, qPrintable(status->text()));
        }

        // The live session's figures while its views are in front, the recorded walk's after.
        auto* summary = window.findChild<SummaryPanel*>();
        auto* live = window.findChild<LivePanel*>();
        QVERIFY(summary && live);
        QVERIFY(!summary->isShowingLive());
        const double recordedPath_m = summary->statistics().pathLength_m;
        QVERIFY(recordedPath_m > 1.0);
        auto* trajectoryTabs = qobject_cast<QTabWidget*>(live->views()->trajectory2D()->parentWidget()->parentWidget());
        QVERIFY(trajectoryTabs);
        trajectoryTabs->setCurrentWidget(live->views()->trajectory2D());
        QVERIFY(summary->isShowingLive());
        QCOMPARE(summary->statistics().pathLength_m, 0.0);  // nothing connected: no live figures yet
        QVERIFY(summary->findChild<QLabel*>(QStringLiteral("liveSource"))->isVisibleTo(summary));
        // The status line too is the session's (it kept the recorded walk's figures): its state so far.
        QCOMPARE(status->text(), QStringLiteral("Live session: %1").arg(live->statusText()));
        QVERIFY(!live->statusText().isEmpty());
        // The recorded walk re-estimated meanwhile (a parameter changed) does not take the line back.
        Parameters params = window.session()->parameters();
        params.acc_std_max_mps2 *= 0.9;
        window.session()->setParameters(params, QStringLiteral("test"));
        QVERIFY(shown.wait(30000));
        QCOMPARE(status->text(), QStringLiteral("Live session: %1").arg(live->statusText()));
        trajectoryTabs->setCurrentWidget(window.findChild<TrajectoryView2D*>(QStringLiteral("trajectory2D")));
        QVERIFY(!summary->isShowingLive());
        QVERIFY(!summary->findChild<QLabel*>(QStringLiteral("liveSource"))->isVisibleTo(summary));
        // Back at the recorded walk: its line, of the new estimate.
        QVERIFY2(status->text().startsWith(QStringLiteral("%1 samples, ").arg(window.session()->recording()->samples.size()))
                     || status->text().contains(QStringLiteral("plausibility warning")),
                 qPrintable(status->text()));
        QVERIFY(status->text() != QStringLiteral("Live session: %1").arg(live->statusText()));
        QCOMPARE(summary->statistics().pathLength_m, window.session()->result()->summary.pathLength_m);
    }

    void togglingZaruChangesTheEstimate()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        Parameters params;
        params.filter_states = static_cast<int>(FilterStates::Fifteen);  // ZARU corrects the gyro bias states
        window.session()->setParameters(params, QStringLiteral("15 states"));
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        const std::shared_ptr<const Result> before = window.session()->result();
        auto* zaru = window.findChild<QCheckBox*>(QStringLiteral("check_use_zaru"));
        QVERIFY(zaru && zaru->isEnabled());
        const bool wasOn = zaru->isChecked();
        zaru->click();
        QCOMPARE(window.session()->parameters().use_zaru, !wasOn);
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() != before && window.session()->result(), 30000);
        const Eigen::Vector3d a = before->position_m.back(), b = window.session()->result()->position_m.back();
        QVERIFY((a - b).norm() > 1e-9);
    }

    void theDetectorComboReRunsAndTheDetectorViewFollows()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        QVERIFY2(statisticAxisLabel(window).contains(QStringLiteral("SHOE")), qPrintable(statisticAxisLabel(window)));
        const std::shared_ptr<const Result> shoe = window.session()->result();

        auto* combo = window.findChild<QComboBox*>(QStringLiteral("choice_detector"));
        QVERIFY(combo);
        combo->setFocus();
        QTest::keyClick(combo, Qt::Key_Home);  // C1/C2/C3, the first choice
        QCOMPARE(window.session()->parameters().detectorKind(), DetectorKind::PaperC1C2C3);
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() != shoe && window.session()->result(), 30000);
        QVERIFY(window.session()->result()->flags.logStatistic != shoe->flags.logStatistic);
        QVERIFY(statisticAxisLabel(window).contains(QStringLiteral("std of |a|")));
        const auto* flags = window.findChild<StanceFlagsPlot*>(QStringLiteral("stanceFlags"));
        QVERIFY(flags->isLaneShown(StanceFlagsPlot::Lane::C1));
        QVERIFY(window.findChild<QSlider*>(QStringLiteral("slider_acc_std_max_mps2"))->isEnabled());

        window.session()->undoStack()->undo();
        QCOMPARE(window.session()->parameters().detector, Parameters().detector);
        QCOMPARE(combo->currentIndex(), Parameters().detector);
        // Until the new estimate arrives the plot draws the result it has, labelled as that result
        // was detected: a label (or threshold) of the newer parameters would not match the curve.
        QVERIFY(statisticAxisLabel(window).contains(QStringLiteral("std of |a|")));
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() && !window.session()->isEstimating()
                                     && window.session()->result()->flags.logStatistic == shoe->flags.logStatistic,
                                 30000);
        QVERIFY(statisticAxisLabel(window).contains(QStringLiteral("SHOE")));
        QVERIFY(!flags->isLaneShown(StanceFlagsPlot::Lane::C1));
    }

    void warningsReachTheStatusBarTheSummaryAndTheTable()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        window.session()->setParameters(missingEveryStance(), QStringLiteral("strict C2"));
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        const std::shared_ptr<const Result> result = window.session()->result();
        QVERIFY(!result->warnings.empty());

        const auto* status = window.findChild<QLabel*>(QStringLiteral("status"));
        QVERIFY(status);
        QVERIFY2(status->text().startsWith(QString::number(result->warnings.size()) + " plausibility warning"),
                 qPrintable(status->text()));
        QVERIFY(status->text().contains(QString::fromStdString(result->warnings.front().message)));
        QVERIFY(status->styleSheet().contains(QStringLiteral("color")));  // stands out

        const auto* summary = window.findChild<SummaryPanel*>();
        QVERIFY(summary->findChild<QGroupBox*>(QStringLiteral("warnings"))->isVisibleTo(summary));
        const auto* missed = std::find_if(result->warnings.data(), result->warnings.data() + result->warnings.size(),
                                          [](const PlausibilityWarning& w) { return w.kind == PlausibilityWarning::Kind::LongSwing; });
        QVERIFY(missed != result->warnings.data() + result->warnings.size());
        const auto index = missed - result->warnings.data();
        auto* label = summary->findChild<QLabel*>(QStringLiteral("warning_%1").arg(index));
        QVERIFY2(label && label->text().contains(QStringLiteral("median filter")), qPrintable(label->text()));  // what blocked it
        emit label->linkActivated(QString::number(index));  // the user clicks its time span
        QCOMPARE(window.session()->timeCursor(), missed->start_s);
        const auto* flags = window.findChild<StanceFlagsPlot*>(QStringLiteral("stanceFlags"));
        QCOMPARE(flags->timeCursor(), missed->start_s);
        QVERIFY(flags->timeRange().contains(missed->start_s));

        const auto* table = summary->findChild<QTableView*>(QStringLiteral("stepTable"));
        int marked = 0;
        for (int row = 0; row < table->model()->rowCount(); ++row)
            marked += table->model()->index(row, 0).data(Qt::BackgroundRole).isValid();
        QVERIFY(marked >= 1);
        QVERIFY(flags->warningLane()->layout() != nullptr);

        // Back to the defaults: the status bar reports the walk again when nothing is found.
        window.session()->setParameters(Parameters(), QStringLiteral("defaults"));
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() && window.session()->result() != result
                                     && !window.session()->isEstimating(), 30000);
        if (window.session()->result()->warnings.empty()) {
            QVERIFY2(status->text().contains(QStringLiteral("steps")), qPrintable(status->text()));
            QVERIFY(status->styleSheet().isEmpty());
            QVERIFY(!summary->findChild<QGroupBox*>(QStringLiteral("warnings"))->isVisibleTo(summary));
        }
    }

    void aChangeLeavesAGhostAndItsBeforeAndAfter()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        window.session()->setParameters(paperDetector(), QStringLiteral("C1/C2/C3"));
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        const std::shared_ptr<const Result> before = window.session()->result();
        auto* view2D = window.findChild<TrajectoryView2D*>(QStringLiteral("trajectory2D"));
        auto* view3D = window.findChild<TrajectoryView3D*>(QStringLiteral("trajectory3D"));
        auto* change = window.findChild<QGroupBox*>(QStringLiteral("lastChange"));
        QVERIFY(view3D->ghostPath().empty());  // nothing to compare with yet
        QVERIFY(!change->isVisibleTo(window.findChild<SummaryPanel*>()));

        window.session()->setParameter(QStringLiteral("acc_std_max_mps2"), 0.2);
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() != before && !window.session()->isEstimating(), 30000);
        const std::shared_ptr<const Result> after = window.session()->result();
        QCOMPARE(view3D->ghostPath().size(), before->position_m.size());
        QVERIFY(view3D->ghostPath().back().isApprox(before->position_m.back()));
        QVERIFY(view2D->ghostCurve());
        QCOMPARE(view2D->ghostCurve()->dataCount(), static_cast<int>(before->position_m.size()));
        QVERIFY(change->isVisibleTo(window.findChild<SummaryPanel*>()));
        auto* path = window.findChild<QLabel*>(QStringLiteral("change_pathLength"));
        QVERIFY2(path->text().contains(QLocale().toString(before->summary.pathLength_m, 'f', 2))
                     && path->text().contains(QLocale().toString(after->summary.pathLength_m, 'f', 2)),
                 qPrintable(path->text()));
        auto* endToStart = window.findChild<QLabel*>(QStringLiteral("change_endToStart"));
        const Judgement judgement = judgeLowerIsBetter(before->summary.endToStart_m, after->summary.endToStart_m);
        QVERIFY(judgement != Judgement::Neither);  // a stricter C2 moves the end
        const QColor expected = judgement == Judgement::Better ? QColor(27, 127, 59) : QColor(176, 0, 32);
        QCOMPARE(endToStart->palette().color(QPalette::WindowText), expected);
        QCOMPARE(endToStart->property("judgement").toString(),
                 judgement == Judgement::Better ? QStringLiteral("better") : QStringLiteral("worse"));
        auto* steps = window.findChild<QLabel*>(QStringLiteral("change_steps"));
        QCOMPARE(steps->text(), QStringLiteral("%1 \u2192 %2").arg(before->summary.steps).arg(after->summary.steps));
        QVERIFY(!window.findChild<QLabel*>(QStringLiteral("change_armse2d"))->isVisibleTo(change));  // no reference

        // A new recording starts afresh: no ghost of another walk.
        window.openRecording(path_);
        QTRY_VERIFY_WITH_TIMEOUT(window.runHistory()->rowCount() == 1 && !window.session()->isEstimating(), 30000);
        QVERIFY(view3D->ghostPath().empty());
        QVERIFY(!change->isVisibleTo(window.findChild<SummaryPanel*>()));
    }

    void goingBackInTheHistoryRestoresParametersAndResult()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        window.session()->setParameters(paperDetector(), QStringLiteral("C1/C2/C3"));
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        const std::shared_ptr<const Result> first = window.session()->result();
        const Parameters firstParameters = window.session()->parameters();
        window.session()->setParameter(QStringLiteral("acc_std_max_mps2"), 0.2);
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() != first && !window.session()->isEstimating(), 30000);
        window.session()->setParameter(QStringLiteral("gyr_max_radps"), 2.0);
        QTRY_VERIFY_WITH_TIMEOUT(window.runHistory()->rowCount() == 3 && !window.session()->isEstimating(), 30000);
        const Parameters lastParameters = window.session()->parameters();

        auto* panel = window.findChild<RunHistoryPanel*>();
        QVERIFY(panel);
        panel->table()->selectRow(0);
        window.findChild<QPushButton*>(QStringLiteral("goBackToRun"))->click();
        QVERIFY(window.session()->parameters() == firstParameters);
        QTRY_VERIFY_WITH_TIMEOUT(window.runHistory()->currentRow() == 0 && !window.session()->isEstimating(), 30000);
        QCOMPARE(window.runHistory()->rowCount(), 3);  // the run again, not a new one
        QCOMPARE(window.session()->result()->summary.pathLength_m, first->summary.pathLength_m);
        QCOMPARE(window.session()->result()->position_m.back(), first->position_m.back());
        QCOMPARE(window.runHistory()->previous()->number, 3);  // the ghost is where the user came from
        // Going back is one undo step like any change.
        window.session()->undoStack()->undo();
        QVERIFY(window.session()->parameters() == lastParameters);
    }

    void selectingAStepMovesTheTimeCursor()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        const std::shared_ptr<const Result> result = window.session()->result();
        QVERIFY(result->steps.size() > 5);
        QTableView* table = window.findChild<SummaryPanel*>()->stepTable();
        QCOMPARE(table->model()->index(0, 0).data().toString(), QStringLiteral("1"));  // steps count from 1
        table->setCurrentIndex(table->model()->index(3, 2));
        QCOMPARE(window.session()->timeCursor(), result->steps[3].stanceStart_s);
        QTest::keyClick(table, Qt::Key_Down);
        QCOMPARE(window.session()->timeCursor(), result->steps[4].stanceStart_s);
        const auto* flags = window.findChild<StanceFlagsPlot*>(QStringLiteral("stanceFlags"));
        QCOMPARE(flags->timeCursor(), result->steps[4].stanceStart_s);
        QVERIFY(flags->timeRange().contains(result->steps[4].stanceStart_s));
    }

    void theHelpMenuOpensTheGuideAndTheShortcuts()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        auto* guideAction = window.findChild<QAction*>(QStringLiteral("userGuide"));
        QVERIFY(guideAction);
        QCOMPARE(guideAction->shortcut(), QKeySequence(QKeySequence::HelpContents));
        guideAction->trigger();
        auto* dialog = window.findChild<HelpDialog*>();
        QVERIFY(dialog && dialog->isVisible());
        const QString guide = dialog->guide()->toPlainText();
        for (const char* topic : {"Opening a recording", "What the views show", "Tuning", "Live input"})
            QVERIFY2(guide.contains(QLatin1String(topic)), topic);
        window.findChild<QAction*>(QStringLiteral("keyboardShortcuts"))->trigger();
        QCOMPARE(window.findChildren<HelpDialog*>().size(), 1);
        QTableWidget* keys = dialog->shortcuts();
        QVERIFY(keys->isVisible());
        const QString open = QKeySequence(QKeySequence::Open).toString(QKeySequence::NativeText);
        const QString compare = QKeySequence(Qt::CTRL | Qt::Key_M).toString(QKeySequence::NativeText);
        QStringList listed;
        for (int row = 0; row < keys->rowCount(); ++row)
            listed << keys->item(row, 0)->text() + QLatin1Char('=') + keys->item(row, 1)->text();
        QVERIFY2(listed.filter(open + QStringLiteral("=File > Open recording")).size() == 1, qPrintable(listed.join('\n')));
        QVERIFY2(listed.filter(compare + QStringLiteral("=Analysis > Compare methods")).size() == 1,
                 qPrintable(listed.join('\n')));
        // Ctrl+1..7 go down the View menu in order (States was Ctrl+7, between 4 and 5).
        QStringList numbered;
        for (QAction* action : window.findChild<QMenu*>(QStringLiteral("viewMenu"))->actions())
            if (const QKeySequence key = action->shortcut(); key.count() == 1 && key[0].key() >= Qt::Key_1 && key[0].key() <= Qt::Key_9)
                numbered << action->shortcut().toString(QKeySequence::PortableText);
        QCOMPARE(numbered, (QStringList{"Ctrl+1", "Ctrl+2", "Ctrl+3", "Ctrl+4", "Ctrl+5", "Ctrl+6", "Ctrl+7"}));
    }

    void germanTranslationIsUsed()
    {
        QTranslator translator;
        QVERIFY2(translator.load(QStringLiteral(FOOTPATH_QM_DIR "/footpath_de.qm")), FOOTPATH_QM_DIR);
        QCoreApplication::installTranslator(&translator);
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        const QString file = window.menuBar()->actions().first()->text();
        QCoreApplication::removeTranslator(&translator);
        QVERIFY2(file != QStringLiteral("&File") && !file.isEmpty(), qPrintable(file));
    }

    void everyLanguageIsCompleteAndHasItsScript_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<int>("script");
        QTest::newRow("de") << QStringLiteral("de") << int(QFontDatabase::Latin);
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN") << int(QFontDatabase::SimplifiedChinese);
    }

    void everyLanguageIsCompleteAndHasItsScript()
    {
        // German and Chinese were partial (the parameter panel stayed English), and on a stock
        // Debian every Chinese character was a box: no font had the script.
        QFETCH(QString, language);
        QFETCH(int, script);
        QFile source(QStringLiteral(FOOTPATH_SOURCE_DIR "/translations/footpath_%1.ts").arg(language));
        QVERIFY(source.open(QIODevice::ReadOnly));
        const QByteArray ts = source.readAll();
        QCOMPARE(ts.count("type=\"unfinished\""), qsizetype(0));
        QVERIFY2(!QFontDatabase::families(QFontDatabase::WritingSystem(script)).isEmpty(),
                 "no font for the language's script: install fonts-wqy-microhei (the README's commands do)");
        QTranslator translator;
        QVERIFY(translator.load(QStringLiteral(FOOTPATH_QM_DIR "/footpath_%1.qm").arg(language)));
        QCoreApplication::installTranslator(&translator);
        ParameterPanel panel;
        const QString label = panel.findChild<QLabel*>(QStringLiteral("label_zv_min_stance_s"))->text();
        QCoreApplication::removeTranslator(&translator);
        QVERIFY2(!label.startsWith(QStringLiteral("Shortest stance")), qPrintable(label));
    }

private:
    QTemporaryDir dir_;
    QString path_;
    std::size_t samples_ = 0;
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
