#include "TrajectoryView2D.h"

#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>

namespace footpath {

namespace {

QCPGraph* addMarkerGraph(QCustomPlot* plot, const QString& name, QCPScatterStyle style)
{
    QCPGraph* graph = plot->addGraph();
    graph->setName(name);
    graph->setLineStyle(QCPGraph::lsNone);
    graph->setScatterStyle(style);
    return graph;
}

}  // namespace

TrajectoryView2D::TrajectoryView2D(QWidget* parent)
    : QWidget(parent), plot_(new QCustomPlot(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(plot_);

    path_ = new QCPCurve(plot_->xAxis, plot_->yAxis);
    path_->setName(tr("Foot path"));
    path_->setPen(QPen(QColor(40, 90, 170), 1.5));
    stances_ = addMarkerGraph(plot_, tr("Stance"), QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(230, 120, 20), 5));
    start_ = addMarkerGraph(plot_, tr("Start"), QCPScatterStyle(QCPScatterStyle::ssSquare, QPen(Qt::darkGreen, 2), Qt::white, 11));
    end_ = addMarkerGraph(plot_, tr("End"), QCPScatterStyle(QCPScatterStyle::ssCross, QPen(Qt::red, 2), Qt::NoBrush, 11));

    plot_->xAxis->setLabel(tr("x (m)"));
    plot_->yAxis->setLabel(tr("y (m)"));
    plot_->legend->setVisible(true);
    plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
}

void TrajectoryView2D::clear()
{
    path_->data()->clear();
    for (QCPGraph* graph : {stances_, start_, end_})
        graph->data()->clear();
    dataBounds_ = QRectF();
    plot_->replot();
}

void TrajectoryView2D::showResult(const Result& result)
{
    QVector<double> t, x, y;
    t.reserve(static_cast<qsizetype>(result.position_m.size()));
    x.reserve(t.capacity());
    y.reserve(t.capacity());
    for (std::size_t k = 0; k < result.position_m.size(); ++k) {
        t << static_cast<double>(k);
        x << result.position_m[k].x();
        y << result.position_m[k].y();
    }
    path_->setData(t, x, y, true);
    stances_->data()->clear();
    for (const Step& step : result.steps)
        stances_->addData(step.position_m.x(), step.position_m.y());
    start_->data()->clear();
    end_->data()->clear();
    if (!x.isEmpty()) {
        start_->addData(x.front(), y.front());
        end_->addData(x.back(), y.back());
    }
    dataBounds_ = QRectF();
    if (!x.isEmpty()) {
        const auto [xMin, xMax] = std::minmax_element(x.cbegin(), x.cend());
        const auto [yMin, yMax] = std::minmax_element(y.cbegin(), y.cend());
        dataBounds_ = QRectF(QPointF(*xMin, *yMin), QPointF(*xMax, *yMax));
    }
    keepEqualAxisScales();
    plot_->replot();
}

void TrajectoryView2D::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    keepEqualAxisScales();
    plot_->replot();
}

void TrajectoryView2D::keepEqualAxisScales()
{
    // Widen whichever axis is shorter in metres per pixel so one metre is as long on both axes.
    const QRect rect = plot_->axisRect()->rect();
    if (rect.width() <= 0 || rect.height() <= 0 || dataBounds_.isNull())
        return;
    const double margin = 0.05 * std::max(dataBounds_.width(), dataBounds_.height()) + 0.1;
    const QCPRange xRange(dataBounds_.left() - margin, dataBounds_.right() + margin);
    const QCPRange yRange(dataBounds_.top() - margin, dataBounds_.bottom() + margin);
    const double perPixel = std::max(xRange.size() / rect.width(), yRange.size() / rect.height());
    plot_->xAxis->setRange(xRange.center(), perPixel * rect.width(), Qt::AlignCenter);
    plot_->yAxis->setRange(yRange.center(), perPixel * rect.height(), Qt::AlignCenter);
}

}  // namespace footpath
