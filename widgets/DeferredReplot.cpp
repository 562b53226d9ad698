#include "DeferredReplot.h"

#include <QEvent>
#include <qcustomplot.h>

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
    if (!pending_)
        return;
    pending_ = false;
    plot_->replot(QCustomPlot::rpQueuedRefresh);  // the paint under way (or the next) shows the new buffers
}

bool DeferredReplot::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == plot_ && event->type() == QEvent::Paint)
        flush();
    return false;
}

}  // namespace footpath
