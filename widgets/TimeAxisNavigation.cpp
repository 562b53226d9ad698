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

}  // namespace footpath
