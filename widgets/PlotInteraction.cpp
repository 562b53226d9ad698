#include "PlotInteraction.h"

#include <QApplication>
#include <QFile>
#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>
#include <QRegularExpression>
#include <QSaveFile>
#include <QSvgGenerator>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace footpath {

namespace {

const QString kInteractionLayer = QStringLiteral("interaction");
constexpr double kWheelZoomBase = 0.85;  // QCustomPlot's own factor per wheel step
constexpr double kWheelStep = 120.0;     // angleDelta of one notch
constexpr int kReadoutPadding_px = 4;
constexpr int kMinimumTimeDecimals = 3;
constexpr qsizetype kEntriesPerLine = 3;  // a 200 Hz sample is 5 ms apart: the readout tells them apart

QCPAxis* timeAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atBottom); }
QCPAxis* valueAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atLeft); }

bool isShown(const QCPAxisRect* rect) { return rect->visible() && rect->layout() != nullptr; }

/// The unit an axis label states in its last parentheses ("Acceleration\n(m/s²)" -> "m/s²"); empty
/// when it states none or a phrase ("file units").
QString unitOfLabel(const QString& label)
{
    static const QRegularExpression lastParentheses(QStringLiteral("\\(([^()]*)\\)\\s*$"));
    const QRegularExpressionMatch match = lastParentheses.match(label);
    const QString unit = match.hasMatch() ? match.captured(1) : QString();
    return unit.contains(QLatin1Char(' ')) ? QString() : unit;
}

QString oneLine(QString label) { return label.replace(QLatin1Char('\n'), QLatin1Char(' ')); }

/// The graphs a readout or an export speaks of in a row: shown, named, with data, on the row's
/// value axis (legend-only entries and the cursor's 0..1 axis are left out).
std::vector<const QCPGraph*> graphsOfRow(const QCustomPlot* plot, const QCPAxisRect* rect)
{
    std::vector<const QCPGraph*> graphs;
    for (int g = 0; g < plot->graphCount(); ++g) {
        const QCPGraph* graph = plot->graph(g);
        if (graph->keyAxis() == timeAxis(rect) && graph->valueAxis() == valueAxis(rect) && graph->visible()
            && !graph->name().isEmpty() && !graph->data()->isEmpty())
            graphs.push_back(graph);
    }
    return graphs;
}

/// The value the graph draws at key: a step curve's held value, else the nearest sample's; nothing
/// outside the graph's keys or where it has a gap (NaN).
std::optional<double> graphValueAt(const QCPGraph* graph, double key)
{
    const QSharedPointer<QCPGraphDataContainer> data = graph->data();
    if (data->isEmpty() || key < data->constBegin()->key || key > (data->constEnd() - 1)->key)
        return std::nullopt;
    auto above = data->findBegin(key, false);  // the first sample at or after key
    if (above == data->constEnd())
        above = data->constEnd() - 1;
    auto chosen = above;
    if (above->key != key && above != data->constBegin()) {
        const auto below = above - 1;
        const bool hold = graph->lineStyle() == QCPGraph::lsStepLeft;
        chosen = hold || key - below->key < above->key - key ? below : above;
    }
    if (std::isnan(chosen->value))
        return std::nullopt;
    return chosen->value;
}

QString csvField(QString text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')))
        return text;
    return QLatin1Char('"') + text.replace(QLatin1Char('"'), QStringLiteral("\"\"")) + QLatin1Char('"');
}

QString csvNumber(double value)
{
    if (value == 0.0)
        return QStringLiteral("0");  // also -0
    return QString::number(value, 'g', 10);
}

}  // namespace

/// The least room between tick labels: a line of text and a gap up an axis, a number and a gap
/// along it.
constexpr int kMinTickSpacingVertical_px = 22;
constexpr int kMinTickSpacingHorizontal_px = 70;

QString formatPlotNumber(double value, int decimals)
{
    QString text = QString::number(value, 'f', std::max(0, decimals));
    // "-0.000": a tiny negative rounded to zero says nothing about its sign worth reading.
    if (text.startsWith(QLatin1Char('-')) && text.count(QLatin1Char('0')) == text.size() - 1 - text.count(QLatin1Char('.')))
        text.remove(0, 1);
    return text;
}

QString formatFigure(double value, int decimals, const QLocale& locale)
{
    if (!std::isfinite(value))
        return QStringLiteral("\u2013");
    decimals = std::max(0, decimals);
    const QString text = locale.toString(value, 'f', decimals);
    // Whatever the locale's digits and signs: a text without a non-zero digit is a zero.
    const bool roundsToZero = std::none_of(text.cbegin(), text.cend(), [](QChar c) { return c.isDigit() && c.digitValue() > 0; });
    return roundsToZero ? locale.toString(0.0, 'f', decimals) : text;
}

int decimalsForSpan(double span)
{
    if (!(span > 0.0) || !std::isfinite(span))
        return 3;
    return std::clamp(3 - static_cast<int>(std::floor(std::log10(span))), 0, 9);
}

double ReadableTicker::getTickStep(const QCPRange& range)
{
    const double exact = range.size() / (tickCount() + 1e-10);
    const double magnitude = std::pow(10.0, std::floor(std::log10(exact)));
    double step = magnitude;
    for (const double mantissa : {2.0, 5.0, 10.0}) {  // the one nearest the asked tick count
        if (std::abs(std::log(mantissa * magnitude / exact)) < std::abs(std::log(step / exact)))
            step = mantissa * magnitude;
    }
    decimals_ = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
    return step;
}

QString ReadableTicker::getTickLabel(double tick, const QLocale& locale, QChar formatChar, int precision)
{
    if (std::abs(tick) >= 1e7)  // beyond what fixed notation reads well
        return QCPAxisTicker::getTickLabel(tick, locale, formatChar, precision);
    return formatPlotNumber(tick, decimals_);
}

void useReadableTicks(QCustomPlot* plot)
{
    for (QCPAxisRect* rect : plot->axisRects()) {
        for (QCPAxis* axis : rect->axes()) {
            const QCPAxisTicker* ticker = axis->ticker().data();
            if (axis->scaleType() == QCPAxis::stLinear && ticker != nullptr && typeid(*ticker) == typeid(QCPAxisTicker))
                axis->setTicker(QSharedPointer<ReadableTicker>::create());
            // As many ticks as the axis has room for: a 70-pixel row's five labels touched.
            if (auto* readable = dynamic_cast<ReadableTicker*>(axis->ticker().data())) {
                const bool vertical = axis->orientation() == Qt::Vertical;
                const int length = vertical ? rect->height() : rect->width();
                const int spacing = vertical ? kMinTickSpacingVertical_px : kMinTickSpacingHorizontal_px;
                readable->setTickCount(std::clamp(length / spacing, 3, 6));
            }
        }
    }
}

/// Draws the hover line, the marker, the snapped dot and the readout box on a buffered layer of its
/// own, so moving the mouse repaints only this.
class PlotInteraction::Overlay : public QCPLayerable {
public:
    Overlay(QCustomPlot* plot, PlotInteraction* owner) : QCPLayerable(plot, kInteractionLayer), owner_(owner) {}

protected:
    void applyDefaultAntialiasingHint(QCPPainter* painter) const override { painter->setAntialiasing(true); }
    QRect clipRect() const override { return mParentPlot->viewport(); }
    void draw(QCPPainter* painter) override;

private:
    void drawMarker(QCPPainter* painter) const;
    void drawReadout(QCPPainter* painter) const;

    PlotInteraction* owner_;
};

void PlotInteraction::Overlay::draw(QCPPainter* painter)
{
    drawMarker(painter);
    const PlotInteraction& o = *owner_;
    if (o.hoveredRect_ == nullptr)
        return;
    const QRect area = o.hoveredRect_->rect();
    if (o.hoverSnapped_) {
        const QPointF dot(timeAxis(o.hoveredRect_)->coordToPixel(o.hoverSnapped_->x()),
                          valueAxis(o.hoveredRect_)->coordToPixel(o.hoverSnapped_->y()));
        painter->setPen(QPen(QColor(20, 20, 20), 1.5));
        painter->setBrush(Qt::white);
        painter->drawEllipse(dot, 4.0, 4.0);
    } else {
        painter->setPen(QPen(QColor(90, 90, 90), 1.0, Qt::DotLine));
        painter->drawLine(QLineF(o.hoverPixel_.x(), area.top(), o.hoverPixel_.x(), area.bottom()));
    }
    drawReadout(painter);
}

void PlotInteraction::Overlay::drawMarker(QCPPainter* painter) const
{
    const PlotInteraction& o = *owner_;
    if (!o.marker_)
        return;
    const QPen pen(QColor(0, 100, 160), 1.5, Qt::DashLine);
    painter->setPen(pen);
    if (o.prober_) {  // a point in a plane: a cross where it is
        const QPointF at(timeAxis(o.marker_->rect)->coordToPixel(o.marker_->point.x()),
                         valueAxis(o.marker_->rect)->coordToPixel(o.marker_->point.y()));
        painter->setPen(QPen(pen.color(), 2.0));
        painter->drawLine(QLineF(at.x() - 7, at.y() - 7, at.x() + 7, at.y() + 7));
        painter->drawLine(QLineF(at.x() - 7, at.y() + 7, at.x() + 7, at.y() - 7));
        return;
    }
    for (const QCPAxisRect* rect : mParentPlot->axisRects()) {  // a moment: through every row
        if (!isShown(rect))
            continue;
        const double x = timeAxis(rect)->coordToPixel(o.marker_->point.x());
        if (x >= rect->left() && x <= rect->right())
            painter->drawLine(QLineF(x, rect->top(), x, rect->bottom()));
    }
}

void PlotInteraction::Overlay::drawReadout(QCPPainter* painter) const
{
    const PlotInteraction& o = *owner_;
    if (o.readout_.isEmpty())
        return;
    QFont font = mParentPlot->font();
    font.setPointSizeF(font.pointSizeF() * 0.9);
    painter->setFont(font);
    const QRect area = o.hoveredRect_->rect();
    const QRect available = area.adjusted(kReadoutPadding_px * 2, kReadoutPadding_px, 0, 0);
    const QRect text = painter->fontMetrics().boundingRect(available, Qt::AlignLeft | Qt::AlignTop, o.readout_);
    // Top left of the row, where legends are not; where the mouse is there, the bottom left.
    QRect box = text.adjusted(-kReadoutPadding_px, -kReadoutPadding_px, kReadoutPadding_px, kReadoutPadding_px);
    if (box.contains(o.hoverPixel_.toPoint()))
        box.moveBottom(area.bottom() - kReadoutPadding_px);
    painter->setPen(QPen(QColor(150, 150, 150)));
    painter->setBrush(QColor(255, 255, 250, 230));
    painter->drawRect(box);
    painter->setPen(QColor(20, 20, 20));
    painter->drawText(box.adjusted(kReadoutPadding_px, kReadoutPadding_px, 0, 0), Qt::AlignLeft | Qt::AlignTop, o.readout_);
}

PlotInteraction::PlotInteraction(QCustomPlot* plot) : QObject(plot), plot_(plot)
{
    plot_->addLayer(kInteractionLayer, plot_->layer(plot_->layerCount() - 1), QCustomPlot::limAbove);
    plot_->layer(kInteractionLayer)->setMode(QCPLayer::lmBuffered);
    overlay_ = new Overlay(plot_, this);
    useReadableTicks(plot_);  // every interactive plot: round ticks, no "-0"
    plot_->setMouseTracking(true);
    plot_->installEventFilter(this);
    if (QWidget* view = plot_->parentWidget())  // keys reach the view, which holds the focus
        view->installEventFilter(this);
    plot_->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(plot_, &QWidget::customContextMenuRequested, this, [this](const QPoint& pos) {
        QMenu* menu = createContextMenu(plot_);
        menu->setAttribute(Qt::WA_DeleteOnClose);
        menu->popup(plot_->mapToGlobal(pos));
    });
    // Rows added after this (a pressure row appears with a file that has one) get round ticks
    // too: their default ticker labelled a pressure axis 1004, 1003.75, 1003.5 and collided.
    connect(plot_, &QCustomPlot::beforeReplot, this, [this] { useReadableTicks(plot_); });
}

QCPAxisRect* PlotInteraction::rowAt(const QPointF& pixel, bool includeAxisMargin) const
{
    for (QCPAxisRect* rect : plot_->axisRects()) {
        if (!isShown(rect))
            continue;
        QRect area = rect->rect();
        if (includeAxisMargin)
            area.setLeft(rect->outerRect().left());
        if (area.contains(pixel.toPoint()))
            return rect;
    }
    return nullptr;
}

bool PlotInteraction::takesValueZoom(const QCPAxisRect* rect) const
{
    if (prober_)
        return false;  // a plane keeps its scales equal: zoom acts on both axes there
    const QCPAxis* axis = valueAxis(rect);
    return axis->visible() && axis->ticks() && qSharedPointerDynamicCast<QCPAxisTickerText>(axis->ticker()).isNull();
}

bool PlotInteraction::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::KeyPress && static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape && marker_) {
        clearMarker();
        return true;
    }
    if (watched != plot_)
        return QObject::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::Wheel: return onWheel(static_cast<QWheelEvent*>(event));
    case QEvent::MouseButtonPress: return onMousePress(static_cast<QMouseEvent*>(event));
    case QEvent::MouseMove: return onMouseMove(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonRelease: return onMouseRelease(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonDblClick:
        if (static_cast<QMouseEvent*>(event)->button() != Qt::LeftButton)
            return false;
        resetView();
        return true;
    case QEvent::Leave: clearProbe(); return false;
    default: return false;
    }
}

bool PlotInteraction::onWheel(QWheelEvent* event)
{
    const QPointF pixel = event->position();
    QCPAxisRect* rect = rowAt(pixel, true);
    if (rect == nullptr || !takesValueZoom(rect))
        return false;
    const bool overValueAxis = pixel.x() < rect->left();
    if (!overValueAxis && !(event->modifiers() & Qt::ControlModifier))
        return false;  // the plain wheel in a row zooms time, as it always did
    const double steps = event->angleDelta().y() / kWheelStep;
    QCPAxis* axis = valueAxis(rect);
    axis->scaleRange(std::pow(kWheelZoomBase, steps), axis->pixelToCoord(pixel.y()));
    plot_->replot(QCustomPlot::rpQueuedReplot);
    event->accept();
    return true;
}

bool PlotInteraction::onMousePress(QMouseEvent* event)
{
    pressPos_ = event->position().toPoint();
    QCPAxisRect* rect = rowAt(event->position(), true);
    if (event->button() != Qt::LeftButton || rect == nullptr || event->position().x() >= rect->left()
        || !takesValueZoom(rect))
        return false;
    draggedValueAxis_ = valueAxis(rect);  // a drag on the value axis pans it, not time
    dragStartRange_ = draggedValueAxis_->range();
    return true;
}

bool PlotInteraction::onMouseMove(QMouseEvent* event)
{
    if (draggedValueAxis_ == nullptr) {
        probeAt(event->position());
        return false;
    }
    QCPAxis* axis = draggedValueAxis_;
    axis->setRange(dragStartRange_);
    const double from = axis->pixelToCoord(pressPos_.y()), to = axis->pixelToCoord(event->position().y());
    if (axis->scaleType() == QCPAxis::stLogarithmic && from > 0.0 && to > 0.0)
        axis->setRange(dragStartRange_.lower * from / to, dragStartRange_.upper * from / to);
    else
        axis->setRange(dragStartRange_.lower + from - to, dragStartRange_.upper + from - to);
    plot_->replot(QCustomPlot::rpQueuedReplot);
    return true;
}

bool PlotInteraction::onMouseRelease(QMouseEvent* event)
{
    if (draggedValueAxis_ != nullptr) {
        draggedValueAxis_ = nullptr;
        return true;
    }
    const bool stayedPut = (event->position().toPoint() - pressPos_).manhattanLength() <= QApplication::startDragDistance();
    if (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier) && stayedPut)
        setMarkerAt(event->position());
    return false;  // QCustomPlot ends its own drag on the release
}

void PlotInteraction::probeAt(const QPointF& pixel)
{
    hoveredRect_ = rowAt(pixel, false);
    hoverPixel_ = pixel;
    hoverSnapped_.reset();
    readout_.clear();
    if (hoveredRect_ != nullptr && prober_) {
        const std::optional<QPointF> marker = marker_ ? std::optional<QPointF>(marker_->point) : std::nullopt;
        if (const std::optional<Probe> probe = prober_(pixel, marker)) {
            readout_ = probe->text;
            hoverSnapped_ = probe->snapped;
        }
    } else if (hoveredRect_ != nullptr) {
        readout_ = timeSeriesReadout(hoveredRect_, timeAxis(hoveredRect_)->pixelToCoord(pixel.x()));
    }
    redrawOverlay();
}

void PlotInteraction::clearProbe()
{
    hoveredRect_ = nullptr;
    hoverSnapped_.reset();
    readout_.clear();
    redrawOverlay();
}

QString PlotInteraction::timeSeriesReadout(QCPAxisRect* rect, double time_s) const
{
    const int timeDecimals = std::max(kMinimumTimeDecimals, decimalsForSpan(timeAxis(rect)->range().size()));
    QString text = tr("t = %1 s").arg(formatPlotNumber(time_s, timeDecimals));
    if (marker_)
        text += tr("   Δt = %1 s from the marker").arg(formatPlotNumber(time_s - marker_->point.x(), timeDecimals));
    const QString unit = unitOfLabel(valueAxis(rect)->label());
    QStringList entries;
    for (const QCPGraph* graph : graphsOfRow(plot_, rect)) {
        const std::optional<double> value = graphValueAt(graph, time_s);
        if (!value)
            continue;
        const std::optional<QString> worded = valueFormatter_ ? valueFormatter_(graph, *value) : std::nullopt;
        QString entry = graph->name() + QStringLiteral(" = ");
        entry += worded ? *worded : graphValueText(graph, *value) + (unit.isEmpty() ? QString() : QLatin1Char(' ') + unit);
        const std::optional<double> atMarker = marker_ ? graphValueAt(graph, marker_->point.x()) : std::nullopt;
        if (atMarker && !worded)
            entry += tr(" (Δ %1)").arg(graphValueText(graph, *value - *atMarker));
        entries << entry;
    }
    // A few entries a line: rows are short, and a line per curve would run past them.
    for (qsizetype e = 0; e < entries.size(); e += kEntriesPerLine)
        text += QLatin1Char('\n') + entries.mid(e, kEntriesPerLine).join(QStringLiteral("    "));
    return text;
}

QString PlotInteraction::graphValueText(const QCPGraph* graph, double value) const
{
    const QCPAxis* axis = graph->valueAxis();
    if (axis->scaleType() == QCPAxis::stLogarithmic)
        return QString::number(value, 'g', 3);
    return formatPlotNumber(value, decimalsForSpan(axis->range().size()));
}

void PlotInteraction::setMarkerAt(const QPointF& pixel)
{
    QCPAxisRect* rect = rowAt(pixel, false);
    if (rect == nullptr)
        return;
    QPointF point(timeAxis(rect)->pixelToCoord(pixel.x()), valueAxis(rect)->pixelToCoord(pixel.y()));
    if (prober_) {
        const std::optional<Probe> probe = prober_(pixel, std::nullopt);
        if (!probe)
            return;  // not near anything the view can measure from
        point = probe->snapped;
    }
    marker_ = Marker{rect, point};
    probeAt(pixel);
}

void PlotInteraction::clearMarker()
{
    marker_.reset();
    if (hoveredRect_ != nullptr)
        probeAt(hoverPixel_);
    else
        redrawOverlay();
}

void PlotInteraction::redrawOverlay()
{
    plot_->layer(kInteractionLayer)->replot();
}

void PlotInteraction::resetView()
{
    if (reset_)
        reset_();
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

bool PlotInteraction::exportPng(const QString& path) const
{
    overlay_->setVisible(false);  // the readout belongs to the mouse, not to the figure
    const bool saved = plot_->savePng(path, plot_->width(), plot_->height(), 2.0);
    overlay_->setVisible(true);
    return saved;
}

bool PlotInteraction::exportPdf(const QString& path) const
{
    overlay_->setVisible(false);
    const bool saved = plot_->savePdf(path, plot_->width(), plot_->height());
    overlay_->setVisible(true);
    return saved;
}

bool PlotInteraction::exportSvg(const QString& path) const
{
    const QSize size(plot_->width(), plot_->height());
    if (size.isEmpty())
        return false;
    QSvgGenerator svg;
    svg.setFileName(path);
    svg.setSize(size);
    svg.setViewBox(QRect(QPoint(0, 0), size));
    svg.setTitle(plot_->window()->windowTitle());
    QCPPainter painter;
    if (!painter.begin(&svg))
        return false;
    overlay_->setVisible(false);
    plot_->toPainter(&painter, size.width(), size.height());
    overlay_->setVisible(true);
    // QSvgGenerator does not report write errors; an empty or missing file is the sign of one.
    return painter.end() && QFileInfo(path).size() > 0;
}

QString PlotInteraction::visibleDataCsv() const
{
    if (csvWriter_)
        return csvWriter_();
    std::vector<QCPAxisRect*> rows;
    for (QCPAxisRect* rect : plot_->axisRects())
        if (isShown(rect))
            rows.push_back(rect);
    std::sort(rows.begin(), rows.end(), [](const QCPAxisRect* a, const QCPAxisRect* b) { return a->top() < b->top(); });
    QStringList header{tr("Time (s)")};
    std::vector<const QCPGraph*> columns;
    std::vector<double> keys;
    for (const QCPAxisRect* rect : rows) {
        const QCPRange visible = timeAxis(rect)->range();
        const QString row = oneLine(valueAxis(rect)->label());
        for (const QCPGraph* graph : graphsOfRow(plot_, rect)) {
            columns.push_back(graph);
            header << csvField(row.isEmpty() ? graph->name() : row + QStringLiteral(": ") + graph->name());
            for (auto it = graph->data()->findBegin(visible.lower, false); it != graph->data()->constEnd() && it->key <= visible.upper; ++it)
                keys.push_back(it->key);
        }
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    QString csv = header.join(QLatin1Char(',')) + QLatin1Char('\n');
    for (const double key : keys) {
        QStringList cells{csvNumber(key)};
        for (const QCPGraph* graph : columns) {
            const std::optional<double> value = graphValueAt(graph, key);
            cells << (value ? csvNumber(*value) : QString());
        }
        csv += cells.join(QLatin1Char(',')) + QLatin1Char('\n');
    }
    return csv;
}

bool PlotInteraction::exportCsv(const QString& path) const
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return false;
    file.write(visibleDataCsv().toUtf8());
    return file.commit();
}

void PlotInteraction::chooseFileAndExport(const QString& title, const QString& filter, const QString& suffix,
                                          const std::function<bool(const QString&)>& write)
{
    QString path = QFileDialog::getSaveFileName(plot_, title, QStringLiteral("plot.") + suffix, filter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QLatin1Char('.') + suffix;
    if (!write(path))
        QMessageBox::warning(plot_, title, tr("Could not write %1.").arg(QDir::toNativeSeparators(path)));
}

QMenu* PlotInteraction::createContextMenu(QWidget* parent)
{
    auto* menu = new QMenu(parent);
    QAction* reset = menu->addAction(tr("Reset view"), this, &PlotInteraction::resetView);
    reset->setObjectName(QStringLiteral("resetView"));
    QAction* clear = menu->addAction(tr("Clear measurement marker"), this, &PlotInteraction::clearMarker);
    clear->setObjectName(QStringLiteral("clearMarker"));
    clear->setEnabled(marker_.has_value());
    clear->setToolTip(tr("Shift+click sets the marker; the readout then shows the differences to it"));
    menu->addSeparator();
    menu->addAction(tr("Export as PNG…"), this, [this] {
        chooseFileAndExport(tr("Export plot as PNG"), tr("PNG images (*.png)"), QStringLiteral("png"),
                            [this](const QString& path) { return exportPng(path); });
    })->setObjectName(QStringLiteral("exportPng"));
    menu->addAction(tr("Export as SVG…"), this, [this] {
        chooseFileAndExport(tr("Export plot as SVG"), tr("SVG images (*.svg)"), QStringLiteral("svg"),
                            [this](const QString& path) { return exportSvg(path); });
    })->setObjectName(QStringLiteral("exportSvg"));
    menu->addAction(tr("Export as PDF (vector)…"), this, [this] {
        chooseFileAndExport(tr("Export plot as PDF"), tr("PDF documents (*.pdf)"), QStringLiteral("pdf"),
                            [this](const QString& path) { return exportPdf(path); });
    })->setObjectName(QStringLiteral("exportPdf"));
    menu->addAction(tr("Export visible data as CSV…"), this, [this] {
        chooseFileAndExport(tr("Export visible data as CSV"), tr("CSV files (*.csv)"), QStringLiteral("csv"),
                            [this](const QString& path) { return exportCsv(path); });
    })->setObjectName(QStringLiteral("exportCsv"));
    return menu;
}

}  // namespace footpath
