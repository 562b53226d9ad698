#include "StatePlots.h"

#include "AnalysisSession.h"
#include "DecimatedGraph.h"
#include "DeferredReplot.h"
#include "PlotInteraction.h"
#include "TimeAxisNavigation.h"
#include "TimeBands.h"

#include <QKeyEvent>
#include <QtConcurrent/QtConcurrentMap>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace footpath {

namespace {

using Row = StatePlots::Row;

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;
constexpr double kValueMargin = 1.1;          // 5 % air above and below the curves and bands
constexpr double kMinimumSpan = 1e-3;         // a constant row still gets an axis to read
constexpr std::size_t kMaxBandPoints = 8000;  // σ changes slowly: more points would only cost drawing time
const QString kStanceLayer = QStringLiteral("stance");
const QString kCursorLayer = QStringLiteral("cursor");
const QColor kStanceBrush(250, 200, 110, 70);  // SignalPlots' light amber, a little lighter under bands

struct RowInfo {
    const char* axisLabel;  // with the unit, translated in the StatePlots context
    int components;
    std::array<const char*, StatePlots::kMaxComponents> names;
    int sigmaStart;  // ErrorStdIndex block
    bool isBias;
};

constexpr std::array<RowInfo, StatePlots::kRowCount> kRowInfos = {{
    {QT_TRANSLATE_NOOP("footpath::StatePlots", "Attitude\n(°)"), 3,
     {QT_TRANSLATE_NOOP("footpath::StatePlots", "roll"), QT_TRANSLATE_NOOP("footpath::StatePlots", "pitch"),
      QT_TRANSLATE_NOOP("footpath::StatePlots", "yaw")},
     ErrorStdIndex::attitude, false},
    {QT_TRANSLATE_NOOP("footpath::StatePlots", "Velocity\n(m/s)"), 3,
     {QT_TRANSLATE_NOOP("footpath::StatePlots", "x"), QT_TRANSLATE_NOOP("footpath::StatePlots", "y"),
      QT_TRANSLATE_NOOP("footpath::StatePlots", "z")},
     ErrorStdIndex::velocity, false},
    {QT_TRANSLATE_NOOP("footpath::StatePlots", "Height\n(m)"), 1,
     {QT_TRANSLATE_NOOP("footpath::StatePlots", "height"), nullptr, nullptr}, ErrorStdIndex::position + 2, false},
    {QT_TRANSLATE_NOOP("footpath::StatePlots", "Gyro bias\n(rad/s)"), 3,
     {QT_TRANSLATE_NOOP("footpath::StatePlots", "x"), QT_TRANSLATE_NOOP("footpath::StatePlots", "y"),
      QT_TRANSLATE_NOOP("footpath::StatePlots", "z")},
     ErrorStdIndex::gyroBias, true},
    {QT_TRANSLATE_NOOP("footpath::StatePlots", "Acc. bias\n(m/s²)"), 3,
     {QT_TRANSLATE_NOOP("footpath::StatePlots", "x"), QT_TRANSLATE_NOOP("footpath::StatePlots", "y"),
      QT_TRANSLATE_NOOP("footpath::StatePlots", "z")},
     ErrorStdIndex::accBias, true},
}};

// SignalPlots' x/y/z colours and dashes, so a printout in grey still tells them apart.
const std::array<QPen, StatePlots::kMaxComponents>& componentPens()
{
    static const std::array<QPen, StatePlots::kMaxComponents> pens = {{
        QPen(QColor(200, 40, 40), 1.2, Qt::SolidLine),
        QPen(QColor(30, 130, 50), 1.0, Qt::DashLine),
        QPen(QColor(30, 80, 190), 1.0, Qt::DotLine),
    }};
    return pens;
}

std::size_t slot(Row row) { return static_cast<std::size_t>(row); }
QCPAxis* timeAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atBottom); }
QCPAxis* valueAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atLeft); }

/// One component of a row's state, read sample by sample in the unit its axis shows; the series
/// is picked once, not at every sample.
class StateSeries {
public:
    StateSeries(const Result& result, Row row, int component)
        : series_(&seriesOf(result, row)), index_(row == Row::Height ? 2 : component),
          scale_(row == Row::Attitude ? kDegreesPerRadian : 1.0)
    {
    }

    /// NaN where the result has no such sample.
    double operator()(std::size_t k) const
    {
        return k < series_->size() ? (*series_)[k][index_] * scale_ : std::numeric_limits<double>::quiet_NaN();
    }

private:
    static const std::vector<Eigen::Vector3d>& seriesOf(const Result& result, Row row)
    {
        switch (row) {
        case Row::Attitude: return result.rollPitchYaw_rad;
        case Row::Velocity: return result.velocity_mps;
        case Row::Height: return result.position_m;  // its z
        case Row::GyroBias: return result.gyroBias_radps;
        case Row::AccBias: break;
        }
        return result.accBias_mps2;
    }

    const std::vector<Eigen::Vector3d>* series_;
    int index_;
    double scale_;
};

/// σ of the component at sample k, in the row's unit. The attitude error is about the navigation
/// axes, which for a foot's small roll and pitch is roll, pitch and yaw closely enough for a band.
double stateSigma(const Result& result, Row row, std::size_t k, int component)
{
    const double sigma = result.errorStd[k][kRowInfos[slot(row)].sigmaStart + component];
    return row == Row::Attitude ? sigma * kDegreesPerRadian : sigma;
}

/// Whether the row's curve jumps from a to b by wrapping around (yaw, or the roll of an upside-down
/// sensor, at ±180°): drawn as a gap rather than a line across the row.
bool wraps(Row row, double a, double b)
{
    return row == Row::Attitude && std::abs(b - a) > 180.0;
}

/// The circular mean of an attitude component, in degrees: the value its curve is drawn around.
/// Taken over at most about 20,000 evenly spread samples: it only places the curve, and the sines
/// and cosines of every sample of a long walk cost more than the rest of the row.
double circularMean_deg(const Result& result, int component)
{
    constexpr std::size_t kMaxSamples = 20000;
    const std::vector<Eigen::Vector3d>& angles = result.rollPitchYaw_rad;
    const std::size_t stride = std::max<std::size_t>(1, angles.size() / kMaxSamples);
    double sine = 0.0, cosine = 0.0;
    for (std::size_t k = 0; k < angles.size(); k += stride) {
        sine += std::sin(angles[k][component]);
        cosine += std::cos(angles[k][component]);
    }
    return sine == 0.0 && cosine == 0.0 ? 0.0 : std::atan2(sine, cosine) * kDegreesPerRadian;
}

/// The angle written within half a turn of `centre` (both in degrees): the roll of a sensor worn
/// upside down reads 175..185 degrees, not a curve jumping between +179 and -179.
double nearCentre_deg(double angle, double centre)
{
    return centre + std::remainder(angle - centre, 360.0);
}

bool isConstant(const Result& result, Row row)
{
    const std::size_t n = result.time_s.size();
    for (int c = 0; c < kRowInfos[slot(row)].components; ++c) {
        const StateSeries value(result, row, c);
        for (std::size_t k = 1; k < n; ++k)
            if (value(k) != value(0))
                return false;
    }
    return true;
}

/// One component's curve and ±1σ band as the row's graphs take them, and the range of their
/// finite values for the row's axis.
struct ComponentSeries {
    QVector<QCPGraphData> curve, lower, upper, sigma;
    QVector<QCPGraphData> coarseCurve;  ///< curve's coarseEnvelope, for drawing it zoomed out
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -std::numeric_limits<double>::infinity();
};

/// Built from a result on any thread: ensureRowsPlotted builds the components side by side.
ComponentSeries buildComponentSeries(const Result& result, Row which, int component, bool bands, bool constantBias)
{
    ComponentSeries series;
    const std::size_t n = result.time_s.size();
    const std::size_t stride = std::max<std::size_t>(1, n / kMaxBandPoints);
    const double gap = std::numeric_limits<double>::quiet_NaN();
    QVector<QCPGraphData>& curve = series.curve;
    QVector<QCPGraphData>& lower = series.lower;
    QVector<QCPGraphData>& upper = series.upper;
    QVector<QCPGraphData>& sigma = series.sigma;
    curve.reserve(constantBias ? 2 : static_cast<qsizetype>(n) + 64);
    if (bands) {
        for (QVector<QCPGraphData>* band : {&lower, &upper, &sigma})
            band->reserve(static_cast<qsizetype>(n / stride) + 64);
    }
    const bool angle = which == Row::Attitude && n > 0;
    const double centre = angle ? circularMean_deg(result, component) : 0.0;
    const StateSeries state(result, which, component);
    const auto widen = [&series](double value) {
        if (std::isfinite(value)) {
            series.lowest = std::min(series.lowest, value);
            series.highest = std::max(series.highest, value);
        }
    };
    std::size_t nextBandSample = 0;  // every stride-th sample and the last
    for (std::size_t k = 0; k < n; ++k) {
        if (constantBias && k != 0 && k + 1 != n)
            continue;  // a flat line (the row is collapsed): its two ends draw the same
        const double raw = state(k);
        const double value = angle && std::abs(raw - centre) > 180.0 ? nearCentre_deg(raw, centre) : raw;
        const double time_s = result.time_s[k];
        if (!curve.isEmpty() && wraps(which, curve.back().value, value)) {
            curve.append(QCPGraphData(0.5 * (curve.back().key + time_s), gap));  // QCustomPlot leaves a gap at NaN
        }
        curve.append(QCPGraphData(time_s, value));
        widen(value);
        if (!bands || (k != nextBandSample && k + 1 != n))
            continue;
        if (k == nextBandSample)
            nextBandSample += stride;
        // A σ that is not finite (a covariance that overflowed) leaves a gap in the band
        // rather than a band to the end of the axis that rescales the whole row.
        const double computed = stateSigma(result, which, k, component);
        const double s = std::isfinite(computed) ? computed : gap;
        if (!lower.isEmpty() && wraps(which, lower.back().value + sigma.back().value, value)) {
            const double between_s = 0.5 * (lower.back().key + time_s);
            lower.append(QCPGraphData(between_s, gap));
            upper.append(QCPGraphData(between_s, gap));
            sigma.append(QCPGraphData(between_s, sigma.back().value));
        }
        lower.append(QCPGraphData(time_s, value - s));
        upper.append(QCPGraphData(time_s, value + s));
        sigma.append(QCPGraphData(time_s, s));
        widen(value - s);
        widen(value + s);
    }
    series.coarseCurve = coarseEnvelope(curve);
    return series;
}

}  // namespace

struct StatePlots::RowFill {
    std::array<ComponentSeries, kMaxComponents> components;
    std::size_t samples = 0;
    bool hasBands = false;
    bool constantBias = false;  ///< a bias the filter did not estimate: a flat line, collapsed
};

std::array<StatePlots::RowFill, StatePlots::kRowCount> StatePlots::fillRows(const Result* result)
{
    std::array<RowFill, kRowCount> fills;
    struct Job {
        std::size_t row;
        int component;
    };
    std::vector<Job> jobs;
    const std::size_t n = result ? result->time_s.size() : 0;
    for (std::size_t r = 0; r < kRowCount; ++r) {
        RowFill& fill = fills[r];
        fill.samples = n;
        fill.hasBands = n > 0 && result->errorStd.size() >= n;
        fill.constantBias = n > 0 && kRowInfos[r].isBias && isConstant(*result, static_cast<Row>(r));
        for (int c = 0; c < kRowInfos[r].components; ++c)
            jobs.push_back({r, c});
    }
    // The components of a 30-minute walk are 180,000 samples each: built on the pool's threads and
    // this one side by side (the rows' fill was most of a parameter change's time in this view).
    const auto build = [&](const Job& job) {
        const RowFill& fill = fills[job.row];
        fills[job.row].components[static_cast<std::size_t>(job.component)] =
            n == 0 ? ComponentSeries{}
                   : buildComponentSeries(*result, static_cast<Row>(job.row), job.component,
                                          fill.hasBands && !fill.constantBias, fill.constantBias);
    };
    QtConcurrent::blockingMap(jobs, build);
    return fills;
}

StatePlots::StatePlots(QWidget* parent) : QWidget(parent), plot_(new QCustomPlot(this)), replot_(new DeferredReplot(plot_))
{
    setFocusPolicy(Qt::StrongFocus);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(plot_);
    plot_->setAutoAddPlottableToLegend(false);
    plot_->setPlottingHint(QCP::phFastPolylines);
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot_->addLayer(kStanceLayer, plot_->layer(QStringLiteral("main")), QCustomPlot::limBelow);
    plot_->addLayer(kCursorLayer, plot_->layer(QStringLiteral("legend")), QCustomPlot::limBelow);
    plot_->layer(kCursorLayer)->setMode(QCPLayer::lmBuffered);
    plot_->plotLayout()->clear();
    plot_->plotLayout()->setRowSpacing(4);
    legend_ = new LegendStrip(plot_);  // above the rows: a legend in a row would hide its curves
    auto* alignedMargins = new QCPMarginGroup(plot_);
    timeRows_ = new LinkedTimeRows(plot_);
    for (std::size_t r = 0; r < kRowCount; ++r) {
        rows_[r].rect = new QCPAxisRect(plot_);
        plot_->plotLayout()->addElement(LegendStrip::kFirstRow + static_cast<int>(r), 0, rows_[r].rect);
        rows_[r].rect->setMarginGroup(QCP::msLeft | QCP::msRight, alignedMargins);
        createRow(r);
        timeRows_->addRow(rows_[r].rect);
        const bool bottom = r + 1 == kRowCount;  // one time scale at the foot of the stack
        timeAxis(rows_[r].rect)->setTickLabels(bottom);
        if (bottom)
            timeAxis(rows_[r].rect)->setLabel(tr("Time (s)"));
    }
    bandLegendEntry_ = plot_->addGraph(timeAxis(rows_.front().rect), rows_.front().rect->axis(QCPAxis::atRight));
    bandLegendEntry_->setName(tr("±1σ"));
    bandLegendEntry_->setPen(Qt::NoPen);
    bandLegendEntry_->setBrush(QColor(120, 120, 120, 70));
    connect(timeRows_, &LinkedTimeRows::rangeChanged, this, &StatePlots::timeRangeChanged);
    connect(timeRows_, &LinkedTimeRows::clicked, this, [this](double time_s) {
        setTimeCursor(time_s);
        emit timeCursorMoved(time_s);
    });
    interaction_ = new PlotInteraction(plot_);
    interaction_->setResetAction([this] {
        showAll();
        for (std::size_t r = 0; r < kRowCount; ++r)
            rescaleRow(r);
    });
    setResult(nullptr);
}

StatePlots::~StatePlots() = default;

void StatePlots::createRow(std::size_t r)
{
    RowParts& row = rows_[r];
    const RowInfo& info = kRowInfos[r];
    valueAxis(row.rect)->setLabel(tr(info.axisLabel));
    row.stance = new TimeBands(row.rect, kStanceBrush);
    row.stance->setLayer(kStanceLayer);
    row.cursor = addCursorLine(plot_, row.rect, kCursorLayer);
    row.componentCount = info.components;
    for (int c = 0; c < info.components; ++c) {
        Component& component = row.components[static_cast<std::size_t>(c)];
        const QPen& pen = componentPens()[static_cast<std::size_t>(c)];
        QColor fill = pen.color();
        fill.setAlpha(45);
        // Bands first, so the curves are drawn over them.
        // Each edge one point a pixel column: the band's fill polygon stays small however long the walk.
        component.lower = new DecimatedGraph(timeAxis(row.rect), valueAxis(row.rect), DecimatedGraph::Reduction::Lowest);
        component.upper = new DecimatedGraph(timeAxis(row.rect), valueAxis(row.rect), DecimatedGraph::Reduction::Highest);
        for (QCPGraph* edge : {component.lower, component.upper}) {
            edge->setPen(Qt::NoPen);
            edge->setSelectable(QCP::stNone);
        }
        component.upper->setBrush(fill);
        component.upper->setChannelFillGraph(component.lower);
        component.curve = new DecimatedGraph(timeAxis(row.rect), valueAxis(row.rect));
        component.curve->setName(tr(info.names[static_cast<std::size_t>(c)]));
        component.curve->setPen(info.components == 1 ? QPen(QColor(0, 110, 120), 1.2) : pen);
        component.curve->setSelectable(QCP::stNone);
        component.sigma = plot_->addGraph(timeAxis(row.rect), valueAxis(row.rect));
        component.sigma->setName(tr("σ %1").arg(component.curve->name()));
        component.sigma->setLineStyle(QCPGraph::lsNone);
        component.sigma->setPen(Qt::NoPen);
        component.sigma->setSelectable(QCP::stNone);
    }
    row.note = new QCPItemText(plot_);
    row.note->setClipToAxisRect(true);
    row.note->setClipAxisRect(row.rect);
    row.note->position->setType(QCPItemPosition::ptAxisRectRatio);
    row.note->position->setAxisRect(row.rect);
    row.note->position->setCoords(0.01, 0.97);
    row.note->setPositionAlignment(Qt::AlignLeft | Qt::AlignBottom);
    row.note->setColor(QColor(90, 90, 90));
    row.note->setBrush(QColor(255, 255, 255, 200));
    row.note->setPadding(QMargins(3, 1, 3, 1));
    row.note->setSelectable(false);
}

void StatePlots::setResult(std::shared_ptr<const Result> result)
{
    result_ = std::move(result);
    const std::vector<QCPRange> stance =
        result_ ? flaggedSpans(result_->time_s, result_->flags.stance) : std::vector<QCPRange>();
    for (RowParts& row : rows_)
        row.stance->setSpans(stance);
    rowsStale_ = true;
    if (isVisible())
        ensureRowsPlotted();
    showAll();
    replot_->request();
}

void StatePlots::ensureRowsPlotted() const
{
    if (!rowsStale_)
        return;
    // The rows are a cache of result_: filling them while hidden would cost a parameter change
    // tens of milliseconds for a tab nobody looks at, so they are filled when shown or asked for.
    auto* self = const_cast<StatePlots*>(this);
    self->rowsStale_ = false;
    std::array<RowFill, kRowCount> fills = fillRows(result_.get());
    for (std::size_t r = 0; r < kRowCount; ++r)
        self->plotRow(r, fills[r]);
    self->refreshLegend();
}

void StatePlots::showEvent(QShowEvent* event)
{
    ensureRowsPlotted();
    QWidget::showEvent(event);
}

void StatePlots::plotRow(std::size_t r, const RowFill& fill)
{
    RowParts& row = rows_[r];
    for (int c = 0; c < row.componentCount; ++c) {
        const ComponentSeries& series = fill.components[static_cast<std::size_t>(c)];
        Component& component = row.components[static_cast<std::size_t>(c)];
        // Handed over whole: the container shares the vector instead of copying 180k pairs again.
        component.curve->setSeries(series.curve, series.coarseCurve);
        component.lower->data()->set(series.lower, true);
        component.upper->data()->set(series.upper, true);
        component.sigma->data()->set(series.sigma, true);
    }
    QString note;
    if (fill.constantBias)
        note = tr("Not estimated (constant)");
    else if (fill.samples > 0 && !fill.hasBands)
        note = tr("No ±1σ band: this estimator keeps no covariance");
    row.note->setText(note);
    row.note->setVisible(!note.isEmpty());
    showCollapsed(r, fill.constantBias);
    row.lowest = std::numeric_limits<double>::infinity();
    row.highest = -row.lowest;
    for (int c = 0; c < row.componentCount; ++c) {
        row.lowest = std::min(row.lowest, fill.components[static_cast<std::size_t>(c)].lowest);
        row.highest = std::max(row.highest, fill.components[static_cast<std::size_t>(c)].highest);
    }
    rescaleRow(r);
}

void StatePlots::refreshLegend()
{
    // Velocity and the biases share the x/y/z pens: their entries appear once. A collapsed row
    // (a state not estimated) draws no curve worth a legend entry.
    std::vector<QCPAbstractPlottable*> entries;
    for (const RowParts& row : rows_) {
        if (row.collapsed)
            continue;
        for (int c = 0; c < row.componentCount; ++c)
            entries.push_back(row.components[static_cast<std::size_t>(c)].curve);
    }
    if (result_ && !result_->errorStd.empty())
        entries.push_back(bandLegendEntry_);
    legend_->setEntries(entries);
}

void StatePlots::showCollapsed(std::size_t r, bool collapsed)
{
    // A state the filter did not estimate is a flat line: a lane saying so, not a row of axis.
    RowParts& row = rows_[r];
    QCPAxis* values = valueAxis(row.rect);
    values->setTicks(!collapsed);
    values->setTickLabels(!collapsed);
    values->grid()->setVisible(!collapsed);
    const int laneHeight = 2 * QFontMetrics(values->labelFont()).height() + 6;  // its two-line label
    row.rect->setMinimumSize(0, collapsed ? laneHeight : 0);
    row.rect->setMaximumSize(QWIDGETSIZE_MAX, collapsed ? laneHeight : QWIDGETSIZE_MAX);
    row.collapsed = collapsed;
    row.note->position->setCoords(0.01, collapsed ? 0.5 : 0.97);
    row.note->setPositionAlignment(Qt::AlignLeft | (collapsed ? Qt::AlignVCenter : Qt::AlignBottom));
}

void StatePlots::rescaleRow(std::size_t r)
{
    const RowParts& row = rows_[r];
    const double lowest = row.lowest, highest = row.highest;
    if (lowest > highest) {
        valueAxis(row.rect)->setRange(-1.0, 1.0);
        return;
    }
    const double centre = (lowest + highest) / 2.0;
    const double span = std::max({(highest - lowest) * kValueMargin, std::abs(centre) * 0.1, kMinimumSpan});
    valueAxis(row.rect)->setRange(centre - span / 2.0, centre + span / 2.0);
}

QCPRange StatePlots::timeRange() const { return timeRows_->range(); }
QCPAxisRect* StatePlots::axisRect(Row row) const
{
    ensureRowsPlotted();  // its value range
    return rows_[slot(row)].rect;
}

QCPLegend* StatePlots::legend() const
{
    ensureRowsPlotted();
    return legend_->legend();
}

QCustomPlot* StatePlots::plot() const
{
    ensureRowsPlotted();
    return plot_;
}

QCPGraph* StatePlots::graph(Row row, int component) const
{
    ensureRowsPlotted();
    return component < rows_[slot(row)].componentCount ? rows_[slot(row)].components[static_cast<std::size_t>(component)].curve : nullptr;
}

QCPGraph* StatePlots::bandLower(Row row, int component) const
{
    ensureRowsPlotted();
    return component < rows_[slot(row)].componentCount ? rows_[slot(row)].components[static_cast<std::size_t>(component)].lower : nullptr;
}

QCPGraph* StatePlots::bandUpper(Row row, int component) const
{
    ensureRowsPlotted();
    return component < rows_[slot(row)].componentCount ? rows_[slot(row)].components[static_cast<std::size_t>(component)].upper : nullptr;
}

QString StatePlots::rowNote(Row row) const
{
    ensureRowsPlotted();
    const QCPItemText* note = rows_[slot(row)].note;
    return note->visible() ? note->text() : QString();
}

void StatePlots::setTimeCursor(double time_s)
{
    timeCursor_s_ = time_s;
    for (RowParts& row : rows_) {
        row.cursor->point1->setCoords(time_s, 0.0);
        row.cursor->point2->setCoords(time_s, 1.0);
        row.cursor->setVisible(true);
    }
    plot_->layer(kCursorLayer)->replot();
}

void StatePlots::setTimeRange(double from_s, double to_s)
{
    timeRows_->setRange(from_s, to_s);
}

void StatePlots::showAll()
{
    if (result_ && result_->time_s.size() >= 2)
        setTimeRange(result_->time_s.front(), result_->time_s.back());
}

void StatePlots::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Home)
        showAll();
    else if (!timeRows_->navigate(event->key()))
        return QWidget::keyPressEvent(event);
    event->accept();
}

void StatePlots::renderTo(QPainter& painter, const QRect& target)
{
    ensureRowsPlotted();
    renderPlotTo(plot_, painter, target);
}

void StatePlots::showEstimate(const AnalysisSession& session)
{
    setResult(session.result());
}

}  // namespace footpath
