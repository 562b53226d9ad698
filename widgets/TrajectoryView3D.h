#pragma once

#include "PathOverlay.h"
#include "Result.h"

#include <Eigen/Core>

#include <QFont>
#include <QPoint>
#include <QPolygonF>
#include <QRectF>
#include <QWidget>

#include <cstddef>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QPainter;

namespace footpath {

/// The foot path in 3D, drawn with QPainter only (no OpenGL: it must work offscreen and inside the
/// PDF report): a ground grid with metre labels, x/y/z arrows, start, end and stance markers, the
/// time cursor and an optional reference. Left-drag orbits, the wheel zooms about the pointer,
/// right- or middle-drag pans, a double-click resets the view. Heights can be exaggerated so a
/// few centimetres of foot lift or a staircase stand out against tens of metres of walk.
class TrajectoryView3D : public QWidget {
    Q_OBJECT
public:
    enum class Projection { Orthographic, Perspective };
    Q_ENUM(Projection)

    explicit TrajectoryView3D(QWidget* parent = nullptr);
    ~TrajectoryView3D() override;

    void setResult(std::shared_ptr<const Result> result);  ///< resets the camera to fit the path
    /// For a path that grows (live input): refits the camera unless the user has orbited, panned
    /// or zoomed since the last fit; Reset view or a double-click fits and follows again.
    void followResult(std::shared_ptr<const Result> result);
    void showResult(const Result& result);  ///< copies; prefer setResult with the session's pointer
    void clear();  ///< removes path, markers and reference

    /// Positions already in the estimate's frame (see alignReferenceToEstimate); empty hides it.
    void setReference(const std::vector<Eigen::Vector3d>& positions_m);
    /// Further paths (the comparison's method sets) drawn with the main one, with a key of their
    /// own; empty removes them. The camera refits to hold them all.
    void setOverlays(const std::vector<PathOverlay>& overlays);
    const std::vector<PathOverlay>& overlays() const { return overlays_; }
    /// The main path's key entry: "Foot path", or the foot ("Left foot") when both feet are shown;
    /// empty restores the default.
    void setPathLabel(const QString& label);
    QString pathLabel() const { return pathLabel_.isEmpty() ? tr("Foot path") : pathLabel_; }
    /// The path before the last parameter change, drawn faintly under the current one so the
    /// change shows; empty hides it. It does not move the camera.
    void setGhostPath(const std::vector<Eigen::Vector3d>& positions_m);
    const std::vector<Eigen::Vector3d>& ghostPath() const { return ghost_m_; }
    /// Where the key (path, reference, markers) is drawn in a view of this size; empty when the
    /// view is too small to hold it beside the path.
    QRectF legendRect(const QSizeF& size) const;
    /// Colours each stride by the motion class of the step it leads to (Zheng et al. 2016), with a key;
    /// a result without classified steps keeps the one path colour.
    void setMotionColouring(bool on);
    bool motionColouring() const { return motionColouring_; }
    /// Whether the path is drawn in the motion classes' colours now.
    bool showsMotionColours() const;
    /// Marks the path sample nearest in time; NaN hides the marker.
    void setTimeCursor(double time_s);
    double timeCursor() const { return timeCursor_s_; }

    /// Vertical scale relative to horizontal (1 = true shape), clamped to [0.1, 50].
    void setHeightExaggeration(double factor);
    double heightExaggeration() const { return heightFactor_; }
    void setProjection(Projection projection);
    Projection projection() const { return projection_; }
    /// Direction the camera looks from: azimuth about z from +x, elevation above the ground
    /// (clamped to [-90, 90]); both in degrees.
    void setViewAngles(double azimuth_deg, double elevation_deg);
    double azimuth_deg() const { return azimuth_deg_; }
    double elevation_deg() const { return elevation_deg_; }
    double zoom() const { return zoom_; }
    /// The default oblique camera, fitted to the whole path at the current height exaggeration.
    void resetView();
    /// How often the scene (the thinned-out paths, their bounds, the motion classes) was built:
    /// once per change that is drawn or asked about, none for changes while nobody looks (for tests).
    int sceneBuilds() const { return sceneBuilds_; }

    using QWidget::render;
    /// Draws the current view (without the toolbar) into any painter; paintEvent uses it too.
    void render(QPainter& painter, const QRectF& target) const;
    /// Whether the stances are marked when the view is rendered into target: only while they stand
    /// apart on screen (stanceMarkersApart); a long walk seen whole has them a pixel or two apart,
    /// and zooming in brings them back. The key lists them only then.
    bool marksStances(const QRectF& target) const;
    /// Where a point (metres, navigation frame) appears when the view is rendered into target.
    QPointF project(const Eigen::Vector3d& position_m, const QRectF& target) const;

signals:
    void heightExaggerationChanged(double factor);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    struct ViewTransform;
    struct Grid;

    QWidget* createToolbar();
    void layOutToolbar();
    /// The paths changed: the scene is built again when next needed; refit also fits the camera then.
    void sceneChanged(bool refit);
    /// Builds the scene (and fits the camera) if a change is pending; every reader of it calls this.
    void ensureScene() const;
    void rebuildScene();
    void resetCamera();  ///< the default angles and zoom; fitCamera() then frames the scene
    void fitCamera();
    ViewTransform viewTransform(const QRectF& target) const;
    /// Where the scene is fitted in a target: above the key when the key is drawn.
    QRectF sceneArea(const QRectF& target) const;
    Grid groundGrid() const;
    void drawGrid(QPainter& painter, const ViewTransform& view, const Grid& grid) const;
    void drawAxisArrows(QPainter& painter, const ViewTransform& view, const QRectF& target) const;
    QPolygonF projectedPolyline(const ViewTransform& view, const std::vector<Eigen::Vector3d>& points,
                                const std::vector<std::size_t>& indices, double floorZ_m) const;
    static void drawInPieces(QPainter& painter, const QPolygonF& polyline);
    void drawPaths(QPainter& painter, const ViewTransform& view, const Grid& grid) const;
    /// The stances (the steps' positions) on screen, in walking order.
    QPolygonF projectedStances(const ViewTransform& view) const;
    /// Start, end, time cursor, and the stance dots given (none when they would merge).
    void drawMarkers(QPainter& painter, const ViewTransform& view, const Grid& grid, const QPolygonF& stances) const;
    using LegendIcon = std::function<void(QPainter&, const QPointF&)>;
    std::vector<std::pair<QString, LegendIcon>> legendEntries(bool withStances = true) const;
    struct LegendLayout {
        QFont font;
        QRectF box;  ///< empty: no room
        double lineHeight = 0.0;
        double columnWidth = 0.0;
        int rows = 0;
    };
    /// One column in the view's font, or in a smaller one, or two columns: the first that fits.
    static LegendLayout legendLayout(const QFont& font, const QRectF& target,
                                     const std::vector<std::pair<QString, LegendIcon>>& entries);
    void drawLegend(QPainter& painter, const QRectF& target, bool withStances) const;
    void drawMotionColouredPath(QPainter& painter, const ViewTransform& view) const;
    void drawOverlays(QPainter& painter, const ViewTransform& view) const;
    void drawGhost(QPainter& painter, const ViewTransform& view) const;
    void drawOverlayLegend(QPainter& painter, const QRectF& target) const;
    void extendSceneByOverlays();
    const std::vector<Eigen::Vector3d>& positions() const;

    std::shared_ptr<const Result> result_;
    std::vector<Eigen::Vector3d> reference_m_;
    std::vector<std::size_t> drawnPathIndices_;  ///< decimated, keeping every stance change
    std::vector<std::size_t> drawnReferenceIndices_;
    std::vector<PathOverlay> overlays_;
    QString pathLabel_;  ///< empty: "Foot path"
    std::vector<std::vector<std::size_t>> drawnOverlayIndices_;
    std::vector<Eigen::Vector3d> ghost_m_;
    std::vector<std::size_t> drawnGhostIndices_;
    Eigen::Vector3d sceneMin_m_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d sceneMax_m_ = Eigen::Vector3d::Zero();
    double timeCursor_s_;

    double heightFactor_ = 1.0;
    Projection projection_ = Projection::Orthographic;
    double azimuth_deg_;
    double elevation_deg_;
    double zoom_ = 1.0;
    QPointF pan_m_;  ///< screen-plane shift of the scene, in metres at the scene centre
    /// Half-size (metres) of the scene as the default camera sees it; the zoom is relative to it,
    /// so orbiting does not change the scale and any target size shows the same framing.
    QPointF fitHalfExtent_m_;

    QPoint lastMousePosition_;
    bool cameraMovedByUser_ = false;  ///< since the last resetView(); followResult keeps the camera
    bool sceneStale_ = false;  ///< the paths changed since the scene was built
    bool ghostStale_ = false;
    bool fitPending_ = false;  ///< the camera is to be fitted to the scene once built
    int sceneBuilds_ = 0;
    QWidget* toolbar_;
    std::vector<QWidget*> toolbarWidgets_;  ///< in reading order; one row or two (layOutToolbar)
    QDoubleSpinBox* heightSpin_;
    QCheckBox* perspectiveCheck_;
    QCheckBox* motionCheck_ = nullptr;
    bool motionColouring_ = false;
    std::vector<MotionClass> sampleMotion_;  ///< per result sample (motionOfSamples)
};

}  // namespace footpath
