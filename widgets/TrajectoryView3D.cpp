#include "TrajectoryView3D.h"

#include "MotionLanes.h"
#include "StanceMarkers.h"
#include "TrajectoryView2D.h"  // nearestSampleAtTime, shared so both views mark the same sample

#include <Eigen/Geometry>
#include <QCheckBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QSignalBlocker>
#include <QToolButton>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <utility>

namespace footpath {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDefaultAzimuth_deg = -60.0;
constexpr double kDefaultElevation_deg = 30.0;
/// A 30-minute 100 Hz walk has 180k samples; this many points draw in a few milliseconds and
/// still follow every stride.
constexpr std::size_t kMaxDrawnPoints = 20000;
constexpr double kFitFraction = 0.85;        ///< of the target the fitted scene fills; the rest is for labels
constexpr double kMinHalfExtent_m = 0.5;     ///< a single point or a straight line still gets a sensible scale
constexpr double kEyeDistanceInRadii = 3.0;  ///< perspective: camera distance from the scene centre
constexpr double kNearFraction = 0.05;       ///< perspective: points closer than this are clamped, not inverted
constexpr double kOrbitDegreesPerPixel = 0.4;
constexpr double kAxisArrow_px = 32.0;
constexpr double kLabelOffsetInSteps = 0.45;  ///< metre labels sit this far outside the grid
constexpr double kZoomPerWheelNotch = 1.2;
constexpr double kMinHeightFactor = 0.1;
constexpr double kMaxHeightFactor = 50.0;

const QColor kPathColour(40, 90, 170);
const QColor kShadowColour(200, 205, 215);
const QColor kGhostColour(100, 100, 100, 120);  ///< the path before the last change: there, not competing
const QColor kReferenceColour(150, 150, 150);
const QColor kStanceColour(230, 120, 20);
const QColor kGridColour(222, 222, 222);
const QColor kLabelColour(110, 110, 110);
const QColor kCursorColour(255, 215, 0);

double toRadians(double degrees)
{
    return degrees * kPi / 180.0;
}

/// 1, 2 or 5 times a power of ten, the smallest not below raw_m.
double niceStep(double raw_m)
{
    const double base = std::pow(10.0, std::floor(std::log10(raw_m)));
    for (double multiple : {1.0, 2.0, 5.0}) {
        if (multiple * base >= raw_m)
            return multiple * base;
    }
    return 10.0 * base;
}

/// Every n-th sample plus every change of the stance flag, so a stance keeps its place even when
/// the samples around it are thinned out.
std::vector<std::size_t> decimatedIndices(std::size_t count, const std::vector<std::uint8_t>& stance)
{
    std::vector<std::size_t> indices;
    if (count == 0)
        return indices;
    const std::size_t every = std::max<std::size_t>(1, (count + kMaxDrawnPoints - 1) / kMaxDrawnPoints);
    const bool haveStance = stance.size() == count;
    for (std::size_t k = 0; k < count; ++k) {
        const bool stanceChanges = haveStance && k > 0 && stance[k] != stance[k - 1];
        if (k % every == 0 || k + 1 == count || stanceChanges)
            indices.push_back(k);
    }
    return indices;
}

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

}  // namespace

/// World (metres) to target pixels for one frame: rotation into the camera basis, height
/// exaggeration, optional perspective, scale and pan.
struct TrajectoryView3D::ViewTransform {
    Eigen::Vector3d centre_m;  ///< scene centre, heights already exaggerated
    Eigen::Vector3d right;     ///< camera basis in world coordinates
    Eigen::Vector3d up;
    Eigen::Vector3d toEye;
    double heightFactor = 1.0;
    double pixelsPerMetre = 1.0;
    QPointF origin_px;  ///< where the scene centre lands, pan included
    bool perspective = false;
    double eyeDistance_m = 1.0;

    QPointF operator()(const Eigen::Vector3d& position_m) const
    {
        const Eigen::Vector3d q =
            Eigen::Vector3d(position_m.x(), position_m.y(), position_m.z() * heightFactor) - centre_m;
        double shrink = 1.0;
        if (perspective) {
            const double depth = std::max(eyeDistance_m - q.dot(toEye), kNearFraction * eyeDistance_m);
            shrink = eyeDistance_m / depth;
        }
        return origin_px + pixelsPerMetre * shrink * QPointF(q.dot(right), -q.dot(up));
    }
};

/// The ground grid: lines every step_m at the lowest height of the scene.
struct TrajectoryView3D::Grid {
    double step_m = 1.0;
    double xMin = 0.0, xMax = 0.0, yMin = 0.0, yMax = 0.0;
    double z_m = 0.0;
};

TrajectoryView3D::TrajectoryView3D(QWidget* parent)
    : QWidget(parent),
      timeCursor_s_(std::numeric_limits<double>::quiet_NaN()),
      azimuth_deg_(kDefaultAzimuth_deg),
      elevation_deg_(kDefaultElevation_deg)
{
    setMinimumSize(200, 150);
    setFocusPolicy(Qt::WheelFocus);
    toolbar_ = createToolbar();
    resetView();
}

TrajectoryView3D::~TrajectoryView3D() = default;

QWidget* TrajectoryView3D::createToolbar()
{
    auto* bar = new QWidget(this);
    bar->setAutoFillBackground(true);
    QPalette palette = bar->palette();
    palette.setColor(QPalette::Window, QColor(255, 255, 255, 230));
    bar->setPalette(palette);
    auto* layout = new QGridLayout(bar);
    layout->setContentsMargins(6, 3, 6, 3);

    heightSpin_ = new QDoubleSpinBox(bar);
    heightSpin_->setRange(kMinHeightFactor, kMaxHeightFactor);
    heightSpin_->setSingleStep(0.5);
    heightSpin_->setDecimals(1);
    heightSpin_->setValue(heightFactor_);
    heightSpin_->setToolTip(tr("Vertical exaggeration: heights are drawn this many times larger"));
    auto* label = new QLabel(tr("Height \u00d7"), bar);
    label->setBuddy(heightSpin_);
    perspectiveCheck_ = new QCheckBox(tr("Perspective"), bar);
    auto* reset = new QToolButton(bar);
    reset->setText(tr("Reset view"));
    reset->setToolTip(tr("Oblique view of the whole path (or double-click the view)"));
    motionCheck_ = new QCheckBox(MotionLanes::tr("Colour by motion"), bar);
    motionCheck_->setToolTip(MotionLanes::tr("Colour each stride by its step's motion class (stairs, elevator); "
                                             "needs a barometer"));
    toolbarWidgets_ = {label, heightSpin_, perspectiveCheck_, motionCheck_, reset};
    for (int column = 0; column < static_cast<int>(toolbarWidgets_.size()); ++column)
        layout->addWidget(toolbarWidgets_[static_cast<std::size_t>(column)], 0, column);
    connect(motionCheck_, &QCheckBox::toggled, this, &TrajectoryView3D::setMotionColouring);
    connect(heightSpin_, &QDoubleSpinBox::valueChanged, this, &TrajectoryView3D::setHeightExaggeration);
    connect(perspectiveCheck_, &QCheckBox::toggled, this, [this](bool on) {
        setProjection(on ? Projection::Perspective : Projection::Orthographic);
    });
    connect(reset, &QToolButton::clicked, this, &TrajectoryView3D::resetView);
    return bar;
}

const std::vector<Eigen::Vector3d>& TrajectoryView3D::positions() const
{
    static const std::vector<Eigen::Vector3d> none;
    return result_ ? result_->position_m : none;
}

void TrajectoryView3D::showResult(const Result& result)
{
    setResult(std::make_shared<const Result>(result));
}

void TrajectoryView3D::setResult(std::shared_ptr<const Result> result)
{
    cameraMovedByUser_ = false;  // a new result is fitted whatever the user did to the old one
    followResult(std::move(result));
}

void TrajectoryView3D::followResult(std::shared_ptr<const Result> result)
{
    result_ = std::move(result);
    sceneChanged(!cameraMovedByUser_);
}

void TrajectoryView3D::clear()
{
    result_.reset();
    reference_m_.clear();
    ghost_m_.clear();
    ghostStale_ = true;
    sceneChanged(false);
}

void TrajectoryView3D::setGhostPath(const std::vector<Eigen::Vector3d>& positions_m)
{
    ghost_m_ = positions_m;
    ghostStale_ = true;
    update();
}

void TrajectoryView3D::sceneChanged(bool refit)
{
    // Built when next drawn or asked about, not here: a view on a tab behind would otherwise
    // rebuild on every parameter change (and every live refresh) for nobody.
    sceneStale_ = true;
    if (refit) {
        resetCamera();
        fitPending_ = true;
    }
    update();
}

void TrajectoryView3D::ensureScene() const
{
    if (!sceneStale_ && !ghostStale_ && !fitPending_)
        return;
    // The scene is a cache of the paths: filling it from a const reader is not a visible change.
    auto* self = const_cast<TrajectoryView3D*>(this);
    if (sceneStale_) {
        self->sceneStale_ = false;
        self->rebuildScene();
    }
    if (ghostStale_) {
        self->ghostStale_ = false;
        self->drawnGhostIndices_ = decimatedIndices(ghost_m_.size(), {});
    }
    if (fitPending_) {
        self->fitPending_ = false;
        self->fitCamera();
    }
}

void TrajectoryView3D::drawGhost(QPainter& painter, const ViewTransform& view) const
{
    constexpr double kTrueHeight = std::numeric_limits<double>::quiet_NaN();
    painter.setPen(QPen(kGhostColour, 2.0));
    drawInPieces(painter, projectedPolyline(view, ghost_m_, drawnGhostIndices_, kTrueHeight));
}

void TrajectoryView3D::setReference(const std::vector<Eigen::Vector3d>& positions_m)
{
    if (positions_m.empty() && reference_m_.empty())
        return;  // still none: no need to rebuild the scene (a walk without reference, after each estimate)
    reference_m_ = positions_m;
    sceneChanged(true);
}

void TrajectoryView3D::setTimeCursor(double time_s)
{
    timeCursor_s_ = time_s;
    update();
}

void TrajectoryView3D::setHeightExaggeration(double factor)
{
    factor = std::clamp(factor, kMinHeightFactor, kMaxHeightFactor);
    if (factor == heightFactor_)
        return;
    heightFactor_ = factor;
    const QSignalBlocker blocker(heightSpin_);
    heightSpin_->setValue(factor);
    emit heightExaggerationChanged(factor);
    update();
}

void TrajectoryView3D::setProjection(Projection projection)
{
    projection_ = projection;
    const QSignalBlocker blocker(perspectiveCheck_);
    perspectiveCheck_->setChecked(projection == Projection::Perspective);
    update();
}

void TrajectoryView3D::setViewAngles(double azimuth_deg, double elevation_deg)
{
    azimuth_deg_ = std::remainder(azimuth_deg, 360.0);
    elevation_deg_ = std::clamp(elevation_deg, -90.0, 90.0);
    update();
}

void TrajectoryView3D::rebuildScene()
{
    ++sceneBuilds_;
    const std::vector<std::uint8_t> noFlags;
    drawnPathIndices_ = decimatedIndices(positions().size(), result_ ? result_->flags.stance : noFlags);
    sampleMotion_ = result_ ? motionOfSamples(*result_) : std::vector<MotionClass>();
    drawnReferenceIndices_ = decimatedIndices(reference_m_.size(), noFlags);
    sceneMin_m_ = sceneMax_m_ = Eigen::Vector3d::Zero();
    bool first = true;
    const std::vector<Eigen::Vector3d>* const sources[] = {&positions(), &reference_m_};
    for (const std::vector<Eigen::Vector3d>* points : sources) {
        for (const Eigen::Vector3d& p : *points) {
            sceneMin_m_ = first ? p : sceneMin_m_.cwiseMin(p);
            sceneMax_m_ = first ? p : sceneMax_m_.cwiseMax(p);
            first = false;
        }
    }
    extendSceneByOverlays();
}

void TrajectoryView3D::resetView()
{
    resetCamera();
    fitPending_ = true;
    ensureScene();
    update();
}

void TrajectoryView3D::resetCamera()
{
    azimuth_deg_ = kDefaultAzimuth_deg;
    elevation_deg_ = kDefaultElevation_deg;
    zoom_ = 1.0;
    cameraMovedByUser_ = false;
}

void TrajectoryView3D::fitCamera()
{
    // Fit what the default camera sees of the floor grid and the paths, whatever the target, and
    // centre that (not the scene's centre, which sits off-centre once the grid is drawn).
    const Grid grid = groundGrid();
    ViewTransform view = viewTransform(QRectF(0.0, 0.0, 1.0, 1.0));
    view.perspective = false;
    view.pixelsPerMetre = 1.0;
    view.origin_px = QPointF();
    QPolygonF seenPoints;
    const double labelRoom = kLabelOffsetInSteps * grid.step_m;  // the metre labels stay in view too
    for (double x : {grid.xMin - labelRoom, grid.xMax + labelRoom})
        for (double y : {grid.yMin - labelRoom, grid.yMax + labelRoom})
            seenPoints << view(Eigen::Vector3d(x, y, grid.z_m));
    for (std::size_t index : drawnPathIndices_)
        seenPoints << view(positions()[index]);
    for (std::size_t index : drawnReferenceIndices_)
        seenPoints << view(reference_m_[index]);
    for (std::size_t i = 0; i < overlays_.size(); ++i)
        for (std::size_t index : drawnOverlayIndices_[i])
            seenPoints << view(overlays_[i].positions_m[index]);
    const QRectF seen = seenPoints.boundingRect();
    fitHalfExtent_m_ = QPointF(std::max(0.5 * seen.width(), kMinHalfExtent_m), std::max(0.5 * seen.height(), kMinHalfExtent_m));
    pan_m_ = -seen.center();
}

TrajectoryView3D::ViewTransform TrajectoryView3D::viewTransform(const QRectF& target) const
{
    const double azimuth = toRadians(azimuth_deg_), elevation = toRadians(elevation_deg_);
    ViewTransform view;
    view.toEye = Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                                 std::sin(elevation));
    view.right = Eigen::Vector3d(-std::sin(azimuth), std::cos(azimuth), 0.0);
    view.up = view.toEye.cross(view.right);
    view.heightFactor = heightFactor_;
    const Eigen::Vector3d scale(1.0, 1.0, heightFactor_);
    view.centre_m = (0.5 * (sceneMin_m_ + sceneMax_m_)).cwiseProduct(scale);
    const QRectF area = sceneArea(target);
    const double fitScale = std::min(area.width() / (2.0 * fitHalfExtent_m_.x()),
                                     area.height() / (2.0 * fitHalfExtent_m_.y()));
    view.pixelsPerMetre = kFitFraction * fitScale * zoom_;
    view.perspective = projection_ == Projection::Perspective;
    const double radius = (0.5 * (sceneMax_m_ - sceneMin_m_).cwiseProduct(scale)).norm();
    view.eyeDistance_m = kEyeDistanceInRadii * std::max(radius, kMinHalfExtent_m);
    if (view.perspective)  // the nearest point of the scene is magnified by up to this much: still fits
        view.pixelsPerMetre *= 1.0 - 1.0 / kEyeDistanceInRadii;
    view.origin_px = area.center() + pan_m_ * view.pixelsPerMetre;
    return view;
}

QRectF TrajectoryView3D::sceneArea(const QRectF& target) const
{
    // The path is fitted above the key, so the key at the bottom does not cover it. The key is
    // measured with its stance entry, which the markers' spacing at this scale decides on.
    if (target.width() <= 1.0 || target.height() <= 1.0)
        return target;  // the unit square resetView() measures the scene in
    const QRectF legend = legendLayout(font(), target, legendEntries()).box;
    if (legend.isEmpty())
        return target;
    // Beside the key or above it, whichever leaves the path the larger scale.
    const QRectF above = target.adjusted(0.0, 0.0, 0.0, -(legend.height() + 8.0));
    const QRectF beside = target.adjusted(legend.width() + 8.0, 0.0, 0.0, 0.0);
    const auto scale = [this](const QRectF& area) {
        return std::min(area.width() / fitHalfExtent_m_.x(), area.height() / fitHalfExtent_m_.y());
    };
    return scale(beside) > scale(above) ? beside : above;
}

TrajectoryView3D::Grid TrajectoryView3D::groundGrid() const
{
    Grid grid;
    const double extent_m = std::max({sceneMax_m_.x() - sceneMin_m_.x(), sceneMax_m_.y() - sceneMin_m_.y(), 1.0});
    grid.step_m = niceStep(extent_m / 6.0);
    // A walk that starts at 0 and wobbles to -1 cm should not earn a whole extra row of cells.
    const double slack = 0.1 * grid.step_m;
    const auto down = [&grid, slack](double v) { return std::floor((v + slack) / grid.step_m) * grid.step_m; };
    const auto up = [&grid, slack](double v) { return std::ceil((v - slack) / grid.step_m) * grid.step_m; };
    grid.xMin = down(sceneMin_m_.x());
    grid.xMax = up(sceneMax_m_.x());
    grid.yMin = down(sceneMin_m_.y());
    grid.yMax = up(sceneMax_m_.y());
    // A straight walk has no width: give it two cells so the grid still reads as a floor.
    if (grid.xMax - grid.xMin < 2.0 * grid.step_m) {
        grid.xMin -= grid.step_m;
        grid.xMax += grid.step_m;
    }
    if (grid.yMax - grid.yMin < 2.0 * grid.step_m) {
        grid.yMin -= grid.step_m;
        grid.yMax += grid.step_m;
    }
    grid.z_m = sceneMin_m_.z();
    return grid;
}

QPointF TrajectoryView3D::project(const Eigen::Vector3d& position_m, const QRectF& target) const
{
    ensureScene();
    return viewTransform(target)(position_m);
}

void TrajectoryView3D::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    render(painter, rect());
}

void TrajectoryView3D::render(QPainter& painter, const QRectF& target) const
{
    ensureScene();
    painter.save();
    painter.setClipRect(target);
    painter.fillRect(target, Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    if (positions().empty() && reference_m_.empty()) {
        painter.setPen(kLabelColour);
        painter.drawText(target, Qt::AlignCenter, tr("No trajectory"));
        painter.restore();
        return;
    }
    const ViewTransform view = viewTransform(target);
    const Grid grid = groundGrid();
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

void TrajectoryView3D::drawGrid(QPainter& painter, const ViewTransform& view, const Grid& grid) const
{
    painter.setPen(QPen(kGridColour, 1.0));
    const auto lines = [&grid](double from, double to) {
        std::vector<double> values;
        for (double v = from; v <= to + 0.5 * grid.step_m; v += grid.step_m)
            values.push_back(v);
        return values;
    };
    const std::vector<double> xs = lines(grid.xMin, grid.xMax), ys = lines(grid.yMin, grid.yMax);
    for (double x : xs)
        painter.drawLine(view({x, grid.yMin, grid.z_m}), view({x, grid.yMax, grid.z_m}));
    for (double y : ys)
        painter.drawLine(view({grid.xMin, y, grid.z_m}), view({grid.xMax, y, grid.z_m}));

    // Labels along the two edges nearer the viewer, just outside the grid, so the path never hides them.
    const double labelOffset = kLabelOffsetInSteps * grid.step_m;
    const double xLabelsAtY = view.toEye.y() < 0.0 ? grid.yMin - labelOffset : grid.yMax + labelOffset;
    const double yLabelsAtX = view.toEye.x() < 0.0 ? grid.xMin - labelOffset : grid.xMax + labelOffset;
    painter.setPen(kLabelColour);
    // Seen edge-on, an axis's labels pile up on each other: draw only those with room.
    std::vector<QRectF> taken;
    const auto label = [&painter, &taken](const QPointF& at, const QString& text) {
        QRectF box = painter.fontMetrics().boundingRect(text);
        box.moveCenter(at);
        const bool collides = std::any_of(taken.cbegin(), taken.cend(),
                                          [&box](const QRectF& other) { return other.intersects(box.adjusted(-3, -1, 3, 1)); });
        if (collides)
            return;
        taken.push_back(box);
        painter.drawText(box, Qt::AlignCenter, text);
    };
    for (double x : xs)
        label(view({x, xLabelsAtY, grid.z_m}), metres(x));
    for (double y : ys)
        label(view({yLabelsAtX, y, grid.z_m}), metres(y));
}

void TrajectoryView3D::drawAxisArrows(QPainter& painter, const ViewTransform& view, const QRectF& target) const
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
        if (length >= 4.0) {  // shorter: the axis points at the viewer and has no direction to show
            const QPointF normal(-unit.y(), unit.x());
            QPainterPath head;
            head.moveTo(tip);
            head.lineTo(tip - 8.0 * unit + 3.5 * normal);
            head.lineTo(tip - 8.0 * unit - 3.5 * normal);
            head.closeSubpath();
            painter.fillPath(head, axis.colour);
        }
        drawCentredText(painter, tip + 10.0 * unit, tr(axis.name));
    }
}

QPolygonF TrajectoryView3D::projectedPolyline(const ViewTransform& view, const std::vector<Eigen::Vector3d>& points,
                                             const std::vector<std::size_t>& indices, double floorZ_m) const
{
    // floorZ_m NaN: the true path; a number: its shadow on the floor at that height.
    QPolygonF polyline;
    polyline.reserve(static_cast<qsizetype>(indices.size()));
    for (std::size_t index : indices) {
        const Eigen::Vector3d& p = points[index];
        const QPointF pixel = view(std::isnan(floorZ_m) ? p : Eigen::Vector3d(p.x(), p.y(), floorZ_m));
        // Points on the same pixel add stroking work and nothing visible.
        if (polyline.isEmpty() || (pixel - polyline.back()).manhattanLength() >= 1.0 || index == indices.back())
            polyline << pixel;
    }
    return polyline;
}

void TrajectoryView3D::drawPaths(QPainter& painter, const ViewTransform& view, const Grid& grid) const
{
    constexpr double kTrueHeight = std::numeric_limits<double>::quiet_NaN();
    // The shadow on the floor is what makes heights readable in a still image. Thin pens take
    // QPainter's fast path, so the two secondary lines cost next to nothing.
    painter.setPen(QPen(kShadowColour, 1.0));
    drawInPieces(painter, projectedPolyline(view, positions(), drawnPathIndices_, grid.z_m));
    painter.setPen(QPen(kReferenceColour, 1.0, Qt::DashLine));
    drawInPieces(painter, projectedPolyline(view, reference_m_, drawnReferenceIndices_, kTrueHeight));
    // A wide pen with flat caps, segment by segment, is the one wide stroke QPainter rasterises
    // quickly (a tenth of the time of a polyline); the joins it leaves out are sub-pixel.
    if (showsMotionColours()) {
        drawMotionColouredPath(painter, view);
        return;
    }
    painter.setPen(QPen(kPathColour, 1.6, Qt::SolidLine, Qt::FlatCap));
    const QPolygonF path = projectedPolyline(view, positions(), drawnPathIndices_, kTrueHeight);
    QVector<QLineF> segments;
    segments.reserve(path.size());
    for (qsizetype k = 1; k < path.size(); ++k)
        segments.append(QLineF(path[k - 1], path[k]));
    painter.drawLines(segments);
}

void TrajectoryView3D::drawInPieces(QPainter& painter, const QPolygonF& polyline)
{
    // One long self-crossing polyline makes QPainter stroke and fill one huge outline (a second
    // for a long walk); short pieces keep joins and dash patterns at a fraction of the cost.
    constexpr qsizetype kPiece = 64;
    for (qsizetype first = 0; first + 1 < polyline.size(); first += kPiece)
        painter.drawPolyline(polyline.constData() + first, static_cast<int>(std::min(kPiece + 1, polyline.size() - first)));
}

QPolygonF TrajectoryView3D::projectedStances(const ViewTransform& view) const
{
    QPolygonF stances;
    if (!result_ || positions().empty())
        return stances;
    stances.reserve(static_cast<qsizetype>(result_->steps.size()));
    for (const Step& step : result_->steps)
        stances << view(step.position_m);
    return stances;
}

bool TrajectoryView3D::marksStances(const QRectF& target) const
{
    ensureScene();
    return stanceMarkersApart(projectedStances(viewTransform(target)));
}

void TrajectoryView3D::drawMarkers(QPainter& painter, const ViewTransform& view, const Grid& grid,
                                   const QPolygonF& stances) const
{
    if (!result_ || positions().empty())
        return;
    // One call for all stances: a long walk has thousands, and ellipses one by one cost more
    // than the whole path.
    painter.setPen(QPen(kStanceColour, 5.2, Qt::SolidLine, Qt::RoundCap));
    painter.drawPoints(stances);
    drawStart(painter, view(positions().front()));
    drawEnd(painter, view(positions().back()));

    if (std::isnan(timeCursor_s_) || result_->time_s.empty())
        return;
    const std::size_t index = std::min(nearestSampleAtTime(result_->time_s, timeCursor_s_), positions().size() - 1);
    const Eigen::Vector3d& cursor = positions()[index];
    painter.setPen(QPen(Qt::black, 1.0, Qt::DashLine));
    painter.drawLine(view(cursor), view({cursor.x(), cursor.y(), grid.z_m}));
    drawCursor(painter, view(cursor));
}

std::vector<std::pair<QString, TrajectoryView3D::LegendIcon>> TrajectoryView3D::legendEntries(bool withStances) const
{
    using Icon = LegendIcon;
    const auto line = [](QPen pen) {
        return Icon([pen](QPainter& p, const QPointF& at) {
            p.setPen(pen);
            p.drawLine(at - QPointF(12.0, 0.0), at + QPointF(12.0, 0.0));
        });
    };
    std::vector<std::pair<QString, Icon>> entries{{pathLabel(), line(QPen(kPathColour, 2.0))},
                                                  {tr("Shadow on the floor"), line(QPen(kShadowColour, 2.0))}};
    if (showsMotionColours()) {  // the path's one colour gives way to the classes'
        entries.erase(entries.begin());
        std::vector<std::pair<QString, Icon>> classes;
        for (const MotionClass motion : motionClassesIn(sampleMotion_))
            classes.emplace_back(motionClassLabel(motion), line(QPen(motionClassColour(motion), 2.0)));
        entries.insert(entries.begin(), classes.begin(), classes.end());
    }
    if (!reference_m_.empty())
        entries.emplace_back(tr("Reference"), line(QPen(kReferenceColour, 1.5, Qt::DashLine)));
    if (!ghost_m_.empty())
        entries.emplace_back(tr("Before the last change"), line(QPen(kGhostColour, 2.0)));
    if (withStances)
        entries.emplace_back(tr("Stance"), drawStance);
    entries.emplace_back(tr("Start"), drawStart);
    entries.emplace_back(tr("End"), drawEnd);
    if (!std::isnan(timeCursor_s_))
        entries.emplace_back(tr("Time cursor"), drawCursor);
    if (heightFactor_ != 1.0)
        entries.emplace_back(tr("Heights drawn \u00d7 %1").arg(heightFactor_, 0, 'g', 3), Icon());
    return entries;
}

TrajectoryView3D::LegendLayout TrajectoryView3D::legendLayout(
    const QFont& font, const QRectF& target, const std::vector<std::pair<QString, LegendIcon>>& entries)
{
    const std::size_t entryCount = entries.size();
    // A small view (the 3D tab on a 1280-pixel screen) gets a smaller key rather than none: the
    // dashed reference and the markers must be explained wherever they are drawn.
    for (const double scale : {1.0, 0.85}) {
        for (const int columns : {1, 2}) {
            LegendLayout layout;
            layout.font = font;
            if (scale != 1.0)
                layout.font.setPointSizeF(font.pointSizeF() * scale);
            const QFontMetricsF metrics(layout.font);
            layout.lineHeight = std::max(metrics.height() + 2.0, 14.0);
            double widestText = 0.0;
            for (const auto& entry : entries)
                widestText = std::max(widestText, metrics.horizontalAdvance(entry.first));
            layout.columnWidth = widestText + 50.0;
            layout.rows = static_cast<int>((entryCount + static_cast<std::size_t>(columns) - 1) / static_cast<std::size_t>(columns));
            const QSizeF size(columns * layout.columnWidth, layout.rows * layout.lineHeight + 8.0);
            if (size.height() <= 0.4 * target.height() && size.width() <= 0.6 * target.width()) {
                layout.box = QRectF(QPointF(target.left() + 8.0, target.bottom() - 8.0 - size.height()), size);
                return layout;
            }
        }
    }
    return {};
}

QRectF TrajectoryView3D::legendRect(const QSizeF& size) const
{
    ensureScene();
    if (positions().empty() && reference_m_.empty())
        return {};
    const QRectF target(QPointF(0, 0), size);
    return legendLayout(font(), target, legendEntries(marksStances(target))).box;
}

void TrajectoryView3D::drawLegend(QPainter& painter, const QRectF& target, bool withStances) const
{
    const auto entries = legendEntries(withStances);
    const LegendLayout layout = legendLayout(painter.font(), target, entries);
    if (layout.box.isEmpty())
        return;  // a very small view needs its room for the path more than for the key
    painter.save();
    painter.setFont(layout.font);
    painter.setPen(QPen(QColor(200, 200, 200), 1.0));
    painter.setBrush(QColor(255, 255, 255, 225));
    painter.drawRect(layout.box);
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

void TrajectoryView3D::setOverlays(const std::vector<PathOverlay>& overlays)
{
    overlays_ = overlays;
    sceneChanged(!cameraMovedByUser_);
}

void TrajectoryView3D::extendSceneByOverlays()
{
    const std::vector<std::uint8_t> noFlags;
    drawnOverlayIndices_.clear();
    bool first = positions().empty() && reference_m_.empty();
    for (const PathOverlay& overlay : overlays_) {
        drawnOverlayIndices_.push_back(decimatedIndices(overlay.positions_m.size(), noFlags));
        for (const Eigen::Vector3d& p : overlay.positions_m) {
            sceneMin_m_ = first ? p : sceneMin_m_.cwiseMin(p);
            sceneMax_m_ = first ? p : sceneMax_m_.cwiseMax(p);
            first = false;
        }
    }
}

void TrajectoryView3D::drawOverlays(QPainter& painter, const ViewTransform& view) const
{
    constexpr double kTrueHeight = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < overlays_.size(); ++i) {
        painter.setPen(QPen(overlays_[i].colour, 1.3));
        drawInPieces(painter, projectedPolyline(view, overlays_[i].positions_m, drawnOverlayIndices_[i], kTrueHeight));
    }
}

void TrajectoryView3D::drawOverlayLegend(QPainter& painter, const QRectF& target) const
{
    // Top left, apart from the main key at the bottom: both stay small enough to leave the path room.
    if (overlays_.empty())
        return;
    painter.save();
    QFont font = painter.font();
    font.setPointSizeF(font.pointSizeF() * 0.85);
    painter.setFont(font);
    const QFontMetricsF metrics(painter.font());
    const double lineHeight = metrics.height() + 2.0;
    double textWidth = 0.0;
    for (const PathOverlay& overlay : overlays_)
        textWidth = std::max(textWidth, metrics.horizontalAdvance(overlay.label));
    // On screen the toolbar sits over the view's top: the key goes under it (not in the report).
    const double top = target.top() + 8.0 + (target == QRectF(rect()) ? toolbar_->geometry().bottom() : 0.0);
    const QRectF box(target.left() + 8.0, top, textWidth + 46.0,
                     static_cast<double>(overlays_.size()) * lineHeight + 8.0);
    if (box.height() > 0.5 * target.height() || box.width() > 0.7 * target.width()) {
        painter.restore();
        return;
    }
    painter.setPen(QPen(QColor(200, 200, 200), 1.0));
    painter.setBrush(QColor(255, 255, 255, 225));
    painter.drawRect(box);
    double y = box.top() + 4.0 + 0.5 * lineHeight;
    for (const PathOverlay& overlay : overlays_) {
        painter.setPen(QPen(overlay.colour, 2.0));
        painter.drawLine(QPointF(box.left() + 8.0, y), QPointF(box.left() + 32.0, y));
        painter.setPen(Qt::black);
        painter.drawText(QRectF(box.left() + 40.0, y - 0.5 * lineHeight, textWidth + 4.0, lineHeight),
                         Qt::AlignVCenter | Qt::AlignLeft, overlay.label);
        y += lineHeight;
    }
    painter.restore();
}

void TrajectoryView3D::setPathLabel(const QString& label)
{
    pathLabel_ = label;
    update();
}

void TrajectoryView3D::setMotionColouring(bool on)
{
    motionColouring_ = on;
    const QSignalBlocker quiet(motionCheck_);
    motionCheck_->setChecked(on);
    update();
}

bool TrajectoryView3D::showsMotionColours() const
{
    ensureScene();  // the classes per sample
    return motionColouring_ && result_ && hasMotionClasses(*result_) && sampleMotion_.size() == positions().size();
}

void TrajectoryView3D::drawMotionColouredPath(QPainter& painter, const ViewTransform& view) const
{
    // Segments grouped by class, one drawLines call each; a segment takes the class of its end.
    std::map<MotionClass, QVector<QLineF>> segments;
    for (std::size_t k = 1; k < drawnPathIndices_.size(); ++k) {
        const std::size_t from = drawnPathIndices_[k - 1], to = drawnPathIndices_[k];
        segments[sampleMotion_[to]].append(QLineF(view(positions()[from]), view(positions()[to])));
    }
    for (const auto& [motion, lines] : segments) {
        painter.setPen(QPen(motionClassColour(motion), 2.2, Qt::SolidLine, Qt::FlatCap));
        painter.drawLines(lines);
    }
}

void TrajectoryView3D::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    layOutToolbar();
}

void TrajectoryView3D::layOutToolbar()
{
    // One row where it fits; in a narrow view (beside the signals on a 1280-pixel screen) two rows
    // rather than controls cut off at the left edge.
    auto* grid = static_cast<QGridLayout*>(toolbar_->layout());
    int oneRow = grid->contentsMargins().left() + grid->contentsMargins().right();
    for (QWidget* widget : toolbarWidgets_)
        oneRow += widget->sizeHint().width() + std::max(0, grid->horizontalSpacing());
    const auto count = static_cast<int>(toolbarWidgets_.size());
    const int perRow = oneRow > width() - 12 ? (count + 1) / 2 : count;
    for (QWidget* widget : toolbarWidgets_)
        grid->removeWidget(widget);
    for (int i = 0; i < count; ++i)
        grid->addWidget(toolbarWidgets_[static_cast<std::size_t>(i)], i / perRow, i % perRow);
    toolbar_->adjustSize();
    toolbar_->move(width() - toolbar_->width() - 6, 6);
}

void TrajectoryView3D::mousePressEvent(QMouseEvent* event)
{
    lastMousePosition_ = event->position().toPoint();
}

void TrajectoryView3D::mouseMoveEvent(QMouseEvent* event)
{
    ensureScene();  // the pan is measured in the fitted scale
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - lastMousePosition_;
    lastMousePosition_ = position;
    if (event->buttons() & (Qt::LeftButton | Qt::RightButton | Qt::MiddleButton))
        cameraMovedByUser_ = true;
    if (event->buttons() & Qt::LeftButton) {
        setViewAngles(azimuth_deg_ - kOrbitDegreesPerPixel * delta.x(), elevation_deg_ + kOrbitDegreesPerPixel * delta.y());
    } else if (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) {
        pan_m_ += QPointF(delta) / viewTransform(rect()).pixelsPerMetre;
        update();
    }
}

void TrajectoryView3D::mouseDoubleClickEvent(QMouseEvent*)
{
    resetView();
}

void TrajectoryView3D::wheelEvent(QWheelEvent* event)
{
    ensureScene();
    // Zoom about the pointer: the scene point under it stays under it.
    const QPointF fromCentre = event->position() - sceneArea(rect()).center();
    const QPointF underPointer_m = fromCentre / viewTransform(rect()).pixelsPerMetre - pan_m_;
    cameraMovedByUser_ = true;
    zoom_ = std::clamp(zoom_ * std::pow(kZoomPerWheelNotch, event->angleDelta().y() / 120.0), 0.05, 500.0);
    pan_m_ = fromCentre / viewTransform(rect()).pixelsPerMetre - underPointer_m;
    event->accept();
    update();
}

}  // namespace footpath
