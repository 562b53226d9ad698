#pragma once

#include <QLocale>
#include <QObject>
#include <QPointF>
#include <QString>
#include <qcustomplot.h>

#include <functional>
#include <optional>

class QMenu;

namespace footpath {

// --- Numbers as the plots write them ---------------------------------------------------------------

/// value with this many decimals, never "-0.000": a value that rounds to zero is written "0.000".
QString formatPlotNumber(double value, int decimals);
/// A figure for a table (summary, step table, comparison, PDF report): value with this many
/// decimals in locale's notation, never "-0.000" (a value that rounds to zero is written as zero),
/// and a dash for a figure that does not exist (NaN, infinite).
QString formatFigure(double value, int decimals, const QLocale& locale = QLocale::c());
/// Decimals that give about four significant digits across a visible span (0 for spans of 1000+).
int decimalsForSpan(double span);

/// Tick steps of 1, 2 or 5 times a power of ten (QCustomPlot's default also allows 2.5, which
/// gives 2.5/7.5 ticks), labelled with as many decimals as the step needs: a pressure axis spanning
/// 0.02 hPa reads 1013.24, 1013.25, 1013.26, not 1013.25 three times. No "-0" labels.
class ReadableTicker : public QCPAxisTicker {
protected:
    double getTickStep(const QCPRange& range) override;
    QString getTickLabel(double tick, const QLocale& locale, QChar formatChar, int precision) override;

private:
    int decimals_ = 0;  ///< from the step of the last generate() pass
};

/// Gives every linear axis of the plot that still has QCustomPlot's default ticker a ReadableTicker
/// (text, log and other special tickers are left alone).
void useReadableTicks(QCustomPlot* plot);

// --- What every plot lets the user do --------------------------------------------------------------

/// The mouse interactions every QCustomPlot-based view shares, installed once per plot:
///  - hover readout: the time under the mouse and each curve's value there in the hovered row
///    (or what a view's own probe says: the 2D path's x, y and time), in a box in the row's corner;
///  - a measurement marker: Shift+click sets it, the readout then adds Δt and each curve's Δ
///    between the marker and the mouse; Esc (in the plot or the view holding it) or the context
///    menu clears it;
///  - Y zoom: Ctrl+wheel over a row, or the wheel over its value axis; dragging the value axis pans it;
///  - double-click, or "Reset view" in the context menu, calls the view's reset;
///  - the context menu: reset view, export as PNG, SVG or PDF (both vector), and the visible
///    range of the curves as CSV.
/// Rows whose value axis labels lanes (a text ticker) take no Y zoom. Time-series views keep their
/// own time-axis navigation (LinkedTimeRows); this adds what is not about time.
class PlotInteraction : public QObject {
    Q_OBJECT
public:
    /// What a view's own probe reports for a point: the readout text and the plot point it snapped
    /// to (drawn as a dot), or nothing to show no readout there.
    struct Probe {
        QString text;
        QPointF snapped;  ///< plot coordinates of the probed sample
    };
    /// For views that are not time series: probe(pixel, marker) where marker is the snapped point
    /// of the measurement marker, if one is set.
    using Prober = std::function<std::optional<Probe>(const QPointF& pixel, const std::optional<QPointF>& marker)>;
    using CsvWriter = std::function<QString()>;
    /// A graph's value as the readout writes it, or nothing for the default number.
    using ValueFormatter = std::function<std::optional<QString>(const QCPGraph* graph, double value)>;

    explicit PlotInteraction(QCustomPlot* plot);

    void setResetAction(std::function<void()> reset) { reset_ = std::move(reset); }
    void setProber(Prober prober) { prober_ = std::move(prober); }
    void setCsvWriter(CsvWriter writer) { csvWriter_ = std::move(writer); }
    void setValueFormatter(ValueFormatter formatter) { valueFormatter_ = std::move(formatter); }

    /// The readout for the mouse at pixel (what hovering does); empty outside the rows.
    void probeAt(const QPointF& pixel);
    void clearProbe();
    /// Sets the measurement marker at pixel (what Shift+click does).
    void setMarkerAt(const QPointF& pixel);
    void clearMarker();
    bool hasMarker() const { return marker_.has_value(); }
    double markerKey() const { return marker_ ? marker_->point.x() : 0.0; }
    QString readoutText() const { return readout_; }

    void resetView();
    bool exportPng(const QString& path) const;
    bool exportSvg(const QString& path) const;
    bool exportPdf(const QString& path) const;
    /// The curves of the shown rows over the visible time range, one column each, one row per
    /// time at which any of them has a sample (a step curve holds its value, a line is interpolated
    /// as drawn); or the view's own CSV writer's text.
    QString visibleDataCsv() const;
    bool exportCsv(const QString& path) const;
    /// The context menu (for the plot's right-click and for tests); the caller owns it.
    QMenu* createContextMenu(QWidget* parent);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    class Overlay;
    struct Marker {
        QCPAxisRect* rect = nullptr;
        QPointF point;  ///< plot coordinates: time and value, or a view's snapped point
    };

    QCPAxisRect* rowAt(const QPointF& pixel, bool includeAxisMargin) const;
    bool takesValueZoom(const QCPAxisRect* rect) const;
    bool onWheel(QWheelEvent* event);
    bool onMousePress(QMouseEvent* event);
    bool onMouseMove(QMouseEvent* event);
    bool onMouseRelease(QMouseEvent* event);
    QString timeSeriesReadout(QCPAxisRect* rect, double time_s) const;
    QString graphValueText(const QCPGraph* graph, double value) const;
    void chooseFileAndExport(const QString& title, const QString& filter, const QString& suffix,
                             const std::function<bool(const QString&)>& write);
    void redrawOverlay();

    QCustomPlot* plot_;
    Overlay* overlay_;
    std::function<void()> reset_;
    Prober prober_;
    CsvWriter csvWriter_;
    ValueFormatter valueFormatter_;
    QString readout_;
    QCPAxisRect* hoveredRect_ = nullptr;
    QPointF hoverPixel_;
    std::optional<QPointF> hoverSnapped_;  ///< the prober's snapped point, plot coordinates
    std::optional<Marker> marker_;
    QPoint pressPos_;
    QCPAxis* draggedValueAxis_ = nullptr;  ///< a value-axis drag in progress
    QCPRange dragStartRange_;
};

}  // namespace footpath
