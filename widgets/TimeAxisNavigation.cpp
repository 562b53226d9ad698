#include "TimeAxisNavigation.h"

#include <QApplication>
#include <QPicture>

#include <algorithm>
#include <numeric>

namespace footpath {

namespace {
constexpr double kZoomInFactor = 0.8;  // +/- keys: a fifth of the visible time per press
constexpr double kPanFraction = 0.1;   // Left/Right keys: a tenth of the visible time per press
}  // namespace

std::optional<QCPRange> keyNavigatedRange(int key, double from_s, double to_s)
{
    const double centre = (from_s + to_s) / 2.0;
    const double width = to_s - from_s;
    switch (key) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:  // '+' without Shift on most layouts
        return QCPRange(centre - kZoomInFactor * width / 2.0, centre + kZoomInFactor * width / 2.0);
    case Qt::Key_Minus:
        return QCPRange(centre - width / kZoomInFactor / 2.0, centre + width / kZoomInFactor / 2.0);
    case Qt::Key_Left:
        return QCPRange(from_s - kPanFraction * width, to_s - kPanFraction * width);
    case Qt::Key_Right:
        return QCPRange(from_s + kPanFraction * width, to_s + kPanFraction * width);
    default:
        return std::nullopt;
    }
}

bool isClick(const QPoint& pressed, const QPoint& released, Qt::MouseButton button)
{
    return button == Qt::LeftButton && (released - pressed).manhattanLength() <= QApplication::startDragDistance();
}

void renderPlotTo(QCustomPlot* plot, QPainter& painter, const QRect& target)
{
    QPicture picture;
    {
        QCPPainter recorder(&picture);
        plot->toPainter(&recorder, target.width(), target.height());
    }
    painter.drawPicture(target.topLeft(), picture);
}

void wrapLegendToWidth(QCPLegend* legend, int available)
{
    std::vector<int> itemWidths;
    for (int i = 0; i < legend->itemCount(); ++i) {
        if (const QCPAbstractLegendItem* item = legend->item(i))  // null: a cell left by a removed item
            itemWidths.push_back(item->minimumOuterSizeHint().width());
    }
    available -= legend->margins().left() + legend->margins().right();
    int perRow = static_cast<int>(itemWidths.size());
    for (; perRow > 1; --perRow) {
        std::vector<int> columnWidths(static_cast<std::size_t>(perRow), 0);
        for (std::size_t i = 0; i < itemWidths.size(); ++i)
            columnWidths[i % columnWidths.size()] = std::max(columnWidths[i % columnWidths.size()], itemWidths[i]);
        // The spacing before the trailing packing column counts too, and a pixel per column to
        // spare for the grid's rounding: an item short of its text clips the last letter ("Foot patl").
        const int needed = std::accumulate(columnWidths.cbegin(), columnWidths.cend(), 0)
                           + perRow * legend->columnSpacing() + perRow;
        if (needed <= available)
            break;
    }
    legend->setWrap(std::max(1, perRow));
    legend->setFillOrder(QCPLegend::foColumnsFirst, true);
    legend->simplify();  // drops the last call's packing column: one, with its spacing, is counted
    // Pack the items to the left: a trailing empty column takes the spare width.
    legend->insertColumn(legend->columnCount());
    legend->setColumnStretchFactor(legend->columnCount() - 1, 1000.0);
}

LegendStrip::LegendStrip(QCustomPlot* plot) : QObject(plot), plot_(plot), legend_(new QCPLegend)
{
    QCPLayoutGrid* layout = plot->plotLayout();
    if (layout->rowCount() > 0)
        layout->insertRow(0);
    layout->addElement(0, 0, legend_);
    layout->setRowStretchFactor(0, 0.001);  // its own height; the rows share the rest
    legend_->setLayer(QStringLiteral("legend"));
    legend_->setBorderPen(Qt::NoPen);
    legend_->setBrush(Qt::NoBrush);
    legend_->setMargins(QMargins(4, 0, 4, 0));
    legend_->setRowSpacing(0);
    legend_->setColumnSpacing(14);
    legend_->setIconSize(24, 10);
    legend_->setMinimumSize(1, 0);  // its width never sets the plot's: it wraps instead
    QFont font = legend_->font();
    font.setPointSizeF(font.pointSizeF() * 0.9);
    legend_->setFont(font);
    connect(plot, &QCustomPlot::beforeReplot, this, &LegendStrip::fitToWidth);
}

namespace {

bool looksAlike(const QCPAbstractPlottable* a, const QCPAbstractPlottable* b)
{
    return a->name() == b->name() && a->pen() == b->pen() && a->brush() == b->brush();
}

}  // namespace

void LegendStrip::setEntries(const std::vector<QCPAbstractPlottable*>& entries)
{
    legend_->clearItems();
    std::vector<const QCPAbstractPlottable*> shown;
    for (QCPAbstractPlottable* entry : entries) {
        const bool duplicate = std::any_of(shown.cbegin(), shown.cend(),
                                           [entry](const QCPAbstractPlottable* s) { return looksAlike(s, entry); });
        if (duplicate)
            continue;
        entry->addToLegend(legend_);
        shown.push_back(entry);
    }
    legend_->setVisible(!shown.empty());
    fitToWidth();
}

bool LegendStrip::showsEntryLike(const QCPAbstractPlottable* plottable) const
{
    for (int i = 0; i < legend_->itemCount(); ++i) {
        auto* item = qobject_cast<QCPPlottableLegendItem*>(legend_->item(i));
        if (item && looksAlike(item->plottable(), plottable))
            return true;
    }
    return false;
}

void LegendStrip::fitToWidth()
{
    wrapLegendToWidth(legend_, plot_->viewport().width());
}

QCPItemStraightLine* addCursorLine(QCustomPlot* plot, QCPAxisRect* rect, const QString& layer)
{
    static const QColor cursorColour(170, 0, 0);
    QCPAxis* unit = rect->axis(QCPAxis::atRight);
    unit->setRange(0.0, 1.0);
    auto* line = new QCPItemStraightLine(plot);
    line->setLayer(layer);
    line->setClipToAxisRect(true);  // the default only when the plot had an axis rect already
    line->setClipAxisRect(rect);
    line->setSelectable(false);
    line->setPen(QPen(cursorColour, 1.5));
    line->point1->setAxes(rect->axis(QCPAxis::atBottom), unit);
    line->point2->setAxes(rect->axis(QCPAxis::atBottom), unit);
    line->point1->setCoords(0.0, 0.0);
    line->point2->setCoords(0.0, 1.0);
    line->setVisible(false);
    return line;
}

LinkedTimeRows::LinkedTimeRows(QCustomPlot* plot) : QObject(plot), plot_(plot)
{
    connect(plot_, &QCustomPlot::mousePress, this, [this](QMouseEvent* event) { pressPos_ = event->position().toPoint(); });
    connect(plot_, &QCustomPlot::mouseRelease, this, &LinkedTimeRows::onMouseRelease);
}

void LinkedTimeRows::addRow(QCPAxisRect* rect)
{
    QCPAxis* time = rect->axis(QCPAxis::atBottom);
    rect->setRangeDrag(Qt::Horizontal);
    rect->setRangeZoom(Qt::Horizontal);
    rect->setRangeDragAxes(time, nullptr);
    rect->setRangeZoomAxes(time, nullptr);
    connect(time, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, &LinkedTimeRows::onRowRangeChanged);
    rows_.push_back(rect);
}

void LinkedTimeRows::setRange(double from_s, double to_s)
{
    // Any row will do: onRowRangeChanged passes the range on to the others.
    if (!rows_.empty())
        rows_.front()->axis(QCPAxis::atBottom)->setRange(from_s, to_s);
}

bool LinkedTimeRows::navigate(int key)
{
    const std::optional<QCPRange> range = keyNavigatedRange(key, from_s_, to_s_);
    if (range)
        setRange(range->lower, range->upper);
    return range.has_value();
}

void LinkedTimeRows::onRowRangeChanged(const QCPRange& range)
{
    if (range.lower == from_s_ && range.upper == to_s_)
        return;  // the echo from a row this handler has just set
    from_s_ = range.lower;
    to_s_ = range.upper;
    for (QCPAxisRect* row : rows_)
        row->axis(QCPAxis::atBottom)->setRange(range);
    plot_->replot(QCustomPlot::rpQueuedReplot);  // a drag changes the range many times per frame
    emit rangeChanged(range.lower, range.upper);
}

void LinkedTimeRows::onMouseRelease(QMouseEvent* event)
{
    // A drag pans the time axis; only a click that stayed put places the cursor.
    const QPoint pos = event->position().toPoint();
    if (!isClick(pressPos_, pos, event->button()) || (event->modifiers() & Qt::ShiftModifier))
        return;
    for (QCPAxisRect* row : rows_) {
        if (row->layout() != nullptr && row->rect().contains(pos)) {  // hidden rows are out of the layout
            emit clicked(row->axis(QCPAxis::atBottom)->pixelToCoord(pos.x()));
            return;
        }
    }
}

}  // namespace footpath
