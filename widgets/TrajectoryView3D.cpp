#include "TrajectoryView3D.h"

#include "AnalysisSession.h"
#include "MotionLanes.h"
#include "Scene3DPainter.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QSignalBlocker>
#include <QToolButton>
#include <QWheelEvent>

#include <algorithm>
#include <cstddef>
#include <utility>

namespace footpath {

TrajectoryView3D::TrajectoryView3D(QWidget* parent) : QWidget(parent)
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
    heightSpin_->setRange(OrbitCamera::kMinHeightFactor, OrbitCamera::kMaxHeightFactor);
    heightSpin_->setSingleStep(0.5);
    heightSpin_->setDecimals(1);
    heightSpin_->setValue(camera_.heightFactor());
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
    scene_.setResult(std::move(result));
    sceneChanged(!cameraMovedByUser_);
}

void TrajectoryView3D::clear()
{
    scene_.clear();
    sceneChanged(false);
}

void TrajectoryView3D::setReference(const std::vector<Eigen::Vector3d>& positions_m)
{
    if (positions_m.empty() && scene_.reference().empty())
        return;  // still none: no need to rebuild the scene (a walk without reference, after each estimate)
    scene_.setReference(positions_m);
    sceneChanged(true);
}

void TrajectoryView3D::setOverlays(const std::vector<PathOverlay>& overlays)
{
    scene_.setOverlays(overlays);
    sceneChanged(!cameraMovedByUser_);
}

void TrajectoryView3D::setGhostPath(const std::vector<Eigen::Vector3d>& positions_m)
{
    scene_.setGhost(positions_m);
    update();
}

void TrajectoryView3D::setPathLabel(const QString& label)
{
    scene_.setPathLabel(label);
    update();
}

void TrajectoryView3D::setTimeCursor(double time_s)
{
    scene_.setTimeCursor(time_s);
    update();
}

void TrajectoryView3D::setMotionColouring(bool on)
{
    scene_.setMotionColouring(on);
    const QSignalBlocker quiet(motionCheck_);
    motionCheck_->setChecked(on);
    update();
}

bool TrajectoryView3D::showsMotionColours() const
{
    ensureScene();
    return scene_.showsMotionColours();
}

void TrajectoryView3D::sceneChanged(bool refit)
{
    // Built when next drawn or asked about, not here: a view on a tab behind would otherwise
    // rebuild on every parameter change (and every live refresh) for nobody.
    if (refit) {
        resetCamera();
        fitPending_ = true;
    }
    update();
}

void TrajectoryView3D::ensureScene() const
{
    scene_.ensureBuilt();
    if (!fitPending_)
        return;
    // The fit is part of building the scene, deferred like it: doing it from a const reader is
    // not a visible change.
    auto* self = const_cast<TrajectoryView3D*>(this);
    self->fitPending_ = false;
    self->camera_.fitTo(scene_.bounds(), scene_.framedPoints());
}

Scene3DPainter TrajectoryView3D::scenePainter(const QRectF& target) const
{
    ensureScene();
    Scene3DPainter painter(scene_, camera_, font());
    // On screen the toolbar sits over the view's top: the overlays' key goes under it (not in the report).
    if (target == QRectF(rect()))
        painter.setTopInset(toolbar_->geometry().bottom());
    return painter;
}

void TrajectoryView3D::setHeightExaggeration(double factor)
{
    const double before = camera_.heightFactor();
    camera_.setHeightFactor(factor);  // clamped
    if (camera_.heightFactor() == before)
        return;
    const QSignalBlocker blocker(heightSpin_);
    heightSpin_->setValue(camera_.heightFactor());
    emit heightExaggerationChanged(camera_.heightFactor());
    update();
}

void TrajectoryView3D::setProjection(Projection projection)
{
    camera_.setPerspective(projection == Projection::Perspective);
    const QSignalBlocker blocker(perspectiveCheck_);
    perspectiveCheck_->setChecked(projection == Projection::Perspective);
    update();
}

void TrajectoryView3D::setViewAngles(double azimuth_deg, double elevation_deg)
{
    camera_.setAngles(azimuth_deg, elevation_deg);
    update();
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
    camera_.resetOrbit();
    cameraMovedByUser_ = false;
}

QPointF TrajectoryView3D::project(const Eigen::Vector3d& position_m, const QRectF& target) const
{
    return scenePainter(target).viewTransform(target)(position_m);
}

bool TrajectoryView3D::marksStances(const QRectF& target) const
{
    return scenePainter(target).marksStances(target);
}

QRectF TrajectoryView3D::legendRect(const QSizeF& size) const
{
    const QRectF target(QPointF(0, 0), size);
    return scenePainter(target).legendRect(target);
}

void TrajectoryView3D::render(QPainter& painter, const QRectF& target) const
{
    scenePainter(target).render(painter, target);
}

void TrajectoryView3D::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    render(painter, rect());
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
    ensureScene();  // a pending fit frames the scene as it was, before this drag moves the camera
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - lastMousePosition_;
    lastMousePosition_ = position;
    if (event->buttons() & (Qt::LeftButton | Qt::RightButton | Qt::MiddleButton))
        cameraMovedByUser_ = true;
    if (event->buttons() & Qt::LeftButton) {
        camera_.orbitBy(QPointF(delta));
        update();
    } else if (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) {
        camera_.panBy(QPointF(delta), scenePainter(rect()).sceneArea(rect()));
        update();
    }
}

void TrajectoryView3D::mouseDoubleClickEvent(QMouseEvent*)
{
    resetView();
}

void TrajectoryView3D::wheelEvent(QWheelEvent* event)
{
    const QRectF area = scenePainter(rect()).sceneArea(rect());  // after a pending fit, as the drag
    cameraMovedByUser_ = true;
    camera_.zoomAbout(event->position(), event->angleDelta().y() / 120.0, area);
    event->accept();
    update();
}

void TrajectoryView3D::showEstimate(const AnalysisSession& session)
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
