#pragma once

#include "OrbitCamera.h"
#include "PathOverlay.h"
#include "PathScene3D.h"
#include "Result.h"
#include "SessionView.h"

#include <Eigen/Core>

#include <QPoint>
#include <QRectF>
#include <QWidget>

#include <memory>
#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QPainter;

namespace footpath {

class Scene3DPainter;

/// The foot path in 3D, drawn with QPainter only (no OpenGL: it must work offscreen and inside the
/// PDF report): a ground grid with metre labels, x/y/z arrows, start, end and stance markers, the
/// time cursor and an optional reference. Left-drag orbits, the wheel zooms about the pointer,
/// right- or middle-drag pans, a double-click resets the view. Heights can be exaggerated so a
/// few centimetres of foot lift or a staircase stand out against tens of metres of walk.
class TrajectoryView3D : public QWidget, public SessionView {
    Q_OBJECT
public:
    enum class Projection { Orthographic, Perspective };
    Q_ENUM(Projection)

    explicit TrajectoryView3D(QWidget* parent = nullptr);
    ~TrajectoryView3D() override;
    void showEstimate(const AnalysisSession& session) override;
    void showTimeCursor(double time_s) override { setTimeCursor(time_s); }

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
    const std::vector<PathOverlay>& overlays() const { return scene_.overlays(); }
    /// The main path's key entry: "Foot path", or the foot ("Left foot") when both feet are shown;
    /// empty restores the default.
    void setPathLabel(const QString& label);
    QString pathLabel() const { return scene_.pathLabel(); }
    /// The path before the last parameter change, drawn faintly under the current one so the
    /// change shows; empty hides it. It does not move the camera.
    void setGhostPath(const std::vector<Eigen::Vector3d>& positions_m);
    const std::vector<Eigen::Vector3d>& ghostPath() const { return scene_.ghost(); }
    /// Where the key (path, reference, markers) is drawn in a view of this size; empty when the
    /// view is too small to hold it beside the path.
    QRectF legendRect(const QSizeF& size) const;
    /// Colours each stride by the motion class of the step it leads to (Zheng et al. 2016), with a key;
    /// a result without classified steps keeps the one path colour.
    void setMotionColouring(bool on);
    bool motionColouring() const { return scene_.motionColouring(); }
    /// Whether the path is drawn in the motion classes' colours now.
    bool showsMotionColours() const;
    /// Marks the path sample nearest in time; NaN hides the marker.
    void setTimeCursor(double time_s);
    double timeCursor() const { return scene_.timeCursor(); }

    /// Vertical scale relative to horizontal (1 = true shape), clamped to [0.1, 50].
    void setHeightExaggeration(double factor);
    double heightExaggeration() const { return camera_.heightFactor(); }
    void setProjection(Projection projection);
    Projection projection() const { return camera_.perspective() ? Projection::Perspective : Projection::Orthographic; }
    /// Direction the camera looks from: azimuth about z from +x, elevation above the ground
    /// (clamped to [-90, 90]); both in degrees.
    void setViewAngles(double azimuth_deg, double elevation_deg);
    double azimuth_deg() const { return camera_.azimuth_deg(); }
    double elevation_deg() const { return camera_.elevation_deg(); }
    double zoom() const { return camera_.zoom(); }
    /// The default oblique camera, fitted to the whole path at the current height exaggeration.
    void resetView();
    /// How often the scene (the thinned-out paths, their bounds, the motion classes) was built:
    /// once per change that is drawn or asked about, none for changes while nobody looks (for tests).
    int sceneBuilds() const { return scene_.builds(); }

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
    QWidget* createToolbar();
    void layOutToolbar();
    /// The paths changed: the scene is built again when next needed; refit also fits the camera then.
    void sceneChanged(bool refit);
    void resetCamera();  ///< the default angles and zoom; ensureScene() then fits the camera
    /// Builds the scene (and fits the camera) if a change is pending; every reader of it calls this.
    void ensureScene() const;
    /// The scene through the camera in target, with the on-screen toolbar kept clear when target is the view.
    Scene3DPainter scenePainter(const QRectF& target) const;

    PathScene3D scene_;
    OrbitCamera camera_;
    QPoint lastMousePosition_;
    bool cameraMovedByUser_ = false;  ///< since the last resetView(); followResult keeps the camera
    bool fitPending_ = false;  ///< the camera is to be fitted to the scene once built
    QWidget* toolbar_;
    std::vector<QWidget*> toolbarWidgets_;  ///< in reading order; one row or two (layOutToolbar)
    QDoubleSpinBox* heightSpin_;
    QCheckBox* perspectiveCheck_;
    QCheckBox* motionCheck_ = nullptr;
};

}  // namespace footpath
