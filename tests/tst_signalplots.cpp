#include "SignalPlots.h"
#include "DecimatedGraph.h"
#include "DeferredReplot.h"
#include "LegendChecks.h"
#include "PlotInteraction.h"
#include "WarningOverlay.h"
#include "detect/StanceDetector.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <QCheckBox>
#include <QElapsedTimer>
#include <QImage>
#include <QPainter>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace footpath;
using Channel = SignalPlots::Channel;
using Row = SignalPlots::Row;

namespace {

struct Walk {
    SimulatedWalk simulated;
    std::shared_ptr<const Recording> recording;
    std::shared_ptr<const Result> result;
};

Walk simulatedWalk(bool withMagnetometer, bool withPressure,
                   const std::vector<Eigen::Vector3d>& path = closedRectanglePath(10.0, 5.0))
{
    WalkSimulatorConfig config;
    config.withMagnetometer = withMagnetometer;
    config.withPressure = withPressure;
    Walk walk;
    walk.simulated = simulateWalk(path, config);
    walk.recording = std::make_shared<const Recording>(walk.simulated.recording);
    walk.result = std::make_shared<const Result>(runPipeline(*walk.recording, Parameters()).result);
    return walk;
}

QCPAxis* timeAxisOf(const SignalPlots& plots, Row row) { return plots.axisRect(row)->axis(QCPAxis::atBottom); }

/// Whether the legend has an entry of this name (x, y and z appear once for all rows).
bool legendNames(const SignalPlots& plots, const QString& name)
{
    for (int i = 0; i < plots.legend()->itemCount(); ++i) {
        auto* item = qobject_cast<QCPPlottableLegendItem*>(plots.legend()->item(i));
        if (item && item->plottable()->name() == name)
            return true;
    }
    return false;
}

/// Shows the widget and lays the plot out, so pixels map to coordinates as on screen.
bool showLaidOut(SignalPlots& plots, int width = 900)
{
    plots.resize(width, 700);
    plots.show();
    const bool exposed = QTest::qWaitForWindowExposed(&plots);
    plots.plot()->replot();
    return exposed;
}

/// Pixels of the stance band's colour (pale amber over white) in the column of time_s in a row.
int bandPixelsAt(const SignalPlots& plots, Row row, double time_s)
{
    plots.plot()->replot();
    const QImage image = plots.plot()->toPixmap().toImage();
    const QCPAxisRect* rect = plots.axisRect(row);
    const int x = static_cast<int>(std::lround(rect->axis(QCPAxis::atBottom)->coordToPixel(time_s)));
    int count = 0;
    for (int y = rect->top() + 1; y < rect->bottom(); ++y) {
        const QColor pixel = image.pixelColor(x, y);
        count += pixel.red() >= 250 && std::abs(pixel.green() - 236) <= 6 && std::abs(pixel.blue() - 204) <= 6;
    }
    return count;
}

int paintedPixels(const QImage& image)
{
    int painted = 0;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2)
            painted += image.pixel(x, y) != qRgb(255, 255, 255);
    return painted;
}

constexpr std::array<Channel, SignalPlots::kChannelCount> kAllChannels = {
    Channel::AccX, Channel::AccY, Channel::AccZ, Channel::AccNorm, Channel::GyrX, Channel::GyrY,
    Channel::GyrZ, Channel::MagX, Channel::MagY, Channel::MagZ, Channel::Pressure, Channel::Height};
constexpr std::array<Row, SignalPlots::kRowCount> kAllRows = {Row::Acceleration, Row::AngularRate, Row::MagneticField,
                                                              Row::Pressure, Row::Height};

}  // namespace

class TestSignalPlots : public QObject {
    Q_OBJECT
private slots:
    void recordedChannels_data()
    {
        QTest::addColumn<bool>("withMagnetometer");
        QTest::addColumn<bool>("withPressure");
        QTest::newRow("inertial only") << false << false;
        QTest::newRow("with magnetometer") << true << false;
        QTest::newRow("with pressure") << false << true;
        QTest::newRow("with both") << true << true;
    }

    void plotsExactlyTheRecordingsSamples_data() { recordedChannels_data(); }
    void plotsExactlyTheRecordingsSamples()
    {
        QFETCH(bool, withMagnetometer);
        QFETCH(bool, withPressure);
        const Walk walk = simulatedWalk(withMagnetometer, withPressure);
        const std::vector<ImuSample>& samples = walk.recording->samples;
        SignalPlots plots;
        plots.setRecording(walk.recording);

        for (const Channel channel : kAllChannels) {
            const QCPGraph* graph = plots.graph(channel);
            const bool magChannel = channel == Channel::MagX || channel == Channel::MagY || channel == Channel::MagZ;
            const bool baroChannel = channel == Channel::Pressure || channel == Channel::Height;
            const bool recorded = magChannel ? withMagnetometer : baroChannel ? withPressure : true;
            if (!recorded) {
                QVERIFY2(graph->data()->isEmpty(), qPrintable(graph->name()));
                continue;
            }
            QCOMPARE(static_cast<std::size_t>(graph->dataCount()), samples.size());
            QCOMPARE(graph->data()->constBegin()->key, samples.front().time_s);
            QCOMPARE((graph->data()->constEnd() - 1)->key, samples.back().time_s);
        }
        const std::size_t middle = samples.size() / 2;
        const auto at = [&](Channel channel) { return plots.graph(channel)->data()->at(static_cast<int>(middle))->value; };
        QCOMPARE(at(Channel::AccY), samples[middle].acc_mps2.y());
        QCOMPARE(at(Channel::AccNorm), samples[middle].acc_mps2.norm());
        QCOMPARE(at(Channel::GyrZ), samples[middle].gyr_radps.z());
        if (withMagnetometer)
            QCOMPARE(at(Channel::MagX), samples[middle].mag.x());
        if (withPressure)
            QCOMPARE(at(Channel::Pressure), samples[middle].pressure_pa / 100.0);  // hPa
    }

    void showsMagneticAndPressureRowsOnlyWhenRecorded_data() { recordedChannels_data(); }
    void showsMagneticAndPressureRowsOnlyWhenRecorded()
    {
        QFETCH(bool, withMagnetometer);
        QFETCH(bool, withPressure);
        SignalPlots plots;
        plots.setRecording(simulatedWalk(withMagnetometer, withPressure).recording);
        QVERIFY(showLaidOut(plots, 1400));  // the toolbar lays its widgets out when shown, if they fit
        QVERIFY(plots.isRowShown(Row::Acceleration));
        QVERIFY(plots.isRowShown(Row::AngularRate));
        QCOMPARE(plots.isRowShown(Row::MagneticField), withMagnetometer);
        QCOMPARE(plots.isRowShown(Row::Pressure), withPressure);
        QCOMPARE(plots.isRowShown(Row::Height), withPressure);
        QCOMPARE(plots.plot()->axisRectCount(), 2 + (withMagnetometer ? 1 : 0) + (withPressure ? 2 : 0));
        // The toolbar offers only channels that exist.
        QCOMPARE(plots.findChild<QCheckBox*>("showMagX")->isVisibleTo(&plots), withMagnetometer);
        QCOMPARE(plots.findChild<QCheckBox*>("showHeight")->isVisibleTo(&plots), withPressure);
        QVERIFY(plots.findChild<QCheckBox*>("showAccX")->isVisibleTo(&plots));
    }

    void barometricHeightIsRelativeToTheFirstSample()
    {
        const Walk walk = simulatedWalk(false, true, stairsPath(5, 0.17, 0.3));
        SignalPlots plots;
        plots.setRecording(walk.recording);
        const QCPGraph* height = plots.graph(Channel::Height);
        const double startHeight = walk.simulated.truePosition_m.front().z();
        for (std::size_t k = 0; k < walk.recording->samples.size(); k += 37) {
            const double expected = walk.simulated.truePosition_m[k].z() - startHeight;
            QVERIFY2(std::abs(height->data()->at(static_cast<int>(k))->value - expected) < 1e-3,
                     qPrintable(QString("sample %1: %2 m, truth %3 m")
                                    .arg(k)
                                    .arg(height->data()->at(static_cast<int>(k))->value)
                                    .arg(expected)));
        }
        QVERIFY(height->data()->at(height->dataCount() - 1)->value > 0.8);  // five steps of 17 cm up
    }

    void shadesStanceOnlyWithAResult()
    {
        const Walk walk = simulatedWalk(true, true);
        SignalPlots plots;
        plots.setRecording(walk.recording);
        const std::vector<double>& times = walk.result->time_s;
        const std::vector<std::uint8_t>& stance = walk.result->flags.stance;
        const std::size_t firstStance = std::find(stance.cbegin(), stance.cend(), 1) - stance.cbegin();
        QVERIFY(firstStance < stance.size());
        QVERIFY(!plots.isStanceShaded(times[firstStance]));

        plots.setResult(walk.result);
        std::size_t stanceSamples = 0;
        for (std::size_t k = 0; k < times.size(); ++k) {
            QCOMPARE(plots.isStanceShaded(times[k]), stance[k] != 0);
            stanceSamples += stance[k];
        }
        QVERIFY(stanceSamples > times.size() / 4);  // the walk stands often enough to test anything
        // Cursor lines only (one per row and the warning lane's): no item per phase.
        QCOMPARE(plots.plot()->itemCount(), SignalPlots::kRowCount + 1);

        plots.setResult(nullptr);
        QVERIFY(!plots.isStanceShaded(times[firstStance]));
        plots.setResult(walk.result);
        plots.setRecording(walk.recording);  // a new recording drops the old result's shading
        QVERIFY(!plots.isStanceShaded(times[firstStance]));
    }

    void marksHeelStrikesAndToeOffsOnTheAngularRateRow()
    {
        const Walk walk = simulatedWalk(true, true);
        SignalPlots plots;
        plots.setRecording(walk.recording);
        QVERIFY(plots.gaitEventMarks(GaitEventKind::HeelStrike)->data()->isEmpty());
        plots.setResult(walk.result);
        std::vector<double> strikes, offs;
        for (const GaitEvent& event : walk.result->gaitEvents) {
            if (event.kind == GaitEventKind::HeelStrike)
                strikes.push_back(event.time_s);
            else if (event.kind == GaitEventKind::ToeOff)
                offs.push_back(event.time_s);
        }
        QVERIFY(strikes.size() > 5);
        const QCPGraph* strikeMarks = plots.gaitEventMarks(GaitEventKind::HeelStrike);
        const QCPGraph* offMarks = plots.gaitEventMarks(GaitEventKind::ToeOff);
        QCOMPARE(std::size_t(strikeMarks->dataCount()), strikes.size());
        QCOMPARE(std::size_t(offMarks->dataCount()), offs.size());
        for (int i = 0; i < strikeMarks->dataCount(); ++i)
            QCOMPARE(strikeMarks->data()->at(i)->key, strikes[std::size_t(i)]);
        QCOMPARE(strikeMarks->valueAxis(), plots.axisRect(Row::AngularRate)->axis(QCPAxis::atLeft));
        QVERIFY(plots.legend()->hasItemWithPlottable(strikeMarks) && plots.legend()->hasItemWithPlottable(offMarks));
        plots.setResult(nullptr);
        QVERIFY(strikeMarks->data()->isEmpty() && !plots.legend()->hasItemWithPlottable(strikeMarks));
    }

    void drawsStanceBandsInEveryRow()
    {
        const Walk walk = simulatedWalk(true, true);
        SignalPlots plots;
        plots.setRecording(walk.recording);
        QVERIFY(showLaidOut(plots));
        const double standing_s = 1.0;  // the simulated walk starts with two seconds at rest
        const double swinging_s = walk.result->steps.at(1).stanceStart_s - 0.3;
        QVERIFY(!plots.isStanceShaded(swinging_s));
        for (const Row row : kAllRows)
            QVERIFY(bandPixelsAt(plots, row, standing_s) <= 2);  // a line's antialiased edge may match

        plots.setResult(walk.result);
        for (const Row row : kAllRows) {
            const int rowHeight = plots.axisRect(row)->height();
            QVERIFY2(bandPixelsAt(plots, row, standing_s) > rowHeight / 2, qPrintable(QString::number(static_cast<int>(row))));
            QVERIFY(bandPixelsAt(plots, row, swinging_s) <= 2);
        }
    }

    void aNewEstimateRedrawsOnlyTheBandsAndEventsYetLooksAsIfDrawnAfresh()
    {
        // A slider move: the same recording, other stances. The rows, legend and lane stay, so the
        // curves' paint buffer is kept and only the bands and gait events are drawn again; the
        // window must then look exactly as a plot drawn from scratch with the new result.
        const Walk walk = simulatedWalk(false, false);
        Parameters wider;
        wider.zv_log_always = 5.5;  // the simulated swings' statistic rises through 4-6.5
        const auto other = std::make_shared<const Result>(runPipeline(*walk.recording, wider).result);
        QVERIFY(other->flags.stance != walk.result->flags.stance);
        QVERIFY(walk.result->warnings.empty() && other->warnings.empty() && !other->gaitEvents.empty());

        SignalPlots plots;
        plots.setRecording(walk.recording);
        plots.setResult(walk.result);
        QVERIFY(showLaidOut(plots));
        auto* deferred = plots.plot()->findChild<DeferredReplot*>();
        QVERIFY(deferred != nullptr);
        QTRY_VERIFY(!deferred->isPending());
        const QImage before = plots.plot()->grab().toImage();
        QSignalSpy wholeReplots(plots.plot(), &QCustomPlot::afterReplot);
        QSignalSpy layerReplots(deferred, &DeferredReplot::layersReplotted);
        plots.setResult(other);
        QTRY_COMPARE(layerReplots.count(), 1);
        QCOMPARE(wholeReplots.count(), 0);
        const QImage after = plots.plot()->grab().toImage();

        SignalPlots fresh;
        fresh.setRecording(walk.recording);
        fresh.setResult(other);
        QVERIFY(showLaidOut(fresh));
        QTRY_VERIFY(!fresh.plot()->findChild<DeferredReplot*>()->isPending());
        const QImage expected = fresh.plot()->grab().toImage();
        QCOMPARE(after.size(), expected.size());
        QVERIFY(after != before);
        QVERIFY(after == expected);

        // A result without stances changes the legend: the whole plot is drawn again.
        Result standing = *other;
        std::fill(standing.flags.stance.begin(), standing.flags.stance.end(), std::uint8_t(0));
        plots.setResult(std::make_shared<const Result>(standing));
        QTRY_COMPARE(wholeReplots.count(), 1);
        QVERIFY(!legendNames(plots, QStringLiteral("Stance")));
    }

    void aPressureRowsTicksAreRoundAndDistinct()
    {
        // The pressure row, made when a file with pressure opens, kept QCustomPlot's own ticker:
        // 1004, 1003.75, 1003.5 (or 997.25, 997.225) and, in a small row, labels on each other.
        Walk walk = simulatedWalk(false, true);
        auto recording = std::make_shared<Recording>(*walk.recording);
        for (std::size_t k = 0; k < recording->samples.size(); ++k)  // 997.2 hPa, a few Pa of wobble
            recording->samples[k].pressure_pa = 99722.0 + 3.0 * std::sin(0.01 * static_cast<double>(k));
        SignalPlots plots;
        plots.resize(600, 700);
        plots.show();
        plots.setRecording(recording);
        plots.setResult(walk.result);
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        plots.plot()->replot();
        QCPAxis* pressure = plots.axisRect(Row::Pressure)->axis(QCPAxis::atLeft);
        QVERIFY(dynamic_cast<ReadableTicker*>(pressure->ticker().data()));
        plots.plot()->replot();  // the ticks of the ticker the first pass gave
        const QVector<QString> labels = pressure->tickVectorLabels();
        QVERIFY(labels.size() >= 2);
        QCOMPARE(QSet<QString>(labels.begin(), labels.end()).size(), labels.size());
        const double spacing = std::abs(pressure->coordToPixel(pressure->tickVector()[1]) - pressure->coordToPixel(pressure->tickVector()[0]));
        QVERIFY2(spacing >= QFontMetrics(pressure->tickLabelFont()).height(), qPrintable(QString::number(spacing)));
    }

    void warningLabelsStayInsideTheirSpanOrBesideIt()
    {
        // "height vs barometer" ran past its bar and out of the lane at the plot's right edge.
        const LabelPlace fits = warningLabelPlace(60, 30, 100, 200, 0, 500);
        QVERIFY(fits.inside);
        QCOMPARE(fits.start, 103.0);
        QCOMPARE(fits.width, 60.0);
        const LabelPlace elided = warningLabelPlace(120, 30, 100, 200, 0, 500);  // elided to the bar
        QVERIFY(elided.inside);
        QCOMPARE(elided.width, 94.0);
        const LabelPlace after = warningLabelPlace(120, 30, 100, 110, 0, 500);  // a narrow bar: beside it
        QVERIFY(!after.inside);
        QCOMPARE(after.start, 113.0);
        const LabelPlace before = warningLabelPlace(120, 30, 450, 460, 0, 500);  // at the lane's end: before it
        QVERIFY(!before.inside);
        QVERIFY(before.start + before.width <= 447.0);
        QCOMPARE(before.width, 120.0);
    }

    void warningsAreShadedInEveryRowWithALane()
    {
        const Walk walk = simulatedWalk(true, false);
        auto result = std::make_shared<Result>(*walk.result);
        result->warnings = {{PlausibilityWarning::Kind::ImplausibleSpeed, 6.0, 7.5,
                             "The estimated foot speed reaches 15.0 m/s, faster than a foot moves."},
                            {PlausibilityWarning::Kind::StanceRatio, 2.0, 20.0, "The foot is at rest 5 % of the time."}};
        SignalPlots plots;
        plots.setRecording(walk.recording);
        QVERIFY(showLaidOut(plots));
        QVERIFY(plots.warningLane()->layout() == nullptr);  // no lane without warnings
        plots.setResult(result);
        QVERIFY(plots.warningLane()->layout() != nullptr);
        QVERIFY(plots.warningLane()->bottom() <= plots.axisRect(Row::Acceleration)->top());  // above the signals
        QVERIFY(plots.warningOverlay().isShaded(7.0));
        QVERIFY(!plots.warningOverlay().isShaded(12.0));  // the stance share is about the whole walk: no band
        QVERIFY(plots.warningOverlay().toolTipAt(7.0).contains(QStringLiteral("15.0 m/s")));
        QVERIFY(plots.warningOverlay().toolTipAt(12.0).contains(QStringLiteral("5 %")));
        QVERIFY(plots.warningOverlay().toolTipAt(1.0).isEmpty());
        QVERIFY(plots.legend()->hasItemWithPlottable(plots.graph(Channel::AccX)));
        QVERIFY(legendNames(plots, QStringLiteral("Stance")));

        // A red tint through every row at 7 s, in no row at 12 s.
        plots.plot()->replot();
        const QImage image = plots.plot()->toPixmap().toImage();
        for (const Row row : {Row::Acceleration, Row::AngularRate, Row::MagneticField}) {
            const QCPAxisRect* rect = plots.axisRect(row);
            const auto tint = [&](double time_s) {
                const int x = static_cast<int>(std::lround(rect->axis(QCPAxis::atBottom)->coordToPixel(time_s)));
                int reddish = 0;
                for (int y = rect->top() + 1; y < rect->bottom(); ++y) {
                    const QColor pixel = image.pixelColor(x, y);
                    reddish += pixel.red() >= 240 && pixel.green() < 235 && pixel.green() > 190 && pixel.blue() > 180;
                }
                return reddish;
            };
            QVERIFY2(tint(7.0) > rect->height() / 3, qPrintable(QString::number(tint(7.0))));
            // No band: at most the few pale red pixels where the red x curve crosses the column, antialiased.
            QVERIFY2(tint(12.0) < rect->height() / 10, qPrintable(QString::number(tint(12.0))));
        }
        plots.setResult(nullptr);
        QVERIFY(plots.warningLane()->layout() == nullptr);
    }

    void timeCursorRunsThroughEveryShownRow()
    {
        SignalPlots plots;
        plots.setRecording(simulatedWalk(true, false).recording);
        QVERIFY(!plots.cursorLine(Row::Acceleration)->visible());  // not placed yet
        plots.setTimeCursor(12.5);
        QCOMPARE(plots.timeCursor(), 12.5);
        for (const Row row : kAllRows) {
            QCOMPARE(plots.cursorLine(row)->visible(), plots.isRowShown(row));
            QCOMPARE(plots.cursorLine(row)->point1->key(), 12.5);
            QCOMPARE(plots.cursorLine(row)->point2->key(), 12.5);
        }
        QVERIFY(!plots.cursorLine(Row::Pressure)->visible());
    }

    void clickEmitsTimeCursorMoved()
    {
        SignalPlots plots;
        plots.setRecording(simulatedWalk(false, false).recording);
        QVERIFY(showLaidOut(plots));
        QSignalSpy moved(&plots, &SignalPlots::timeCursorMoved);
        const QCPAxisRect* rect = plots.axisRect(Row::AngularRate);
        const double target_s = 7.3;
        const QPoint pixel(static_cast<int>(std::lround(timeAxisOf(plots, Row::AngularRate)->coordToPixel(target_s))),
                           rect->center().y());
        QTest::mouseClick(plots.plot(), Qt::LeftButton, Qt::NoModifier, pixel);
        QCOMPARE(moved.count(), 1);
        const double secondsPerPixel = plots.timeRange().size() / rect->width();
        const double clicked_s = moved.first().first().toDouble();
        QVERIFY2(std::abs(clicked_s - target_s) <= secondsPerPixel, qPrintable(QString::number(clicked_s)));
        QCOMPARE(plots.timeCursor(), clicked_s);
        QCOMPARE(plots.cursorLine(Row::Acceleration)->point1->key(), clicked_s);

        // A press and a release far apart is a drag, not a click.
        QTest::mousePress(plots.plot(), Qt::LeftButton, Qt::NoModifier, pixel);
        QTest::mouseRelease(plots.plot(), Qt::LeftButton, Qt::NoModifier, pixel + QPoint(60, 0));
        QCOMPARE(moved.count(), 1);
    }

    void timeAxesOfAllRowsAreLinked()
    {
        SignalPlots plots;
        plots.setRecording(simulatedWalk(true, true).recording);
        QSignalSpy changed(&plots, &SignalPlots::timeRangeChanged);

        timeAxisOf(plots, Row::Acceleration)->setRange(3.0, 7.0);  // what a drag or wheel in a row does
        for (const Row row : kAllRows)
            QCOMPARE(timeAxisOf(plots, row)->range(), QCPRange(3.0, 7.0));
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.last().at(0).toDouble(), 3.0);
        QCOMPARE(changed.last().at(1).toDouble(), 7.0);

        plots.setTimeRange(4.0, 6.0);
        for (const Row row : kAllRows)
            QCOMPARE(timeAxisOf(plots, row)->range(), QCPRange(4.0, 6.0));
        QCOMPARE(changed.count(), 2);
        plots.setTimeRange(4.0, 6.0);  // no change, no signal: two linked widgets do not ping-pong
        QCOMPARE(changed.count(), 2);
    }

    void wheelZoomsTheTimeAxisOnly()
    {
        SignalPlots plots;
        plots.setRecording(simulatedWalk(false, false).recording);
        QVERIFY(showLaidOut(plots));
        const QCPRange timeBefore = plots.timeRange();
        const QCPRange valuesBefore = plots.axisRect(Row::Acceleration)->axis(QCPAxis::atLeft)->range();
        const QPointF centre = plots.axisRect(Row::Acceleration)->center();
        QWheelEvent wheel(centre, plots.plot()->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(plots.plot(), &wheel);
        QVERIFY(plots.timeRange().size() < 0.95 * timeBefore.size());
        QCOMPARE(timeAxisOf(plots, Row::AngularRate)->range(), plots.timeRange());
        QCOMPARE(plots.axisRect(Row::Acceleration)->axis(QCPAxis::atLeft)->range(), valuesBefore);
    }

    void keysZoomPanAndHomeShowsAll()
    {
        const Walk walk = simulatedWalk(false, false);
        SignalPlots plots;
        plots.setRecording(walk.recording);
        const QCPRange all(walk.recording->samples.front().time_s, walk.recording->samples.back().time_s);
        QCOMPARE(plots.timeRange(), all);

        QTest::keyClick(&plots, Qt::Key_Plus);
        QVERIFY(std::abs(plots.timeRange().size() - 0.8 * all.size()) < 1e-9);
        QVERIFY(std::abs(plots.timeRange().center() - all.center()) < 1e-9);
        const QCPRange zoomed = plots.timeRange();
        QTest::keyClick(&plots, Qt::Key_Right);
        QVERIFY(std::abs(plots.timeRange().lower - (zoomed.lower + 0.1 * zoomed.size())) < 1e-9);
        QTest::keyClick(&plots, Qt::Key_Left);
        QTest::keyClick(&plots, Qt::Key_Left);
        QVERIFY(std::abs(plots.timeRange().lower - (zoomed.lower - 0.1 * zoomed.size())) < 1e-9);
        QTest::keyClick(&plots, Qt::Key_Minus);
        QVERIFY(std::abs(plots.timeRange().size() - all.size()) < 1e-9);
        QTest::keyClick(&plots, Qt::Key_Home);
        QCOMPARE(plots.timeRange(), all);
        QCOMPARE(timeAxisOf(plots, Row::AngularRate)->range(), all);
    }

    void rowsStayAsHighAsTheirTitles()
    {
        // Pulling the summary dock up squeezed the rows until their axis titles ran into each
        // other: the plot now keeps each row as high as its title is long.
        SignalPlots plots;
        const Walk walk = simulatedWalk(true, true);
        plots.setRecording(walk.recording);
        plots.setResult(walk.result);
        QVERIFY(showLaidOut(plots, 600));
        plots.resize(600, 200);  // far less than five rows need
        QTest::qWait(50);
        plots.plot()->replot();
        for (const Row row : {Row::Acceleration, Row::AngularRate, Row::MagneticField, Row::Pressure, Row::Height}) {
            const QCPAxis* values = plots.axisRect(row)->axis(QCPAxis::atLeft);
            const QFontMetrics metrics(values->labelFont());
            int longest = 0;
            for (const QString& line : values->label().split(QLatin1Char('\n')))
                longest = std::max(longest, metrics.horizontalAdvance(line));
            QVERIFY2(plots.axisRect(row)->height() >= longest,
                     qPrintable(QStringLiteral("%1: %2 px for a %3 px title").arg(values->label()).arg(plots.axisRect(row)->height()).arg(longest)));
        }
    }

    void legendSitsAboveTheRowsAndWrapsWhenNarrow()
    {
        // As in the workspace at 1280x800 (a third of the width), and wider: no entry clipped, none
        // over the curves.
        for (const int width : {330, 480, 900}) {
            SignalPlots plots;
            const Walk walk = simulatedWalk(true, true);
            plots.setRecording(walk.recording);
            plots.setResult(walk.result);
            QVERIFY(showLaidOut(plots, width));
            const QString problem = legendProblem(plots.plot(), plots.legend());
            QVERIFY2(problem.isEmpty(), qPrintable(QStringLiteral("%1 px: %2").arg(width).arg(problem)));
            QVERIFY(plots.legend()->outerRect().bottom() <= plots.axisRect(Row::Acceleration)->top());
            // x, y and z once for the acceleration, angular rate and magnetic field rows.
            int xEntries = 0;
            for (int i = 0; i < plots.legend()->itemCount(); ++i) {
                auto* item = qobject_cast<QCPPlottableLegendItem*>(plots.legend()->item(i));
                xEntries += item && item->plottable()->name() == QStringLiteral("x") ? 1 : 0;
            }
            QCOMPARE(xEntries, 1);
        }
    }

    void channelTogglesHideGraphsAndEmptyRows()
    {
        SignalPlots plots;
        plots.setRecording(simulatedWalk(false, false).recording);
        const QCPGraph* gyrY = plots.graph(Channel::GyrY);
        QVERIFY(legendNames(plots, QStringLiteral("y")));

        plots.setChannelVisible(Channel::GyrY, false);
        QVERIFY(!gyrY->visible());
        QVERIFY(!plots.isChannelVisible(Channel::GyrY));
        QVERIFY(plots.graph(Channel::GyrX)->visible());
        QVERIFY(!plots.findChild<QCheckBox*>("showGyrY")->isChecked());
        QVERIFY(legendNames(plots, QStringLiteral("y")));  // the acceleration's y still has the entry
        plots.setChannelVisible(Channel::AccY, false);
        QVERIFY(!legendNames(plots, QStringLiteral("y")));
        plots.setChannelVisible(Channel::AccY, true);

        plots.findChild<QCheckBox*>("showGyrY")->click();  // the toolbar switches it back on
        QVERIFY(gyrY->visible());
        QVERIFY(plots.isChannelVisible(Channel::GyrY));

        for (const Channel channel : {Channel::AccX, Channel::AccY, Channel::AccZ, Channel::AccNorm})
            plots.setChannelVisible(channel, false);
        QVERIFY(!plots.isRowShown(Row::Acceleration));  // a row with nothing to show gives its space away
        QCOMPARE(plots.plot()->axisRectCount(), 1);
        QVERIFY(timeAxisOf(plots, Row::AngularRate)->tickLabels());
        plots.setChannelVisible(Channel::AccNorm, true);
        QVERIFY(plots.isRowShown(Row::Acceleration));
        QCOMPARE(plots.plot()->axisRect(0), plots.axisRect(Row::Acceleration));  // back on top
        QVERIFY(!timeAxisOf(plots, Row::Acceleration)->tickLabels());  // time labels only at the bottom
    }

    void rendersForTheReport()
    {
        const Walk walk = simulatedWalk(true, true);
        SignalPlots plots;
        plots.setRecording(walk.recording);
        plots.setResult(walk.result);
        QImage image(800, 600, QImage::Format_RGB32);
        image.fill(Qt::white);
        {
            QPainter painter(&image);
            plots.renderTo(painter, image.rect());
        }
        QVERIFY2(paintedPixels(image) > image.width() * image.height() / 4 / 20,
                 qPrintable(QString::number(paintedPixels(image))));
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString pdf = dir.filePath("signals.pdf");
        QVERIFY(plots.plot()->savePdf(pdf, 800, 600));
        QVERIFY(QFileInfo(pdf).size() > 1000);
    }

    void decimatedDrawingKeepsASpikeAndZoomingInDrawsEverySample()
    {
        // Half an hour at 100 Hz, flat but for one sample of 25 m/s²: zoomed out, a few points per
        // pixel column are drawn and the spike is one of them; zoomed in to 2 s, every sample is.
        constexpr std::size_t kSamples = 180000, kSpike = 123457;
        constexpr double kSpikeValue = 25.0;
        auto recording = std::make_shared<Recording>();
        for (std::size_t k = 0; k < kSamples; ++k) {
            ImuSample sample;
            sample.time_s = 0.01 * static_cast<double>(k);
            sample.acc_mps2 = Eigen::Vector3d(k == kSpike ? kSpikeValue : 0.1, 0.0, 9.81);
            sample.gyr_radps = Eigen::Vector3d::Zero();
            recording->samples.push_back(sample);
        }
        SignalPlots plots;
        plots.setRecording(recording);
        QVERIFY(showLaidOut(plots));
        const auto* accX = dynamic_cast<const DecimatedGraph*>(plots.graph(Channel::AccX));
        QVERIFY(accX);
        const double spike_s = recording->samples[kSpike].time_s;

        const QVector<QCPGraphData> zoomedOut = accX->drawnData();
        const int columns = plots.axisRect(Row::Acceleration)->width();
        QVERIFY2(zoomedOut.size() <= 4 * columns + 8, qPrintable(QString::number(zoomedOut.size())));
        const auto peak = std::max_element(zoomedOut.begin(), zoomedOut.end(),
                                           [](const QCPGraphData& a, const QCPGraphData& b) { return a.value < b.value; });
        QCOMPARE(peak->value, kSpikeValue);
        const double secondsPerColumn = 1800.0 / columns;
        QVERIFY2(std::abs(peak->key - spike_s) <= 2.0 * secondsPerColumn, qPrintable(QString::number(peak->key)));

        plots.setTimeRange(spike_s - 1.0, spike_s + 1.0);
        plots.plot()->replot();
        const QVector<QCPGraphData> zoomedIn = accX->drawnData();
        std::size_t inRange = 0;
        for (std::size_t k = kSpike - 100; k <= kSpike + 100; ++k, ++inRange) {
            const ImuSample& sample = recording->samples[k];
            const bool drawn = std::any_of(zoomedIn.begin(), zoomedIn.end(), [&sample](const QCPGraphData& point) {
                return point.key == sample.time_s && point.value == sample.acc_mps2.x();
            });
            QVERIFY2(drawn, qPrintable(QString::number(sample.time_s)));
        }
        QVERIFY(static_cast<std::size_t>(zoomedIn.size()) >= inRange);
    }

    void emptyRecordingDoesNotCrash()
    {
        SignalPlots plots;
        plots.setRecording(std::make_shared<const Recording>());
        plots.setResult(std::make_shared<const Result>());
        plots.setRecording(nullptr);
        QTest::keyClick(&plots, Qt::Key_Home);
        QVERIFY(!plots.grab().isNull());
        QVERIFY(plots.graph(Channel::AccX)->data()->isEmpty());
    }

    /// Not a pass/fail check (machines differ): prints the time a 30-minute recording takes.
    void halfHourRecordingTiming()
    {
        WalkSimulatorConfig config;
        config.withPressure = true;
        const double walkingSpeed_mps = config.strideLength_m / (config.stanceDuration_s + config.swingDuration_s);
        const SimulatedWalk walk = simulateWalk(straightLinePath(30.0 * 60.0 * walkingSpeed_mps), config);
        auto recording = std::make_shared<const Recording>(walk.recording);
        auto result = std::make_shared<Result>();
        for (const ImuSample& sample : recording->samples)
            result->time_s.push_back(sample.time_s);
        result->flags = detectStance(recording->samples, Parameters());

        SignalPlots plots;
        QVERIFY(showLaidOut(plots));  // a hidden plot may be laid out tiny and draw next to nothing
        qInfo("plot area %dx%d px", plots.plot()->width(), plots.plot()->height());
        QElapsedTimer timer;
        timer.start();
        plots.setRecording(recording);
        plots.plot()->replot();
        const qint64 recording_ms = timer.restart();
        plots.setResult(result);
        plots.plot()->replot();
        const qint64 result_ms = timer.restart();
        plots.setTimeRange(600.0, 660.0);
        plots.plot()->replot();
        const qint64 zoom_ms = timer.restart();
        plots.setTimeCursor(630.0);
        const qint64 cursor_ms = timer.elapsed();
        qInfo("%zu samples (%.1f min): setRecording+replot %lld ms, setResult+replot %lld ms, "
              "zoom+replot %lld ms, cursor %lld ms",
              recording->samples.size(), recording->duration_s() / 60.0, static_cast<long long>(recording_ms),
              static_cast<long long>(result_ms), static_cast<long long>(zoom_ms), static_cast<long long>(cursor_ms));
        QVERIFY(recording->duration_s() >= 29.0 * 60.0);
        QCOMPARE(static_cast<std::size_t>(plots.graph(Channel::Height)->dataCount()), recording->samples.size());
    }
};

QTEST_MAIN(TestSignalPlots)
#include "tst_signalplots.moc"
