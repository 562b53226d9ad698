// The history of tuning runs: one run per undo step, going back finds the run again, the previous
// run is the one before the latest change, and the figures are judged better or worse.
#include "RunHistory.h"

#include <QSignalSpy>
#include <QTableView>
#include <QtTest>

#include <cmath>

using namespace footpath;

namespace {

std::shared_ptr<const Result> resultWithPath(double pathLength_m, double endToStart_m)
{
    auto result = std::make_shared<Result>();
    result->summary.pathLength_m = pathLength_m;
    result->summary.endToStart_m = endToStart_m;
    result->summary.steps = 7;
    result->position_m = {Eigen::Vector3d::Zero(), Eigen::Vector3d(pathLength_m, 0.0, 0.0)};
    return result;
}

Parameters withGyrMax(double value)
{
    Parameters params;
    params.gyr_max_radps = value;
    return params;
}

void record(RunHistory& history, double gyrMax, double pathLength_m, const void* gesture, int undoIndex)
{
    const std::shared_ptr<const Result> result = resultWithPath(pathLength_m, 0.1 * pathLength_m);
    history.record(result, withGyrMax(gyrMax), runFigures(*result, nullptr), gesture, undoIndex);
}

// Stand-ins for undo commands: only their (distinct) addresses count.
int stepA = 0;
int stepB = 0;
int stepC = 0;

}  // namespace

class TestRunHistory : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { qRegisterMetaType<footpath::Parameters>(); }

    void eachUndoStepIsOneRunAndTheChangeIsNamed()
    {
        RunHistory history;
        record(history, 1.0, 40.0, nullptr, 0);
        QCOMPARE(history.rowCount(), 1);
        QVERIFY(!history.previous());
        // A dragged slider: three results of one merged undo step are one run with the last value.
        record(history, 1.2, 41.0, &stepA, 1);
        record(history, 1.4, 42.0, &stepA, 1);
        record(history, 1.5, 43.0, &stepA, 1);
        QCOMPARE(history.rowCount(), 2);
        QCOMPARE(history.current()->parameters.gyr_max_radps, 1.5);
        QCOMPARE(history.current()->figures.pathLength_m, 43.0);
        QCOMPARE(history.previous()->figures.pathLength_m, 40.0);
        const QString change = history.current()->change;
        QVERIFY2(change.contains(QString::fromStdString(labelWithUnit(*findParameterField("gyr_max_radps")))),
                 qPrintable(change));
        QVERIFY2(change.contains(QStringLiteral("1 \u2192 1.5")), qPrintable(change));
        // The next step is a run of its own.
        record(history, 2.0, 44.0, &stepB, 2);
        QCOMPARE(history.rowCount(), 3);
        QCOMPARE(history.previous()->parameters.gyr_max_radps, 1.5);
    }

    void afterAnUndoTheLatestChangeIsTheUndoneOneReversed()
    {
        // "Last change" said "First run" after an undo back to the first run (its own change).
        RunHistory history;
        record(history, 1.0, 40.0, nullptr, 0);
        record(history, 1.5, 43.0, &stepA, 1);
        QVERIFY2(history.latestChange().contains(QStringLiteral("1 \u2192 1.5")), qPrintable(history.latestChange()));
        record(history, 1.0, 40.0, nullptr, 0);  // undo
        QCOMPARE(history.current()->number, 1);
        const QString change = history.latestChange();
        QVERIFY2(change.startsWith(QStringLiteral("Back to run 1: ")), qPrintable(change));
        QVERIFY2(change.contains(QStringLiteral("1.5 \u2192 1")), qPrintable(change));
        QVERIFY(!change.contains(QStringLiteral("First run")));
    }

    void goingBackFindsTheRunAgainAndThePreviousIsTheOneLeft()
    {
        RunHistory history;
        record(history, 1.0, 40.0, nullptr, 0);
        record(history, 2.0, 45.0, &stepA, 1);
        record(history, 3.0, 50.0, &stepB, 2);
        QSignalSpy changed(&history, &RunHistory::currentChanged);
        // Undo twice lands on the first parameters: their run is current, no new run is added.
        record(history, 1.0, 40.0, &stepC, 3);
        QCOMPARE(history.rowCount(), 3);
        QCOMPARE(history.currentRow(), 0);
        QCOMPARE(history.current()->number, 1);
        QCOMPARE(history.previous()->number, 3);
        QVERIFY(changed.count() >= 1);
        // The current run is bold in the table.
        QVERIFY(history.data(history.index(0, RunHistory::Number), Qt::FontRole).value<QFont>().bold());
        QVERIFY(!history.data(history.index(2, RunHistory::Number), Qt::FontRole).isValid());
    }

    void keepsTheLastRuns()
    {
        RunHistory history;
        std::vector<int> steps(RunHistory::kMaxRuns + 5);
        for (std::size_t i = 0; i < steps.size(); ++i)
            record(history, 0.5 + 0.1 * static_cast<double>(i), 40.0 + static_cast<double>(i), &steps[i],
                   static_cast<int>(i) + 1);
        QCOMPARE(history.rowCount(), RunHistory::kMaxRuns);
        QCOMPARE(history.runAt(0)->number, 6);
        QCOMPARE(history.current()->number, RunHistory::kMaxRuns + 5);
    }

    void clearForgetsEverything()
    {
        RunHistory history;
        record(history, 1.0, 40.0, nullptr, 0);
        record(history, 2.0, 45.0, &stepA, 1);
        history.clear();
        QCOMPARE(history.rowCount(), 0);
        QVERIFY(!history.current());
        QVERIFY(!history.previous());
    }

    void lowerErrorsAreBetterAndPathLengthNeedsTheKnownLength()
    {
        QCOMPARE(judgeLowerIsBetter(0.5, 0.3), Judgement::Better);
        QCOMPARE(judgeLowerIsBetter(0.3, 0.5), Judgement::Worse);
        QCOMPARE(judgeLowerIsBetter(0.3, 0.3), Judgement::Neither);
        QCOMPARE(judgeLowerIsBetter(RunFigures::kNone, 0.3), Judgement::Neither);
        RunFigures before, after;
        before.pathLength_m = 48.0;
        after.pathLength_m = 49.5;
        QCOMPARE(judgePathLength(before, after), Judgement::Neither);
        before.referenceLength_m = after.referenceLength_m = 50.0;
        QCOMPARE(judgePathLength(before, after), Judgement::Better);
        QCOMPARE(judgePathLength(after, before), Judgement::Worse);
    }

    void figuresComeFromTheResultAndTheReference()
    {
        const std::shared_ptr<const Result> result = resultWithPath(12.0, 0.6);
        Recording recording;
        recording.samples.resize(2);
        recording.reference.knownLength_m = 11.0;
        recording.reference.positions_m = {Eigen::Vector3d::Zero(), Eigen::Vector3d(11.0, 0.0, 0.0)};
        const RunFigures figures = runFigures(*result, &recording);
        QCOMPARE(figures.pathLength_m, 12.0);
        QCOMPARE(figures.endToStart_m, 0.6);
        QCOMPARE(figures.steps, 7);
        QCOMPARE(figures.referenceLength_m, 11.0);
        QVERIFY(std::isfinite(figures.armse2d_m) && figures.armse2d_m > 0.0);
        QVERIFY(std::isnan(runFigures(*result, nullptr).armse2d_m));
    }

    void choosingAnEarlierRunAsksForItsParameters()
    {
        RunHistory history;
        record(history, 1.0, 40.0, nullptr, 0);
        record(history, 2.0, 45.0, &stepA, 1);
        RunHistoryPanel panel(&history);
        QSignalSpy chosen(&panel, &RunHistoryPanel::runChosen);
        panel.table()->selectRow(0);
        QVERIFY(panel.findChild<QWidget*>(QStringLiteral("goBackToRun"))->isEnabled());
        emit panel.table()->activated(history.index(0, 0));
        QCOMPARE(chosen.count(), 1);
        QCOMPARE(chosen.first().at(0).value<Parameters>().gyr_max_radps, 1.0);
        QCOMPARE(chosen.first().at(1).toInt(), 1);
        // The run on screen is not offered again.
        panel.table()->selectRow(1);
        QVERIFY(!panel.findChild<QWidget*>(QStringLiteral("goBackToRun"))->isEnabled());
    }
};

QTEST_MAIN(TestRunHistory)
#include "tst_runhistory.moc"
