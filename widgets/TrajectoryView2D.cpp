#include "TrajectoryView2D.h"

#include "AnalysisSession.h"
#include "DeferredReplot.h"
#include "MotionLanes.h"
#include "PixelCurve.h"
#include "PlotInteraction.h"
#include "StanceMarkers.h"
#include "TimeAxisNavigation.h"
#include "metrics/Evaluation.h"

#include <Eigen/Geometry>
#include <QMouseEvent>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>

namespace footpath {

namespace {

/// Few enough that the coloured path is a few dozen drawLines calls, enough that the bands read as
/// a smooth scale.
constexpr int kColourLevels = 40;
/// A click this close (pixels) to the path moves the time cursor; farther away it is ignored.
constexpr double kClickTolerance_px = 15.0;
/// A press and release farther apart than this (pixels) was a pan, not a click.
constexpr int kClickMaxMovement_px = 4;
/// Speeds above this quantile are drawn in the top colour, so one divergent sample does not
/// squeeze every real stride into the bottom of the scale.
constexpr double kSpeedScaleQuantile = 0.99;

const QColor kPathColour(40, 90, 170);
constexpr double kGhostTolerance_px = 3.0;  // the ghost's faint 2.5 px line: finer detail would not show

// Functions, not globals: a QCPScatterStyle holds a QPixmap, which needs the application first.
QCPScatterStyle stanceDot()
{
    return QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(230, 120, 20), 5);
}

QCPScatterStyle stanceRing()
{
    return QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(40, 40, 40), 1.2), Qt::white, 6);
}

/// Plasma without its pale yellow end, which would vanish on the white background.
QCPColorGradient pathGradient()
{
    QCPColorGradient gradient;
    gradient.setColorStopAt(0.0, QColor(13, 8, 135));
    gradient.setColorStopAt(0.25, QColor(106, 0, 168));
    gradient.setColorStopAt(0.5, QColor(177, 42, 144));
    gradient.setColorStopAt(0.75, QColor(225, 100, 98));
    gradient.setColorStopAt(1.0, QColor(245, 150, 40));
    gradient.setLevelCount(kColourLevels);
    return gradient;
}

QCPGraph* addMarkerGraph(QCustomPlot* plot, const QString& name, QCPScatterStyle style)
{
    auto* graph = new StampedMarkerGraph(plot->xAxis, plot->yAxis);
    graph->setName(name);
    graph->setLineStyle(QCPGraph::lsNone);
    graph->setScatterStyle(style);
    return graph;
}

/// Smallest rectangle holding every horizontal position; nullopt for none. (A QRectF alone cannot
/// tell "nothing" from one point or a straight walk along x, which have zero width or height.)
std::optional<QRectF> horizontalBounds(const std::vector<Eigen::Vector3d>& positions)
{
    if (positions.empty())
        return std::nullopt;
    double xMin = positions.front().x(), xMax = xMin, yMin = positions.front().y(), yMax = yMin;
    for (const Eigen::Vector3d& p : positions) {
        xMin = std::min(xMin, p.x());
        xMax = std::max(xMax, p.x());
        yMin = std::min(yMin, p.y());
        yMax = std::max(yMax, p.y());
    }
    return QRectF(QPointF(xMin, yMin), QPointF(xMax, yMax));
}

std::optional<QRectF> unite(const std::optional<QRectF>& a, const std::optional<QRectF>& b)
{
    if (!a || !b)
        return a ? a : b;
    return QRectF(QPointF(std::min(a->left(), b->left()), std::min(a->top(), b->top())),
                  QPointF(std::max(a->right(), b->right()), std::max(a->bottom(), b->bottom())));
}

double quantile(std::vector<double> values, double q)
{
    if (values.empty())
        return 0.0;
    const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + k, values.end());
    return values[static_cast<std::size_t>(k)];
}

}  // namespace

/// The foot path as line segments grouped by colour level: one drawLines call per level, and
/// consecutive samples less than a pixel apart merged, so a 30-minute 100 Hz path redraws in a few
/// tens of milliseconds however it is coloured (QCPCurve would need one curve per colour run, and
/// speed changes colour several times per stride).
class ColouredPathPlottable : public QCPAbstractPlottable {
public:
    ColouredPathPlottable(QCPAxis* keyAxis, QCPAxis* valueAxis) : QCPAbstractPlottable(keyAxis, valueAxis) {}

    void setPoints(const std::vector<Eigen::Vector3d>& positions_m)
    {
        points_m_.clear();
        bounds_ = QRectF();
        extendPoints(positions_m);
    }

    /// The points of positions_m after those already held (a path that grew at its end).
    void extendPoints(const std::vector<Eigen::Vector3d>& positions_m)
    {
        const std::size_t held = std::min(points_m_.size(), positions_m.size());
        points_m_.resize(held);
        points_m_.reserve(positions_m.size());
        for (std::size_t k = held; k < positions_m.size(); ++k) {
            const QPointF point(positions_m[k].x(), positions_m[k].y());
            // unite(), not QRectF::united(), which ignores the zero-size rectangle of a single point.
            bounds_ = points_m_.empty() ? QRectF(point, point) : *unite(bounds_, QRectF(point, point));
            points_m_.push_back(point);
        }
        levels_.clear();
        levelColours_.clear();
    }

    /// The smallest rectangle holding the points (metres); nullopt for none.
    std::optional<QRectF> bounds() const { return points_m_.empty() ? std::nullopt : std::optional<QRectF>(bounds_); }

    /// One value per point mapped onto gradient over range; empty values: the pen colour throughout.
    /// The gradient is a copy because QCPColorGradient::color() updates a cache.
    void setValues(const std::vector<double>& values, const QCPRange& range, QCPColorGradient gradient)
    {
        levels_.clear();
        levelColours_.clear();
        if (values.size() != points_m_.size() || range.size() <= 0.0)
            return;
        levels_.reserve(values.size());
        for (double value : values) {
            const double fraction = (value - range.lower) / range.size();
            levels_.push_back(static_cast<std::uint8_t>(std::clamp(static_cast<int>(fraction * kColourLevels), 0, kColourLevels - 1)));
        }
        for (int level = 0; level < kColourLevels; ++level)
            levelColours_.push_back(QColor::fromRgb(gradient.color((level + 0.5) / kColourLevels, QCPRange(0.0, 1.0))));
    }

    /// One category per point, drawn in colours[category] (the motion classes).
    void setCategories(std::vector<std::uint8_t> categories, std::vector<QColor> colours)
    {
        levels_.clear();
        levelColours_.clear();
        if (categories.size() != points_m_.size())
            return;
        levels_ = std::move(categories);
        levelColours_ = std::move(colours);
    }

    /// The colour the segment ending at this point is drawn in.
    QColor colourAt(std::size_t index) const
    {
        return index < levels_.size() ? levelColours_[levels_[index]] : mPen.color();
    }

    double selectTest(const QPointF&, bool, QVariant*) const override { return -1.0; }

    QCPRange getKeyRange(bool& foundRange, QCP::SignDomain) const override
    {
        foundRange = !points_m_.empty();
        return QCPRange(bounds_.left(), bounds_.right());
    }

    QCPRange getValueRange(bool& foundRange, QCP::SignDomain, const QCPRange&) const override
    {
        foundRange = !points_m_.empty();
        return QCPRange(bounds_.top(), bounds_.bottom());
    }

protected:
    void draw(QCPPainter* painter) override
    {
        if (points_m_.size() < 2)
            return;
        const std::vector<QVector<QLineF>> linesByLevel = segmentsInPixels();
        applyDefaultAntialiasingHint(painter);
        QPen pen = mPen;
        for (std::size_t level = 0; level < linesByLevel.size(); ++level) {
            if (!levelColours_.empty())
                pen.setColor(levelColours_[level]);
            painter->setPen(pen);
            painter->drawLines(linesByLevel[level]);
        }
    }

    void drawLegendIcon(QCPPainter* painter, const QRectF& rect) const override
    {
        const int pieces = levelColours_.empty() ? 1 : 3;
        QPen pen = mPen;
        for (int piece = 0; piece < pieces; ++piece) {
            if (!levelColours_.empty())
                pen.setColor(levelColours_[static_cast<std::size_t>(piece) * (levelColours_.size() - 1) / 2]);
            painter->setPen(pen);
            const double x0 = rect.left() + rect.width() * piece / pieces;
            const double x1 = rect.left() + rect.width() * (piece + 1) / pieces;
            painter->drawLine(QLineF(x0, rect.center().y(), x1, rect.center().y()));
        }
    }

private:
    std::vector<QVector<QLineF>> segmentsInPixels() const
    {
        std::vector<QVector<QLineF>> linesByLevel(levels_.empty() ? 1 : levelColours_.size());
        const PixelMap toPixels(mKeyAxis.data(), mValueAxis.data());
        // A foot at rest puts hundreds of samples on one pixel, and a swing's are nearly on one
        // line: a segment per straight run (within a pixel) draws the same line with hundreds of
        // segments instead of 100,000 (a 30-minute walk: 17 -> 5 ms a redraw, BM_PathReplot).
        // Each segment is drawn in the colour of its end; a run ends where the colour changes.
        QPointF lastKept;
        bool anyKept = false;
        const auto keep = [&](const QPointF& pixel, std::size_t k) {
            if (anyKept)
                linesByLevel[levels_.empty() ? 0 : levels_[k]].append(QLineF(lastKept, pixel));
            lastKept = pixel;
            anyKept = true;
        };
        StraightRunSimplifier runs(1.0);
        for (std::size_t k = 0; k < points_m_.size(); ++k) {
            if (!levels_.empty() && k > 0 && levels_[k] != levels_[k - 1])
                runs.breakRun(keep);
            runs.add(toPixels(points_m_[k].x(), points_m_[k].y()), k, keep);
        }
        runs.finish(keep);
        return linesByLevel;
    }

    std::vector<QPointF> points_m_;
    std::vector<std::uint8_t> levels_;  ///< per point; empty when drawn in the pen colour
    std::vector<QColor> levelColours_;
    QRectF bounds_;
};

std::size_t nearestSampleAtTime(const std::vector<double>& times_s, double time_s)
{
    if (times_s.size() < 2)
        return 0;
    const auto after = std::lower_bound(times_s.cbegin(), times_s.cend(), time_s);
    if (after == times_s.cbegin())
        return 0;
    if (after == times_s.cend())
        return times_s.size() - 1;
    const auto before = after - 1;
    const auto index = std::distance(times_s.cbegin(), time_s - *before <= *after - time_s ? before : after);
    return static_cast<std::size_t>(index);
}

TrajectoryView2D::TrajectoryView2D(QWidget* parent)
    : QWidget(parent), plot_(new QCustomPlot(this)), replot_(new DeferredReplot(plot_)),
      timeCursor_s_(std::numeric_limits<double>::quiet_NaN())
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(plot_);

    // Created in drawing order: the reference under the path, the markers on top.
    reference_ = new PixelCurve(plot_->xAxis, plot_->yAxis);
    reference_->setName(tr("Reference"));
    reference_->setPen(QPen(QColor(150, 150, 150), 1.5, Qt::DashLine));
    reference_->removeFromLegend();
    path_ = new ColouredPathPlottable(plot_->xAxis, plot_->yAxis);
    path_->setName(tr("Foot path"));
    path_->setPen(QPen(kPathColour, 1.5));
    stances_ = addMarkerGraph(plot_, tr("Stance"), stanceDot());
    start_ = addMarkerGraph(plot_, tr("Start"), QCPScatterStyle(QCPScatterStyle::ssSquare, QPen(Qt::darkGreen, 2), Qt::white, 11));
    end_ = addMarkerGraph(plot_, tr("End"), QCPScatterStyle(QCPScatterStyle::ssCross, QPen(Qt::red, 2), Qt::NoBrush, 11));

    plot_->addLayer(QStringLiteral("cursor"), plot_->layer(QStringLiteral("main")), QCustomPlot::limAbove);
    cursorLayer_ = plot_->layer(QStringLiteral("cursor"));
    cursorLayer_->setMode(QCPLayer::lmBuffered);
    cursor_ = addMarkerGraph(plot_, tr("Time cursor"),
                             QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(Qt::black, 2), QColor(255, 215, 0), 13));
    cursor_->setLayer(cursorLayer_);
    cursor_->removeFromLegend();

    plot_->xAxis->setLabel(tr("x (m)"));
    plot_->yAxis->setLabel(tr("y (m)"));
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    createLegendRow();
    createColourScale();

    connect(plot_, &QCustomPlot::afterLayout, this, &TrajectoryView2D::keepEqualAxisScales);
    connect(plot_, &QCustomPlot::mousePress, this, &TrajectoryView2D::onMousePress);
    connect(plot_, &QCustomPlot::mouseRelease, this, &TrajectoryView2D::onMouseRelease);
    createPlotInteraction();
}

void TrajectoryView2D::createPlotInteraction()
{
    interaction_ = new PlotInteraction(plot_);
    interaction_->setResetAction([this] { fitViewToData(); });  // also what a double-click does
    interaction_->setProber([this](const QPointF& pixel, const std::optional<QPointF>& marker)
                                -> std::optional<PlotInteraction::Probe> {
        std::size_t index = 0;
        if (!nearestPathSampleToPixel(pixel, index) || index >= result_->time_s.size())
            return std::nullopt;
        const Eigen::Vector3d& p = result_->position_m[index];
        const double t = result_->time_s[index];
        QString text = tr("x = %1 m   y = %2 m   t = %3 s")
                           .arg(formatPlotNumber(p.x(), 2), formatPlotNumber(p.y(), 2), formatPlotNumber(t, 3));
        if (marker) {
            // The marker is a path sample too: find its time from its position.
            const QPointF at(plot_->xAxis->coordToPixel(marker->x()), plot_->yAxis->coordToPixel(marker->y()));
            std::size_t from = 0;
            if (nearestPathSampleToPixel(at, from) && from < result_->time_s.size()) {
                const Eigen::Vector2d d = p.head<2>() - result_->position_m[from].head<2>();
                text += tr("\nfrom the marker: Δt = %1 s   Δx = %2 m   Δy = %3 m   distance %4 m")
                            .arg(formatPlotNumber(t - result_->time_s[from], 3), formatPlotNumber(d.x(), 2),
                                 formatPlotNumber(d.y(), 2), formatPlotNumber(d.norm(), 2));
            }
        }
        return PlotInteraction::Probe{text, QPointF(p.x(), p.y())};
    });
    interaction_->setCsvWriter([this] {
        // The path samples in view, in time order.
        QString csv = QStringLiteral("time_s,x_m,y_m,z_m\n");
        if (!result_)
            return csv;
        const QRectF shown = visibleRegion();
        for (std::size_t k = 0; k < result_->position_m.size() && k < result_->time_s.size(); ++k) {
            const Eigen::Vector3d& p = result_->position_m[k];
            if (shown.contains(QPointF(p.x(), p.y())))
                csv += QStringLiteral("%1,%2,%3,%4\n").arg(result_->time_s[k], 0, 'g', 10).arg(p.x(), 0, 'g', 10)
                           .arg(p.y(), 0, 'g', 10).arg(p.z(), 0, 'g', 10);
        }
        return csv;
    });
}

void TrajectoryView2D::createLegendRow()
{
    // Below the plot, not over it: a legend inside the axes hides part of any path that fills them.
    QCPLegend* legend = plot_->legend;
    legend->setVisible(true);
    plot_->axisRect()->insetLayout()->take(legend);
    plot_->plotLayout()->addElement(1, 0, legend);
    plot_->plotLayout()->setRowStretchFactor(1, 0.001);
    plot_->plotLayout()->setRowSpacing(0);
    legend->setFillOrder(QCPLegend::foColumnsFirst);
    legend->setBorderPen(Qt::NoPen);
    legend->setBrush(Qt::NoBrush);
    legend->setMargins(QMargins(6, 0, 6, 4));
    legend->setColumnSpacing(18);
    legend->setMinimumSize(1, 0);  // its width never sets the widget's: it wraps instead (height: as needed)
    // Entries come and go with the overlays and the motion classes: fitted before every drawing.
    connect(plot_, &QCustomPlot::beforeReplot, this, &TrajectoryView2D::showStanceMarkersIfApart);
    connect(plot_, &QCustomPlot::beforeReplot, this, &TrajectoryView2D::wrapLegendToWidth);
}

bool TrajectoryView2D::layOutForPrinting()
{
    // A hidden widget's plot keeps its first viewport: set it to the widget's size, fit the path
    // into it (the first replot's layout), then decide on the markers with the fitted ranges (the
    // second's).
    plot_->setViewport(QRect(QPoint(0, 0), size()));
    for (int pass = 0; pass < 2; ++pass)
        plot_->replot(QCustomPlot::rpImmediateRefresh);
    return stances_->visible() && !stances_->data()->isEmpty();
}

void TrajectoryView2D::showStanceMarkersIfApart()
{
    // Half an hour seen whole puts 1500 stances a pixel or two apart on a 300-pixel plot: the path
    // became an orange line. Zoomed in that far apart, they come back (the 3D view's rule too).
    // In walking order, from the steps: the graph keeps its points sorted by x.
    const PixelMap toPixels(plot_->xAxis, plot_->yAxis);
    QPolygonF markers;
    if (result_) {
        for (const Step& step : result_->steps)
            markers << toPixels(step.position_m.x(), step.position_m.y());
    }
    const bool apart = stanceMarkersApart(markers);
    if (apart == stances_->visible())
        return;
    stances_->setVisible(apart);
    if (apart)
        stances_->addToLegend();
    else
        stances_->removeFromLegend();
}

void TrajectoryView2D::wrapLegendToWidth()
{
    // The legend sits under the path's column only: with the colour scale beside the path it has
    // less than the plot's width (wrapping to the whole width clipped the last letters). A layout
    // pass tells the column's width; the legend's own width (at least 1) does not change it.
    QCPLayoutGrid* grid = plot_->plotLayout();
    grid->setOuterRect(plot_->viewport());
    for (const auto phase : {QCPLayoutElement::upPreparation, QCPLayoutElement::upMargins, QCPLayoutElement::upLayout})
        grid->update(phase);
    footpath::wrapLegendToWidth(plot_->legend, plot_->legend->outerRect().width());
}

void TrajectoryView2D::resizeEvent(QResizeEvent* event)
{
    wrapLegendToWidth();  // before the plot lays itself out at the new size
    QWidget::resizeEvent(event);
}

void TrajectoryView2D::createColourScale()
{
    // Built once and moved in and out of the layout, so None gives the path its full width.
    colourScale_ = new QCPColorScale(plot_);
    colourScale_->setGradient(pathGradient());
    colourScale_->setBarWidth(12);
    colourScale_->setVisible(false);
    colourScaleMargins_ = new QCPMarginGroup(plot_);
}

void TrajectoryView2D::showColourScale(bool show)
{
    QCPLayoutGrid* grid = plot_->plotLayout();
    if (show && !grid->hasElement(0, 1)) {
        grid->addElement(0, 1, colourScale_);
        // Same top and bottom margins as the plot, so the scale spans exactly the axis rect.
        plot_->axisRect()->setMarginGroup(QCP::msTop | QCP::msBottom, colourScaleMargins_);
        colourScale_->setMarginGroup(QCP::msTop | QCP::msBottom, colourScaleMargins_);
    } else if (!show && grid->hasElement(0, 1)) {
        plot_->axisRect()->setMarginGroup(QCP::msTop | QCP::msBottom, nullptr);
        colourScale_->setMarginGroup(QCP::msTop | QCP::msBottom, nullptr);
        grid->take(colourScale_);
        grid->simplify();
    }
    colourScale_->setVisible(show);
}

void TrajectoryView2D::clear()
{
    result_.reset();
    referencePositions_m_.clear();
    showReferenceCurve();
    showPathAndMarkers();
    replot_->request();
}

void TrajectoryView2D::showResult(const Result& result)
{
    setResult(std::make_shared<const Result>(result));
}

void TrajectoryView2D::setResult(std::shared_ptr<const Result> result)
{
    viewMovedByUser_ = false;  // a new result is fitted whatever the user did to the old one
    followResult(std::move(result));
}

void TrajectoryView2D::followResult(std::shared_ptr<const Result> result)
{
    if (!result) {
        clear();
        return;
    }
    const bool grown = result == result_;  // the same path object, samples appended since (live input)
    result_ = std::move(result);
    showPathAndMarkers(grown);
    if (!viewMovedByUser_)
        fitViewToData();
    replot_->request();
}

void TrajectoryView2D::setReference(const std::vector<Eigen::Vector3d>& positions_m)
{
    if (positions_m.empty() && referencePositions_m_.empty())
        return;  // still none: nothing to fit or draw anew (a walk without reference, after each estimate)
    referencePositions_m_ = positions_m;
    showReferenceCurve();
    fitViewToData();
    replot_->request();
}

void TrajectoryView2D::showReferenceCurve()
{
    QVector<double> x, y;
    for (const Eigen::Vector3d& p : referencePositions_m_) {
        x << p.x();
        y << p.y();
    }
    reference_->setData(x, y);
    if (referencePositions_m_.empty())
        reference_->removeFromLegend();
    else if (!plot_->legend->hasItemWithPlottable(reference_))
        reference_->addToLegend();
    wrapLegendToWidth();
}

void TrajectoryView2D::setPathLabel(const QString& label)
{
    path_->setName(label.isEmpty() ? tr("Foot path") : label);
    wrapLegendToWidth();
    replot_->request();
}

QString TrajectoryView2D::pathLabel() const
{
    return path_->name();
}

void TrajectoryView2D::setOverlays(const std::vector<PathOverlay>& overlays)
{
    if (!overlayLegend_)
        createOverlayLegend();
    overlayLegend_->clearItems();  // before the curves go: its items point at them
    for (QCPCurve* curve : overlayCurves_)
        plot_->removePlottable(curve);
    overlayCurves_.clear();
    overlayPositions_m_.clear();
    for (const PathOverlay& overlay : overlays) {
        auto* curve = new PixelCurve(plot_->xAxis, plot_->yAxis);
        curve->setLayer(QStringLiteral("overlays"));
        curve->setName(overlay.label);
        curve->setPen(QPen(overlay.colour, 1.3));
        QVector<double> t, x, y;
        for (const Eigen::Vector3d& p : overlay.positions_m) {
            t << static_cast<double>(t.size());
            x << p.x();
            y << p.y();
        }
        curve->setData(t, x, y, true);
        // One or two (the other foot) join the main key below the plot, beside the path they go
        // with; more (a comparison's sets) get a key of their own over the plot: a dozen entries
        // below it would take the height of the path itself in a narrow view.
        if (overlays.size() > kOverlaysInMainKey) {
            curve->removeFromLegend();
            overlayLegend_->addItem(new QCPPlottableLegendItem(overlayLegend_, curve));
        }
        overlayCurves_.push_back(curve);
        overlayPositions_m_.insert(overlayPositions_m_.end(), overlay.positions_m.begin(), overlay.positions_m.end());
    }
    overlayLegend_->setVisible(overlayLegend_->itemCount() > 0);
    wrapLegendToWidth();
    fitViewToData();
    replot_->request();
}

void TrajectoryView2D::setGhostPath(const std::vector<Eigen::Vector3d>& positions_m)
{
    if (!ghost_) {
        // Under everything else, so the current path, its markers, the reference and the overlays
        // (the other foot, compared runs) stay on top of its opaque line.
        QCPLayer* overlays = plot_->layer(QStringLiteral("overlays"));
        plot_->addLayer(QStringLiteral("ghost"), overlays ? overlays : plot_->layer(QStringLiteral("main")),
                        QCustomPlot::limBelow);
        auto* ghost = new PixelCurve(plot_->xAxis, plot_->yAxis);
        ghost->setTolerance(kGhostTolerance_px);
        ghost_ = ghost;
        ghost_->setLayer(QStringLiteral("ghost"));
        ghost_->setName(tr("Before the last change"));
        // The faint grey a translucent (110, 110, 110, 90) pen leaves on the white plot, opaque:
        // its many short segments then draw quickly without darkening where they overlap.
        ghost_->setPen(QPen(QColor(204, 204, 204), 2.5));
    }
    QVector<QCPCurveData> points;  // handed over whole: the curve shares it instead of copying
    points.reserve(static_cast<qsizetype>(positions_m.size()));
    for (const Eigen::Vector3d& p : positions_m)
        points.append(QCPCurveData(static_cast<double>(points.size()), p.x(), p.y()));
    ghost_->data()->set(points, true);
    if (positions_m.empty())
        ghost_->removeFromLegend();
    else if (!plot_->legend->hasItemWithPlottable(ghost_))
        ghost_->addToLegend();
    wrapLegendToWidth();
    replot_->request();
}

void TrajectoryView2D::createOverlayLegend()
{
    // Below the current path, above the ghost of the last run when there is one.
    plot_->addLayer(QStringLiteral("overlays"), plot_->layer(QStringLiteral("main")), QCustomPlot::limBelow);
    overlayLegend_ = new QCPLegend;
    plot_->axisRect()->insetLayout()->addElement(overlayLegend_, Qt::AlignTop | Qt::AlignLeft);
    overlayLegend_->setLayer(QStringLiteral("legend"));
    overlayLegend_->setBrush(QColor(255, 255, 255, 190));  // the paths under it still show
    overlayLegend_->setBorderPen(QPen(QColor(200, 200, 200)));
    QFont font = plot_->legend->font();
    font.setPointSizeF(font.pointSizeF() * 0.85);
    overlayLegend_->setFont(font);
    overlayLegend_->setIconSize(20, 10);
    overlayLegend_->setRowSpacing(0);
    overlayLegend_->setVisible(false);
}

void TrajectoryView2D::setColouring(Colouring colouring)
{
    colouring_ = colouring;
    updateColouring();
    replot_->request();
}

void TrajectoryView2D::setTimeCursor(double time_s)
{
    timeCursor_s_ = time_s;
    updateTimeCursorMarker();
    cursorLayer_->replot();
}

void TrajectoryView2D::showPathAndMarkers(bool grown)
{
    const std::vector<Eigen::Vector3d> none;
    const std::vector<Eigen::Vector3d>& positions = result_ ? result_->position_m : none;
    if (grown)
        path_->extendPoints(positions);
    else
        path_->setPoints(positions);
    for (QCPGraph* graph : {stances_, start_, end_})
        graph->data()->clear();
    if (result_) {
        for (const Step& step : result_->steps)
            stances_->addData(step.position_m.x(), step.position_m.y());
    }
    if (!positions.empty()) {
        start_->addData(positions.front().x(), positions.front().y());
        end_->addData(positions.back().x(), positions.back().y());
    }
    updateColouring();
    updateTimeCursorMarker();
}

void TrajectoryView2D::updateColouring()
{
    if (showMotionColouring())
        return;
    std::vector<double> values;
    QCPRange range;
    if (result_ && colouring_ == Colouring::Time && result_->time_s.size() == result_->position_m.size()) {
        values = result_->time_s;
        range = QCPRange(values.empty() ? 0.0 : values.front(), values.empty() ? 0.0 : values.back());
        colourScale_->axis()->setLabel(tr("time (s)"));
    } else if (result_ && colouring_ == Colouring::Speed && result_->velocity_mps.size() == result_->position_m.size()) {
        for (const Eigen::Vector3d& v : result_->velocity_mps)
            values.push_back(v.norm());
        range = QCPRange(0.0, quantile(values, kSpeedScaleQuantile));
        colourScale_->axis()->setLabel(tr("foot speed (m/s)"));
    }
    path_->setValues(values, range, pathGradient());
    // Orange dots vanish on the warm end of the gradient; open circles read on every colour.
    stances_->setScatterStyle(values.empty() ? stanceDot() : stanceRing());
    colourScale_->setDataRange(range);
    showColourScale(!values.empty() && range.size() > 0.0);
}

/// Colours each stride by the class of the step it leads to, with a legend entry per class shown.
/// False (and no class entries) when not coloured by motion or no step is classified: the path is
/// then drawn as for no colouring.
bool TrajectoryView2D::showMotionColouring()
{
    for (QCPGraph* entry : motionLegend_)
        plot_->removePlottable(entry);
    motionLegend_.clear();
    // Wider while coloured by class: a class is read from a colour, and 1.5 px of it hides behind the stance rings.
    path_->setPen(QPen(kPathColour, colouring_ == Colouring::Motion ? 2.5 : 1.5));
    if (colouring_ != Colouring::Motion || !result_ || !hasMotionClasses(*result_) ||
        result_->time_s.size() != result_->position_m.size())
        return false;
    const std::vector<MotionClass> classes = motionOfSamples(*result_);
    std::vector<std::uint8_t> categories;
    categories.reserve(classes.size());
    for (const MotionClass motion : classes)
        categories.push_back(static_cast<std::uint8_t>(motion));
    const std::array allClasses{MotionClass::Unknown,    MotionClass::Level,      MotionClass::StairsUp,
                                MotionClass::StairsDown, MotionClass::ElevatorUp, MotionClass::ElevatorDown};
    std::vector<QColor> colours;
    for (const MotionClass motion : allClasses) {  // indexed by the enum's value
        colours.push_back(motionClassColour(motion));
        if (std::find(classes.begin(), classes.end(), motion) == classes.end())
            continue;
        QCPGraph* entry = plot_->addGraph();
        entry->setName(motionClassLabel(motion));
        entry->setPen(QPen(motionClassColour(motion), 3.0));
        entry->setSelectable(QCP::stNone);
        if (!plot_->legend->hasItemWithPlottable(entry))
            entry->addToLegend();
        motionLegend_.push_back(entry);
    }
    path_->setCategories(std::move(categories), std::move(colours));
    stances_->setScatterStyle(stanceRing());
    showColourScale(false);
    wrapLegendToWidth();
    return true;
}

QColor TrajectoryView2D::pathColourAt(std::size_t index) const
{
    return path_->colourAt(index);
}

void TrajectoryView2D::updateTimeCursorMarker()
{
    cursor_->data()->clear();
    if (!result_ || std::isnan(timeCursor_s_) || result_->position_m.empty() || result_->time_s.empty())
        return;
    const std::size_t index =
        std::min(nearestSampleAtTime(result_->time_s, timeCursor_s_), result_->position_m.size() - 1);
    cursor_->addData(result_->position_m[index].x(), result_->position_m[index].y());
}

void TrajectoryView2D::fitViewToData()
{
    const std::optional<QRectF> bounds =
        unite(unite(path_->bounds(), horizontalBounds(referencePositions_m_)),
              horizontalBounds(overlayPositions_m_));
    if (!bounds)
        return;  // nothing to show: keep whatever the axes show
    // The fixed part keeps a single point or a straight line from filling the view edge to edge.
    const double margin = 0.05 * std::max(bounds->width(), bounds->height()) + 0.1;
    viewRegion_ = bounds->adjusted(-margin, -margin, margin, margin);
    viewMovedByUser_ = false;
    // The current ranges count as ours, so the next layout fits viewRegion_ instead of keeping them.
    lastFitted_ = visibleRegion();
    keepEqualAxisScales();
}

void TrajectoryView2D::keepEqualAxisScales()
{
    // Runs after every layout, so the axis rect is the one about to be drawn. Ranges that differ
    // from our last fit were panned or zoomed by the user: that becomes the region to keep.
    if (plot_->axisRect()->rect().isEmpty())
        return;
    if (visibleRegion() != lastFitted_ || viewRegion_.isEmpty()) {
        viewMovedByUser_ = viewMovedByUser_ || !viewRegion_.isEmpty();
        viewRegion_ = visibleRegion();
    }
    fitViewRegionIntoAxisRect();
    // New ranges mean new tick labels, which may widen the margins: lay out once more and fit
    // into the final rect, so equal scales hold for what is drawn, not for the previous frame.
    for (auto phase : {QCPLayoutElement::upPreparation, QCPLayoutElement::upMargins, QCPLayoutElement::upLayout})
        plot_->plotLayout()->update(phase);
    fitViewRegionIntoAxisRect();
    plot_->axisRect()->update(QCPLayoutElement::upPreparation);  // ticks for the final ranges
    lastFitted_ = visibleRegion();
}

void TrajectoryView2D::fitViewRegionIntoAxisRect()
{
    const QRect rect = plot_->axisRect()->rect();
    if (rect.width() <= 0 || rect.height() <= 0)
        return;
    const double perPixel = std::max(viewRegion_.width() / rect.width(), viewRegion_.height() / rect.height());
    plot_->xAxis->setRange(viewRegion_.center().x(), perPixel * rect.width(), Qt::AlignCenter);
    plot_->yAxis->setRange(viewRegion_.center().y(), perPixel * rect.height(), Qt::AlignCenter);
}

QRectF TrajectoryView2D::visibleRegion() const
{
    const QCPRange x = plot_->xAxis->range(), y = plot_->yAxis->range();
    return QRectF(QPointF(x.lower, y.lower), QPointF(x.upper, y.upper));
}

void TrajectoryView2D::onMousePress(QMouseEvent* event)
{
    pressPosition_ = event->position().toPoint();
}

void TrajectoryView2D::onMouseRelease(QMouseEvent* event)
{
    // Left-drag pans, so only a press and release in the same place counts as a click.
    // Shift+click sets the measurement marker instead (PlotInteraction).
    if (event->button() != Qt::LeftButton || (event->modifiers() & Qt::ShiftModifier)
        || (event->position().toPoint() - pressPosition_).manhattanLength() > kClickMaxMovement_px)
        return;
    std::size_t index = 0;
    if (!nearestPathSampleToPixel(event->position(), index) || index >= result_->time_s.size())
        return;
    setTimeCursor(result_->time_s[index]);
    emit timeCursorMoved(result_->time_s[index]);
}

bool TrajectoryView2D::nearestPathSampleToPixel(const QPointF& pixel, std::size_t& index) const
{
    if (!result_ || result_->position_m.empty())
        return false;
    const Eigen::Vector2d clicked(plot_->xAxis->pixelToCoord(pixel.x()), plot_->yAxis->pixelToCoord(pixel.y()));
    double bestSquared = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < result_->position_m.size(); ++k) {
        const double squared = (result_->position_m[k].head<2>() - clicked).squaredNorm();
        if (squared < bestSquared) {
            bestSquared = squared;
            index = k;
        }
    }
    // Equal scales: one tolerance in metres holds in both directions.
    const double metresPerPixel = plot_->xAxis->range().size() / plot_->axisRect()->width();
    return std::sqrt(bestSquared) <= kClickTolerance_px * metresPerPixel;
}

void TrajectoryView2D::showEstimate(const AnalysisSession& session)
{
    if (!session.result()) {
        clear();
        return;
    }
    setResult(session.result());
    // The reference is drawn in the estimate's frame, aligned as ARMSE aligns it.
    setReference(session.evaluation()->alignedReference);
}

}  // namespace footpath
