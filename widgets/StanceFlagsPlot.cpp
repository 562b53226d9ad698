#include "StanceFlagsPlot.h"

#include "AnalysisSession.h"
#include "DecimatedGraph.h"
#include "DeferredReplot.h"
#include "DetectorInputRows.h"
#include "DetectorStatisticRow.h"
#include "MotionLanes.h"
#include "PlotInteraction.h"
#include "ReferenceStanceLane.h"
#include "StanceFlagsPlotAxes.h"
#include "TimeAxisNavigation.h"
#include "TimeBands.h"
#include "WarningOverlay.h"

#include <QApplication>
#include <QKeyEvent>
#include <QPicture>
#include <QToolBar>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <optional>

namespace footpath {

namespace {

using Lane = StanceFlagsPlot::Lane;
using Input = StanceFlagsPlot::Input;

constexpr double kLaneSpacing = 1.5;   // a lane is 1 high; the rest is the gap to the next
constexpr double kLaneMargin = 0.3;    // air above the top lane and below the bottom one
const QString kCursorLayer = QStringLiteral("cursor");
const QString kStanceLayer = QStringLiteral("stance");

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

// For the statistic detectors C1 = C2 = C3 = C: one statistic, one condition.
const char* const kStatisticConditionLabel = QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "C: statistic\n< threshold");
const char* const kStatisticStanceLabel = QT_TRANSLATE_NOOP("footpath::StanceFlagsPlot", "Stance");

std::size_t slot(Lane lane) { return static_cast<std::size_t>(lane); }
std::size_t slot(Input input) { return static_cast<std::size_t>(input); }
constexpr std::size_t kWarningRow = 0;
constexpr std::size_t kNotesRow = 1;
constexpr std::size_t kLanesRow = 2;
constexpr std::size_t kReferenceRow = 3;
constexpr std::size_t kMotionRow = 4;
constexpr std::size_t kStatisticRow = 5;
std::size_t rowOf(Input input) { return 6 + slot(input); }  // below the lanes and the statistic

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

}  // namespace

StanceFlagsPlot::StanceFlagsPlot(QWidget* parent)
    : QWidget(parent), plot_(new QCustomPlot(this)), replot_(new DeferredReplot(plot_)), toolBar_(new QToolBar(tr("Detector"), this)),
      inputsAction_(toolBar_->addAction(tr("Show detector inputs")))
{
    setFocusPolicy(Qt::StrongFocus);  // keys arrive here; the plot passes clicks' focus up
    inputsAction_->setObjectName(QStringLiteral("showDetectorInputs"));
    inputsAction_->setCheckable(true);
    toolBar_->setMovable(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(toolBar_);
    layout->addWidget(plot_, 1);

    plot_->setAutoAddPlottableToLegend(false);
    plot_->setPlottingHint(QCP::phFastPolylines);  // solid pens wider than 1 px: segments, not a stroked path
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot_->addLayer(kStanceLayer, plot_->layer(QStringLiteral("main")), QCustomPlot::limBelow);
    plot_->addLayer(kCursorLayer, plot_->layer(QStringLiteral("legend")), QCustomPlot::limBelow);
    // Its own paint buffer: moving the cursor redraws one line per row, not the curves.
    plot_->layer(kCursorLayer)->setMode(QCPLayer::lmBuffered);
    plot_->plotLayout()->clear();  // drops the default axis rect: the rows below replace it
    plot_->plotLayout()->setRowSpacing(4);
    legend_ = new LegendStrip(plot_);  // above the rows: a legend in a row would hide its curves
    auto* alignedMargins = new QCPMarginGroup(plot_);  // time axes line up although labels differ
    for (RowParts& row : rows_) {
        row.rect = new QCPAxisRect(plot_);
        plot_->plotLayout()->addElement(plot_->plotLayout()->rowCount(), 0, row.rect);  // arrangeRows() sorts
        row.rect->setMarginGroup(QCP::msLeft | QCP::msRight, alignedMargins);
        row.cursor = addCursorLine(plot_, row.rect, kCursorLayer);
    }
    createLanesRow();
    reference_ = std::make_unique<ReferenceStanceLane>(plot_, rows_[kReferenceRow].rect);
    statisticRow_ = std::make_unique<DetectorStatisticRow>(plot_, rows_[kStatisticRow].rect, kStanceLayer);
    inputRows_ = std::make_unique<DetectorInputRows>(
        plot_, std::array<QCPAxisRect*, kInputCount>{inputRect(Input::AccNorm), inputRect(Input::AccStdDev), inputRect(Input::GyrNorm)});
    warnings_ = new WarningOverlay(plot_);
    for (std::size_t r = 0; r < kRowCount; ++r)
        if (r != kWarningRow && r != kNotesRow && r != kMotionRow && r != kReferenceRow)  // the lanes keep their own colours
            warnings_->addRow(rows_[r].rect);
    warnings_->setLane(rows_[kWarningRow].rect);
    motion_ = new MotionLanes(plot_);
    motion_->setMotionLane(rows_[kMotionRow].rect);
    motion_->setNotesLane(rows_[kNotesRow].rect);
    inputRows_->rescale();
    wireInteractions();
    setParameters(params_);  // names, lanes and rows of the default detector
    createPlotInteraction();
}

void StanceFlagsPlot::createPlotInteraction()
{
    interaction_ = new PlotInteraction(plot_);
    interaction_->setResetAction([this] {
        showAll();
        inputRows_->rescale();
        statisticRow_->plotStatistic(result_.get());  // frames the statistic row again
    });
    // The lanes' curves run between two levels: the readout names the flag instead.
    interaction_->setValueFormatter([this](const QCPGraph* graph, double value) -> std::optional<QString> {
        if (std::optional<QString> readout = reference_->readout(graph, value))
            return readout;
        for (std::size_t l = 0; l < kLaneCount; ++l)
            if (graph == lanes_[l])
                return value == laneLevel(static_cast<Lane>(l), true) ? tr("1 (set)") : tr("0");
        return std::nullopt;
    });
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
    QCPAxisRect* rect = rows_[kLanesRow].rect;
    QCPAxis* axis = valueAxis(rect);
    axis->setTickLength(0, 0);
    axis->setSubTicks(false);
    axis->grid()->setVisible(false);  // grid lines would run through the middle of every lane
    for (std::size_t l = 0; l < kLaneCount; ++l) {
        const Lane lane = static_cast<Lane>(l);
        // Created before the outline, so drawn beneath it on the same layer.
        laneFills_[l] = new TimeBands(rect, laneInfos()[l].fill);
        laneFills_[l]->setLevels(laneLevel(lane, false), laneLevel(lane, true));
        laneFills_[l]->setLayer(QStringLiteral("main"));
        lanes_[l] = plot_->addGraph(timeAxis(rect), axis);
        lanes_[l]->setName(tr(laneInfos()[l].label));
        lanes_[l]->setLineStyle(QCPGraph::lsStepLeft);
        lanes_[l]->setPen(QPen(QColor(40, 40, 40), 1.0));
        lanes_[l]->setSelectable(QCP::stNone);
    }
}

void StanceFlagsPlot::labelLanes()
{
    // A statistic detector has one condition: C1, C2 and C3 would repeat C, so only C and the
    // stance lane are shown, and named for what they are.
    const bool paper = usesPaperDetector();
    auto ticker = QSharedPointer<QCPAxisTickerText>::create();
    for (std::size_t l = 0; l < kLaneCount; ++l) {
        const Lane lane = static_cast<Lane>(l);
        const bool shown = paper || lane == Lane::C || lane == Lane::Stance;
        lanes_[l]->setVisible(shown);
        laneFills_[l]->setVisible(shown);
        if (!shown)
            continue;
        const char* label = paper ? laneInfos()[l].label
                                  : (lane == Lane::C ? kStatisticConditionLabel : kStatisticStanceLabel);
        ticker->addTick(laneLevel(lane, false) + 0.5, tr(label));
    }
    QCPAxis* axis = valueAxis(rows_[kLanesRow].rect);
    axis->setTicker(ticker);
    axis->setRange(laneLevel(Lane::Stance, false) - kLaneMargin,
                   laneLevel(paper ? Lane::C1 : Lane::C, true) + kLaneMargin);
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

bool StanceFlagsPlot::usesPaperDetector() const
{
    return params_.detectorKind() == DetectorKind::PaperC1C2C3;
}

void StanceFlagsPlot::setRecording(std::shared_ptr<const Recording> recording)
{
    result_.reset();
    inputRows_->setRecording(recording.get());
    reference_->setRecording(recording.get(), inputRows_->times());
    showResultLanes();
    arrangeRows();
    showAll();
    replot_->request();
}

void StanceFlagsPlot::setResult(std::shared_ptr<const Result> result)
{
    result_ = std::move(result);
    showResultLanes();
    arrangeRows();  // the warning lane comes or goes
    replot_->request();
}

void StanceFlagsPlot::showResultLanes()
{
    // The rows that come and go with the result now; the curves over all samples when seen.
    warnings_->setWarnings(result_ ? result_->warnings : std::vector<PlausibilityWarning>());
    motion_->setResult(result_.get());
    curvesStale_ = true;
    if (isVisible())
        ensureCurvesPlotted();
}

void StanceFlagsPlot::ensureCurvesPlotted() const
{
    if (!curvesStale_)
        return;
    // The lanes and the statistic are a cache of result_: filling them while on a tab behind
    // would cost every parameter change milliseconds for nobody.
    auto* self = const_cast<StanceFlagsPlot*>(this);
    self->curvesStale_ = false;
    self->plotLanes();
    self->statisticRow_->plotStatistic(result_.get());
    self->replot_->request();  // a grab while hidden may have used the request the result made
}

void StanceFlagsPlot::showEvent(QShowEvent* event)
{
    ensureCurvesPlotted();
    QWidget::showEvent(event);
}

void StanceFlagsPlot::setParameters(const Parameters& params)
{
    params_ = params;
    inputRows_->setParameters(params);
    labelLanes();
    statisticRow_->name(params_, usesPaperDetector());
    const bool paper = usesPaperDetector();
    inputsAction_->setEnabled(paper);
    inputsAction_->setToolTip(paper ? tr("Plot |a|, its local standard deviation and |ω| with the detector's thresholds")
                                    : tr("The inputs of the C1/C2/C3 detector; the chosen detector decides on its "
                                         "statistic, shown below the lanes"));
    arrangeRows();
    replot_->request();
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
    statisticRow_->shadeStance(result_.get());
}

void StanceFlagsPlot::setInputsVisible(bool visible)
{
    if (visible == inputsVisible_)
        return;
    inputsVisible_ = visible;
    inputsAction_->setChecked(visible);
    arrangeRows();
    replot_->request();
}

void StanceFlagsPlot::arrangeRows()
{
    QCPLayoutGrid* layout = plot_->plotLayout();
    for (RowParts& row : rows_) {
        if (row.rect->layout() != nullptr)
            layout->take(row.rect);
    }
    layout->simplify();
    const bool inputsShown = inputsVisible_ && usesPaperDetector();
    int shownCount = LegendStrip::kFirstRow;
    QCPAxisRect* bottom = nullptr;
    for (std::size_t r = 0; r < kRowCount; ++r) {
        RowParts& row = rows_[r];
        bool shown = r == kWarningRow ? warnings_->hasWarnings() : (r == kLanesRow || r == kStatisticRow || inputsShown);
        if (r == kNotesRow || r == kMotionRow)
            shown = r == kNotesRow ? motion_->hasNotes() : motion_->hasMotionLane();
        if (r == kReferenceRow)
            shown = reference_->hasStance();
        // Out of the layout a row keeps its old geometry: hide it, or it would paint over the others.
        row.rect->setVisible(shown);
        row.cursor->setVisible(shown && cursorPlaced_);
        timeAxis(row.rect)->setTickLabels(false);
        timeAxis(row.rect)->setLabel(QString());
        if (!shown)
            continue;
        layout->addElement(shownCount, 0, row.rect);
        // Five lanes need more height than one curve, two lanes less; the warning lane has its own.
        if (r == kLanesRow)
            layout->setRowStretchFactor(shownCount, usesPaperDetector() ? 1.3 : 0.6);
        else if (r == kStatisticRow)
            layout->setRowStretchFactor(shownCount, 1.8);
        ++shownCount;
        bottom = row.rect;
    }
    timeAxis(bottom)->setTickLabels(true);  // one time scale at the foot of the stack is enough
    timeAxis(bottom)->setLabel(tr("Time (s)"));
    // The axes name the curves; the legend names the thresholds (each name says its quantity) and
    // the shading.
    std::vector<QCPAbstractPlottable*> entries = statisticRow_->legendEntries();
    if (inputsShown)
        entries.insert(entries.end(), inputRows_->thresholds().begin(), inputRows_->thresholds().end());
    legend_->setEntries(entries);
}

bool StanceFlagsPlot::isLaneShown(Lane lane) const
{
    ensureCurvesPlotted();
    return lanes_[slot(lane)]->visible();
}
bool StanceFlagsPlot::isInputRowShown(Input input) const { return inputRect(input)->layout() != nullptr; }
QCPLegend* StanceFlagsPlot::legend() const
{
    ensureCurvesPlotted();
    return legend_->legend();
}
QCPAxisRect* StanceFlagsPlot::lanesRect() const { return rows_[kLanesRow].rect; }
QCPGraph* StanceFlagsPlot::statisticGraph() const
{
    ensureCurvesPlotted();
    return statisticRow_->statistic();
}
QCPAxisRect* StanceFlagsPlot::statisticRect() const
{
    ensureCurvesPlotted();
    return rows_[kStatisticRow].rect;
}
QCPAxisRect* StanceFlagsPlot::warningLane() const { return rows_[kWarningRow].rect; }
QCPAxisRect* StanceFlagsPlot::motionLane() const { return rows_[kMotionRow].rect; }
QCPAxisRect* StanceFlagsPlot::referenceLane() const { return rows_[kReferenceRow].rect; }
bool StanceFlagsPlot::isReferenceStance(double time_s) const { return reference_->isStance(time_s); }
const QString& StanceFlagsPlot::referenceSource() const { return reference_->source(); }
QCPAxisRect* StanceFlagsPlot::methodNotesLane() const { return rows_[kNotesRow].rect; }
QCPAxisRect* StanceFlagsPlot::inputRect(Input input) const { return rows_[rowOf(input)].rect; }
QCPGraph* StanceFlagsPlot::laneGraph(Lane lane) const
{
    ensureCurvesPlotted();
    return lanes_[slot(lane)];
}
QCPGraph* StanceFlagsPlot::inputGraph(Input input) const { return inputRows_->graph(input); }
QCPGraph* StanceFlagsPlot::thresholdGraph(Threshold threshold) const { return inputRows_->threshold(threshold); }
bool StanceFlagsPlot::isStatisticStanceShaded(double time_s) const
{
    ensureCurvesPlotted();
    return statisticRow_->isStanceShaded(time_s);
}
QCPGraph* StanceFlagsPlot::statisticThresholdGraph() const
{
    ensureCurvesPlotted();
    return statisticRow_->threshold();
}
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
    const std::vector<double>& times = inputRows_->times();
    if (times.size() >= 2)
        setTimeRange(times.front(), times.back());
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
    ensureCurvesPlotted();
    renderPlotTo(plot_, painter, target);
}

void StanceFlagsPlot::showRecording(const AnalysisSession& session)
{
    setRecording(session.recording());
}

void StanceFlagsPlot::showEstimate(const AnalysisSession& session)
{
    // The threshold drawn is the one this result was detected with, not a newer one on its way.
    setParameters(session.resultParameters());
    setResult(session.result());
}

}  // namespace footpath
