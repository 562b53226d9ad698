#include "SignalPlots.h"

#include "AnalysisSession.h"
#include "DecimatedGraph.h"
#include "DeferredReplot.h"
#include "PlotInteraction.h"
#include "TimeAxisNavigation.h"
#include "TimeBands.h"
#include "WarningOverlay.h"

#include <QApplication>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMetaEnum>
#include <QPicture>
#include <QToolBar>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

/// The least height of a row of signals.
constexpr int kMinRowHeight_px = 60;

using Channel = SignalPlots::Channel;
using Row = SignalPlots::Row;

/// Whether two lists of warnings show the same: kinds, spans and messages.
bool sameWarningSpans(const std::vector<PlausibilityWarning>& a, const std::vector<PlausibilityWarning>& b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const PlausibilityWarning& x, const PlausibilityWarning& y) {
        return x.kind == y.kind && x.start_s == y.start_s && x.end_s == y.end_s && x.message == y.message;
    });
}

constexpr double kValueMargin = 1.1;   // value axes get 5 % air above and below the data
const QString kStanceLayer = QStringLiteral("stance");
const QString kCursorLayer = QStringLiteral("cursor");
const QString kGaitEventLayer = QStringLiteral("gaitEvents");
const QColor kStanceBrush(250, 200, 110, 90);  // light amber: a pale grey band on paper

struct ChannelInfo {
    Row row;
    const char* name;  // translated in the SignalPlots context
    QColor colour;
    Qt::PenStyle style;
    double width;
};

// Colour and dash pattern both differ, so the rows still read on a black-and-white printout.
// Dashed and dotted pens stay 1 px wide: wider ones go through QPainter's path stroker, which
// takes seconds for half an hour of samples; wide solid pens take the fast-polyline path.
const std::array<ChannelInfo, SignalPlots::kChannelCount>& channelInfos()
{
    static const QColor red(200, 40, 40), green(30, 130, 50), blue(30, 80, 190), black(20, 20, 20);
    static const std::array<ChannelInfo, SignalPlots::kChannelCount> infos = {{
        {Row::Acceleration, QT_TRANSLATE_NOOP("footpath::SignalPlots", "x"), red, Qt::SolidLine, 1.0},
        {Row::Acceleration, QT_TRANSLATE_NOOP("footpath::SignalPlots", "y"), green, Qt::DashLine, 1.0},
        {Row::Acceleration, QT_TRANSLATE_NOOP("footpath::SignalPlots", "z"), blue, Qt::DotLine, 1.0},
        {Row::Acceleration, QT_TRANSLATE_NOOP("footpath::SignalPlots", "|a|"), black, Qt::SolidLine, 1.6},
        {Row::AngularRate, QT_TRANSLATE_NOOP("footpath::SignalPlots", "x"), red, Qt::SolidLine, 1.0},
        {Row::AngularRate, QT_TRANSLATE_NOOP("footpath::SignalPlots", "y"), green, Qt::DashLine, 1.0},
        {Row::AngularRate, QT_TRANSLATE_NOOP("footpath::SignalPlots", "z"), blue, Qt::DotLine, 1.0},
        {Row::MagneticField, QT_TRANSLATE_NOOP("footpath::SignalPlots", "x"), red, Qt::SolidLine, 1.0},
        {Row::MagneticField, QT_TRANSLATE_NOOP("footpath::SignalPlots", "y"), green, Qt::DashLine, 1.0},
        {Row::MagneticField, QT_TRANSLATE_NOOP("footpath::SignalPlots", "z"), blue, Qt::DotLine, 1.0},
        {Row::Pressure, QT_TRANSLATE_NOOP("footpath::SignalPlots", "Pressure"), QColor(110, 40, 150), Qt::SolidLine, 1.2},
        {Row::Height, QT_TRANSLATE_NOOP("footpath::SignalPlots", "Height"), QColor(0, 110, 120), Qt::SolidLine, 1.2},
    }};
    return infos;
}

struct RowInfo {
    const char* title;      // toolbar group
    const char* axisLabel;  // value axis, with the unit
};

constexpr std::array<RowInfo, SignalPlots::kRowCount> kRowInfos = {{
    {QT_TRANSLATE_NOOP("footpath::SignalPlots", "Acceleration"), QT_TRANSLATE_NOOP("footpath::SignalPlots", "Acceleration\n(m/s²)")},
    {QT_TRANSLATE_NOOP("footpath::SignalPlots", "Angular rate"), QT_TRANSLATE_NOOP("footpath::SignalPlots", "Angular rate\n(rad/s)")},
    {QT_TRANSLATE_NOOP("footpath::SignalPlots", "Magnetic field"), QT_TRANSLATE_NOOP("footpath::SignalPlots", "Magnetic field\n(file units)")},
    {QT_TRANSLATE_NOOP("footpath::SignalPlots", "Pressure"), QT_TRANSLATE_NOOP("footpath::SignalPlots", "Pressure\n(hPa)")},
    {QT_TRANSLATE_NOOP("footpath::SignalPlots", "Height"), QT_TRANSLATE_NOOP("footpath::SignalPlots", "Baro. height\n(m)")},
}};

std::size_t slot(Channel channel) { return static_cast<std::size_t>(channel); }
std::size_t slot(Row row) { return static_cast<std::size_t>(row); }

/// Height above the 101325 Pa level in the standard atmosphere: the formula the walk simulator
/// and barometer datasheets use, so differences of it are heights relative to a sample.
double standardAtmosphereHeight_m(double pressure_pa)
{
    return (1.0 - std::pow(pressure_pa / 101325.0, 1.0 / 5.25588)) / 2.25577e-5;
}

double channelValue(Channel channel, const ImuSample& sample, double firstHeight_m)
{
    switch (channel) {
    case Channel::AccX: return sample.acc_mps2.x();
    case Channel::AccY: return sample.acc_mps2.y();
    case Channel::AccZ: return sample.acc_mps2.z();
    case Channel::AccNorm: return sample.acc_mps2.norm();
    case Channel::GyrX: return sample.gyr_radps.x();
    case Channel::GyrY: return sample.gyr_radps.y();
    case Channel::GyrZ: return sample.gyr_radps.z();
    case Channel::MagX: return sample.mag.x();
    case Channel::MagY: return sample.mag.y();
    case Channel::MagZ: return sample.mag.z();
    case Channel::Pressure: return sample.pressure_pa / 100.0;  // hPa: four digits read better than six
    case Channel::Height: return standardAtmosphereHeight_m(sample.pressure_pa) - firstHeight_m;
    }
    return 0.0;
}

QCPAxis* timeAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atBottom); }
/// The hidden right axis spans 0..1 whatever the signal's range: the cursor uses it to run through
/// the row's full height.
QCPAxis* unitAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atRight); }

}  // namespace

SignalPlots::SignalPlots(QWidget* parent)
    : QWidget(parent), plot_(new QCustomPlot(this)), replot_(new DeferredReplot(plot_)), toolBar_(new QToolBar(tr("Channels"), this))
{
    channelVisible_.fill(true);
    setFocusPolicy(Qt::StrongFocus);  // keys arrive here; the plot passes clicks' focus up
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
    plot_->addLayer(kGaitEventLayer, plot_->layer(QStringLiteral("main")), QCustomPlot::limAbove);
    // Paint buffers of their own: moving the cursor redraws one line per row, and a new estimate
    // of the same recording its stance bands and gait events, not the 180k-sample curves between.
    for (const QString& layer : {kCursorLayer, kStanceLayer, kGaitEventLayer})
        plot_->layer(layer)->setMode(QCPLayer::lmBuffered);

    createRows();
    createGraphs();
    createToolBar();
    wireInteractions();
    arrangeRows();
    interaction_ = new PlotInteraction(plot_);
    interaction_->setResetAction([this] {
        showAll();
        rescaleValueAxes();
    });
}

SignalPlots::~SignalPlots()
{
    // Rows taken out of the layout would outlive it as bare children of the plot, whose QObject
    // clean-up runs after QCustomPlot's own; hand them back so it tears them down in its order.
    for (RowParts* row : allRows()) {
        if (row->rect->layout() == nullptr)
            plot_->plotLayout()->addElement(plot_->plotLayout()->rowCount(), 0, row->rect);
    }
}

std::vector<SignalPlots::RowParts*> SignalPlots::allRows()
{
    std::vector<RowParts*> all{&warningLane_};
    for (RowParts& row : rows_)
        all.push_back(&row);
    return all;
}

void SignalPlots::createRows()
{
    plot_->plotLayout()->clear();  // drops the default axis rect: the rows below replace it
    plot_->plotLayout()->setRowSpacing(4);
    legend_ = new LegendStrip(plot_);  // above the rows: a legend in a row would hide its curves
    auto* alignedMargins = new QCPMarginGroup(plot_);  // time axes line up although labels differ
    for (std::size_t r = 0; r < kRowCount; ++r) {
        auto* rect = new QCPAxisRect(plot_);
        plot_->plotLayout()->addElement(plot_->plotLayout()->rowCount(), 0, rect);  // arrangeRows() sorts
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, alignedMargins);
        rect->axis(QCPAxis::atLeft)->setLabel(tr(kRowInfos[r].axisLabel));
        rows_[r].rect = rect;
        rows_[r].cursor = addCursorLine(plot_, rect, kCursorLayer);
        rows_[r].stance = new TimeBands(rect, kStanceBrush);
        rows_[r].stance->setLayer(kStanceLayer);
    }
    stanceLegendEntry_ = plot_->addGraph(timeAxis(rows_.front().rect), unitAxis(rows_.front().rect));
    stanceLegendEntry_->setName(tr("Stance"));
    stanceLegendEntry_->setPen(Qt::NoPen);
    stanceLegendEntry_->setBrush(kStanceBrush);
    createGaitEventMarks();
    createWarningLane(alignedMargins);
}

void SignalPlots::createGaitEventMarks()
{
    // The gait lab's stance (heel strike to toe off) beside the shaded ZUPT stance (foot at rest):
    // a mark pointing down where the foot lands, up where it leaves, on the zero line the
    // sagittal rate crosses near both.
    const QCPAxisRect* rate = rows_[slot(Row::AngularRate)].rect;
    const auto marks = [&](const QString& name, QCPScatterStyle::ScatterShape shape, const QColor& colour) {
        QCPGraph* graph = plot_->addGraph(timeAxis(rate), rate->axis(QCPAxis::atLeft));
        graph->setName(name);
        graph->setLineStyle(QCPGraph::lsNone);
        graph->setScatterStyle(QCPScatterStyle(shape, colour, colour, 8));
        graph->setSelectable(QCP::stNone);
        graph->setLayer(kGaitEventLayer);
        return graph;
    };
    heelStrikes_ = marks(tr("Heel strike"), QCPScatterStyle::ssTriangleInverted, QColor(40, 40, 40));
    toeOffs_ = marks(tr("Toe off"), QCPScatterStyle::ssTriangle, QColor(150, 40, 150));
}

void SignalPlots::plotGaitEvents()
{
    QVector<double> strikes, offs;
    static const std::vector<GaitEvent> none;  // both branches lvalues: the events are not copied
    for (const GaitEvent& event : result_ ? result_->gaitEvents : none) {
        if (event.kind == GaitEventKind::HeelStrike)
            strikes << event.time_s;
        else if (event.kind == GaitEventKind::ToeOff)
            offs << event.time_s;
    }
    heelStrikes_->setData(strikes, QVector<double>(strikes.size(), 0.0), true);
    toeOffs_->setData(offs, QVector<double>(offs.size(), 0.0), true);
}

void SignalPlots::createWarningLane(QCPMarginGroup* alignedMargins)
{
    warningLane_.rect = new QCPAxisRect(plot_);
    plot_->plotLayout()->addElement(plot_->plotLayout()->rowCount(), 0, warningLane_.rect);  // arrangeRows() sorts
    warningLane_.rect->setMarginGroup(QCP::msLeft | QCP::msRight, alignedMargins);
    warningLane_.cursor = addCursorLine(plot_, warningLane_.rect, kCursorLayer);
    warnings_ = new WarningOverlay(plot_);
    for (const RowParts& row : rows_)
        warnings_->addRow(row.rect);
    warnings_->setLane(warningLane_.rect);
}

void SignalPlots::createGraphs()
{
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const ChannelInfo& info = channelInfos()[c];
        const QCPAxisRect* rect = rows_[slot(info.row)].rect;
        QCPGraph* graph = new DecimatedGraph(timeAxis(rect), rect->axis(QCPAxis::atLeft));
        graph->setName(tr(info.name));
        graph->setPen(QPen(info.colour, info.width, info.style));
        graph->setSelectable(QCP::stNone);
        graphs_[c] = graph;
    }
}

void SignalPlots::createToolBar()
{
    toolBar_->setMovable(false);
    for (std::size_t r = 0; r < kRowCount; ++r) {
        auto* group = new QWidget(toolBar_);
        auto* layout = new QHBoxLayout(group);
        layout->setContentsMargins(8, 0, 8, 0);
        QList<std::size_t> channels;
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            if (slot(channelInfos()[c].row) == r)
                channels << c;
        }
        if (channels.size() > 1)  // a single channel's check box names the row itself
            layout->addWidget(new QLabel(tr(kRowInfos[r].title), group));
        for (const std::size_t c : channels) {
            auto* box = new QCheckBox(tr(channelInfos()[c].name), group);
            box->setObjectName(QStringLiteral("show") +  // "showAccX": for tests and style sheets
                               QLatin1String(QMetaEnum::fromType<Channel>().valueToKey(static_cast<int>(c))));
            box->setChecked(true);
            box->setToolTip(tr("Show or hide this channel of the %1 row").arg(tr(kRowInfos[r].title)));
            layout->addWidget(box);
            channelBoxes_[c] = box;
        }
        rows_[r].group = toolBar_->addWidget(group);
    }
}

void SignalPlots::wireInteractions()
{
    timeRows_ = new LinkedTimeRows(plot_);
    for (const RowParts& row : rows_)
        timeRows_->addRow(row.rect);
    timeRows_->addRow(warningLane_.rect);
    connect(timeRows_, &LinkedTimeRows::rangeChanged, this, &SignalPlots::timeRangeChanged);
    connect(timeRows_, &LinkedTimeRows::clicked, this, [this](double time_s) {
        setTimeCursor(time_s);
        emit timeCursorMoved(time_s);
    });
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const Channel channel = static_cast<Channel>(c);
        connect(channelBoxes_[c], &QCheckBox::toggled, this, [this, channel](bool on) { setChannelVisible(channel, on); });
    }
}

void SignalPlots::setRecording(std::shared_ptr<const Recording> recording)
{
    recording_ = std::move(recording);
    result_.reset();
    static const Recording noRecording;  // both branches lvalues: the recording is not copied
    plotSignals(recording_ ? *recording_ : noRecording);
    plotStanceShading();
    plotGaitEvents();
    for (std::size_t r = 0; r < kRowCount; ++r)
        rows_[r].group->setVisible(rowHasData(static_cast<Row>(r)));
    arrangeRows();
    rescaleValueAxes();
    showAll();
    replot_->request();
}

void SignalPlots::plotSignals(const Recording& recording)
{
    const std::vector<ImuSample>& samples = recording.samples;
    const auto count = static_cast<qsizetype>(samples.size());
    QVector<double> keys(count);
    for (qsizetype k = 0; k < count; ++k)
        keys[k] = samples[k].time_s;
    const double firstHeight_m = recording.hasPressure() ? standardAtmosphereHeight_m(samples.front().pressure_pa) : 0.0;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!rowHasData(channelInfos()[c].row)) {
            graphs_[c]->data()->clear();
            continue;
        }
        QVector<double> values(count);
        for (qsizetype k = 0; k < count; ++k)
            values[k] = channelValue(static_cast<Channel>(c), samples[k], firstHeight_m);
        graphs_[c]->setData(keys, values, true);  // presorted: no sorting pass over 180k samples
    }
}

void SignalPlots::setResult(std::shared_ptr<const Result> result)
{
    const bool hadStances = !rows_.front().stance->isEmpty(), hadGaitEvents = !heelStrikes_->data()->isEmpty();
    const bool sameWarnings = sameWarningSpans(warnings_->warnings(), result ? result->warnings : std::vector<PlausibilityWarning>());
    result_ = std::move(result);
    plotStanceShading();
    plotGaitEvents();
    if (sameWarnings && hadStances == !rows_.front().stance->isEmpty() && hadGaitEvents == !heelStrikes_->data()->isEmpty()) {
        // The rows, their legend and the warning lane stay as they are: only the bands and the
        // event marks are drawn again, over the curves' kept buffer.
        replot_->requestLayers({plot_->layer(kStanceLayer), plot_->layer(kGaitEventLayer)});
        return;
    }
    arrangeRows();  // the legend gains or loses its stance entry, the warning lane comes or goes
    replot_->request();
}

void SignalPlots::plotStanceShading()
{
    const std::vector<QCPRange> spans =
        result_ ? flaggedSpans(result_->time_s, result_->flags.stance) : std::vector<QCPRange>();
    for (RowParts& row : rows_)
        row.stance->setSpans(spans);
    warnings_->setWarnings(result_ ? result_->warnings : std::vector<PlausibilityWarning>());
}

void SignalPlots::rescaleValueAxes()
{
    for (std::size_t r = 0; r < kRowCount; ++r) {
        bool first = true;
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            if (slot(channelInfos()[c].row) != r || !channelVisible_[c] || graphs_[c]->data()->isEmpty())
                continue;
            graphs_[c]->rescaleValueAxis(!first);
            first = false;
        }
        if (!first)
            rows_[r].rect->axis(QCPAxis::atLeft)->scaleRange(kValueMargin);
    }
}

bool SignalPlots::rowHasData(Row row) const
{
    switch (row) {
    case Row::Acceleration:
    case Row::AngularRate: return true;  // shown empty before a recording, so the widget is recognisable
    case Row::MagneticField: return recording_ && recording_->hasMag();
    case Row::Pressure:
    case Row::Height: return recording_ && recording_->hasPressure();
    }
    return false;
}

/// Each shown row at least as high as its axis title is long, the plot as high as those rows: a
/// summary dock pulled up squeezed the rows until their titles ran into each other.
void SignalPlots::keepRowsReadable()
{
    for (RowParts* row : allRows()) {
        if (row->rect->layout() == nullptr || row == &warningLane_)
            continue;
        const QCPAxis* values = row->rect->axis(QCPAxis::atLeft);
        const QFontMetrics metrics(values->labelFont());
        int longest = 0;
        for (const QString& line : values->label().split(QLatin1Char('\n')))
            longest = std::max(longest, metrics.horizontalAdvance(line));
        row->rect->setMinimumSize(0, std::max(kMinRowHeight_px, longest + metrics.height()));
    }
    // What the layout needs with those rows, their margins, the lane and the legend.
    plot_->plotLayout()->update(QCPLayoutElement::upMargins);
    plot_->setMinimumHeight(plot_->plotLayout()->minimumOuterSizeHint().height());
}

void SignalPlots::arrangeRows()
{
    QCPLayoutGrid* layout = plot_->plotLayout();
    for (RowParts* row : allRows()) {
        if (row->rect->layout() != nullptr)
            layout->take(row->rect);
    }
    layout->simplify();
    QCPAxisRect* bottom = nullptr;
    int shownCount = LegendStrip::kFirstRow;
    std::vector<QCPAbstractPlottable*> legendEntries;
    const bool laneShown = warnings_->hasWarnings();
    warningLane_.rect->setVisible(laneShown);
    warningLane_.cursor->setVisible(laneShown && cursorPlaced_);
    timeAxis(warningLane_.rect)->setTickLabels(false);
    if (laneShown)
        layout->addElement(shownCount++, 0, warningLane_.rect);
    for (std::size_t r = 0; r < kRowCount; ++r) {
        bool anyChannelOn = false;
        for (std::size_t c = 0; c < kChannelCount; ++c)
            anyChannelOn = anyChannelOn || (slot(channelInfos()[c].row) == r && channelVisible_[c]);
        const bool shown = anyChannelOn && rowHasData(static_cast<Row>(r));
        RowParts& row = rows_[r];
        // Out of the layout a row keeps its old geometry: hide it, or it would paint over the others.
        row.rect->setVisible(shown);
        row.cursor->setVisible(shown && cursorPlaced_);
        timeAxis(row.rect)->setTickLabels(false);
        timeAxis(row.rect)->setLabel(QString());
        if (!shown)
            continue;
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            if (slot(channelInfos()[c].row) == r && channelVisible_[c])
                legendEntries.push_back(graphs_[c]);
        }
        if (r == slot(Row::AngularRate) && !heelStrikes_->data()->isEmpty())
            legendEntries.insert(legendEntries.end(), {heelStrikes_, toeOffs_});
        layout->addElement(shownCount++, 0, row.rect);
        bottom = row.rect;
    }
    if (bottom != nullptr) {  // one time scale at the foot of the stack is enough
        timeAxis(bottom)->setTickLabels(true);
        timeAxis(bottom)->setLabel(tr("Time (s)"));
    }
    keepRowsReadable();
    if (bottom != nullptr && !rows_.front().stance->isEmpty())
        legendEntries.push_back(stanceLegendEntry_);
    legend_->setEntries(legendEntries);  // x, y and z once: every row draws them with the same pens
}

void SignalPlots::setChannelVisible(Channel channel, bool visible)
{
    const std::size_t c = slot(channel);
    if (channelVisible_[c] == visible)
        return;
    channelVisible_[c] = visible;
    graphs_[c]->setVisible(visible);
    channelBoxes_[c]->setChecked(visible);
    arrangeRows();
    rescaleValueAxes();
    replot_->request();
}

bool SignalPlots::isChannelVisible(Channel channel) const { return channelVisible_[slot(channel)]; }
bool SignalPlots::isRowShown(Row row) const { return rows_[slot(row)].rect->layout() != nullptr; }
QCPAxisRect* SignalPlots::axisRect(Row row) const { return rows_[slot(row)].rect; }
QCPGraph* SignalPlots::graph(Channel channel) const { return graphs_[slot(channel)]; }
QCPLegend* SignalPlots::legend() const { return legend_->legend(); }
QCPGraph* SignalPlots::gaitEventMarks(GaitEventKind kind) const
{
    return kind == GaitEventKind::HeelStrike ? heelStrikes_ : kind == GaitEventKind::ToeOff ? toeOffs_ : nullptr;
}
bool SignalPlots::isStanceShaded(double time_s) const { return rows_.front().stance->contains(time_s); }
QCPItemStraightLine* SignalPlots::cursorLine(Row row) const { return rows_[slot(row)].cursor; }
QCPRange SignalPlots::timeRange() const { return timeRows_->range(); }

void SignalPlots::setTimeCursor(double time_s)
{
    timeCursor_s_ = time_s;
    cursorPlaced_ = true;
    for (RowParts* row : allRows()) {
        row->cursor->point1->setCoords(time_s, 0.0);
        row->cursor->point2->setCoords(time_s, 1.0);
        row->cursor->setVisible(row->rect->layout() != nullptr);
    }
    plot_->layer(kCursorLayer)->replot();
}

void SignalPlots::setTimeRange(double from_s, double to_s)
{
    timeRows_->setRange(from_s, to_s);
}

void SignalPlots::showAll()
{
    if (recording_ && recording_->samples.size() >= 2)
        setTimeRange(recording_->samples.front().time_s, recording_->samples.back().time_s);
}

void SignalPlots::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Home)
        showAll();
    else if (!timeRows_->navigate(event->key()))
        return QWidget::keyPressEvent(event);
    event->accept();
}

void SignalPlots::renderTo(QPainter& painter, const QRect& target)
{
    renderPlotTo(plot_, painter, target);
}

void SignalPlots::showRecording(const AnalysisSession& session)
{
    setRecording(session.recording());
}

void SignalPlots::showEstimate(const AnalysisSession& session)
{
    setResult(session.result());
}

}  // namespace footpath
