#pragma once

#include "OrbitCamera.h"
#include "PathScene3D.h"

#include <QCoreApplication>
#include <QFont>
#include <QPolygonF>
#include <QRectF>
#include <QString>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

class QPainter;

namespace footpath {

/// Draws a PathScene3D through an OrbitCamera with QPainter only (no OpenGL: it must work
/// offscreen and inside the PDF report): the ground grid with metre labels, the paths, an x/y/z
/// triad, start, end, stance and cursor markers, and the keys. It also tells where things land in a
/// target, for the widget's mouse handling and for tests. It holds references: make one per use.
class Scene3DPainter {
    // The texts keep the 3D view's translation context, where they were translated.
    Q_DECLARE_TR_FUNCTIONS(footpath::TrajectoryView3D)

public:
    /// layoutFont: the font the key is measured in when the scene is fitted beside or above it
    /// (the widget's); the key itself is drawn in the painter's font.
    Scene3DPainter(const PathScene3D& scene, const OrbitCamera& camera, const QFont& layoutFont);
    /// Room at the top of the target that the overlays' key stays below (the widget's toolbar).
    void setTopInset(double inset_px) { topInset_px_ = inset_px; }

    void render(QPainter& painter, const QRectF& target) const;
    ViewTransform viewTransform(const QRectF& target) const;
    /// Where the scene is fitted in a target: beside or above the key when the key is drawn.
    QRectF sceneArea(const QRectF& target) const;
    /// Whether the stances are marked in target: only while they stand apart on screen
    /// (stanceMarkersApart).
    bool marksStances(const QRectF& target) const;
    /// Where the main key is drawn in target; empty when there is no room for it or nothing to explain.
    QRectF legendRect(const QRectF& target) const;

private:
    using LegendIcon = std::function<void(QPainter&, const QPointF&)>;
    using LegendEntries = std::vector<std::pair<QString, LegendIcon>>;
    struct LegendLayout {
        QFont font;
        QRectF box;  ///< in the target; empty: no room
        double lineHeight = 0.0;
        double columnWidth = 0.0;
        int rows = 0;
    };

    static void drawGrid(QPainter& painter, const ViewTransform& view, const PathScene3D::Grid& grid);
    /// Draws text centred at at unless it would touch one of the boxes taken, and takes its box.
    static void drawLabelWithRoom(QPainter& painter, const QPointF& at, const QString& text, std::vector<QRectF>& taken);
    static void drawAxisArrows(QPainter& painter, const ViewTransform& view, const QRectF& target);
    /// The drawn points on screen, those on the same pixel as the one before left out; with floorZ_m,
    /// the line's shadow on the floor at that height.
    static QPolygonF projectedPolyline(const ViewTransform& view, const PathScene3D::Line& line,
                                       std::optional<double> floorZ_m = std::nullopt);
    static void drawInPieces(QPainter& painter, const QPolygonF& polyline);
    void drawGhost(QPainter& painter, const ViewTransform& view) const;
    void drawOverlays(QPainter& painter, const ViewTransform& view) const;
    void drawPaths(QPainter& painter, const ViewTransform& view, const PathScene3D::Grid& grid) const;
    void drawOneColourPath(QPainter& painter, const ViewTransform& view) const;
    void drawMotionColouredPath(QPainter& painter, const ViewTransform& view) const;
    /// The stances on screen, in walking order.
    QPolygonF projectedStances(const ViewTransform& view) const;
    /// Start, end, time cursor, and the stance dots given (none when they would merge).
    void drawMarkers(QPainter& painter, const ViewTransform& view, const PathScene3D::Grid& grid,
                     const QPolygonF& stances) const;
    LegendEntries legendEntries(bool withStances = true) const;
    /// One column in the given font, or two, or the same in a smaller font: the first that fits.
    static LegendLayout legendLayout(const QFont& font, const QRectF& target, const LegendEntries& entries);
    /// The entries in this font and number of columns; the box has its size, not yet its place.
    static LegendLayout legendLayoutIn(const QFont& font, int columns, const LegendEntries& entries);
    static LegendLayout placedAtBottomLeft(LegendLayout layout, const QRectF& target);
    void drawLegend(QPainter& painter, const QRectF& target, bool withStances) const;
    void drawOverlayLegend(QPainter& painter, const QRectF& target) const;

    const PathScene3D& scene_;
    const OrbitCamera& camera_;
    QFont layoutFont_;
    double topInset_px_ = 0.0;
};

}  // namespace footpath
