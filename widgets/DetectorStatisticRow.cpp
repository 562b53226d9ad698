#include "DetectorStatisticRow.h"

#include "DecimatedGraph.h"
#include "StanceFlagsPlotAxes.h"
#include "TimeBands.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace footpath {

namespace {

constexpr double kStatisticHeadroom_dec = 0.3;  // statistic row: air above and below the data, in decades
constexpr double kMinimumStatisticSpan_dec = 2.0;
const QColor kStanceBrush(250, 200, 110, 90);  // SignalPlots' light amber
const QColor kThresholdColour(200, 40, 40);

/// The decades the finite values of both series span (log10 values), or nothing if none is finite.
std::optional<QCPRange> finiteSpan(const std::vector<float>& a, const std::vector<float>& b)
{
    double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
    for (const std::vector<float>* series : {&a, &b})
        for (const float value : *series)
            if (std::isfinite(value)) {
                lowest = std::min(lowest, static_cast<double>(value));
                highest = std::max(highest, static_cast<double>(value));
            }
    if (lowest > highest)
        return std::nullopt;
    return QCPRange(lowest, highest);
}

/// A log10 value as the log axis plots it; -inf (a statistic of exactly 0) sits on the axis' floor
/// rather than leaving a gap, +inf on its ceiling. 2^(x log2 10), not pow(10, x): the same value
/// to about 1e-15, at 40 % of the time (1.9 -> 0.7 ms for a 30-minute walk's statistic).
double plottedValue(float logValue, const QCPRange& decades)
{
    if (std::isnan(logValue))
        return std::numeric_limits<double>::quiet_NaN();
    constexpr double kLog2Of10 = 3.32192809488736234787;
    return std::exp2(kLog2Of10 * std::clamp(static_cast<double>(logValue), decades.lower, decades.upper));
}

}  // namespace

DetectorStatisticRow::DetectorStatisticRow(QCustomPlot* plot, QCPAxisRect* rect, const QString& stanceLayer) : rect_(rect)
{
    QCPAxis* axis = valueAxis(rect);
    axis->setScaleType(QCPAxis::stLogarithmic);
    auto ticker = QSharedPointer<QCPAxisTickerLog>::create();
    ticker->setLogBase(10.0);
    ticker->setSubTickCount(0);  // nine sub-ticks per decade would crowd a row spanning many decades
    axis->setTicker(ticker);
    axis->setNumberFormat(QStringLiteral("eb"));  // 10 with a superscript exponent
    axis->setNumberPrecision(0);
    stance_ = new TimeBands(rect, kStanceBrush);
    stance_->setLayer(stanceLayer);
    statistic_ = new DecimatedGraph(timeAxis(rect), axis);
    statistic_->setPen(QPen(QColor(20, 20, 20), 1.0));
    statistic_->setSelectable(QCP::stNone);
    threshold_ = plot->addGraph(timeAxis(rect), axis);
    threshold_->setLineStyle(QCPGraph::lsStepLeft);
    threshold_->setPen(QPen(kThresholdColour, 1.5));
    threshold_->setSelectable(QCP::stNone);
    stanceLegendEntry_ = plot->addGraph(timeAxis(rect), unitAxis(rect));
    stanceLegendEntry_->setName(tr("Stance"));
    stanceLegendEntry_->setPen(Qt::NoPen);
    stanceLegendEntry_->setBrush(kStanceBrush);
}

void DetectorStatisticRow::plotStatistic(const Result* result)
{
    statistic_->data()->clear();
    threshold_->data()->clear();
    if (!result)
        return;
    const StanceFlags& flags = result->flags;
    const std::optional<QCPRange> span = finiteSpan(flags.logStatistic, flags.logThreshold);
    if (!span)
        return;
    // Whole decades around the data, so the axis follows this recording and detector.
    const double lowest = std::floor(span->lower - kStatisticHeadroom_dec);
    const double highest = std::max(std::ceil(span->upper + kStatisticHeadroom_dec), lowest + kMinimumStatisticSpan_dec);
    const QCPRange decades(lowest, highest);
    const std::vector<double>& times = result->time_s;
    // Filled as QCPGraphData and handed over whole: the container shares the vector.
    QVector<QCPGraphData> statistic;
    QVector<double> thresholdKeys, threshold;
    const std::size_t n = std::min({times.size(), flags.logStatistic.size(), flags.logThreshold.size()});
    statistic.reserve(static_cast<qsizetype>(n));
    for (std::size_t k = 0; k < n; ++k) {
        statistic.append(QCPGraphData(times[k], plottedValue(flags.logStatistic[k], decades)));
        // A fixed threshold is two points; an adaptive one a point wherever it moves.
        if (k == 0 || k + 1 == n || flags.logThreshold[k] != flags.logThreshold[k - 1]) {
            thresholdKeys << times[k];
            threshold << plottedValue(flags.logThreshold[k], decades);
        }
    }
    statistic_->setSeries(statistic, coarseEnvelope(statistic));
    threshold_->setData(thresholdKeys, threshold, true);
    valueAxis(rect_)->setRange(std::pow(10.0, lowest), std::pow(10.0, highest));
}

void DetectorStatisticRow::shadeStance(const Result* result)
{
    stance_->setSpans(result ? flaggedSpans(result->time_s, result->flags.stance) : std::vector<QCPRange>());
    stanceLegendEntry_->setVisible(!stance_->isEmpty());
}

void DetectorStatisticRow::name(const Parameters& params, bool paperDetector)
{
    // The paper's detector plots its C2 input; a statistic detector its statistic, named by the
    // detector's own name in the parameter list (a new detector is named without an edit here).
    const ParameterField* detector = findParameterField("detector");
    const auto kind = static_cast<std::size_t>(params.detector);
    const QString label =
        paperDetector || !detector || kind >= detector->choiceNames.size()
            ? tr("std of |a|\n(m/s²)")
            : tr("%1\nstatistic").arg(QString::fromUtf8(detector->choiceNames[kind]).toUpper());
    valueAxis(rect_)->setLabel(label);
    statistic_->setName(QString(label).replace(QLatin1Char('\n'), QLatin1Char(' ')));
    if (paperDetector)
        threshold_->setName(tr("max std = %1 m/s²").arg(params.acc_std_max_mps2));
    else if (params.zv_adaptive)
        threshold_->setName(tr("threshold (adaptive)"));
    else
        threshold_->setName(tr("threshold = 10^%1").arg(params.zv_log_threshold));
}

bool DetectorStatisticRow::isStanceShaded(double time_s) const { return stance_->contains(time_s); }

std::vector<QCPAbstractPlottable*> DetectorStatisticRow::legendEntries() const { return {threshold_, stanceLegendEntry_}; }

}  // namespace footpath
