#include "SignalPlots.h"
#include "StanceFlagsPlot.h"
#include "detect/StanceDetector.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <QAction>
#include <QElapsedTimer>
#include <QImage>
#include <QPainter>
#include <QSignalSpy>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace footpath;
using Lane = StanceFlagsPlot::Lane;
using Input = StanceFlagsPlot::Input;
using Threshold = StanceFlagsPlot::Threshold;

namespace {

struct Walk {
    std::shared_ptr<const Recording> recording;
    std::shared_ptr<const Result> result;
};

Walk simulatedWalk()
{
    WalkSimulatorConfig config;
    config.accNoiseStd_mps2 = 0.05;  // noise makes C1 and C3 flicker, so the lanes differ
    config.gyrNoiseStd_radps = 0.02;
    Walk walk;
    walk.recording = std::make_shared<const Recording>(simulateWalk(closedRectanglePath(10.0, 5.0), config).recording);
    walk.result = std::make_shared<const Result>(runPipeline(*walk.recording, Parameters()).result);
    return walk;
}

const std::vector<std::uint8_t>& flagsOf(const Result& result, Lane lane)
{
    switch (lane) {
    case Lane::C1: return result.flags.c1;
    case Lane::C2: return result.flags.c2;
    case Lane::C3: return result.flags.c3;
    case Lane::C: return result.flags.c;
    case Lane::Stance: break;
    }
    return result.flags.stance;
}

/// What a step-left curve shows at key: the value of the last point at or before it.
double stepValueAt(const QCPGraph* graph, double key)
{
    const auto data = graph->data();
    const auto after = std::upper_bound(data->constBegin(), data->constEnd(), key,
                                        [](double k, const QCPGraphData& point) { return k < point.key; });
    return after == data->constBegin() ? std::numeric_limits<double>::quiet_NaN() : (after - 1)->value;
}

std::vector<double> timesOf(const Recording& recording)
{
    std::vector<double> times;
    for (const ImuSample& sample : recording.samples)
        times.push_back(sample.time_s);
    return times;
}

std::vector<double> accNormsOf(const Recording& recording)
{
    std::vector<double> norms;
    for (const ImuSample& sample : recording.samples)
        norms.push_back(sample.acc_mps2.norm());
    return norms;
}

/// Shows the widget and lays the plot out, so pixels map to coordinates as on screen.
bool showLaidOut(QWidget& widget, QCustomPlot* plot)
{
    widget.resize(900, 700);
    widget.show();
    const bool exposed = QTest::qWaitForWindowExposed(&widget);
    plot->replot();
    return exposed;
}

QCPAxis* timeAxisOf(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atBottom); }

constexpr std::array<Lane, StanceFlagsPlot::kLaneCount> kAllLanes = {Lane::C1, Lane::C2, Lane::C3, Lane::C,
                                                                     Lane::Stance};
constexpr std::array<Input, StanceFlagsPlot::kInputCount> kAllInputs = {Input::AccNorm, Input::AccStdDev,
                                                                        Input::GyrNorm};

}  // namespace

class TestStanceFlagsPlot : public QObject {
    Q_OBJECT
private slots:
    void lanesEqualTheResultsFlagsSampleBySample()
    {
        const Walk walk = simulatedWalk();
        StanceFlagsPlot plot;
        plot.setRecording(walk.recording);
        for (const Lane lane : kAllLanes)
            QVERIFY(plot.laneGraph(lane)->data()->isEmpty());

        plot.setResult(walk.result);
        const std::vector<double>& times = walk.result->time_s;
        for (const Lane lane : kAllLanes) {
            const std::vector<std::uint8_t>& flags = flagsOf(*walk.result, lane);
            const QCPGraph* graph = plot.laneGraph(lane);
            std::size_t changes = 0;
            for (std::size_t k = 1; k < times.size(); ++k) {
                if (flags[k] == flags[k - 1])
                    continue;
                ++changes;  // both sides of every edge, where an off-by-one would show
                QCOMPARE(stepValueAt(graph, times[k - 1]), StanceFlagsPlot::laneLevel(lane, flags[k - 1] != 0));
                QCOMPARE(stepValueAt(graph, times[k]), StanceFlagsPlot::laneLevel(lane, flags[k] != 0));
            }
            QVERIFY2(changes >= 20, qPrintable(QString("lane %1: %2 changes").arg(static_cast<int>(lane)).arg(changes)));
            for (std::size_t k = 0; k < times.size(); k += 7)
                QCOMPARE(stepValueAt(graph, times[k]), StanceFlagsPlot::laneLevel(lane, flags[k] != 0));
            QVERIFY(static_cast<std::size_t>(graph->dataCount()) <= changes + 2);  // no point per sample
        }
        QVERIFY(StanceFlagsPlot::laneLevel(Lane::C1, false) > StanceFlagsPlot::laneLevel(Lane::C2, true));  // lanes do not overlap

        plot.setResult(nullptr);
        QVERIFY(plot.laneGraph(Lane::Stance)->data()->isEmpty());
        plot.setResult(walk.result);
        plot.setRecording(walk.recording);  // a new recording drops the old result's lanes
        QVERIFY(plot.laneGraph(Lane::Stance)->data()->isEmpty());
    }

    void fillsTheLanesWhereTheFlagIsSet()
    {
        const Walk walk = simulatedWalk();
        StanceFlagsPlot plot;
        plot.setRecording(walk.recording);
        plot.setResult(walk.result);
        QVERIFY(showLaidOut(plot, plot.plot()));
        const QImage image = plot.plot()->toPixmap().toImage();
        const QCPAxis* levels = plot.lanesRect()->axis(QCPAxis::atLeft);
        const int y = static_cast<int>(std::lround(levels->coordToPixel(StanceFlagsPlot::laneLevel(Lane::Stance, false) + 0.5)));
        const auto xAt = [&](double time_s) {
            return static_cast<int>(std::lround(timeAxisOf(plot.lanesRect())->coordToPixel(time_s)));
        };
        const QColor standing = image.pixelColor(xAt(1.0), y);  // the walk starts at rest
        const QColor swinging = image.pixelColor(xAt(walk.result->steps.at(1).stanceStart_s - 0.3), y);
        QVERIFY2(standing.red() > 200 && standing.blue() < 120, qPrintable(standing.name()));  // stance amber
        QCOMPARE(swinging, QColor(Qt::white));
    }

    void inputsAndThresholdsAppearOnToggle()
    {
        const Walk walk = simulatedWalk();
        StanceFlagsPlot plot;
        plot.setRecording(walk.recording);
        QVERIFY(!plot.inputsVisible());
        QCOMPARE(plot.plot()->axisRectCount(), 1);
        for (const Input input : kAllInputs)
            QVERIFY(!plot.inputGraph(input)->realVisibility());
        QVERIFY(!plot.thresholdGraph(Threshold::GyrMax)->realVisibility());
        QVERIFY(timeAxisOf(plot.lanesRect())->tickLabels());

        plot.findChild<QAction*>("showDetectorInputs")->trigger();  // the toolbar toggle
        QVERIFY(plot.inputsVisible());
        QCOMPARE(plot.plot()->axisRectCount(), 1 + StanceFlagsPlot::kInputCount);
        for (const Input input : kAllInputs)
            QVERIFY(plot.inputGraph(input)->realVisibility());
        for (const Threshold threshold : {Threshold::AccMin, Threshold::AccMax, Threshold::AccStdMax, Threshold::GyrMax})
            QVERIFY(plot.thresholdGraph(threshold)->realVisibility());
        QVERIFY(!timeAxisOf(plot.lanesRect())->tickLabels());  // the time scale moved to the bottom row
        QVERIFY(timeAxisOf(plot.inputRect(Input::GyrNorm))->tickLabels());

        plot.setInputsVisible(false);
        QCOMPARE(plot.plot()->axisRectCount(), 1);
        QVERIFY(!plot.findChild<QAction*>("showDetectorInputs")->isChecked());
    }

    void inputCurvesAreTheDetectorsInputs()
    {
        const Walk walk = simulatedWalk();
        StanceFlagsPlot plot;
        plot.setRecording(walk.recording);
        const std::vector<ImuSample>& samples = walk.recording->samples;
        const std::vector<double> stdDev =
            centredStdDev(timesOf(*walk.recording), accNormsOf(*walk.recording), Parameters().window_half_s);
        for (const Input input : kAllInputs)
            QCOMPARE(static_cast<std::size_t>(plot.inputGraph(input)->dataCount()), samples.size());
        for (std::size_t k = 0; k < samples.size(); k += 53) {
            const int i = static_cast<int>(k);
            QCOMPARE(plot.inputGraph(Input::AccNorm)->data()->at(i)->value, samples[k].acc_mps2.norm());
            QCOMPARE(plot.inputGraph(Input::AccStdDev)->data()->at(i)->value, stdDev[k]);
            QCOMPARE(plot.inputGraph(Input::GyrNorm)->data()->at(i)->value, samples[k].gyr_radps.norm());
        }
    }

    void thresholdLinesFollowSetParameters()
    {
        const Walk walk = simulatedWalk();
        StanceFlagsPlot plot;
        plot.setRecording(walk.recording);
        plot.setInputsVisible(true);
        Parameters params;
        params.acc_min_mps2 = 8.5;
        params.acc_max_mps2 = 12.0;
        params.acc_std_max_mps2 = 0.7;
        params.gyr_max_radps = 1.3;
        params.window_half_s = 0.25;
        plot.setParameters(params);

        const std::vector<std::pair<Threshold, double>> expected = {
            {Threshold::AccMin, 8.5}, {Threshold::AccMax, 12.0}, {Threshold::AccStdMax, 0.7}, {Threshold::GyrMax, 1.3}};
        for (const auto& [threshold, value] : expected) {
            const QCPGraph* line = plot.thresholdGraph(threshold);
            QCOMPARE(line->dataCount(), 2);
            QCOMPARE(line->data()->at(0)->value, value);
            QCOMPARE(line->data()->at(1)->value, value);
            QCOMPARE(line->data()->at(0)->key, walk.recording->samples.front().time_s);  // across the recording
            QCOMPARE(line->data()->at(1)->key, walk.recording->samples.back().time_s);
            QVERIFY2(line->name().contains(QString::number(value)), qPrintable(line->name()));
            // The value axis frames the threshold.
            QVERIFY(line->valueAxis()->range().contains(value));
        }
        // A new window changes the std curve exactly as the detector computes it.
        const std::vector<double> stdDev = centredStdDev(timesOf(*walk.recording), accNormsOf(*walk.recording), 0.25);
        const int middle = static_cast<int>(stdDev.size() / 2);
        QCOMPARE(plot.inputGraph(Input::AccStdDev)->data()->at(middle)->value, stdDev[static_cast<std::size_t>(middle)]);
    }

    void timeCursorRunsThroughEveryRowAndClicksMoveIt()
    {
        StanceFlagsPlot plot;
        plot.setRecording(simulatedWalk().recording);
        plot.setInputsVisible(true);
        QVERIFY(showLaidOut(plot, plot.plot()));
        plot.setTimeCursor(9.25);
        QCOMPARE(plot.timeCursor(), 9.25);
        int cursorLines = 0;
        for (int i = 0; i < plot.plot()->itemCount(); ++i) {
            const auto* line = qobject_cast<QCPItemStraightLine*>(plot.plot()->item(i));
            QVERIFY(line != nullptr);
            QVERIFY(line->visible());
            QCOMPARE(line->point1->key(), 9.25);
            QCOMPARE(line->point2->key(), 9.25);
            ++cursorLines;
        }
        QCOMPARE(cursorLines, 1 + StanceFlagsPlot::kInputCount);

        QSignalSpy moved(&plot, &StanceFlagsPlot::timeCursorMoved);
        const QCPAxisRect* rect = plot.inputRect(Input::AccStdDev);
        const double target_s = 15.4;
        const QPoint pixel(static_cast<int>(std::lround(timeAxisOf(rect)->coordToPixel(target_s))), rect->center().y());
        QTest::mouseClick(plot.plot(), Qt::LeftButton, Qt::NoModifier, pixel);
        QCOMPARE(moved.count(), 1);
        const double secondsPerPixel = plot.timeRange().size() / rect->width();
        QVERIFY(std::abs(moved.first().first().toDouble() - target_s) <= secondsPerPixel);
        QCOMPARE(plot.timeCursor(), moved.first().first().toDouble());
    }

    void timeRangeSignalsAndKeys()
    {
        const Walk walk = simulatedWalk();
        StanceFlagsPlot plot;
        plot.setRecording(walk.recording);
        QSignalSpy changed(&plot, &StanceFlagsPlot::timeRangeChanged);
        plot.setTimeRange(2.0, 8.0);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.last().at(0).toDouble(), 2.0);
        QCOMPARE(changed.last().at(1).toDouble(), 8.0);
        for (const Input input : kAllInputs)  // hidden rows follow too, ready for when they are shown
            QCOMPARE(timeAxisOf(plot.inputRect(input))->range(), QCPRange(2.0, 8.0));
        plot.setTimeRange(2.0, 8.0);
        QCOMPARE(changed.count(), 1);

        timeAxisOf(plot.inputRect(Input::GyrNorm))->setRange(4.0, 5.0);  // what a drag or wheel does
        QCOMPARE(timeAxisOf(plot.lanesRect())->range(), QCPRange(4.0, 5.0));
        QCOMPARE(changed.count(), 2);

        QTest::keyClick(&plot, Qt::Key_Home);
        QCOMPARE(plot.timeRange(),
                 QCPRange(walk.recording->samples.front().time_s, walk.recording->samples.back().time_s));
        QCOMPARE(changed.count(), 3);
        QTest::keyClick(&plot, Qt::Key_Plus);
        QVERIFY(plot.timeRange().size() < walk.recording->duration_s());
    }

    void timeRangeLinksWithSignalPlots()
    {
        const Walk walk = simulatedWalk();
        StanceFlagsPlot flags;
        SignalPlots signalPlots;
        flags.setRecording(walk.recording);
        signalPlots.setRecording(walk.recording);
        // What MainWindow does: each follows the other, and equal ranges end the exchange.
        connect(&flags, &StanceFlagsPlot::timeRangeChanged, &signalPlots, &SignalPlots::setTimeRange);
        connect(&signalPlots, &SignalPlots::timeRangeChanged, &flags, &StanceFlagsPlot::setTimeRange);
        QSignalSpy flagsChanged(&flags, &StanceFlagsPlot::timeRangeChanged);

        signalPlots.setTimeRange(10.0, 12.0);
        QCOMPARE(flags.timeRange(), QCPRange(10.0, 12.0));
        QTest::keyClick(&flags, Qt::Key_Right);
        QCOMPARE(signalPlots.timeRange(), flags.timeRange());
        QCOMPARE(flagsChanged.count(), 2);
    }

    void rendersForTheReport()
    {
        const Walk walk = simulatedWalk();
        StanceFlagsPlot plot;
        plot.setRecording(walk.recording);
        plot.setResult(walk.result);
        plot.setInputsVisible(true);
        QImage image(800, 600, QImage::Format_RGB32);
        image.fill(Qt::white);
        {
            QPainter painter(&image);
            plot.renderTo(painter, image.rect());
        }
        int painted = 0;
        for (int y = 0; y < image.height(); y += 2)
            for (int x = 0; x < image.width(); x += 2)
                painted += image.pixel(x, y) != qRgb(255, 255, 255);
        QVERIFY2(painted > image.width() * image.height() / 4 / 20, qPrintable(QString::number(painted)));
    }

    void emptyInputsDoNotCrash()
    {
        StanceFlagsPlot plot;
        plot.setRecording(std::make_shared<const Recording>());
        plot.setResult(std::make_shared<const Result>());
        plot.setParameters(Parameters());
        plot.setInputsVisible(true);
        plot.setRecording(nullptr);
        QTest::keyClick(&plot, Qt::Key_Home);
        QVERIFY(!plot.grab().isNull());
        QVERIFY(plot.thresholdGraph(Threshold::AccMax)->data()->isEmpty());
    }

    /// Not a pass/fail check (machines differ): prints the time a 30-minute recording takes.
    void halfHourRecordingTiming()
    {
        const WalkSimulatorConfig config;
        const double walkingSpeed_mps = config.strideLength_m / (config.stanceDuration_s + config.swingDuration_s);
        const SimulatedWalk walk = simulateWalk(straightLinePath(30.0 * 60.0 * walkingSpeed_mps), config);
        auto recording = std::make_shared<const Recording>(walk.recording);
        auto result = std::make_shared<Result>();
        result->time_s = timesOf(*recording);
        result->flags = detectStance(recording->samples, Parameters());

        StanceFlagsPlot plot;
        QVERIFY(showLaidOut(plot, plot.plot()));
        plot.setInputsVisible(true);
        QElapsedTimer timer;
        timer.start();
        plot.setRecording(recording);
        plot.plot()->replot();
        const qint64 recording_ms = timer.restart();
        plot.setResult(result);
        plot.plot()->replot();
        const qint64 result_ms = timer.restart();
        Parameters params;
        params.window_half_s = 0.2;
        plot.setParameters(params);
        plot.plot()->replot();
        const qint64 parameters_ms = timer.elapsed();
        qInfo("%zu samples (%.1f min), inputs shown: setRecording+replot %lld ms, setResult+replot %lld ms, "
              "setParameters (new window)+replot %lld ms",
              recording->samples.size(), recording->duration_s() / 60.0, static_cast<long long>(recording_ms),
              static_cast<long long>(result_ms), static_cast<long long>(parameters_ms));
        QCOMPARE(static_cast<std::size_t>(plot.inputGraph(Input::AccStdDev)->dataCount()), recording->samples.size());
    }
};

QTEST_MAIN(TestStanceFlagsPlot)
#include "tst_stanceflagsplot.moc"
