#include "SignalPlots.h"
#include "PlotInteraction.h"
#include "LegendChecks.h"
#include "StanceFlagsPlot.h"
#include "TestData.h"
#include "WarningOverlay.h"
#include "detect/StanceDetector.h"
#include "io/Import.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <QAction>
#include <QElapsedTimer>
#include <QImage>
#include <QPainter>
#include <QSignalSpy>
#include <QTabWidget>
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

/// The defaults with the paper's C1/C2/C3 detector: five lanes and the input rows.
Parameters paperDetector()
{
    Parameters params;
    params.detector = static_cast<int>(DetectorKind::PaperC1C2C3);
    return params;
}

Walk simulatedWalk(const Parameters& params = paperDetector())
{
    WalkSimulatorConfig config;
    config.accNoiseStd_mps2 = 0.05;  // noise makes C1 and C3 flicker, so the lanes differ
    config.gyrNoiseStd_radps = 0.02;
    Walk walk;
    walk.recording = std::make_shared<const Recording>(simulateWalk(closedRectanglePath(10.0, 5.0), config).recording);
    walk.result = std::make_shared<const Result>(runPipeline(*walk.recording, params).result);
    return walk;
}

/// 20 s at 100 Hz: stance for the first 2 s, then none; a missed stance from 5 to 8 s and a
/// finding about the whole walk. Enough for the warnings, without a pipeline run.
std::shared_ptr<const Result> resultWithWarnings()
{
    auto result = std::make_shared<Result>();
    for (int k = 0; k < 2000; ++k) {
        const double t = k * 0.01;
        result->time_s.push_back(t);
        const bool stance = t < 2.0;
        for (auto* flags : {&result->flags.c1, &result->flags.c2, &result->flags.c3, &result->flags.c, &result->flags.stance})
            flags->push_back(stance ? 1 : 0);
        result->flags.logStatistic.push_back(stance ? 1.5f : 6.0f);
        result->flags.logThreshold.push_back(4.0f);
    }
    result->warnings = {
        {PlausibilityWarning::Kind::FewStances, 0.0, 19.99, "Only 1 stance phase in 20 s."},
        {PlausibilityWarning::Kind::LongSwing, 5.0, 8.0, "No stance for 3.0 s while moving; at its quietest (t = 6.10 s) "
                                                         "the detector statistic was 10^5.2, above its threshold 10^4.0."},
    };
    return result;
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

    void aPlotOnATabBehindFillsItsCurvesWhenShown()
    {
        // Behind another tab a result brings its warning lane at once, and its lanes and
        // statistic (every sample) when the tab comes to the front.
        const Walk walk = simulatedWalk();
        QTabWidget tabs;
        tabs.addTab(new QWidget, QStringLiteral("in front"));
        auto* plot = new StanceFlagsPlot;
        tabs.addTab(plot, QStringLiteral("detector"));
        plot->setRecording(walk.recording);
        tabs.resize(900, 700);
        tabs.show();
        QVERIFY(QTest::qWaitForWindowExposed(&tabs));
        // Read past the accessors, which fill the curves for whoever asks.
        const auto* customPlot = plot->findChild<QCustomPlot*>();
        QVERIFY(customPlot);
        const auto filledGraphs = [customPlot] {
            int filled = 0;
            for (int i = 0; i < customPlot->graphCount(); ++i)
                filled += customPlot->graph(i)->dataCount() > 0;
            return filled;
        };
        const int withoutResult = filledGraphs();
        plot->setResult(resultWithWarnings());
        QCoreApplication::processEvents();
        QCOMPARE(filledGraphs(), withoutResult);
        QVERIFY(plot->warningLane()->layout() != nullptr);  // the lane is there already

        tabs.setCurrentWidget(plot);
        QVERIFY(filledGraphs() > withoutResult + 3);  // the lanes and the statistic
        QCOMPARE(plot->statisticGraph()->dataCount(), 2000);
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
        plot.setParameters(paperDetector());
        plot.setRecording(walk.recording);
        QVERIFY(!plot.inputsVisible());
        QCOMPARE(plot.plot()->axisRectCount(), 2);  // the lanes and the statistic
        for (const Input input : kAllInputs)
            QVERIFY(!plot.inputGraph(input)->realVisibility());
        QVERIFY(!plot.thresholdGraph(Threshold::GyrMax)->realVisibility());
        QVERIFY(!timeAxisOf(plot.lanesRect())->tickLabels());
        QVERIFY(timeAxisOf(plot.statisticRect())->tickLabels());  // one time scale, at the foot

        plot.findChild<QAction*>("showDetectorInputs")->trigger();  // the toolbar toggle
        QVERIFY(plot.inputsVisible());
        QCOMPARE(plot.plot()->axisRectCount(), 2 + StanceFlagsPlot::kInputCount);
        for (const Input input : kAllInputs)
            QVERIFY(plot.inputGraph(input)->realVisibility());
        for (const Threshold threshold : {Threshold::AccMin, Threshold::AccMax, Threshold::AccStdMax, Threshold::GyrMax})
            QVERIFY(plot.thresholdGraph(threshold)->realVisibility());
        QVERIFY(!timeAxisOf(plot.statisticRect())->tickLabels());  // the time scale moved to the bottom row
        QVERIFY(timeAxisOf(plot.inputRect(Input::GyrNorm))->tickLabels());
        // The legend above the rows names the thresholds; at a third of a 1280-pixel screen it wraps.
        QVERIFY(plot.legend()->hasItemWithPlottable(plot.thresholdGraph(Threshold::GyrMax)));
        plot.resize(330, 500);
        plot.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plot));
        plot.plot()->replot();
        const QString problem = legendProblem(plot.plot(), plot.legend());
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        QVERIFY(plot.legend()->outerRect().bottom() <= plot.lanesRect()->top());

        plot.setInputsVisible(false);
        QCOMPARE(plot.plot()->axisRectCount(), 2);
        QVERIFY(!plot.legend()->hasItemWithPlottable(plot.thresholdGraph(Threshold::GyrMax)));
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
        plot.setParameters(paperDetector());
        plot.setRecording(simulatedWalk().recording);
        plot.setInputsVisible(true);
        QVERIFY(showLaidOut(plot, plot.plot()));
        plot.setTimeCursor(9.25);
        QCOMPARE(plot.timeCursor(), 9.25);
        int cursorLines = 0;
        for (int i = 0; i < plot.plot()->itemCount(); ++i) {
            const auto* line = qobject_cast<QCPItemStraightLine*>(plot.plot()->item(i));
            QVERIFY(line != nullptr);
            QCOMPARE(line->point1->key(), 9.25);
            QCOMPARE(line->point2->key(), 9.25);
            cursorLines += line->visible();  // the warning lane's is hidden with the lane
        }
        QCOMPARE(cursorLines, 2 + StanceFlagsPlot::kInputCount);

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
        plot.setParameters(paperDetector());
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

    void statisticRowShowsTheStatisticAndItsThreshold_data()
    {
        QTest::addColumn<int>("detector");
        QTest::addColumn<QString>("axisLabel");
        QTest::addColumn<bool>("movingThreshold");
        QTest::newRow("shoe, adaptive") << static_cast<int>(DetectorKind::Shoe) << "SHOE" << true;
        QTest::newRow("c1c2c3") << static_cast<int>(DetectorKind::PaperC1C2C3) << "std of |a|" << false;
    }

    void statisticRowShowsTheStatisticAndItsThreshold()
    {
        QFETCH(int, detector);
        QFETCH(QString, axisLabel);
        QFETCH(bool, movingThreshold);
        Parameters params;
        params.detector = detector;
        // The simulated walk rests so quietly that the default "always at rest" bound would hold the
        // threshold flat; a lower bound lets the drawn line follow the running minimum.
        params.zv_log_always = 2.0;
        const Walk walk = simulatedWalk(params);
        const StanceFlags& flags = walk.result->flags;
        QCOMPARE(flags.logStatistic.size(), walk.result->time_s.size());
        StanceFlagsPlot plot;
        plot.setParameters(params);
        plot.setRecording(walk.recording);
        plot.setResult(walk.result);

        const QCPAxis* axis = plot.statisticRect()->axis(QCPAxis::atLeft);
        QCOMPARE(axis->scaleType(), QCPAxis::stLogarithmic);
        QVERIFY2(axis->label().contains(axisLabel), qPrintable(axis->label()));
        const QCPGraph* statistic = plot.statisticGraph();
        QCOMPARE(static_cast<std::size_t>(statistic->dataCount()), flags.logStatistic.size());
        float lowest = std::numeric_limits<float>::infinity(), highest = -lowest;
        for (std::size_t k = 0; k < flags.logStatistic.size(); ++k) {
            if (!std::isfinite(flags.logStatistic[k]))
                continue;
            lowest = std::min(lowest, flags.logStatistic[k]);
            highest = std::max(highest, flags.logStatistic[k]);
            if (k % 37 == 0)
                QVERIFY(std::abs(std::log10(statistic->data()->at(static_cast<int>(k))->value) - flags.logStatistic[k]) < 1e-4);
        }
        // The axis follows the data: it holds it, with less than two decades to spare on either side.
        const QCPRange range = axis->range();
        QVERIFY(range.lower <= std::pow(10.0, lowest) && std::pow(10.0, highest) <= range.upper);
        QVERIFY2(std::log10(range.lower) > lowest - 2.0 && std::log10(range.upper) < highest + 2.0,
                 qPrintable(QString("%1..%2 for %3..%4").arg(range.lower).arg(range.upper).arg(lowest).arg(highest)));

        // The threshold line is the one the detector compared with, sample by sample.
        const QCPGraph* threshold = plot.statisticThresholdGraph();
        for (std::size_t k = 0; k < flags.logThreshold.size(); k += 41)
            QVERIFY(std::abs(std::log10(stepValueAt(threshold, walk.result->time_s[k])) - flags.logThreshold[k]) < 1e-4);
        QCOMPARE(threshold->dataCount() > 2, movingThreshold);
        if (!movingThreshold)
            QVERIFY(std::abs(threshold->data()->at(0)->value - params.acc_std_max_mps2) < 1e-6);

        // Stance is shaded in the row.
        const double stanceAt = walk.result->steps.at(2).stanceStart_s + 0.01;
        QVERIFY(plot.isStatisticStanceShaded(stanceAt));
        QVERIFY(!plot.isStatisticStanceShaded(walk.result->steps.at(2).stanceStart_s - 0.3));
    }

    void aStatisticDetectorShowsOnlyCAndStance()
    {
        StanceFlagsPlot plot;
        plot.setRecording(simulatedWalk().recording);
        Parameters shoe;
        shoe.detector = static_cast<int>(DetectorKind::Shoe);
        plot.setParameters(shoe);
        for (const Lane lane : {Lane::C1, Lane::C2, Lane::C3})
            QVERIFY(!plot.isLaneShown(lane));
        QVERIFY(plot.isLaneShown(Lane::C) && plot.isLaneShown(Lane::Stance));
        auto* inputs = plot.findChild<QAction*>("showDetectorInputs");
        QVERIFY(!inputs->isEnabled());  // C1/C2/C3's inputs mean nothing here
        plot.setInputsVisible(true);
        QVERIFY(!plot.isInputRowShown(Input::AccStdDev));
        QCOMPARE(plot.plot()->axisRectCount(), 2);

        plot.setParameters(paperDetector());  // the inputs asked for come with the paper's detector
        for (const Lane lane : kAllLanes)
            QVERIFY(plot.isLaneShown(lane));
        QVERIFY(inputs->isEnabled());
        QVERIFY(plot.isInputRowShown(Input::AccStdDev));
        QVERIFY(plot.statisticRect()->axis(QCPAxis::atLeft)->label().contains(QStringLiteral("std of |a|")));
    }

    void everyStatisticDetectorNamesItsOwnStatistic()
    {
        // The axis labels were a list beside the detector list: a sixth detector would have been
        // labelled SHOE. They come from the detectors' own names now.
        StanceFlagsPlot plot;
        plot.setRecording(simulatedWalk().recording);
        const ParameterField* detector = findParameterField("detector");
        for (std::size_t kind = 0; kind < detector->choiceNames.size(); ++kind) {
            Parameters params;
            params.detector = static_cast<int>(kind);
            plot.setParameters(params);
            const QString label = plot.statisticRect()->axis(QCPAxis::atLeft)->label();
            if (params.detectorKind() == DetectorKind::PaperC1C2C3)
                QVERIFY2(label.contains(QStringLiteral("std of |a|")), qPrintable(label));
            else
                QCOMPARE(label, QString::fromUtf8(detector->choiceNames[kind]).toUpper() + QStringLiteral("\nstatistic"));
        }
    }

    void warningsAreShadedLabelledAndExplained()
    {
        const std::shared_ptr<const Result> result = resultWithWarnings();
        StanceFlagsPlot plot;
        plot.setResult(result);
        QVERIFY(plot.warningLane()->layout() != nullptr);  // the lane of labelled bars is shown
        const WarningOverlay& warnings = plot.warningOverlay();
        QVERIFY(warnings.isShaded(6.0));    // the missed stance
        QVERIFY(!warnings.isShaded(12.0));  // the whole-walk finding is a bar in the lane, not a band
        const QString tip = warnings.toolTipAt(6.0);
        QVERIFY2(tip.contains(QStringLiteral("above its threshold")) && tip.contains(QStringLiteral("5.00")),
                 qPrintable(tip));
        QVERIFY(tip.contains(warningLabel(PlausibilityWarning::Kind::LongSwing)));
        QVERIFY(tip.contains(QStringLiteral("Only 1 stance phase")));  // both findings hold 6 s
        QVERIFY(!warnings.toolTipAt(12.0).contains(QStringLiteral("No stance")));

        // On screen: a red tint in the band, none beside it.
        QVERIFY(showLaidOut(plot, plot.plot()));
        plot.setTimeRange(0.0, 20.0);
        plot.plot()->replot();
        const QImage image = plot.plot()->toPixmap().toImage();
        const QCPAxisRect* rect = plot.statisticRect();
        const auto pixelAt = [&](double time_s, double value) {
            return image.pixelColor(static_cast<int>(rect->axis(QCPAxis::atBottom)->coordToPixel(time_s)),
                                    static_cast<int>(rect->axis(QCPAxis::atLeft)->coordToPixel(value)));
        };
        const QColor inBand = pixelAt(6.5, 100.0), beside = pixelAt(11.0, 100.0);
        QVERIFY2(inBand.red() > inBand.green() + 15 && inBand.red() > 200, qPrintable(inBand.name()));
        QCOMPARE(beside, QColor(Qt::white));

        plot.setResult(nullptr);
        QVERIFY(plot.warningLane()->layout() == nullptr);
        QVERIFY(!plot.warningOverlay().isShaded(6.0));
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
        result->flags = detectStance(recording->samples, paperDetector());

        StanceFlagsPlot plot;
        QVERIFY(showLaidOut(plot, plot.plot()));
        plot.setParameters(paperDetector());
        plot.setInputsVisible(true);
        QElapsedTimer timer;
        timer.start();
        plot.setRecording(recording);
        plot.plot()->replot();
        const qint64 recording_ms = timer.restart();
        plot.setResult(result);
        plot.plot()->replot();
        const qint64 result_ms = timer.restart();
        Parameters params = paperDetector();
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

    void theAxesHoldTheRunningTrialsData()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const ImportResult imported = importRecording(datasetPath(QStringLiteral("pyshoe-vicon/2017-11-27-11-22-22.csv")).toStdString());
        QVERIFY(imported.ok());
        auto recording = std::make_shared<const Recording>(imported.recording);
        auto result = std::make_shared<const Result>(runPipeline(*recording, paperDetector()).result);
        StanceFlagsPlot plot;
        QVERIFY(showLaidOut(plot, plot.plot()));
        plot.setParameters(paperDetector());
        plot.setInputsVisible(true);
        plot.setRecording(recording);
        plot.setResult(result);
        plot.plot()->replot();
        // Running swings the std of |a| far above a walking threshold: the row must show it.
        for (const Input input : {Input::AccNorm, Input::AccStdDev, Input::GyrNorm}) {
            const QCPRange shown = plot.inputRect(input)->axis(QCPAxis::atLeft)->range();
            const QCPGraph* graph = plot.inputGraph(input);
            int inside = 0;
            for (const QCPGraphData& point : *graph->data())
                inside += shown.contains(point.value);
            QVERIFY2(inside >= 0.98 * graph->dataCount(),
                     qPrintable(QStringLiteral("input %1: %2 of %3 samples within %4..%5")
                                    .arg(static_cast<int>(input)).arg(inside).arg(graph->dataCount())
                                    .arg(shown.lower).arg(shown.upper)));
        }
        // ... and the statistic row every finite statistic.
        const QCPRange statistic = plot.statisticRect()->axis(QCPAxis::atLeft)->range();
        for (const float value : result->flags.logStatistic)
            if (std::isfinite(value))
                QVERIFY(statistic.contains(std::pow(10.0, static_cast<double>(value))));
        // pyshoe's zero-velocity labels from the motion capture are the reference stance lane.
        QVERIFY(!recording->reference.stance.empty());
        QVERIFY(plot.referenceLane()->layout() != nullptr);
        QVERIFY(plot.isReferenceStance(recording->samples.front().time_s + 0.5));  // standing still at the start
        QVERIFY(!plot.referenceSource().isEmpty());
    }

    void ipolGaitEventsAreTheReferenceLane()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const ImportResult imported = importRecording(datasetPath(QStringLiteral("xsens-mtw-ipol/1-1_lf.txt")).toStdString());
        QVERIFY(imported.ok());
        auto recording = std::make_shared<const Recording>(imported.recording);
        const std::vector<SampleRange>& swings = recording->reference.swings;
        QVERIFY(swings.size() >= 3);
        QVERIFY(recording->reference.stance.empty());
        StanceFlagsPlot plot;
        plot.setRecording(recording);
        QVERIFY(plot.referenceLane()->layout() != nullptr);
        const std::vector<ImuSample>& samples = recording->samples;
        const SampleRange& swing = swings[1];
        QVERIFY(!plot.isReferenceStance(samples[(swing.first + swing.last) / 2].time_s));  // mid-swing
        const std::size_t between = (swings[0].last + swings[1].first) / 2;
        QVERIFY(plot.isReferenceStance(samples[between].time_s));  // between two swings
        QVERIFY(!plot.isReferenceStance(samples.front().time_s));  // before the first labelled event: unknown
        // A recording without a reference has no such lane.
        plot.setRecording(simulatedWalk().recording);
        QVERIFY(plot.referenceLane()->layout() == nullptr);
    }

    void laneReadoutNamesTheFlags()
    {
        const Walk w = simulatedWalk();
        StanceFlagsPlot plot;
        QVERIFY(showLaidOut(plot, plot.plot()));
        plot.setParameters(paperDetector());
        plot.setRecording(w.recording);
        plot.setResult(w.result);
        plot.plot()->replot();
        const QCPAxisRect* lanes = plot.lanesRect();
        const QCPAxis* time = lanes->axis(QCPAxis::atBottom);
        plot.interaction()->probeAt(QPointF(time->coordToPixel(w.result->time_s[10]), lanes->center().y()));
        const QString readout = plot.interaction()->readoutText();
        QVERIFY2(readout.contains(QStringLiteral("Stance (median) = 1 (set)")), qPrintable(readout));  // standing at the start
        QVERIFY(!readout.contains(QStringLiteral("6.0")));  // not the lane's plotting level
    }
};

QTEST_MAIN(TestStanceFlagsPlot)
#include "tst_stanceflagsplot.moc"
