#include "Scene3DPainter.h"

#include "MotionLanes.h"
#include "StanceMarkers.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>

namespace footpath {

namespace {

constexpr double kAxisArrow_px = 32.0;

const QColor kPathColour(40, 90, 170);
const QColor kShadowColour(200, 205, 215);
const QColor kGhostColour(100, 100, 100, 120);  ///< the path before the last change: there, not competing
const QColor kReferenceColour(150, 150, 150);
const QColor kStanceColour(230, 120, 20);
const QColor kGridColour(222, 222, 222);
const QColor kLabelColour(110, 110, 110);
const QColor kCursorColour(255, 215, 0);
const QColor kKeyFrameColour(200, 200, 200);
const QColor kKeyBackground(255, 255, 255, 225);

QString metres(double value_m)
{
    // Adding 0.0 turns -0 into 0; 'g' drops the rounding noise of value = first + i * step.
    return QCoreApplication::translate("footpath::TrajectoryView3D", "%1 m").arg(QString::number(value_m + 0.0, 'g', 6));
}

void drawStance(QPainter& painter, const QPointF& at)
{
    painter.setPen(Qt::NoPen);
    painter.setBrush(kStanceColour);
    painter.drawEllipse(at, 2.6, 2.6);
}

void drawStart(QPainter& painter, const QPointF& at)
{
    painter.setPen(QPen(Qt::darkGreen, 2.0));
    painter.setBrush(Qt::white);
    painter.drawRect(QRectF(at - QPointF(5.0, 5.0), QSizeF(10.0, 10.0)));
}

void drawEnd(QPainter& painter, const QPointF& at)
{
    painter.setPen(QPen(Qt::red, 2.0));
    painter.drawLine(at + QPointF(-5.0, -5.0), at + QPointF(5.0, 5.0));
    painter.drawLine(at + QPointF(-5.0, 5.0), at + QPointF(5.0, -5.0));
}

void drawCursor(QPainter& painter, const QPointF& at)
{
    painter.setPen(QPen(Qt::black, 2.0));
    painter.setBrush(kCursorColour);
    painter.drawEllipse(at, 6.5, 6.5);
}

void drawCentredText(QPainter& painter, const QPointF& centre, const QString& text)
{
    const QRectF box(centre - QPointF(60.0, 10.0), QSizeF(120.0, 20.0));
    painter.drawText(box, Qt::AlignCenter, text);
}

/// The keys' box: a light frame over a nearly opaque white, so a path under it still shows faintly.
void drawKeyBox(QPainter& painter, const QRectF& box)
{
    painter.setPen(QPen(kKeyFrameColour, 1.0));
    painter.setBrush(kKeyBackground);
    painter.drawRect(box);
}

void drawArrowHead(QPainter& painter, const QPointF& tip, const QPointF& unit, const QColor& colour)
{
    const QPointF normal(-unit.y(), unit.x());
    QPainterPath head;
    head.moveTo(tip);
    head.lineTo(tip - 8.0 * unit + 3.5 * normal);
    head.lineTo(tip - 8.0 * unit - 3.5 * normal);
    head.closeSubpath();
    painter.fillPath(head, colour);
}

/// from, from + step, ... up to to (and a rounding error beyond).
std::vector<double> gridLines(double from, double to, double step)
{
    std::vector<double> values;
    for (double v = from; v <= to + 0.5 * step; v += step)
        values.push_back(v);
    return values;
}

}  // namespace

Scene3DPainter::Scene3DPainter(const PathScene3D& scene, const OrbitCamera& camera, const QFont& layoutFont)
    : scene_(scene), camera_(camera), layoutFont_(layoutFont)
{
}

void Scene3DPainter::render(QPainter& painter, const QRectF& target) const
{
    painter.save();
    painter.setClipRect(target);
    painter.fillRect(target, Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    if (scene_.isEmpty()) {
        painter.setPen(kLabelColour);
        painter.drawText(target, Qt::AlignCenter, tr("No trajectory"));
        painter.restore();
        return;
    }
    const ViewTransform view = viewTransform(target);
    const PathScene3D::Grid grid = scene_.grid();
    drawGrid(painter, view, grid);
    drawGhost(painter, view);
    drawOverlays(painter, view);
    drawPaths(painter, view, grid);
    drawAxisArrows(painter, view, target);
    const QPolygonF stances = projectedStances(view);
    const bool marked = stanceMarkersApart(stances);
    drawMarkers(painter, view, grid, marked ? stances : QPolygonF());
    drawLegend(painter, target, marked);
    drawOverlayLegend(painter, target);
    painter.restore();
}

ViewTransform Scene3DPainter::viewTransform(const QRectF& target) const
{
    return camera_.transform(scene_.bounds(), sceneArea(target));
}

QRectF Scene3DPainter::sceneArea(const QRectF& target) const
{
    // The path is fitted beside or above the key, so the key does not cover it. The key is
    // measured with its stance entry, which the markers' spacing at this scale decides on.
    const QRectF legend = legendLayout(layoutFont_, target, legendEntries()).box;
    if (legend.isEmpty())
        return target;
    // Whichever leaves the path the larger scale.
    const QRectF above = target.adjusted(0.0, 0.0, 0.0, -(legend.height() + 8.0));
    const QRectF beside = target.adjusted(legend.width() + 8.0, 0.0, 0.0, 0.0);
    return camera_.fittedScale(beside.size()) > camera_.fittedScale(above.size()) ? beside : above;
}

bool Scene3DPainter::marksStances(const QRectF& target) const
{
    return stanceMarkersApart(projectedStances(viewTransform(target)));
}

QRectF Scene3DPainter::legendRect(const QRectF& target) const
{
    if (scene_.isEmpty())
        return {};
    return legendLayout(layoutFont_, target, legendEntries(marksStances(target))).box;
}

void Scene3DPainter::drawGrid(QPainter& painter, const ViewTransform& view, const PathScene3D::Grid& grid)
{
    painter.setPen(QPen(kGridColour, 1.0));
    const std::vector<double> xs = gridLines(grid.xMin, grid.xMax, grid.step_m);
    const std::vector<double> ys = gridLines(grid.yMin, grid.yMax, grid.step_m);
    for (double x : xs)
        painter.drawLine(view({x, grid.yMin, grid.z_m}), view({x, grid.yMax, grid.z_m}));
    for (double y : ys)
        painter.drawLine(view({grid.xMin, y, grid.z_m}), view({grid.xMax, y, grid.z_m}));

    // Labels along the two edges nearer the viewer, just outside the grid, so the path never hides them.
    const double labelOffset = grid.labelOffset_m();
    const double xLabelsAtY = view.toEye.y() < 0.0 ? grid.yMin - labelOffset : grid.yMax + labelOffset;
    const double yLabelsAtX = view.toEye.x() < 0.0 ? grid.xMin - labelOffset : grid.xMax + labelOffset;
    painter.setPen(kLabelColour);
    std::vector<QRectF> taken;
    for (double x : xs)
        drawLabelWithRoom(painter, view({x, xLabelsAtY, grid.z_m}), metres(x), taken);
    for (double y : ys)
        drawLabelWithRoom(painter, view({yLabelsAtX, y, grid.z_m}), metres(y), taken);
}

void Scene3DPainter::drawLabelWithRoom(QPainter& painter, const QPointF& at, const QString& text, std::vector<QRectF>& taken)
{
    // Seen edge-on, an axis's labels pile up on each other: draw only those with room.
    QRectF box = painter.fontMetrics().boundingRect(text);
    box.moveCenter(at);
    const bool collides = std::any_of(taken.cbegin(), taken.cend(),
                                      [&box](const QRectF& other) { return other.intersects(box.adjusted(-3, -1, 3, 1)); });
    if (collides)
        return;
    taken.push_back(box);
    painter.drawText(box, Qt::AlignCenter, text);
}

void Scene3DPainter::drawAxisArrows(QPainter& painter, const ViewTransform& view, const QRectF& target)
{
    // A fixed-size triad in a corner: it shows which way x, y and z point from any angle and
    // never stretches off screen with zoom or height exaggeration, as arrows in the scene would.
    const QPointF origin = target.bottomRight() - QPointF(kAxisArrow_px + 16.0, kAxisArrow_px + 16.0);
    const struct {
        Eigen::Vector3d direction;
        QColor colour;
        const char* name;
    } axes[] = {{Eigen::Vector3d::UnitX(), QColor(200, 40, 40), QT_TR_NOOP("x")},
                {Eigen::Vector3d::UnitY(), QColor(30, 150, 60), QT_TR_NOOP("y")},
                {Eigen::Vector3d::UnitZ(), QColor(40, 80, 210), QT_TR_NOOP("z")}};
    for (const auto& axis : axes) {
        const QPointF along = kAxisArrow_px * QPointF(axis.direction.dot(view.right), -axis.direction.dot(view.up));
        const QPointF tip = origin + along;
        painter.setPen(QPen(axis.colour, 2.0, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(origin, tip);
        const double length = std::hypot(along.x(), along.y());
        const QPointF unit = length < 4.0 ? QPointF(0.7, -0.7) : along / length;
        if (length >= 4.0)  // shorter: the axis points at the viewer and has no direction to show
            drawArrowHead(painter, tip, unit, axis.colour);
        drawCentredText(painter, tip + 10.0 * unit, tr(axis.name));
    }
}

QPolygonF Scene3DPainter::projectedPolyline(const ViewTransform& view, const PathScene3D::Line& line,
                                            std::optional<double> floorZ_m)
{
    QPolygonF polyline;
    polyline.reserve(static_cast<qsizetype>(line.drawn.size()));
    for (std::size_t index : line.drawn) {
        const Eigen::Vector3d& p = line.points_m[index];
        const QPointF pixel = view(floorZ_m ? Eigen::Vector3d(p.x(), p.y(), *floorZ_m) : p);
        // Points on the same pixel add stroking work and nothing visible.
        if (polyline.isEmpty() || (pixel - polyline.back()).manhattanLength() >= 1.0 || index == line.drawn.back())
            polyline << pixel;
    }
    return polyline;
}

void Scene3DPainter::drawInPieces(QPainter& painter, const QPolygonF& polyline)
{
    // One long self-crossing polyline makes QPainter stroke and fill one huge outline (a second
    // for a long walk); short pieces keep joins and dash patterns at a fraction of the cost.
    constexpr qsizetype kPiece = 64;
    for (qsizetype first = 0; first + 1 < polyline.size(); first += kPiece)
        painter.drawPolyline(polyline.constData() + first, static_cast<int>(std::min(kPiece + 1, polyline.size() - first)));
}

void Scene3DPainter::drawGhost(QPainter& painter, const ViewTransform& view) const
{
    painter.setPen(QPen(kGhostColour, 2.0));
    drawInPieces(painter, projectedPolyline(view, scene_.drawnGhost()));
}

void Scene3DPainter::drawOverlays(QPainter& painter, const ViewTransform& view) const
{
    for (std::size_t i = 0; i < scene_.overlays().size(); ++i) {
        painter.setPen(QPen(scene_.overlays()[i].colour, 1.3));
        drawInPieces(painter, projectedPolyline(view, scene_.drawnOverlay(i)));
    }
}

void Scene3DPainter::drawPaths(QPainter& painter, const ViewTransform& view, const PathScene3D::Grid& grid) const
{
    // The shadow on the floor is what makes heights readable in a still image. Thin pens take
    // QPainter's fast path, so the two secondary lines cost next to nothing.
    painter.setPen(QPen(kShadowColour, 1.0));
    drawInPieces(painter, projectedPolyline(view, scene_.drawnPath(), grid.z_m));
    painter.setPen(QPen(kReferenceColour, 1.0, Qt::DashLine));
    drawInPieces(painter, projectedPolyline(view, scene_.drawnReference()));
    if (scene_.showsMotionColours())
        drawMotionColouredPath(painter, view);
    else
        drawOneColourPath(painter, view);
}

void Scene3DPainter::drawOneColourPath(QPainter& painter, const ViewTransform& view) const
{
    // A wide pen with flat caps, segment by segment, is the one wide stroke QPainter rasterises
    // quickly (a tenth of the time of a polyline); the joins it leaves out are sub-pixel.
    painter.setPen(QPen(kPathColour, 1.6, Qt::SolidLine, Qt::FlatCap));
    const QPolygonF path = projectedPolyline(view, scene_.drawnPath());
    QVector<QLineF> segments;
    segments.reserve(path.size());
    for (qsizetype k = 1; k < path.size(); ++k)
        segments.append(QLineF(path[k - 1], path[k]));
    painter.drawLines(segments);
}

void Scene3DPainter::drawMotionColouredPath(QPainter& painter, const ViewTransform& view) const
{
    // Segments grouped by class, one drawLines call each (wide, flat caps, as drawOneColourPath);
    // a segment takes the class of its end.
    const PathScene3D::Line path = scene_.drawnPath();
    const std::vector<MotionClass>& motion = scene_.sampleMotion();
    std::map<MotionClass, QVector<QLineF>> segments;
    for (std::size_t k = 1; k < path.drawn.size(); ++k) {
        const std::size_t from = path.drawn[k - 1], to = path.drawn[k];
        segments[motion[to]].append(QLineF(view(path.points_m[from]), view(path.points_m[to])));
    }
    for (const auto& [motionClass, lines] : segments) {
        painter.setPen(QPen(motionClassColour(motionClass), 2.2, Qt::SolidLine, Qt::FlatCap));
        painter.drawLines(lines);
    }
}

QPolygonF Scene3DPainter::projectedStances(const ViewTransform& view) const
{
    QPolygonF stances;
    stances.reserve(static_cast<qsizetype>(scene_.stances().size()));
    for (const Step& step : scene_.stances())
        stances << view(step.position_m);
    return stances;
}

void Scene3DPainter::drawMarkers(QPainter& painter, const ViewTransform& view, const PathScene3D::Grid& grid,
                                 const QPolygonF& stances) const
{
    if (!scene_.hasPath())
        return;
    // One call for all stances: a long walk has thousands, and ellipses one by one cost more
    // than the whole path.
    painter.setPen(QPen(kStanceColour, 5.2, Qt::SolidLine, Qt::RoundCap));
    painter.drawPoints(stances);
    drawStart(painter, view(scene_.path().front()));
    drawEnd(painter, view(scene_.path().back()));

    const std::optional<Eigen::Vector3d> cursor = scene_.cursorPosition();
    if (!cursor)
        return;
    painter.setPen(QPen(Qt::black, 1.0, Qt::DashLine));
    painter.drawLine(view(*cursor), view({cursor->x(), cursor->y(), grid.z_m}));
    drawCursor(painter, view(*cursor));
}

Scene3DPainter::LegendEntries Scene3DPainter::legendEntries(bool withStances) const
{
    const auto line = [](QPen pen) {
        return LegendIcon([pen](QPainter& p, const QPointF& at) {
            p.setPen(pen);
            p.drawLine(at - QPointF(12.0, 0.0), at + QPointF(12.0, 0.0));
        });
    };
    LegendEntries entries;
    if (scene_.showsMotionColours()) {  // the path's one colour gives way to the classes'
        for (const MotionClass motion : motionClassesIn(scene_.sampleMotion()))
            entries.emplace_back(motionClassLabel(motion), line(QPen(motionClassColour(motion), 2.0)));
    } else {
        entries.emplace_back(scene_.pathLabel(), line(QPen(kPathColour, 2.0)));
    }
    entries.emplace_back(tr("Shadow on the floor"), line(QPen(kShadowColour, 2.0)));
    if (!scene_.reference().empty())
        entries.emplace_back(tr("Reference"), line(QPen(kReferenceColour, 1.5, Qt::DashLine)));
    if (!scene_.ghost().empty())
        entries.emplace_back(tr("Before the last change"), line(QPen(kGhostColour, 2.0)));
    if (withStances)
        entries.emplace_back(tr("Stance"), drawStance);
    entries.emplace_back(tr("Start"), drawStart);
    entries.emplace_back(tr("End"), drawEnd);
    if (!std::isnan(scene_.timeCursor()))
        entries.emplace_back(tr("Time cursor"), drawCursor);
    if (camera_.heightFactor() != 1.0)
        entries.emplace_back(tr("Heights drawn \u00d7 %1").arg(camera_.heightFactor(), 0, 'g', 3), LegendIcon());
    return entries;
}

Scene3DPainter::LegendLayout Scene3DPainter::legendLayout(const QFont& font, const QRectF& target,
                                                          const LegendEntries& entries)
{
    // A small view (the 3D tab on a 1280-pixel screen) gets a smaller key rather than none: the
    // dashed reference and the markers must be explained wherever they are drawn.
    for (const double scale : {1.0, 0.85}) {
        QFont scaled = font;
        if (scale != 1.0)
            scaled.setPointSizeF(font.pointSizeF() * scale);
        for (const int columns : {1, 2}) {
            const LegendLayout layout = legendLayoutIn(scaled, columns, entries);
            const QSizeF size = layout.box.size();
            if (size.height() <= 0.4 * target.height() && size.width() <= 0.6 * target.width())
                return placedAtBottomLeft(layout, target);
        }
    }
    return {};
}

Scene3DPainter::LegendLayout Scene3DPainter::legendLayoutIn(const QFont& font, int columns, const LegendEntries& entries)
{
    LegendLayout layout;
    layout.font = font;
    const QFontMetricsF metrics(layout.font);
    layout.lineHeight = std::max(metrics.height() + 2.0, 14.0);
    double widestText = 0.0;
    for (const auto& entry : entries)
        widestText = std::max(widestText, metrics.horizontalAdvance(entry.first));
    layout.columnWidth = widestText + 50.0;
    const auto perColumn = static_cast<std::size_t>(columns);
    layout.rows = static_cast<int>((entries.size() + perColumn - 1) / perColumn);
    layout.box.setSize(QSizeF(columns * layout.columnWidth, layout.rows * layout.lineHeight + 8.0));
    return layout;
}

Scene3DPainter::LegendLayout Scene3DPainter::placedAtBottomLeft(LegendLayout layout, const QRectF& target)
{
    const QSizeF size = layout.box.size();
    layout.box = QRectF(QPointF(target.left() + 8.0, target.bottom() - 8.0 - size.height()), size);
    return layout;
}

void Scene3DPainter::drawLegend(QPainter& painter, const QRectF& target, bool withStances) const
{
    const LegendEntries entries = legendEntries(withStances);
    const LegendLayout layout = legendLayout(painter.font(), target, entries);
    if (layout.box.isEmpty())
        return;  // a very small view needs its room for the path more than for the key
    painter.save();
    painter.setFont(layout.font);
    drawKeyBox(painter, layout.box);
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const auto& [text, icon] = entries[i];
        const double left = layout.box.left() + static_cast<double>(i / static_cast<std::size_t>(layout.rows)) * layout.columnWidth;
        const double y = layout.box.top() + 4.0 + (static_cast<double>(i % static_cast<std::size_t>(layout.rows)) + 0.5) * layout.lineHeight;
        if (icon)
            icon(painter, QPointF(left + 20.0, y));
        painter.setPen(icon ? Qt::black : QColor(170, 40, 40));
        painter.drawText(QRectF(left + 40.0, y - 0.5 * layout.lineHeight, layout.columnWidth - 40.0, layout.lineHeight),
                         Qt::AlignVCenter | Qt::AlignLeft, text);
    }
    painter.restore();
}

void Scene3DPainter::drawOverlayLegend(QPainter& painter, const QRectF& target) const
{
    // Top left, apart from the main key at the bottom: both stay small enough to leave the path room.
    const std::vector<PathOverlay>& overlays = scene_.overlays();
    if (overlays.empty())
        return;
    painter.save();
    QFont font = painter.font();
    font.setPointSizeF(font.pointSizeF() * 0.85);
    painter.setFont(font);
    const QFontMetricsF metrics(painter.font());  // the painter's: in the target device's resolution
    const double lineHeight = metrics.height() + 2.0;
    double textWidth = 0.0;
    for (const PathOverlay& overlay : overlays)
        textWidth = std::max(textWidth, metrics.horizontalAdvance(overlay.label));
    const QRectF box(target.left() + 8.0, target.top() + 8.0 + topInset_px_, textWidth + 46.0,
                     static_cast<double>(overlays.size()) * lineHeight + 8.0);
    if (box.height() > 0.5 * target.height() || box.width() > 0.7 * target.width()) {
        painter.restore();
        return;
    }
    drawKeyBox(painter, box);
    double y = box.top() + 4.0 + 0.5 * lineHeight;
    for (const PathOverlay& overlay : overlays) {
        painter.setPen(QPen(overlay.colour, 2.0));
        painter.drawLine(QPointF(box.left() + 8.0, y), QPointF(box.left() + 32.0, y));
        painter.setPen(Qt::black);
        painter.drawText(QRectF(box.left() + 40.0, y - 0.5 * lineHeight, textWidth + 4.0, lineHeight),
                         Qt::AlignVCenter | Qt::AlignLeft, overlay.label);
        y += lineHeight;
    }
    painter.restore();
}

}  // namespace footpath
