// The live views' path grows by appending, and a parameter change re-estimates a live session
// off the GUI thread: the path appended refresh by refresh equals the path of the whole estimate,
// the event loop keeps running while a long re-estimate runs, and the re-estimate equals the
// estimator run on the GUI thread over the same samples.
#include "LiveReestimator.h"
#include "LiveViews.h"
#include "TrajectoryView2D.h"
#include "nav/StreamingEstimator.h"
#include "sim/WalkSimulator.h"

#include <QTimer>
#include <QWidget>
#include <QtTest>
#include <qcustomplot.h>

#include <memory>

using namespace footpath;

namespace {

/// Laps of a rectangle: about a minute and a half of walking at 100 Hz.
const std::vector<ImuSample>& walkSamples()
{
    static const std::vector<ImuSample> samples = [] {
        std::vector<Eigen::Vector3d> path{Eigen::Vector3d::Zero()};
        const std::vector<Eigen::Vector3d> lap = closedRectanglePath(10.0, 5.0);
        for (int i = 0; i < 3; ++i)
            path.insert(path.end(), lap.begin() + 1, lap.end());
        return simulateWalk(path, WalkSimulatorConfig()).recording.samples;
    }();
    return samples;
}

/// The walk played again after itself `copies` times, each copy one sample interval after the
/// last: a long session without simulating one.
std::vector<ImuSample> repeatedWalk(int copies)
{
    const std::vector<ImuSample>& walk = walkSamples();
    const double period_s = walk.back().time_s - walk.front().time_s + (walk[1].time_s - walk[0].time_s);
    std::vector<ImuSample> samples;
    samples.reserve(walk.size() * static_cast<std::size_t>(copies));
    for (int copy = 0; copy < copies; ++copy)
        for (ImuSample sample : walk) {
            sample.time_s += copy * period_s;
            samples.push_back(sample);
        }
    return samples;
}

Result estimateOnThisThread(const std::vector<ImuSample>& samples, const Parameters& params, bool finish)
{
    StreamingEstimator estimator(params);
    for (const ImuSample& sample : samples)
        estimator.push(sample);
    if (finish)
        estimator.finish();
    return estimator.result();
}

Parameters liveParameters(double adaptFraction = Parameters().zv_adapt_fraction)
{
    Parameters params;
    params.estimator = static_cast<int>(EstimatorKind::Ekf);  // live runs the filter
    params.zv_adapt_fraction = adaptFraction;
    return params;
}

}  // namespace

class TestLiveReestimate : public QObject {
    Q_OBJECT
private slots:
    void pathAppendedRefreshByRefreshEqualsTheWholeEstimate()
    {
        QWidget parent;
        LiveViews views(&parent);
        StreamingEstimator estimator(liveParameters());
        const std::vector<ImuSample>& samples = walkSamples();
        std::shared_ptr<const Result> shown;
        for (std::size_t k = 0; k < samples.size(); ++k) {
            estimator.push(samples[k]);
            if (k % 500 != 499)
                continue;
            std::shared_ptr<const Result> path = views.showPath(estimator.result(), {}, true);
            QVERIFY(path);
            if (shown)
                QCOMPARE(path.get(), shown.get());  // the same path, grown: not a copy per refresh
            shown = path;
            QCOMPARE(path->time_s.size(), estimator.result().time_s.size());
        }
        estimator.finish();
        shown = views.showPath(estimator.result(), {}, true);

        const Result whole = pathOnly(estimator.result());
        QVERIFY(whole.time_s.size() > samples.size() / 2);
        QCOMPARE(shown->time_s, whole.time_s);
        QCOMPARE(shown->position_m, whole.position_m);
        QCOMPARE(shown->velocity_mps, whole.velocity_mps);
        QCOMPARE(shown->flags.stance, whole.flags.stance);
        QCOMPARE(shown->steps.size(), whole.steps.size());
        QCOMPARE(shown->summary.pathLength_m, whole.summary.pathLength_m);

        // The 2D view, fed the growing path, holds the extent of the whole path.
        TrajectoryView2D fresh;
        fresh.setResult(std::make_shared<const Result>(whole));
        bool grownFound = false, freshFound = false;
        const QCPAbstractPlottable* grownPath = views.trajectory2D()->plot()->plottable(1);
        const QCPAbstractPlottable* freshPath = fresh.plot()->plottable(1);
        QCOMPARE(grownPath->getKeyRange(grownFound), freshPath->getKeyRange(freshFound));
        QCOMPARE(grownPath->getValueRange(grownFound), freshPath->getValueRange(freshFound));
        QVERIFY(grownFound && freshFound);

        views.restartPath();  // new parameters: a new path, the old one left as it was
        const std::size_t before = shown->time_s.size();
        StreamingEstimator restarted(liveParameters());
        for (std::size_t k = 0; k < 3000; ++k)
            restarted.push(samples[k]);
        const std::shared_ptr<const Result> again = views.showPath(restarted.result(), {}, true);
        QVERIFY(again.get() != shown.get());
        QCOMPARE(again->time_s.size(), restarted.result().time_s.size());
        QCOMPARE(shown->time_s.size(), before);
    }

    void reestimateRunsOffTheGuiThreadAndEqualsTheEstimateOnIt()
    {
        const std::vector<ImuSample> samples = repeatedWalk(8);  // about 12 minutes at 100 Hz
        const Parameters params = liveParameters(0.3);
        LiveReestimator reestimator;
        std::shared_ptr<StreamingEstimator> arrived;
        std::size_t arrivedSamples = 0;
        int reports = 0;
        connect(&reestimator, &LiveReestimator::finished, this,
                [&](std::shared_ptr<StreamingEstimator> estimator, std::size_t count) {
                    arrived = std::move(estimator);
                    arrivedSamples = count;
                    ++reports;
                });
        // A timer on the GUI thread: it ticks only while the event loop runs.
        int ticks = 0;
        QTimer ticker;
        ticker.setInterval(2);
        connect(&ticker, &QTimer::timeout, this, [&] { ++ticks; });
        ticker.start();

        reestimator.start(samples, params, false);
        QVERIFY(reestimator.isRunning());
        QCOMPARE(reports, 0);  // not done inside start()
        QTRY_VERIFY_WITH_TIMEOUT(arrived != nullptr, 60000);
        QVERIFY2(ticks >= 3, qPrintable(QStringLiteral("the event loop ran %1 times").arg(ticks)));
        QCOMPARE(arrivedSamples, samples.size());
        QCOMPARE(arrived->parameters(), params);

        // Caught up with samples that arrived meanwhile and finished, as LivePanel does.
        const std::vector<ImuSample> more = repeatedWalk(9);
        for (std::size_t k = arrivedSamples; k < more.size(); ++k)
            arrived->push(more[k]);
        arrived->finish();
        const Result onGuiThread = estimateOnThisThread(more, params, true);
        QCOMPARE(arrived->result().time_s, onGuiThread.time_s);
        QCOMPARE(arrived->result().position_m, onGuiThread.position_m);
        QCOMPARE(arrived->result().flags.stance, onGuiThread.flags.stance);
        QCOMPARE(reports, 1);
    }

    void aNewerParameterChangeSupersedesTheRunning()
    {
        const std::vector<ImuSample> samples = repeatedWalk(4);
        LiveReestimator reestimator;
        std::vector<Parameters> reported;
        connect(&reestimator, &LiveReestimator::finished, this,
                [&](std::shared_ptr<StreamingEstimator> estimator, std::size_t) {
                    reported.push_back(estimator->parameters());
                });
        reestimator.start(samples, liveParameters(0.2), true);
        reestimator.start(samples, liveParameters(0.3), true);
        reestimator.start(samples, liveParameters(0.4), true);
        QTRY_VERIFY_WITH_TIMEOUT(!reestimator.isRunning(), 60000);
        QTest::qWait(50);  // a late report of an older run would come now
        QCOMPARE(reported.size(), std::size_t(1));
        QCOMPARE(reported.front(), liveParameters(0.4));

        reestimator.start(samples, liveParameters(0.5), true);
        reestimator.cancel();  // a new session: nothing may take over
        QTRY_VERIFY_WITH_TIMEOUT(!reestimator.isRunning(), 60000);
        QTest::qWait(50);
        QCOMPARE(reported.size(), std::size_t(1));
    }

    void nothingRunsOnceCancelled()
    {
        // The Live dock shows "Re-estimating" while isRunning(): after a cancel (new session,
        // parameters the estimator refuses) it must say so at once, not once the cancelled run has
        // stopped on the pool and its end has reached the event loop, which no refresh may follow.
        const std::vector<ImuSample> samples = repeatedWalk(8);
        LiveReestimator reestimator;
        int reports = 0;
        Parameters reported;
        connect(&reestimator, &LiveReestimator::finished, this,
                [&](std::shared_ptr<StreamingEstimator> estimator, std::size_t) {
                    reported = estimator->parameters();
                    ++reports;
                });
        reestimator.start(samples, liveParameters(0.2), false);
        QVERIFY(reestimator.isRunning());
        reestimator.cancel();
        QVERIFY(!reestimator.isRunning());
        QTest::qWait(200);  // the cancelled run ends meanwhile
        QVERIFY(!reestimator.isRunning());
        QCOMPARE(reports, 0);

        // Started again before the cancelled run has wound down: running until its own report.
        reestimator.start(samples, liveParameters(0.3), false);
        reestimator.cancel();
        reestimator.start(samples, liveParameters(0.4), false);
        QVERIFY(reestimator.isRunning());
        QTRY_COMPARE_WITH_TIMEOUT(reports, 1, 60000);
        QCOMPARE(reported, liveParameters(0.4));
        QVERIFY(!reestimator.isRunning());
    }
};

QTEST_MAIN(TestLiveReestimate)
#include "tst_livereestimate.moc"
