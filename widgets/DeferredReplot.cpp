#include "DeferredReplot.h"

#include <QElapsedTimer>
#include <QEvent>
#include <qcustomplot.h>

#include <utility>

namespace footpath {

DeferredReplot::DeferredReplot(QCustomPlot* plot) : QObject(plot), plot_(plot)
{
    plot_->installEventFilter(this);
}

void DeferredReplot::request()
{
    pending_ = true;
    if (plot_->isVisible())
        schedule();
}

void DeferredReplot::requestLayers(const QList<QCPLayer*>& layers)
{
    for (QCPLayer* layer : layers)
        if (!pendingLayers_.contains(layer))
            pendingLayers_.append(layer);
    if (plot_->isVisible())
        schedule();
}

void DeferredReplot::schedule()
{
    if (scheduled_)
        return;
    scheduled_ = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            scheduled_ = false;
            if (plot_->isVisible())
                flush();
        },
        Qt::QueuedConnection);
}

void DeferredReplot::flush()
{
    const QList<QCPLayer*> layers = std::exchange(pendingLayers_, {});
    if (pending_) {
        pending_ = false;
        plot_->replot(QCustomPlot::rpQueuedRefresh);  // the paint under way (or the next) shows the new buffers
        return;
    }
    if (layers.isEmpty())
        return;
    QElapsedTimer timer;
    timer.start();
    // Each redraws its own buffer and asks for a paint that composes all buffers; a plot whose
    // buffers are invalid (resized, a layer's mode changed) replots whole instead.
    for (QCPLayer* layer : layers)
        layer->replot();
    emit layersReplotted(static_cast<double>(timer.nsecsElapsed()) / 1e6);
}

bool DeferredReplot::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == plot_ && event->type() == QEvent::Paint)
        flush();
    return false;
}

}  // namespace footpath
