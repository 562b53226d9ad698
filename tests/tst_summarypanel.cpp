#include "SummaryPanel.h"
#include "TestData.h"
#include "WarningOverlay.h"
#include "gait/GaitEvents.h"
#include "io/Import.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <QBarSeries>
#include <QBarSet>
#include <QChart>
#include <QChartView>
#include <QTabWidget>
#include <QGroupBox>
#include <QLabel>
#include <QLineSeries>
#include <QSignalSpy>
#include <QTableView>
#include <QtTest>

#include <cmath>
#include <numeric>

using namespace footpath;

namespace {

constexpr double kWalkLength_m = 20.0;

/// A 20 m straight walk: lround(20 / 1.4) = 14 equal strides of 20/14 m, each 0.45 s of stance
/// plus 0.65 s of swing.
struct EstimatedWalk {
    std::shared_ptr<const Recording> recording;
    std::shared_ptr<const Result> result;
    int trueStrides = 0;
};

const EstimatedWalk& straightWalk()
{
    static const EstimatedWalk walk = [] {
        const WalkSimulatorConfig config;
        SimulatedWalk simulated = simulateWalk(straightLinePath(kWalkLength_m), config);
        EstimatedWalk estimated;
        estimated.recording = std::make_shared<const Recording>(std::move(simulated.recording));
        estimated.result = std::make_shared<const Result>(runPipeline(*estimated.recording, Parameters()).result);
        estimated.trueStrides = static_cast<int>(std::lround(kWalkLength_m / config.strideLength_m));
        return estimated;
    }();
    return walk;
}

std::shared_ptr<const Recording> withoutReference(const Recording& recording)
{
    auto copy = std::make_shared<Recording>(recording);
    copy->reference = Reference();
    return copy;
}

QXYSeries* lineSeries(SummaryPanel& panel, const char* chartName)
{
    auto* view = panel.findChild<QChartView*>(chartName);
    if (!view || view->chart()->series().size() != 1)
        return nullptr;
    return qobject_cast<QLineSeries*>(view->chart()->series().first());
}

QBarSet* histogramBars(SummaryPanel& panel, const char* chartName)
{
    auto* view = panel.findChild<QChartView*>(chartName);
    if (!view || view->chart()->series().size() != 1)
        return nullptr;
    auto* bars = qobject_cast<QBarSeries*>(view->chart()->series().first());
    return bars && bars->count() == 1 ? bars->barSets().first() : nullptr;
}

double sum(const QBarSet& set)
{
    double total = 0.0;
    for (int i = 0; i < set.count(); ++i)
        total += set.at(i);
    return total;
}

bool figureShown(SummaryPanel& panel, const QString& key)
{
    auto* label = panel.findChild<QLabel*>(QStringLiteral("figure_") + key);
    return label && label->isVisibleTo(&panel);
}

/// The straight walk's result with a stride far too long in its middle and a whole-walk finding.
std::shared_ptr<const Result> withWarnings(std::size_t& markedStep)
{
    auto result = std::make_shared<Result>(*straightWalk().result);
    markedStep = result->steps.size() / 2;
    const Step& previous = result->steps[markedStep - 1];
    const Step& step = result->steps[markedStep];
    result->warnings = {
        {PlausibilityWarning::Kind::StanceRatio, 1.0, result->time_s.back(), "The foot is at rest 90 % of the time."},
        {PlausibilityWarning::Kind::StrideLength, previous.stanceEnd_s, step.stanceStart_s, "The stride to step 8 is 4.20 m long."},
    };
    return result;
}

QString figureText(SummaryPanel& panel, const QString& key)
{
    auto* label = panel.findChild<QLabel*>(QStringLiteral("figure_") + key);
    return label ? label->text() : QString();
}

}  // namespace

class TestSummaryPanel : public QObject {
    Q_OBJECT
private slots:
    void figuresMatchTheWalkedOnes()
    {
        const EstimatedWalk& walk = straightWalk();
        const Result& result = *walk.result;
        const GaitStatistics stats = computeGaitStatistics(result);
        QCOMPARE(static_cast<int>(stats.strides), walk.trueStrides);
        QCOMPARE(stats.stancePhases, result.steps.size());
        QCOMPARE(stats.strides, result.summary.steps);
        const double trueStride_m = kWalkLength_m / walk.trueStrides;
        QVERIFY2(std::abs(stats.meanStrideLength_m - trueStride_m) < 0.02, qPrintable(QString::number(stats.meanStrideLength_m)));
        // 0.45 s stance + 0.65 s swing = 1.1 s per stride, two steps (one per foot) per stride. The
        // first stride also holds the 2 s standing still before the walk: the median ignores it.
        QVERIFY2(std::abs(stats.medianStrideDuration_s - 1.1) < 0.005, qPrintable(QString::number(stats.medianStrideDuration_s)));
        QVERIFY(stats.meanStrideDuration_s > 1.15);
        QVERIFY2(std::abs(stats.cadence_stepsPerMin - 120.0 / 1.1) < 0.5, qPrintable(QString::number(stats.cadence_stepsPerMin)));
        QCOMPARE(stats.strideRate_perMin, stats.cadence_stepsPerMin / 2.0);
        QCOMPARE(stats.pathLength_m, result.summary.pathLength_m);
    }

    void figuresEqualTheOnesComputedByHandFromTheSteps()
    {
        const Result& result = *straightWalk().result;
        const GaitStatistics stats = computeGaitStatistics(result);
        double lengthSum = 0.0;
        double durationSum = 0.0;
        for (std::size_t k = 1; k < result.steps.size(); ++k) {
            lengthSum += result.steps[k].strideLength_m;
            durationSum += result.steps[k].strideDuration_s;
        }
        const double n = static_cast<double>(result.steps.size() - 1);
        const double meanLength = lengthSum / n;
        double squares = 0.0;
        for (std::size_t k = 1; k < result.steps.size(); ++k)
            squares += std::pow(result.steps[k].strideLength_m - meanLength, 2);
        QVERIFY(std::abs(stats.meanStrideLength_m - meanLength) < 1e-12);
        QVERIFY(std::abs(stats.strideLengthStd_m - std::sqrt(squares / (n - 1.0))) < 1e-12);
        QVERIFY(std::abs(stats.meanStrideDuration_s - durationSum / n) < 1e-12);
        std::vector<double> durations;
        for (std::size_t k = 1; k < result.steps.size(); ++k)
            durations.push_back(result.steps[k].strideDuration_s);
        std::sort(durations.begin(), durations.end());
        const std::size_t half = durations.size() / 2;
        const double medianDuration =
            durations.size() % 2 ? durations[half] : (durations[half - 1] + durations[half]) / 2.0;
        QCOMPARE(stats.medianStrideDuration_s, medianDuration);
        QVERIFY(std::abs(stats.cadence_stepsPerMin - 120.0 / medianDuration) < 1e-9);
        const double stanceSum = std::accumulate(result.steps.begin(), result.steps.end(), 0.0,
                                                 [](double s, const Step& step) { return s + step.stanceEnd_s - step.stanceStart_s; });
        QVERIFY(std::abs(stats.meanStanceDuration_s - stanceSum / static_cast<double>(result.steps.size())) < 1e-12);
    }

    void thePanelShowsTheFigures()
    {
        const EstimatedWalk& walk = straightWalk();
        SummaryPanel panel;
        panel.setResult(walk.result);
        const GaitStatistics& stats = panel.statistics();
        QVERIFY(figureText(panel, "cadence").contains(QLocale().toString(stats.cadence_stepsPerMin, 'f', 0)));
        QVERIFY(figureText(panel, "strideLength").contains(QLocale().toString(stats.meanStrideLength_m, 'f', 3)));
        QVERIFY(figureText(panel, "strides").contains(QString::number(walk.trueStrides)));
        QVERIFY(figureText(panel, "pathLength").contains(QLocale().toString(walk.result->summary.pathLength_m, 'f', 2)));
    }

    void theGaitFiguresAreTheResultsGaitMeans()
    {
        const EstimatedWalk& walk = straightWalk();
        const GaitSummary& gait = walk.result->gait;
        QVERIFY(gait.straightStrides > 5);
        SummaryPanel panel;
        panel.setResult(walk.result);
        QVERIFY(panel.findChild<QGroupBox*>(QStringLiteral("gaitFigures"))->isVisibleTo(&panel));
        QCOMPARE(figureText(panel, "gaitStrides"), QStringLiteral("%1 (%2 turning)").arg(gait.strides).arg(gait.turningStrides));
        QCOMPARE(figureText(panel, "gaitStrideTime"), QLocale().toString(gait.strideTime_s, 'f', 3) + QStringLiteral(" s"));
        QCOMPARE(figureText(panel, "gaitStanceSwing"), QLocale().toString(gait.stancePct, 'f', 1) + QStringLiteral(" % / ")
                                                           + QLocale().toString(gait.swingPct, 'f', 1) + QStringLiteral(" %"));
        // Both feet only when set, and not under a live session.
        auto* bothFeet = panel.findChild<QGroupBox*>(QStringLiteral("bothFeet"));
        QVERIFY(!bothFeet->isVisibleTo(&panel));
        const BilateralGait both = analyseBilateralGait(*walk.result, *walk.result);  // one foot twice: symmetric
        panel.setBothFeet(both);
        QVERIFY(bothFeet->isVisibleTo(&panel));
        QCOMPARE(figureText(panel, "symmetryStrideLength"), QLocale().toString(0.0, 'f', 1) + QStringLiteral(" %"));
        panel.showLive(walk.result);
        QVERIFY(!bothFeet->isVisibleTo(&panel));
        panel.showRecorded();
        QVERIFY(bothFeet->isVisibleTo(&panel));
        panel.setBothFeet(std::nullopt);
        QVERIFY(!bothFeet->isVisibleTo(&panel));
    }

    void theTableHasOneSortableRowPerStep()
    {
        const Result& result = *straightWalk().result;
        SummaryPanel panel;
        panel.setResult(straightWalk().result);
        auto* table = panel.findChild<QTableView*>("stepTable");
        QVERIFY(table);
        QAbstractItemModel* model = table->model();
        QCOMPARE(static_cast<std::size_t>(model->rowCount()), result.steps.size());
        // With Motion and Baro height (hidden without pressure), then the gait stride's heel strike,
        // toe off, stance % and clearance.
        QCOMPARE(model->columnCount(), 15);
        QCOMPARE(model->headerData(11, Qt::Horizontal).toString(), QStringLiteral("Heel strike (s)"));
        const std::vector<const GaitStride*> strides = gaitStridesOfSteps(result);
        int withStride = 0;
        for (int row = 0; row < model->rowCount(); ++row) {
            const GaitStride* stride = strides[std::size_t(row)];
            const double heelStrike = model->index(row, 11).data(Qt::UserRole).toDouble();
            withStride += stride != nullptr;
            QVERIFY(stride ? heelStrike == stride->heelStrike.time_s : std::isnan(heelStrike));
            if (stride)
                QCOMPARE(model->index(row, 13).data(Qt::UserRole).toDouble(), stride->stancePct);
        }
        QVERIFY(withStride >= model->rowCount() - 2);  // all but the first and last stance
        constexpr int strideColumn = 4;
        table->sortByColumn(strideColumn, Qt::DescendingOrder);
        for (int row = 1; row < model->rowCount(); ++row)
            QVERIFY(model->index(row - 1, strideColumn).data(Qt::UserRole).toDouble()
                    >= model->index(row, strideColumn).data(Qt::UserRole).toDouble());
        // The first stance ends no stride: shown as a dash, not as a 0 m stride.
        table->sortByColumn(0, Qt::AscendingOrder);
        QCOMPARE(model->index(0, strideColumn).data().toString(), QStringLiteral("\u2013"));
    }

    void theChartsHaveOnePointOrBarPerStrideOrStance()
    {
        const GaitStatistics stats = computeGaitStatistics(*straightWalk().result);
        SummaryPanel panel;
        panel.setResult(straightWalk().result);
        QXYSeries* strideLengths = lineSeries(panel, "strideLengthChart");
        QXYSeries* stanceDurations = lineSeries(panel, "stanceDurationChart");
        QVERIFY(strideLengths && stanceDurations);
        QCOMPARE(static_cast<std::size_t>(strideLengths->count()), stats.strides);
        QCOMPARE(static_cast<std::size_t>(stanceDurations->count()), stats.stancePhases);
        QCOMPARE(strideLengths->at(0).y(), straightWalk().result->steps[1].strideLength_m);
        QBarSet* strideBars = histogramBars(panel, "strideLengthHistogram");
        QBarSet* stanceBars = histogramBars(panel, "stanceDurationHistogram");
        QVERIFY(strideBars && stanceBars);
        QCOMPARE(sum(*strideBars), static_cast<double>(stats.strides));
        QCOMPARE(sum(*stanceBars), static_cast<double>(stats.stancePhases));
        // The gait tab: one point per gait stride.
        const std::vector<GaitStride>& strides = straightWalk().result->gaitStrides;
        QXYSeries* gaitStance = lineSeries(panel, "gaitStanceChart");
        QXYSeries* clearance = lineSeries(panel, "clearanceChart");
        QVERIFY(gaitStance && clearance && !strides.empty());
        QCOMPARE(std::size_t(gaitStance->count()), strides.size());
        QCOMPARE(gaitStance->at(0).y(), strides.front().stancePct);
        QCOMPARE(clearance->at(clearance->count() - 1).y(), strides.back().clearance_m);
    }

    void chartsBehindTheStepTableAreFilledWhenTheirTabIsShown()
    {
        // On screen with the step table in front, a new result leaves the charts for later; the
        // tab brought to the front shows the new result's steps, not the old one's.
        SummaryPanel panel;
        panel.resize(1000, 400);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        auto* tabs = panel.findChild<QTabWidget*>(QStringLiteral("summaryTabs"));
        QVERIFY(tabs);
        QCOMPARE(tabs->currentIndex(), 0);
        auto firstSteps = std::make_shared<Result>(*straightWalk().result);
        firstSteps->steps.resize(3);
        panel.setResult(firstSteps);
        panel.setResult(straightWalk().result);
        QXYSeries* before = lineSeries(panel, "strideLengthChart");
        QVERIFY(!before || static_cast<std::size_t>(before->count()) <= 2);  // not filled for either yet, or the first
        tabs->setCurrentIndex(1);
        QXYSeries* strideLengths = lineSeries(panel, "strideLengthChart");
        QVERIFY(strideLengths);
        QCOMPARE(static_cast<std::size_t>(strideLengths->count()), computeGaitStatistics(*straightWalk().result).strides);
    }

    void histogramsUseNiceBinsAndCountEveryValue()
    {
        // Quartiles 1.13 and 1.27: the fences at -/+ 3 IQR (0.42) leave 1.91 above the bins. The
        // other four span 0.26; over 5 bins that is 0.052, rounded up to 0.1, edges on multiples.
        const Histogram h = makeHistogram({1.01, 1.13, 1.22, 1.27, 1.91}, 0.01);
        QCOMPARE(h.binWidth, 0.1);
        QVERIFY(std::abs(h.firstEdge - 1.0) < 1e-12);
        QCOMPARE(h.counts, (std::vector<int>{1, 1, 2}));
        QCOMPARE(h.below, 0);
        QCOMPARE(h.above, 1);
        QVERIFY(std::abs(h.lastEdge() - 1.3) < 1e-12);
        QCOMPARE(h.total(), 5);

        const Histogram same = makeHistogram({1.4, 1.4, 1.4}, 0.01);  // no spread: one minimum-width bin
        QCOMPARE(same.binWidth, 0.01);
        QCOMPARE(same.counts, std::vector<int>{3});
        QCOMPARE(same.total(), 3);

        const Histogram even = makeHistogram({1.0, 2.0, 3.0, 4.0}, 0.01);  // values on edges go up
        QCOMPARE(even.binWidth, 1.0);  // 3 / 5 bins = 0.6, rounded up to 1
        QCOMPARE(even.counts, (std::vector<int>{1, 1, 1, 1}));

        const Histogram outliers = makeHistogram({0.0, 1.2, 1.21, 1.22, 1.23, 1.24, 9.0}, 0.01);
        QCOMPARE(outliers.below, 1);
        QCOMPARE(outliers.above, 1);
        QCOMPARE(outliers.total(), 7);

        QVERIFY(makeHistogram({}, 0.01).counts.empty());
        QCOMPARE(makeHistogram({1.0, std::nan(""), 1.5}, 0.01).total(), 2);
    }

    void referenceRowsAppearOnlyWithTheirReference()
    {
        const EstimatedWalk& walk = straightWalk();
        SummaryPanel panel;
        panel.setRecording(walk.recording);  // the simulator provides positions and the walked length
        panel.setResult(walk.result);
        QVERIFY(figureShown(panel, "armse2d"));
        QVERIFY(figureShown(panel, "armse3d"));
        QVERIFY(figureShown(panel, "distanceError"));
        QVERIFY(!figureShown(panel, "loopClosure"));   // a straight walk does not end at its start
        QVERIFY(!figureShown(panel, "stanceF1"));      // no labelled gait events
        const ArmseResult armse = computeArmse(walk.result->position_m, walk.recording->reference.positions_m);
        QVERIFY(panel.statistics().armse);
        QCOMPARE(panel.statistics().armse->armse2d_m, armse.armse2d_m);
        QVERIFY(figureText(panel, "armse2d").contains(QLocale().toString(armse.armse2d_m, 'f', 3)));

        panel.setRecording(withoutReference(*walk.recording));
        QVERIFY(!figureShown(panel, "armse2d"));
        QVERIFY(!figureShown(panel, "distanceError"));
        QVERIFY(figureShown(panel, "cadence"));
    }

    void loopClosureAndStanceScoresAppearWithTheirReference()
    {
        const SimulatedWalk loop = simulateWalk(closedRectanglePath(6.0, 3.0), WalkSimulatorConfig());
        auto recording = std::make_shared<Recording>(loop.recording);
        // Gait events from the simulator's truth: every run of swing samples is one swing.
        for (std::size_t k = 0; k < loop.trueStance.size();) {
            if (loop.trueStance[k]) {
                ++k;
                continue;
            }
            std::size_t end = k;
            while (end + 1 < loop.trueStance.size() && !loop.trueStance[end + 1])
                ++end;
            recording->reference.swings.push_back({k, end});
            k = end + 1;
        }
        const auto result = std::make_shared<const Result>(runPipeline(*recording, Parameters()).result);
        SummaryPanel panel;
        panel.setRecording(recording);
        panel.setResult(result);
        QVERIFY(figureShown(panel, "loopClosure"));
        QVERIFY(figureShown(panel, "stanceF1"));
        const StanceScore score = scoreStanceDetection(result->flags.stance, recording->reference.swings);
        QCOMPARE(panel.statistics().stanceScore->f1, score.f1);
        // The detector finds every simulated stance, inside the true one (its window trims the ends).
        QCOMPARE(score.detectedPhases, score.referencePhases);
        QVERIFY2(score.precision > 0.95, qPrintable(QString::number(score.precision)));
        QVERIFY(figureText(panel, "stanceF1").contains(QLocale().toString(score.f1, 'f', 3)));
    }

    void labelledWalkShowsTheGaitStanceFirstAndSaysWhatWasMerged()
    {
        // The shared IPOL walk whose first "stride" was a weight shift (0.006 m lasting 4.6 s):
        // against its labels the summary showed ZUPT precision / recall / F1 1.000 / 0.26 / 0.41
        // with no word, and a stride count that was not the labelled swings'.
        FOOTPATH_REQUIRE_DATASETS();
        ImportResult read = importRecording(datasetPath("xsens-mtw-ipol/1-1_lf.txt").toStdString());
        QVERIFY(read.ok());
        auto recording = std::make_shared<const Recording>(std::move(read.recording));
        const auto result = std::make_shared<const Result>(runPipeline(*recording, Parameters()).result);
        SummaryPanel panel;
        panel.setRecording(recording);
        panel.setResult(result);
        // The gait lab's figure comes first, and each row says what it compares.
        QVERIFY(figureShown(panel, "gaitStance"));
        const QStringList gaitFigures = figureText(panel, "gaitStance").split(QStringLiteral(" / "));
        QCOMPARE(gaitFigures.size(), 3);
        QVERIFY2(QLocale().toDouble(gaitFigures[2]) > 0.95, qPrintable(figureText(panel, "gaitStance")));
        auto* gaitName = panel.findChild<QLabel*>(QStringLiteral("figureName_gaitStance"));
        auto* restName = panel.findChild<QLabel*>(QStringLiteral("figureName_stanceF1"));
        QVERIFY(gaitName && restName);
        QVERIFY(gaitName->y() < restName->y());
        QVERIFY(restName->text().contains(QStringLiteral("ZUPT")));
        QVERIFY(restName->toolTip().contains(QStringLiteral("low by design")));
        // Strides against the labelled swings of the trial: equal.
        const StrideCount strides = *panel.statistics().strideCount;
        QCOMPARE(strides.labelled, std::size_t(17));
        QCOMPARE(strides.detected, strides.labelled);
        QCOMPARE(figureText(panel, "stancePhases"), QStringLiteral("17 detected, 17 labelled swings"));
        // The standing's weight shifts were merged into their stances, and the count says so.
        QVERIFY(!result->mergedMovements.empty());
        QVERIFY(result->mergedMovements.front().displacement_m < 0.02);
        QVERIFY(result->mergedMovements.front().end_s - result->mergedMovements.front().start_s > 0.4);
        QVERIFY2(figureText(panel, "strides").contains(QStringLiteral("merged")), qPrintable(figureText(panel, "strides")));
        auto* count = panel.findChild<QLabel*>(QStringLiteral("figure_strides"));
        QVERIFY(count->toolTip().contains(QStringLiteral("shifting the weight")));
        QCOMPARE(result->summary.steps, std::size_t(17));
        for (std::size_t i = 1; i < result->steps.size(); ++i)
            QVERIFY2(result->steps[i].strideLength_m > kMinStrideDistance_m * 0.5, qPrintable(QString::number(i)));
    }

    void aResultOfAnotherRecordingIsNotEvaluated()
    {
        // While a new recording's estimate runs, the old result must not be compared sample by
        // sample with the new reference.
        const SimulatedWalk other = simulateWalk(straightLinePath(5.0), WalkSimulatorConfig());
        SummaryPanel panel;
        panel.setRecording(std::make_shared<const Recording>(other.recording));
        panel.setResult(straightWalk().result);
        QVERIFY(!panel.statistics().armse);
        QVERIFY(!figureShown(panel, "armse2d"));
    }

    void warningsHeadTheFiguresAndMoveTheCursor()
    {
        std::size_t markedStep = 0;
        const std::shared_ptr<const Result> result = withWarnings(markedStep);
        SummaryPanel panel;
        auto* group = panel.findChild<QGroupBox*>("warnings");
        auto* none = panel.findChild<QLabel*>("noWarnings");
        QVERIFY(!group->isVisibleTo(&panel) && !none->isVisibleTo(&panel));  // no result: nothing to say

        panel.setResult(result);
        QVERIFY(group->isVisibleTo(&panel));
        QVERIFY(!none->isVisibleTo(&panel));
        QVERIFY(panel.findChild<QLabel*>("warningsTitle")->text().startsWith(QStringLiteral("2 ")));
        for (std::size_t i = 0; i < result->warnings.size(); ++i) {
            auto* label = panel.findChild<QLabel*>(QStringLiteral("warning_%1").arg(i));
            QVERIFY(label);
            QVERIFY(label->text().contains(QString::fromStdString(result->warnings[i].message).toHtmlEscaped()));
            QVERIFY2(label->text().contains(warningSpanText(result->warnings[i])), qPrintable(label->text()));
        }
        QSignalSpy requested(&panel, &SummaryPanel::timeCursorRequested);
        emit panel.findChild<QLabel*>("warning_1")->linkActivated(QStringLiteral("1"));  // its time span clicked
        QCOMPARE(requested.count(), 1);
        QCOMPARE(requested.first().first().toDouble(), result->warnings[1].start_s);

        panel.setResult(straightWalk().result);  // the same walk without findings
        QVERIFY(straightWalk().result->warnings.empty());
        QVERIFY(!group->isVisibleTo(&panel));
        QVERIFY(none->isVisibleTo(&panel));
        QVERIFY(!panel.findChild<QLabel*>("warning_0"));  // the old labels are gone
    }

    void aLiveSessionIsShownInPlaceOfTheRecordedWalkAndBack()
    {
        // The recorded walk (with a reference) is in the panel; a live session (with its warnings)
        // takes its place, a new recorded result meanwhile waits, and going back shows that one.
        const auto& walk = straightWalk();
        SummaryPanel panel;
        panel.setRecording(walk.recording);
        panel.setResult(walk.result);
        const double recordedPath_m = panel.statistics().pathLength_m;
        QVERIFY(panel.statistics().armse.has_value());
        RunFigures before, after;
        panel.showChange(&before, after, QStringLiteral("acc_std_max_mps2 0.5 -> 0.4"));
        auto* change = panel.findChild<QGroupBox*>("lastChange");
        QVERIFY(change->isVisibleTo(&panel));

        std::size_t markedStep = 0;
        auto live = std::make_shared<Result>(*withWarnings(markedStep));
        live->steps.resize(live->steps.size() / 2);  // a session half as far along
        live->summary.pathLength_m = recordedPath_m / 2.0;
        panel.showLive(live);
        QVERIFY(panel.isShowingLive());
        QCOMPARE(panel.statistics().pathLength_m, recordedPath_m / 2.0);
        QCOMPARE(panel.stepTable()->model()->rowCount(), static_cast<int>(live->steps.size()));
        QVERIFY(!panel.statistics().armse.has_value());  // the recorded walk's reference is not the session's
        QVERIFY(panel.findChild<QLabel*>("warningsTitle")->text().startsWith(QStringLiteral("2 ")));
        QVERIFY(panel.findChild<QLabel*>("liveSource")->isVisibleTo(&panel));
        QVERIFY(!change->isVisibleTo(&panel));  // a change of the recorded walk's parameters

        panel.setResult(walk.result);  // the recorded walk re-estimated meanwhile: kept, not shown
        QCOMPARE(panel.statistics().pathLength_m, recordedPath_m / 2.0);
        panel.showRecorded();
        QVERIFY(!panel.isShowingLive());
        QCOMPARE(panel.statistics().pathLength_m, recordedPath_m);
        QVERIFY(panel.statistics().armse.has_value());
        QVERIFY(change->isVisibleTo(&panel));
        QVERIFY(!panel.findChild<QLabel*>("liveSource")->isVisibleTo(&panel));
    }

    void stepsWhoseStrideOverlapsAWarningAreMarked()
    {
        std::size_t markedStep = 0;
        const std::shared_ptr<const Result> result = withWarnings(markedStep);
        // The stride of step k runs from the end of stance k-1 to the end of stance k: the long
        // stride's span marks its own row only, and the whole-walk finding marks none.
        QCOMPARE(warningsOfStep(*result, markedStep), std::vector<std::size_t>{1});
        QVERIFY(warningsOfStep(*result, markedStep - 1).empty());
        QVERIFY(warningsOfStep(*result, markedStep + 1).empty());

        SummaryPanel panel;
        panel.setResult(result);
        auto* table = panel.findChild<QTableView*>("stepTable");
        QAbstractItemModel* model = table->model();
        table->sortByColumn(0, Qt::AscendingOrder);
        for (int row = 0; row < model->rowCount(); ++row) {
            const bool marked = static_cast<std::size_t>(row) == markedStep;
            for (int column : {0, 4})
                QCOMPARE(model->index(row, column).data(Qt::BackgroundRole).isValid(), marked);
            QCOMPARE(model->index(row, 0).data(Qt::DecorationRole).isValid(), marked);  // the warning icon
        }
        const auto index = model->index(static_cast<int>(markedStep), 2);
        QVERIFY(model->data(index, Qt::ToolTipRole).toString().contains(QStringLiteral("4.20 m")));

        // A click on a step asks for the time cursor at its stance.
        QSignalSpy requested(&panel, &SummaryPanel::timeCursorRequested);
        emit table->clicked(index);
        QCOMPARE(requested.count(), 1);
        QCOMPARE(requested.first().first().toDouble(), result->steps[markedStep].stanceStart_s);
    }

    void clearEmptiesEverything()
    {
        SummaryPanel panel;
        panel.setRecording(straightWalk().recording);
        panel.setResult(straightWalk().result);
        panel.clear();
        QCOMPARE(panel.findChild<QTableView*>("stepTable")->model()->rowCount(), 0);
        QVERIFY(panel.findChild<QChartView*>("strideLengthChart")->chart()->series().isEmpty());
        QVERIFY(panel.findChild<QChartView*>("strideLengthHistogram")->chart()->series().isEmpty());
        QCOMPARE(figureText(panel, "pathLength"), QStringLiteral("\u2013"));
        QVERIFY(!figureShown(panel, "armse2d"));
        panel.resize(900, 300);
        QVERIFY(!panel.grab().isNull());  // empty charts draw without crashing
    }
};

QTEST_MAIN(TestSummaryPanel)
#include "tst_summarypanel.moc"
