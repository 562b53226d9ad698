#include "TimeAxisNavigation.h"

#include <QApplication>
#include <QPicture>

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
