#pragma once

#include <QPoint>
#include <qcustomplot.h>

#include <optional>
#include <vector>

class QPainter;

namespace footpath {

/// What SignalPlots and StanceFlagsPlot share about moving along time.

/// The time range after a navigation key (+/= zoom in, - zoom out, Left/Right pan) applied to
/// [from, to]; nothing for other keys.
std::optional<QCPRange> keyNavigatedRange(int key, double from_s, double to_s);

/// A left-button release that stayed within the platform's drag distance of its press: a click
/// that places the time cursor, not the end of a pan.
bool isClick(const QPoint& pressed, const QPoint& released, Qt::MouseButton button);

/// Draws the plot into target as vector commands: QCustomPlot paints only through its own
/// QCPPainter, so the drawing is recorded in a QPicture that the caller's painter replays.
void renderPlotTo(QCustomPlot* plot, QPainter& painter, const QRect& target);

/// Lays the legend's items out in as many columns as fit into `available` pixels (items share
/// column widths), more lines rather than a legend wider than its place, packed to the left.
void wrapLegendToWidth(QCPLegend* legend, int available);

/// One legend for all rows of a plot, in a strip above them, never over the data: entries that
/// look alike (the x of acceleration and of angular rate: same name and pen) appear once, and it
/// wraps onto more lines when the plot is too narrow for one. Out of the layout until placed.
class LegendStrip : public QObject {
    Q_OBJECT
public:
    explicit LegendStrip(QCustomPlot* plot);

    QCPLegend* legend() const { return legend_; }
    /// Shows these plottables' entries in order, one per look (name, pen, brush).
    void setEntries(const std::vector<QCPAbstractPlottable*>& entries);
    /// Whether an entry looking like plottable's is shown.
    bool showsEntryLike(const QCPAbstractPlottable* plottable) const;
    /// The strip is the layout's row 0 (made by the constructor): the rows go below it.
    static constexpr int kFirstRow = 1;

private:
    void fitToWidth();

    QCustomPlot* plot_;
    QCPLegend* legend_;
};

/// The time cursor's line through one row's full height, on layer, hidden until placed. It runs on
/// the row's hidden right axis, which this sets to 0..1 whatever the row shows.
QCPItemStraightLine* addCursorLine(QCustomPlot* plot, QCPAxisRect* rect, const QString& layer);

/// The rows of one QCustomPlot that share a time axis (SignalPlots, StanceFlagsPlot): dragging or
/// zooming any row moves them all, navigation keys move them, and a click that stayed put (not
/// the end of a pan, nor a Shift+click, which sets PlotInteraction's marker) in a shown row becomes
/// a time.
class LinkedTimeRows : public QObject {
    Q_OBJECT
public:
    explicit LinkedTimeRows(QCustomPlot* plot);

    /// Links the row's bottom (time) axis; drag and zoom act on it alone.
    void addRow(QCPAxisRect* rect);
    /// Shows [from_s, to_s] in every row; rangeChanged follows if that is a change.
    void setRange(double from_s, double to_s);
    QCPRange range() const { return QCPRange(from_s_, to_s_); }
    /// Applies +/-, Left or Right (keyNavigatedRange); false for any other key.
    bool navigate(int key);

signals:
    void rangeChanged(double from_s, double to_s);
    void clicked(double time_s);

private:
    void onRowRangeChanged(const QCPRange& range);
    void onMouseRelease(QMouseEvent* event);

    QCustomPlot* plot_;
    std::vector<QCPAxisRect*> rows_;
    double from_s_ = 0.0;  ///< the range all rows share; compared to stop the linking recursing
    double to_s_ = 0.0;
    QPoint pressPos_;
};

}  // namespace footpath
