#pragma once

#include <QObject>

class QCustomPlot;

namespace footpath {

/// Replots a QCustomPlot once for any number of requests, and only when it will be seen: at the
/// next event-loop pass while the plot is visible, otherwise just before it is next painted (a
/// hidden tab is redrawn when the user brings it to the front, not on every parameter change).
/// A grab() or render() of a hidden plot paints it, so it is brought up to date first.
class DeferredReplot : public QObject {
public:
    explicit DeferredReplot(QCustomPlot* plot);

    void request();
    bool isPending() const { return pending_; }
    /// Replots now if a request is pending.
    void flush();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void schedule();

    QCustomPlot* plot_;
    bool pending_ = false;
    bool scheduled_ = false;
};

}  // namespace footpath
