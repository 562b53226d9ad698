#include "LegendChecks.h"
#include "PlotInteraction.h"
#include "StatePlots.h"
#include "DecimatedGraph.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <QSignalSpy>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <tuple>

using namespace footpath;
using Row = StatePlots::Row;

namespace {

constexpr std::size_t kSamples = 500;
constexpr double kPi = 3.14159265358979323846;

/// A result with known states and standard deviations: velocity x ramps with σ 0.2 m/s, roll is
/// 10° with σ 0.01 rad, height 1.5 m with σ 0.05 m; the biases move (so they count as estimated).
std::shared_ptr<Result> knownResult(bool withCovariance)
{
    auto result = std::make_shared<Result>();
    for (std::size_t k = 0; k < kSamples; ++k) {
        const double t = static_cast<double>(k) / 100.0;
        result->time_s.push_back(t);
        result->position_m.emplace_back(0.0, 0.0, 1.5);
        result->velocity_mps.emplace_back(t, 0.0, 0.0);
        result->rollPitchYaw_rad.emplace_back(10.0 * kPi / 180.0, 0.0, 0.0);
        result->gyroBias_radps.emplace_back(1e-4 * t, 0.0, 0.0);
        result->accBias_mps2.emplace_back(1e-3 * t, 0.0, 0.0);
        result->flags.stance.push_back(k < 100 ? 1 : 0);
        if (!withCovariance)
            continue;
        Eigen::Matrix<float, 15, 1> sigma = Eigen::Matrix<float, 15, 1>::Constant(0.001f);
        sigma[ErrorStdIndex::velocity] = 0.2f;
        sigma[ErrorStdIndex::attitude] = 0.01f;
        sigma[ErrorStdIndex::position + 2] = 0.05f;
        result->errorStd.push_back(sigma);
    }
    return result;
}

/// Width of the band (upper - lower) and its centre at time_s.
std::pair<double, double> bandAt(const StatePlots& plots, Row row, int component, double time_s)
{
    const auto valueAt = [time_s](const QCPGraph* graph) { return graph->data()->findBegin(time_s, false)->value; };
    const double upper = valueAt(plots.bandUpper(row, component)), lower = valueAt(plots.bandLower(row, component));
    return {upper - lower, (upper + lower) / 2.0};
}

}  // namespace

class TestStatePlots : public QObject {
    Q_OBJECT

private slots:
    void aCoarseCopyDrawsTheSameEnvelope()
    {
        // 30 minutes at 100 Hz: a wave, noise, a one-sample spike each way and NaN gaps (wrapped
        // angles). Drawn zoomed out from the coarse copy, each pixel column spans what the full data
        // spans there, give or take the neighbouring columns; the extremes and the gaps are the
        // same; zoomed in, or with other data set, the points drawn are the full data's.
        QVector<QCPGraphData> data;
        std::uint32_t seed = 7;
        for (int k = 0; k < 180000; ++k) {
            seed = seed * 1664525u + 1013904223u;
            double value = std::sin(k * 0.003) + 0.2 * (static_cast<double>(seed >> 8) / double(1u << 24) - 0.5);
            if (k == 50001)
                value = 9.0;
            if (k == 120007)
                value = -7.0;
            if (k % 30011 == 0 && k > 0)
                value = std::numeric_limits<double>::quiet_NaN();
            data.append(QCPGraphData(k * 0.01, value));
        }
        QCustomPlot plot;
        plot.resize(1000, 300);
        plot.xAxis->setRange(0.0, 1800.0);
        plot.yAxis->setRange(-8.0, 10.0);
        auto* coarse = new DecimatedGraph(plot.xAxis, plot.yAxis);
        auto* full = new DecimatedGraph(plot.xAxis, plot.yAxis);
        coarse->setSeries(data, coarseEnvelope(data));
        full->data()->set(data, true);
        plot.replot();
        const QVector<QCPGraphData> fromCoarse = coarse->drawnData(), fromFull = full->drawnData();
        QVERIFY2(fromCoarse.size() < 5000, qPrintable(QString::number(fromCoarse.size())));
        // Each column's lowest and highest value drawn, by pixel column.
        std::map<int, std::pair<double, double>> coarseColumns, fullColumns;
        int coarseGaps = 0, fullGaps = 0;
        for (auto [points, columns, gaps] : {std::tuple{&fromCoarse, &coarseColumns, &coarseGaps},
                                              std::tuple{&fromFull, &fullColumns, &fullGaps}})
            for (const QCPGraphData& point : *points) {
                if (std::isnan(point.value)) {
                    ++*gaps;
                    continue;
                }
                const int column = static_cast<int>(std::floor(plot.xAxis->coordToPixel(point.key)));
                auto [it, added] = columns->try_emplace(column, point.value, point.value);
                it->second = {std::min(it->second.first, point.value), std::max(it->second.second, point.value)};
            }
        QCOMPARE(coarseGaps, fullGaps);
        QCOMPARE(coarseGaps, 5);
        const auto spanNear = [](const std::map<int, std::pair<double, double>>& columns, int column) {
            std::pair<double, double> span{HUGE_VAL, -HUGE_VAL};
            for (int c = column - 1; c <= column + 1; ++c)
                if (const auto it = columns.find(c); it != columns.end())
                    span = {std::min(span.first, it->second.first), std::max(span.second, it->second.second)};
            return span;
        };
        for (const auto& [ofThese, ofThose] : {std::pair{&coarseColumns, &fullColumns}, std::pair{&fullColumns, &coarseColumns}})
            for (const auto& [column, span] : *ofThese) {
                const auto near = spanNear(*ofThose, column);
                QVERIFY2(span.first >= near.first && span.second <= near.second, qPrintable(QString::number(column)));
            }
        double lowest = HUGE_VAL, highest = -HUGE_VAL;
        for (const QCPGraphData& point : fromCoarse)
            if (!std::isnan(point.value)) {
                lowest = std::min(lowest, point.value);
                highest = std::max(highest, point.value);
            }
        QCOMPARE(highest, 9.0);
        QCOMPARE(lowest, -7.0);
        // Drawn from the copy: every value drawn is one of its points' (the full data's adaptive
        // sampling also draws each column's first and last sample, most of them not in the copy).
        const QVector<QCPGraphData> envelope = coarseEnvelope(data, 16);
        std::vector<double> kept;
        for (const QCPGraphData& point : envelope)
            if (!std::isnan(point.value))  // the gaps' NaN would unsort the list
                kept.push_back(point.value);
        std::sort(kept.begin(), kept.end());
        const auto inCopy = [&kept](const QCPGraphData& point) {
            return std::isnan(point.value) || std::binary_search(kept.begin(), kept.end(), point.value);
        };
        QVERIFY(std::all_of(fromCoarse.begin(), fromCoarse.end(), inCopy));
        QVERIFY(!std::all_of(fromFull.begin(), fromFull.end(), inCopy));

        plot.xAxis->setRange(500.0, 520.0);  // 2,000 samples on 1,000 pixels: the full data
        plot.replot();
        QCOMPARE(coarse->drawnData().size(), full->drawnData().size());
        plot.xAxis->setRange(0.0, 1800.0);
        coarse->data()->set(data.mid(0, 90000), true);  // other data: the copy is not its own
        full->data()->set(data.mid(0, 90000), true);
        plot.replot();
        QCOMPARE(coarse->drawnData().size(), full->drawnData().size());
    }

    void bandsAreOneSigmaEitherSideFromErrorStd()
    {
        StatePlots plots;
        plots.setResult(knownResult(true));
        const auto [velocityWidth, velocityCentre] = bandAt(plots, Row::Velocity, 0, 2.0);
        QVERIFY(std::abs(velocityWidth - 0.4) < 1e-6);  // ±0.2 m/s
        QVERIFY(std::abs(velocityCentre - 2.0) < 1e-6);  // around the curve
        const auto [rollWidth, rollCentre] = bandAt(plots, Row::Attitude, 0, 1.0);
        QVERIFY(std::abs(rollWidth - 2.0 * 0.01 * 180.0 / kPi) < 1e-4);  // rad -> °, like the curve
        QVERIFY(std::abs(rollCentre - 10.0) < 1e-4);
        const auto [heightWidth, heightCentre] = bandAt(plots, Row::Height, 0, 3.0);
        QVERIFY(std::abs(heightWidth - 0.1) < 1e-6);
        QVERIFY(std::abs(heightCentre - 1.5) < 1e-6);
        QVERIFY(plots.rowNote(Row::Velocity).isEmpty());
        // The curves themselves, with the unit their row states.
        QCOMPARE(plots.graph(Row::Attitude, 0)->data()->findBegin(1.0, false)->value, 10.0);
        QVERIFY(plots.axisRect(Row::Attitude)->axis(QCPAxis::atLeft)->label().contains(QStringLiteral("°")));
        // The value axes hold curve and band.
        QVERIFY(plots.axisRect(Row::Velocity)->axis(QCPAxis::atLeft)->range().contains(-0.2));
        QVERIFY(plots.axisRect(Row::Velocity)->axis(QCPAxis::atLeft)->range().contains(4.99 + 0.2));
    }

    void withoutCovarianceTheRowsSaySoAndDrawNoBand()
    {
        StatePlots plots;
        plots.setResult(knownResult(false));  // as the Feliz estimator delivers it
        for (const Row row : {Row::Attitude, Row::Velocity, Row::Height, Row::GyroBias, Row::AccBias}) {
            QVERIFY(plots.bandUpper(row, 0)->data()->isEmpty());
            QVERIFY2(plots.rowNote(row).contains(QStringLiteral("covariance")), qPrintable(plots.rowNote(row)));
            QVERIFY(!plots.graph(row, 0)->data()->isEmpty());  // the estimate is still drawn
        }
    }

    void anglesAreDrawnAroundTheirMeanAndWrapsAreGaps()
    {
        // A sensor worn upside down: roll flickers between +179 and -179 degrees. Drawn around its
        // mean it is one curve near 180; yaw turning through whole circles has a gap at each wrap
        // (between the two samples, not a line through the row).
        auto result = knownResult(true);
        for (std::size_t k = 0; k < kSamples; ++k) {
            const double roll_deg = (k % 2 == 0 ? 179.0 : -179.0) + 0.5 * std::sin(0.1 * static_cast<double>(k));
            const double yaw_deg = std::remainder(3.0 * static_cast<double>(k), 360.0);  // 4 turns
            result->rollPitchYaw_rad[k] = Eigen::Vector3d(roll_deg, 5.0, yaw_deg) * kPi / 180.0;
        }
        StatePlots plots;
        plots.setResult(result);
        const QCPGraph* roll = plots.graph(Row::Attitude, 0);
        QCOMPARE(roll->dataCount(), static_cast<int>(kSamples));  // no gaps: it never wraps
        const double first = roll->data()->begin()->value;
        QVERIFY2(std::abs(std::abs(first) - 180.0) < 2.0, qPrintable(QString::number(first)));
        for (const QCPGraphData& point : *roll->data())  // one side of the turn: +180 or -180, not both
            QVERIFY2(std::abs(point.value - first) < 3.0, qPrintable(QString::number(point.value)));
        const QCPGraph* yaw = plots.graph(Row::Attitude, 2);
        int gaps = 0;
        double previousKey = -1.0, previousValue = std::nan("");
        for (const QCPGraphData& point : *yaw->data()) {
            QVERIFY(point.key > previousKey);  // strictly between its neighbours
            if (std::isnan(point.value))
                ++gaps;
            else if (!std::isnan(previousValue))
                QVERIFY2(std::abs(point.value - previousValue) < 10.0, qPrintable(QString::number(point.key)));
            previousKey = point.key;
            previousValue = point.value;
        }
        QVERIFY2(gaps >= 3 && gaps <= 5, qPrintable(QString::number(gaps)));
        // What a replot draws keeps every gap: no line across the row from one side of a wrap to the other.
        plots.resize(200, 500);  // under half as many pixel columns as samples: the curve is drawn decimated
        (void)plots.grab();
        const auto* drawnYaw = dynamic_cast<const DecimatedGraph*>(yaw);
        QVERIFY(drawnYaw);
        const QVector<QCPGraphData> drawn = drawnYaw->drawnData();
        QCOMPARE(std::count_if(drawn.begin(), drawn.end(), [](const QCPGraphData& p) { return std::isnan(p.value); }),
                 gaps);
        for (qsizetype i = 1; i < drawn.size(); ++i)
            QVERIFY2(std::isnan(drawn[i - 1].value) || std::isnan(drawn[i].value)
                         || std::abs(drawn[i].value - drawn[i - 1].value) < 180.0,
                     qPrintable(QString::number(drawn[i].key)));
    }

    void bandEdgesAreOnePointAPixelColumnAroundEverySample()
    {
        // A band over more samples than pixel columns is drawn as its envelope: in each column the
        // highest upper and the lowest lower edge, so its fill polygon stays small and still
        // covers every sample's ±1σ.
        auto result = knownResult(true);
        for (std::size_t k = 0; k < kSamples; ++k)
            result->velocity_mps[k].x() = std::sin(0.7 * static_cast<double>(k));  // faster than a column
        StatePlots plots;
        plots.setResult(result);
        plots.resize(200, 500);
        (void)plots.grab();
        for (const bool upper : {true, false}) {
            const auto* edge = dynamic_cast<const DecimatedGraph*>(upper ? plots.bandUpper(Row::Velocity, 0)
                                                                         : plots.bandLower(Row::Velocity, 0));
            QVERIFY(edge);
            const QCPAxis* time = edge->keyAxis();
            const QVector<QCPGraphData> drawn = edge->drawnData();
            QVERIFY(drawn.size() > 10);
            QVERIFY(drawn.size() <= plots.axisRect(Row::Velocity)->width() + 1);
            std::map<double, double> columnValue;
            for (const QCPGraphData& point : drawn) {
                const double column = std::floor(time->coordToPixel(point.key));
                QVERIFY2(!columnValue.count(column), "two points in one pixel column");
                columnValue[column] = point.value;
            }
            for (const QCPGraphData& point : *edge->data()) {
                const auto column = columnValue.find(std::floor(time->coordToPixel(point.key)));
                QVERIFY(column != columnValue.end());
                QVERIFY(upper ? point.value <= column->second : point.value >= column->second);
            }
        }
    }

    void constantBiasesAreNotPresentedAsEstimates()
    {
        auto result = knownResult(true);
        for (Eigen::Vector3d& bias : result->gyroBias_radps)
            bias.setZero();
        StatePlots plots;
        plots.setResult(result);
        QVERIFY(plots.rowNote(Row::GyroBias).contains(QStringLiteral("Not estimated")));
        QVERIFY(plots.bandUpper(Row::GyroBias, 0)->data()->isEmpty());
        QVERIFY(plots.rowNote(Row::AccBias).isEmpty());
        QVERIFY(!plots.bandUpper(Row::AccBias, 0)->data()->isEmpty());
    }

    void followsTheSharedTimeAxisAndCursor()
    {
        StatePlots plots;
        plots.setResult(knownResult(true));
        QSignalSpy ranges(&plots, &StatePlots::timeRangeChanged);
        plots.setTimeRange(1.0, 2.0);
        QCOMPARE(ranges.count(), 1);
        for (const Row row : {Row::Attitude, Row::AccBias})
            QCOMPARE(plots.axisRect(row)->axis(QCPAxis::atBottom)->range(), QCPRange(1.0, 2.0));
        plots.setTimeCursor(1.5);
        QCOMPARE(plots.timeCursor(), 1.5);
        plots.interaction()->resetView();
        QCOMPARE(plots.timeRange().upper, static_cast<double>(kSamples - 1) / 100.0);
    }

    void legendSitsAboveTheRowsWithEachLookOnce()
    {
        for (const int width : {330, 900}) {
            StatePlots plots;
            plots.setResult(knownResult(true));
            plots.resize(width, 420);
            plots.show();
            QVERIFY(QTest::qWaitForWindowExposed(&plots));
            plots.plot()->replot();
            const QString problem = legendProblem(plots.plot(), plots.legend());
            QVERIFY2(problem.isEmpty(), qPrintable(QStringLiteral("%1 px: %2").arg(width).arg(problem)));
            QVERIFY(plots.legend()->outerRect().bottom() <= plots.axisRect(Row::Attitude)->top());
            // Velocity's x/y/z pens are the biases': one entry each; roll, pitch and yaw have their own.
            QVERIFY(plots.legend()->hasItemWithPlottable(plots.graph(Row::Velocity, 0)));
            QVERIFY(!plots.legend()->hasItemWithPlottable(plots.graph(Row::AccBias, 0)));
            QVERIFY(plots.legend()->hasItemWithPlottable(plots.graph(Row::Attitude, 2)));
        }
    }

    void readoutNamesStateAndSigma()
    {
        StatePlots plots;
        plots.setResult(knownResult(true));
        plots.resize(900, 800);
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        plots.plot()->replot();
        const QCPAxisRect* rect = plots.axisRect(Row::Velocity);
        plots.interaction()->probeAt(QPointF(rect->axis(QCPAxis::atBottom)->coordToPixel(2.0), rect->center().y()));
        const QString readout = plots.interaction()->readoutText();
        QVERIFY2(readout.contains(QStringLiteral("σ x = 0.20")), qPrintable(readout));
        QVERIFY2(readout.contains(QStringLiteral("m/s")), qPrintable(readout));
    }

    void aSimulatedWalkHasBandsEverywhere()
    {
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(6.0, 3.0), WalkSimulatorConfig());
        auto result = std::make_shared<const Result>(runPipeline(walk.recording, Parameters()).result);
        QVERIFY(!result->errorStd.empty());
        StatePlots plots;
        plots.setResult(result);
        for (const Row row : {Row::Attitude, Row::Velocity, Row::Height}) {
            QVERIFY(!plots.bandUpper(row, 0)->data()->isEmpty());
            const auto [width, centre] = bandAt(plots, row, 0, result->time_s[result->time_s.size() / 2]);
            Q_UNUSED(centre);
            QVERIFY(width > 0.0);
        }
    }
};

QTEST_MAIN(TestStatePlots)
#include "tst_stateplots.moc"
