#include "DetectorInputRows.h"

#include "DecimatedGraph.h"
#include "StanceFlagsPlotAxes.h"

#include "detect/StanceDetector.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

using Input = DetectorInputRows::Input;

constexpr double kBandHeadroom = 1.5;  // |a| row: this many band widths above and below the band
constexpr double kMinimumAccBand_mps2 = 0.5;  // framing for (invalid) parameters with no band
constexpr double kThresholdHeadroom = 3.0;    // std and |w| rows: from 0 to at least this many thresholds
constexpr double kDataShare = 0.99;  // input rows hold this share of the samples; rarer peaks run off the top
constexpr double kValueMargin = 1.05;  // air above the data an input row holds

struct InputInfo {
    const char* name;
    const char* axisLabel;
};

constexpr std::array<InputInfo, DetectorInputRows::kInputCount> kInputInfos = {{
    {QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "|a|"), QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "|a|\n(m/s²)")},
    {QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "std of |a|"), QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "std of |a|\n(m/s²)")},
    {QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "|ω|"), QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "|ω|\n(rad/s)")},
}};

struct ThresholdInfo {
    Input input;           // the row whose curve it bounds
    const char* nameUnit;  // "%1" is the value
    double Parameters::*value;
    QColor colour;
    Qt::PenStyle style;
};

const std::array<ThresholdInfo, DetectorInputRows::kThresholdCount>& thresholdInfos()
{
    static const std::array<ThresholdInfo, DetectorInputRows::kThresholdCount> infos = {{
        {Input::AccNorm, QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "min |a| = %1 m/s²"), &Parameters::acc_min_mps2,
         QColor(30, 80, 190), Qt::DashLine},
        {Input::AccNorm, QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "max |a| = %1 m/s²"), &Parameters::acc_max_mps2,
         QColor(200, 40, 40), Qt::DashDotLine},
        {Input::AccStdDev, QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "max std = %1 m/s²"),
         &Parameters::acc_std_max_mps2, QColor(200, 40, 40), Qt::DashDotLine},
        {Input::GyrNorm, QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "max |ω| = %1 rad/s"), &Parameters::gyr_max_radps,
         QColor(200, 40, 40), Qt::DashDotLine},
    }};
    return infos;
}

std::size_t slot(Input input) { return static_cast<std::size_t>(input); }

/// The value below which share of the graph's finite values lie (0 for none).
double quantileOf(const QCPGraph* graph, double share)
{
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(graph->data()->size()));
    for (const QCPGraphData& point : *graph->data())
        if (std::isfinite(point.value))
            values.push_back(point.value);
    if (values.empty())
        return 0.0;
    const auto at = values.begin() + static_cast<std::ptrdiff_t>(share * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), at, values.end());
    return *at;
}

}  // namespace

DetectorInputRows::DetectorInputRows(QCustomPlot* plot, const std::array<QCPAxisRect*, kInputCount>& rects) : rects_(rects)
{
    for (std::size_t i = 0; i < kInputCount; ++i) {
        QCPAxisRect* rect = rects_[i];
        valueAxis(rect)->setLabel(tr(kInputInfos[i].axisLabel));
        inputs_[i] = new DecimatedGraph(timeAxis(rect), valueAxis(rect));
        inputs_[i]->setName(tr(kInputInfos[i].name));
        inputs_[i]->setPen(QPen(QColor(20, 20, 20), 1.0));
        inputs_[i]->setSelectable(QCP::stNone);
    }
    for (std::size_t t = 0; t < kThresholdCount; ++t) {
        const ThresholdInfo& info = thresholdInfos()[t];
        const QCPAxisRect* rect = rectOf(info.input);
        thresholds_[t] = plot->addGraph(timeAxis(rect), valueAxis(rect));
        thresholds_[t]->setPen(QPen(info.colour, 1.5, info.style));
        thresholds_[t]->setSelectable(QCP::stNone);
    }
}

void DetectorInputRows::setRecording(const Recording* recording)
{
    times_s_.clear();
    accNorm_.clear();
    std::vector<double> gyrNorm;
    if (recording) {
        for (const ImuSample& sample : recording->samples) {
            times_s_.push_back(sample.time_s);
            accNorm_.push_back(sample.acc_mps2.norm());
            gyrNorm.push_back(sample.gyr_radps.norm());
        }
    }
    const QVector<double> keys = toQVector(times_s_);
    inputs_[slot(Input::AccNorm)]->setData(keys, toQVector(accNorm_), true);
    inputs_[slot(Input::GyrNorm)]->setData(keys, toQVector(gyrNorm), true);
    measure(Input::AccNorm);
    measure(Input::GyrNorm);
    plotAccStdDev();
    plotThresholds();
    rescale();
}

void DetectorInputRows::setParameters(const Parameters& params)
{
    const bool windowChanged = params.window_half_s != params_.window_half_s;
    params_ = params;
    if (windowChanged)
        plotAccStdDev();  // rescaled below
    plotThresholds();
    rescale();
}

void DetectorInputRows::plotAccStdDev()
{
    // The detector's own function, so the curve is exactly what C2 compared.
    const std::vector<double> accStdDev = centredStdDev(times_s_, accNorm_, params_.window_half_s);
    inputs_[slot(Input::AccStdDev)]->setData(toQVector(times_s_), toQVector(accStdDev), true);
    measure(Input::AccStdDev);
}

void DetectorInputRows::measure(Input input)
{
    const QCPGraph* graph = inputs_[slot(input)];
    bulk_[slot(input)] = Bulk{quantileOf(graph, 1.0 - kDataShare), quantileOf(graph, kDataShare)};
}

void DetectorInputRows::plotThresholds()
{
    for (std::size_t t = 0; t < kThresholdCount; ++t) {
        const ThresholdInfo& info = thresholdInfos()[t];
        const double value = params_.*info.value;
        thresholds_[t]->setName(tr(info.nameUnit).arg(value));
        thresholds_[t]->data()->clear();
        if (!times_s_.empty()) {  // a horizontal line across the recording
            thresholds_[t]->addData(times_s_.front(), value);
            thresholds_[t]->addData(times_s_.back(), value);
        }
    }
}

void DetectorInputRows::rescale()
{
    // Each row holds its thresholds with room around them and the bulk of its data (a running
    // trial's std of |a| is many times a walking threshold); the rarest swing peaks run off the
    // top, which reads as "far above" all the same, rather than squashing the rest into a line.
    const double band = std::max(params_.acc_max_mps2 - params_.acc_min_mps2, kMinimumAccBand_mps2);
    const QCPGraph* accNorm = inputs_[slot(Input::AccNorm)];
    const double accLow = accNorm->data()->isEmpty() ? params_.acc_min_mps2 : bulk_[slot(Input::AccNorm)].low;
    valueAxis(rectOf(Input::AccNorm))
        ->setRange(std::max(0.0, std::min(params_.acc_min_mps2 - kBandHeadroom * band, accLow)),
                   std::max(params_.acc_max_mps2 + kBandHeadroom * band, bulk_[slot(Input::AccNorm)].high * kValueMargin));
    valueAxis(rectOf(Input::AccStdDev))
        ->setRange(0.0, std::max(kThresholdHeadroom * params_.acc_std_max_mps2, bulk_[slot(Input::AccStdDev)].high * kValueMargin));
    valueAxis(rectOf(Input::GyrNorm))
        ->setRange(0.0, std::max(kThresholdHeadroom * params_.gyr_max_radps, bulk_[slot(Input::GyrNorm)].high * kValueMargin));
}

QCPGraph* DetectorInputRows::graph(Input input) const { return inputs_[slot(input)]; }
QCPGraph* DetectorInputRows::threshold(Threshold threshold) const { return thresholds_[static_cast<std::size_t>(threshold)]; }
QCPAxisRect* DetectorInputRows::rectOf(Input input) const { return rects_[slot(input)]; }

}  // namespace footpath
