#pragma once

#include <QList>
#include <QObject>

class QCPLayer;
class QCustomPlot;

namespace footpath {

/// Replots a QCustomPlot once for any number of requests, and only when it will be seen: at the
/// next event-loop pass while the plot is visible, otherwise just before it is next painted (a
/// hidden tab is redrawn when the user brings it to the front, not on every parameter change).
/// A grab() or render() of a hidden plot paints it, so it is brought up to date first.
class DeferredReplot : public QObject {
    Q_OBJECT
public:
    explicit DeferredReplot(QCustomPlot* plot);

    /// The whole plot: anything may have changed, its layout included.
    void request();
    /// Only what these layers (in QCPLayer::lmBuffered mode, each with a paint buffer of its own)
    /// draw has changed: they are redrawn over the other layers' kept buffers (a slider move
    /// redraws the stance bands, not 180,000-sample curves). A whole replot pending or requested
    /// later covers them.
    void requestLayers(const QList<QCPLayer*>& layers);
    bool isPending() const { return pending_ || !pendingLayers_.isEmpty(); }
    /// Replots now if a request is pending.
    void flush();

signals:
    /// After a replot of only some layers (QCustomPlot::afterReplot comes after a whole one), with
    /// how long it took.
    void layersReplotted(double milliseconds);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void schedule();

    QCustomPlot* plot_;
    bool pending_ = false;
    QList<QCPLayer*> pendingLayers_;
    bool scheduled_ = false;
};

}  // namespace footpath
