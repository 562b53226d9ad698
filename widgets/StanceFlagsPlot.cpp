#include "StanceFlagsPlot.h"

#include "TimeAxisNavigation.h"

#include "detect/StanceDetector.h"

#include <QApplication>
#include <QKeyEvent>
#include <QPicture>
#include <QToolBar>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

using Lane = StanceFlagsPlot::Lane;
using Input = StanceFlagsPlot::Input;
using Threshold = StanceFlagsPlot::Threshold;

constexpr double kLaneSpacing = 1.5;   // a lane is 1 high; the rest is the gap to the next
constexpr double kLaneMargin = 0.3;    // air above the top lane and below the bottom one
constexpr double kBandHeadroom = 1.5;  // |a| row: this many band widths above and below the band
constexpr double kMinimumAccBand_mps2 = 0.5;  // framing for (invalid) parameters with no band
constexpr double kThresholdHeadroom = 3.0;    // std and |w| rows: from 0 to this many thresholds
const QString kCursorLayer = QStringLiteral("cursor");
const QColor kCursorColour(170, 0, 0);

struct LaneInfo {
    const char* label;  // translated in the StanceFlagsPlot context
    QColor fill;
};

// Fills of clearly different lightness so the lanes also part on a black-and-white printout; the
// stance lane has SignalPlots' amber.
const std::array<LaneInfo, StanceFlagsPlot::kLaneCount>& laneInfos()
{
    static const std::array<LaneInfo, StanceFlagsPlot::kLaneCount> infos = {{
        {QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "C1: |a| in range"), QColor(170, 200, 235)},
        {QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "C2: |a| steady"), QColor(170, 220, 180)},
        {QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "C3: |ω| small"), QColor(215, 190, 230)},
        {QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "C = C1·C2·C3"), QColor(120, 120, 120)},
        {QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "Stance (median)"), QColor(240, 170, 60)},
    }};
    return infos;
}

struct InputInfo {
    const char* name;
    const char* axisLabel;
};

constexpr std::array<InputInfo, StanceFlagsPlot::kInputCount> kInputInfos = {{
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

const std::array<ThresholdInfo, StanceFlagsPlot::kThresholdCount>& thresholdInfos()
{
    static const std::array<ThresholdInfo, StanceFlagsPlot::kThresholdCount> infos = {{
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

std::size_t slot(Lane lane) { return static_cast<std::size_t>(lane); }
std::size_t slot(Input input) { return static_cast<std::size_t>(input); }
std::size_t slot(Threshold threshold) { return static_cast<std::size_t>(threshold); }
std::size_t rowOf(Input input) { return 1 + slot(input); }  // row 0 holds the lanes

const std::vector<std::uint8_t>& laneFlags(const StanceFlags& flags, Lane lane)
{
    switch (lane) {
    case Lane::C1: return flags.c1;
    case Lane::C2: return flags.c2;
    case Lane::C3: return flags.c3;
    case Lane::C: return flags.c;
    case Lane::Stance: break;
    }
    return flags.stance;
}

QCPAxis* timeAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atBottom); }
QCPAxis* valueAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atLeft); }
/// The hidden right axis spans 0..1 whatever the row shows: the cursor uses it to fill the height.
QCPAxis* unitAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atRight); }

QCPLegend* addRowLegend(QCPAxisRect* rect)
{
    auto* legend = new QCPLegend;
    rect->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
    legend->setLayer(QStringLiteral("legend"));
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);  // one line: rows are short
    legend->setIconSize(26, 10);
    legend->setColumnSpacing(6);
    legend->setBrush(QColor(255, 255, 255, 210));
    legend->setBorderPen(QPen(QColor(180, 180, 180)));
    QFont font = legend->font();
    font.setPointSizeF(font.pointSizeF() * 0.85);
    legend->setFont(font);
    return legend;
}

QCPItemStraightLine* addCursorLine(QCustomPlot* plot, QCPAxisRect* rect)
{
    auto* line = new QCPItemStraightLine(plot);
    line->setLayer(kCursorLayer);
    line->setClipToAxisRect(true);  // the default only when the plot had an axis rect already
    line->setClipAxisRect(rect);
    line->setSelectable(false);
    line->setPen(QPen(kCursorColour, 1.5));
    line->point1->setAxes(timeAxis(rect), unitAxis(rect));
    line->point2->setAxes(timeAxis(rect), unitAxis(rect));
    line->setVisible(false);
    return line;
}

QVector<double> toQVector(const std::vector<double>& values) { return QVector<double>(values.begin(), values.end()); }

/// Spans of consecutive set flags, each from its first sample to the sample after its last (as a
/// step plot draws them), so a one-sample flag still has a width.
std::vector<QCPRange> flaggedSpans(const std::vector<double>& times, const std::vector<std::uint8_t>& flags)
{
    std::vector<QCPRange> spans;
    const std::size_t n = std::min(times.size(), flags.size());
    for (std::size_t k = 0; k < n; ++k) {
        if (!flags[k] || (k > 0 && flags[k - 1]))
            continue;
        std::size_t end = k;
        while (end < n && flags[end])
            ++end;
        // A run up to the last sample reaches one sample interval past it, like any other run.
        const double lastInterval_s = n >= 2 ? times[n - 1] - times[n - 2] : 0.0;
        spans.emplace_back(times[k], end < n ? times[end] : times[n - 1] + lastInterval_s);
    }
    return spans;
}

}  // namespace

/// The filled part of a lane: rectangles between two levels over the spans where the flag is set,
/// merged where they touch in pixels. As a filled step curve (a QCPGraph with a brush) half an
/// hour of flags costs Qt's rasteriser about a second per lane: the polygon has thousands of edges.
class StanceFlagsPlot::LaneFill : public QCPLayerable {
public:
    LaneFill(QCPAxisRect* rect, double bottom, double top, const QBrush& brush)
        : QCPLayerable(rect->parentPlot(), QString(), rect), rect_(rect), bottom_(bottom), top_(top), brush_(brush)
    {
    }

    void setSpans(std::vector<QCPRange> spans) { spans_ = std::move(spans); }

protected:
    void applyDefaultAntialiasingHint(QCPPainter* painter) const override { painter->setAntialiasing(false); }
    QRect clipRect() const override { return rect_->rect(); }

    void draw(QCPPainter* painter) override
    {
        const QCPAxis* axis = rect_->axis(QCPAxis::atBottom);
        const QRect area = rect_->rect();
        auto span = std::lower_bound(spans_.cbegin(), spans_.cend(), axis->range().lower,
                                     [](const QCPRange& s, double t) { return s.upper < t; });
        double left = 0.0, right = -1.0;  // the band being merged, in pixels; empty while right < left
        for (; span != spans_.cend() && span->lower <= axis->range().upper; ++span) {
            const double from = std::max(std::floor(axis->coordToPixel(span->lower)), area.left() - 1.0);
            const double to = std::min(std::max(from + 1.0, std::ceil(axis->coordToPixel(span->upper))), area.right() + 1.0);
            if (from <= right) {
                right = std::max(right, to);
                continue;
            }
            fillBand(painter, left, right);
            left = from;
            right = to;
        }
        fillBand(painter, left, right);
    }

private:
    void fillBand(QCPPainter* painter, double left, double right) const
    {
        if (right <= left)
            return;
        const QCPAxis* levels = rect_->axis(QCPAxis::atLeft);
        const double top = levels->coordToPixel(top_);
        painter->fillRect(QRectF(left, top, right - left, levels->coordToPixel(bottom_) - top), brush_);
    }

    QCPAxisRect* rect_;
    double bottom_;
    double top_;
    QBrush brush_;
    std::vector<QCPRange> spans_;  ///< sorted, disjoint
};

StanceFlagsPlot::StanceFlagsPlot(QWidget* parent)
    : QWidget(parent), plot_(new QCustomPlot(this)), toolBar_(new QToolBar(tr("Detector"), this)),
      inputsAction_(toolBar_->addAction(tr("Show detector inputs")))
{
    setFocusPolicy(Qt::StrongFocus);  // keys arrive here; the plot passes clicks' focus up
    inputsAction_->setObjectName(QStringLiteral("showDetectorInputs"));
    inputsAction_->setCheckable(true);
    inputsAction_->setToolTip(tr("Plot |a|, its local standard deviation and |ω| with the detector's thresholds"));
    toolBar_->setMovable(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(toolBar_);
    layout->addWidget(plot_, 1);

    plot_->setAutoAddPlottableToLegend(false);
    plot_->setPlottingHint(QCP::phFastPolylines);  // solid pens wider than 1 px: segments, not a stroked path
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot_->addLayer(kCursorLayer, plot_->layer(QStringLiteral("legend")), QCustomPlot::limBelow);
    // Its own paint buffer: moving the cursor redraws one line per row, not the curves.
    plot_->layer(kCursorLayer)->setMode(QCPLayer::lmBuffered);
    plot_->plotLayout()->clear();  // drops the default axis rect: the rows below replace it
    plot_->plotLayout()->setRowSpacing(4);
    auto* alignedMargins = new QCPMarginGroup(plot_);  // time axes line up although labels differ
    for (RowParts& row : rows_) {
        row.rect = new QCPAxisRect(plot_);
        plot_->plotLayout()->addElement(plot_->plotLayout()->rowCount(), 0, row.rect);  // arrangeRows() sorts
        row.rect->setMarginGroup(QCP::msLeft | QCP::msRight, alignedMargins);
        unitAxis(row.rect)->setRange(0.0, 1.0);
        row.cursor = addCursorLine(plot_, row.rect);
    }
    createLanesRow();
    createInputRows();
    rescaleInputAxes();
    wireInteractions();
    arrangeRows();
}

StanceFlagsPlot::~StanceFlagsPlot()
{
    // Rows taken out of the layout would outlive it as bare children of the plot, whose QObject
    // clean-up runs after QCustomPlot's own; hand them back so it tears them down in its order.
    for (RowParts& row : rows_) {
        if (row.rect->layout() == nullptr)
            plot_->plotLayout()->addElement(plot_->plotLayout()->rowCount(), 0, row.rect);
    }
}

double StanceFlagsPlot::laneLevel(Lane lane, bool flag)
{
    const auto fromBottom = static_cast<double>(kLaneCount - 1 - static_cast<int>(lane));
    return fromBottom * kLaneSpacing + (flag ? 1.0 : 0.0);
}

void StanceFlagsPlot::createLanesRow()
{
    QCPAxisRect* rect = rows_.front().rect;
    auto ticker = QSharedPointer<QCPAxisTickerText>::create();
    for (std::size_t l = 0; l < kLaneCount; ++l)
        ticker->addTick(laneLevel(static_cast<Lane>(l), false) + 0.5, tr(laneInfos()[l].label));
    QCPAxis* axis = valueAxis(rect);
    axis->setTicker(ticker);
    axis->setTickLength(0, 0);
    axis->setSubTicks(false);
    axis->grid()->setVisible(false);  // grid lines would run through the middle of every lane
    axis->setRange(laneLevel(Lane::Stance, false) - kLaneMargin, laneLevel(Lane::C1, true) + kLaneMargin);
    for (std::size_t l = 0; l < kLaneCount; ++l) {
        const Lane lane = static_cast<Lane>(l);
        // Created before the outline, so drawn beneath it on the same layer.
        laneFills_[l] = new LaneFill(rect, laneLevel(lane, false), laneLevel(lane, true), laneInfos()[l].fill);
        laneFills_[l]->setLayer(QStringLiteral("main"));
        lanes_[l] = plot_->addGraph(timeAxis(rect), axis);
        lanes_[l]->setName(tr(laneInfos()[l].label));
        lanes_[l]->setLineStyle(QCPGraph::lsStepLeft);
        lanes_[l]->setPen(QPen(QColor(40, 40, 40), 1.0));
        lanes_[l]->setSelectable(QCP::stNone);
    }
}

void StanceFlagsPlot::createInputRows()
{
    std::array<QCPLegend*, kInputCount> legends{};
    for (std::size_t i = 0; i < kInputCount; ++i) {
        QCPAxisRect* rect = rows_[rowOf(static_cast<Input>(i))].rect;
        valueAxis(rect)->setLabel(tr(kInputInfos[i].axisLabel));
        inputs_[i] = plot_->addGraph(timeAxis(rect), valueAxis(rect));
        inputs_[i]->setName(tr(kInputInfos[i].name));
        inputs_[i]->setPen(QPen(QColor(20, 20, 20), 1.0));
        inputs_[i]->setSelectable(QCP::stNone);
        legends[i] = addRowLegend(rect);
        inputs_[i]->addToLegend(legends[i]);
    }
    for (std::size_t t = 0; t < kThresholdCount; ++t) {
        const ThresholdInfo& info = thresholdInfos()[t];
        const QCPAxisRect* rect = rows_[rowOf(info.input)].rect;
        thresholds_[t] = plot_->addGraph(timeAxis(rect), valueAxis(rect));
        thresholds_[t]->setPen(QPen(info.colour, 1.5, info.style));
        thresholds_[t]->setSelectable(QCP::stNone);
        thresholds_[t]->addToLegend(legends[slot(info.input)]);
    }
}

void StanceFlagsPlot::wireInteractions()
{
    timeRows_ = new LinkedTimeRows(plot_);
    for (const RowParts& row : rows_)
        timeRows_->addRow(row.rect);
    connect(timeRows_, &LinkedTimeRows::rangeChanged, this, &StanceFlagsPlot::timeRangeChanged);
    connect(timeRows_, &LinkedTimeRows::clicked, this, [this](double time_s) {
        setTimeCursor(time_s);
        emit timeCursorMoved(time_s);
    });
    connect(inputsAction_, &QAction::toggled, this, &StanceFlagsPlot::setInputsVisible);
}

void StanceFlagsPlot::setRecording(std::shared_ptr<const Recording> recording)
{
    result_.reset();
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
    plotAccStdDev();
    plotThresholds();
    plotLanes();
    showAll();
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void StanceFlagsPlot::setResult(std::shared_ptr<const Result> result)
{
    result_ = std::move(result);
    plotLanes();
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void StanceFlagsPlot::setParameters(const Parameters& params)
{
    const bool windowChanged = params.window_half_s != params_.window_half_s;
    params_ = params;
    if (windowChanged)
        plotAccStdDev();
    plotThresholds();
    rescaleInputAxes();
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void StanceFlagsPlot::plotLanes()
{
    const std::vector<double> noTimes;
    const std::vector<double>& times = result_ ? result_->time_s : noTimes;
    for (std::size_t l = 0; l < kLaneCount; ++l) {
        const Lane lane = static_cast<Lane>(l);
        const std::vector<std::uint8_t> noFlags;
        const std::vector<std::uint8_t>& flags = result_ ? laneFlags(result_->flags, lane) : noFlags;
        // Only the samples where the flag changes, plus the last: a step curve through them is the
        // flag at every sample, in thousands of points rather than 180k.
        QVector<double> keys, values;
        const std::size_t n = std::min(times.size(), flags.size());
        for (std::size_t k = 0; k < n; ++k) {
            if (k == 0 || k + 1 == n || flags[k] != flags[k - 1]) {
                keys << times[k];
                values << laneLevel(lane, flags[k] != 0);
            }
        }
        lanes_[l]->setData(keys, values, true);
        laneFills_[l]->setSpans(flaggedSpans(times, flags));
    }
}

void StanceFlagsPlot::plotAccStdDev()
{
    // The detector's own function, so the curve is exactly what C2 compared.
    const std::vector<double> accStdDev = centredStdDev(times_s_, accNorm_, params_.window_half_s);
    inputs_[slot(Input::AccStdDev)]->setData(toQVector(times_s_), toQVector(accStdDev), true);
}

void StanceFlagsPlot::plotThresholds()
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

void StanceFlagsPlot::rescaleInputAxes()
{
    // Framed around the thresholds rather than the data: swing peaks of 40 m/s² or 10 rad/s would
    // squash the band that decides stance into a line. Peaks run off the top, which reads as
    // "far above" all the same.
    const double band = std::max(params_.acc_max_mps2 - params_.acc_min_mps2, kMinimumAccBand_mps2);
    valueAxis(inputRect(Input::AccNorm))
        ->setRange(std::max(0.0, params_.acc_min_mps2 - kBandHeadroom * band), params_.acc_max_mps2 + kBandHeadroom * band);
    valueAxis(inputRect(Input::AccStdDev))->setRange(0.0, kThresholdHeadroom * params_.acc_std_max_mps2);
    valueAxis(inputRect(Input::GyrNorm))->setRange(0.0, kThresholdHeadroom * params_.gyr_max_radps);
}

void StanceFlagsPlot::setInputsVisible(bool visible)
{
    if (visible == inputsVisible_)
        return;
    inputsVisible_ = visible;
    inputsAction_->setChecked(visible);
    arrangeRows();
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void StanceFlagsPlot::arrangeRows()
{
    QCPLayoutGrid* layout = plot_->plotLayout();
    for (RowParts& row : rows_) {
        if (row.rect->layout() != nullptr)
            layout->take(row.rect);
    }
    layout->simplify();
    int shownCount = 0;
    for (std::size_t r = 0; r < kRowCount; ++r) {
        RowParts& row = rows_[r];
        const bool shown = r == 0 || inputsVisible_;
        // Out of the layout a row keeps its old geometry: hide it, or it would paint over the others.
        row.rect->setVisible(shown);
        row.cursor->setVisible(shown && cursorPlaced_);
        timeAxis(row.rect)->setTickLabels(false);
        timeAxis(row.rect)->setLabel(QString());
        if (shown)
            layout->addElement(shownCount++, 0, row.rect);
    }
    layout->setRowStretchFactor(0, 1.5);  // five lanes need more height than one curve
    QCPAxisRect* bottom = inputsVisible_ ? rows_.back().rect : rows_.front().rect;
    timeAxis(bottom)->setTickLabels(true);  // one time scale at the foot of the stack is enough
    timeAxis(bottom)->setLabel(tr("Time (s)"));
}

QCPAxisRect* StanceFlagsPlot::lanesRect() const { return rows_.front().rect; }
QCPAxisRect* StanceFlagsPlot::inputRect(Input input) const { return rows_[rowOf(input)].rect; }
QCPGraph* StanceFlagsPlot::laneGraph(Lane lane) const { return lanes_[slot(lane)]; }
QCPGraph* StanceFlagsPlot::inputGraph(Input input) const { return inputs_[slot(input)]; }
QCPGraph* StanceFlagsPlot::thresholdGraph(Threshold threshold) const { return thresholds_[slot(threshold)]; }
QCPRange StanceFlagsPlot::timeRange() const { return timeRows_->range(); }

void StanceFlagsPlot::setTimeCursor(double time_s)
{
    timeCursor_s_ = time_s;
    cursorPlaced_ = true;
    for (RowParts& row : rows_) {
        row.cursor->point1->setCoords(time_s, 0.0);
        row.cursor->point2->setCoords(time_s, 1.0);
        row.cursor->setVisible(row.rect->layout() != nullptr);
    }
    plot_->layer(kCursorLayer)->replot();
}

void StanceFlagsPlot::setTimeRange(double from_s, double to_s)
{
    timeRows_->setRange(from_s, to_s);
}

void StanceFlagsPlot::showAll()
{
    if (times_s_.size() >= 2)
        setTimeRange(times_s_.front(), times_s_.back());
}

void StanceFlagsPlot::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Home)
        showAll();
    else if (!timeRows_->navigate(event->key()))
        return QWidget::keyPressEvent(event);
    event->accept();
}

void StanceFlagsPlot::renderTo(QPainter& painter, const QRect& target)
{
    renderPlotTo(plot_, painter, target);
}

}  // namespace footpath
