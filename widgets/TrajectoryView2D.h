#pragma once

#include "SessionView.h"
#include "PathOverlay.h"
#include "Result.h"

#include <Eigen/Core>

#include <QColor>
#include <QPoint>
#include <QRectF>
#include <QWidget>

#include <cstddef>
#include <memory>
#include <vector>

class QCustomPlot;
class QCPColorScale;
class QCPCurve;
class QCPGraph;
class QCPLegend;
class QCPLayer;
class QCPMarginGroup;
class QMouseEvent;

namespace footpath {

class ColouredPathPlottable;
class DeferredReplot;
class PlotInteraction;

/// Index of the sample whose time is closest to time_s (0 for an empty or one-sample series).
/// Shared by the trajectory views so both put the time cursor on the same sample.
std::size_t nearestSampleAtTime(const std::vector<double>& times_s, double time_s);

/// Top view of the estimated foot path: the path (one colour, or coloured by time or speed with a
/// colour scale), one dot per stance, start and end marked, a time cursor, an optional reference
/// overlay, equal scales on both axes so a rectangle looks like one. Drawn by QCustomPlot without
/// OpenGL. Plain setters and signals: MainWindow wires it to the session.
class TrajectoryView2D : public QWidget, public SessionView {
    Q_OBJECT
public:
    /// Overlays up to this many are keyed in the main key below the plot, more in a box over it.
    static constexpr std::size_t kOverlaysInMainKey = 2;

    enum class Colouring { None, Time, Speed, Motion };  ///< Motion: each stride by its step's class (Zheng et al. 2016)
    Q_ENUM(Colouring)

    explicit TrajectoryView2D(QWidget* parent = nullptr);
    void showEstimate(const AnalysisSession& session) override;
    void showTimeCursor(double time_s) override { setTimeCursor(time_s); }

    void setResult(std::shared_ptr<const Result> result);
    /// For a path that grows (live input): refits the view unless the user has panned or zoomed
    /// since the last fit; a double-click fits and follows again. Given the result it already
    /// shows, grown in place by appended samples, it converts only the new samples.
    void followResult(std::shared_ptr<const Result> result);
    void showResult(const Result& result);  ///< copies; prefer setResult with the session's pointer
    void clear();  ///< removes path, markers and reference; the axes keep their range

    void setColouring(Colouring colouring);
    Colouring colouring() const { return colouring_; }
    /// The main path's key entry: "Foot path", or the foot ("Left foot") when both feet are shown;
    /// empty restores the default.
    void setPathLabel(const QString& label);
    QString pathLabel() const;

    /// Positions already in the estimate's frame (see alignReferenceToEstimate); empty hides it.
    void setReference(const std::vector<Eigen::Vector3d>& positions_m);

    /// Moves the marker to the path sample nearest in time; NaN hides the marker.
    void setTimeCursor(double time_s);
    double timeCursor() const { return timeCursor_s_; }

    QCustomPlot* plot() const { return plot_; }  ///< for the report and for tests
    /// Lays the plot out at the widget's size without showing it (the report draws a view that was
    /// never on screen) and decides on the stance markers at that scale. Returns whether they are
    /// drawn.
    bool layOutForPrinting();
    /// Hover readout (x, y, time of the nearest path sample), Shift+click marker, context menu, export.
    PlotInteraction* interaction() const { return interaction_; }
    /// The legend entries of the motion classes the path shows while coloured by motion (for tests).
    const std::vector<QCPGraph*>& motionLegendEntries() const { return motionLegend_; }
    /// The colour the path is drawn in at sample index (the pen colour when not coloured).
    QColor pathColourAt(std::size_t index) const;

    /// Further paths (the comparison's method sets) under the main one, each with an entry in a
    /// key of their own in the plot's top left corner; empty removes them. The view refits to hold
    /// them all.
    void setOverlays(const std::vector<PathOverlay>& overlays);
    const std::vector<QCPCurve*>& overlayCurves() const { return overlayCurves_; }  ///< for tests
    QCPLegend* overlayLegend() const { return overlayLegend_; }  ///< null until the first overlays

    /// The path before the last parameter change, drawn faintly under the current one (with a key
    /// entry) so the change shows; empty hides it. The view is not refitted for it.
    void setGhostPath(const std::vector<Eigen::Vector3d>& positions_m);
    QCPCurve* ghostCurve() const { return ghost_; }  ///< null until the first ghost; for tests

signals:
    /// The user clicked near the path: time of the nearest path sample.
    void timeCursorMoved(double time_s);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void createLegendRow();
    void wrapLegendToWidth();
    /// Draws (and lists) the stance markers only while they stand apart on screen
    /// (stanceMarkersApart): a long walk seen whole would be a row of dots hiding its path.
    void showStanceMarkersIfApart();
    void createColourScale();
    void showColourScale(bool show);
    void showReferenceCurve();
    void showPathAndMarkers(bool grown = false);  ///< grown: result_ is the shown path with samples appended
    void updateColouring();
    bool showMotionColouring();
    void createOverlayLegend();
    void updateTimeCursorMarker();
    void fitViewToData();
    void keepEqualAxisScales();
    void fitViewRegionIntoAxisRect();
    QRectF visibleRegion() const;  ///< metres
    void createPlotInteraction();
    void onMousePress(QMouseEvent* event);
    void onMouseRelease(QMouseEvent* event);
    bool nearestPathSampleToPixel(const QPointF& pixel, std::size_t& index) const;

    QCustomPlot* plot_;
    DeferredReplot* replot_;  ///< the setters' replots: once per event-loop pass, none while hidden
    ColouredPathPlottable* path_;
    QCPCurve* reference_;
    QCPGraph* stances_;
    QCPGraph* start_;
    QCPGraph* end_;
    QCPGraph* cursor_;
    QCPLayer* cursorLayer_;  ///< buffered on its own, so moving the cursor does not redraw the path
    PlotInteraction* interaction_ = nullptr;
    QCPColorScale* colourScale_;
    QCPMarginGroup* colourScaleMargins_;

    std::shared_ptr<const Result> result_;
    std::vector<Eigen::Vector3d> referencePositions_m_;
    Colouring colouring_ = Colouring::None;
    double timeCursor_s_;
    QPoint pressPosition_;
    /// What must stay visible (metres): the data on a new result, else what the user panned or
    /// zoomed to. Every layout fits it with equal scales, so resizing never compounds margins.
    QRectF viewRegion_;
    QRectF lastFitted_;  ///< the axis ranges we set last, to tell the user's pan/zoom from our fit
    bool viewMovedByUser_ = false;  ///< since the last fit to the data; followResult keeps the view
    std::vector<QCPGraph*> motionLegend_;  ///< legend-only graphs, one per class shown
    std::vector<QCPCurve*> overlayCurves_;
    QCPLegend* overlayLegend_ = nullptr;
    std::vector<Eigen::Vector3d> overlayPositions_m_;  ///< all overlays' points, for fitting the view
    QCPCurve* ghost_ = nullptr;
};

}  // namespace footpath
