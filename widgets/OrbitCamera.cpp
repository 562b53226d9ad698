#include "OrbitCamera.h"

#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDefaultAzimuth_deg = -60.0;
constexpr double kDefaultElevation_deg = 30.0;
constexpr double kFitFraction = 0.85;        ///< of the target the fitted scene fills; the rest is for labels
constexpr double kMinHalfExtent_m = 0.5;     ///< a single point or a straight line still gets a sensible scale
constexpr double kEyeDistanceInRadii = 3.0;  ///< perspective: camera distance from the orbit centre
constexpr double kNearFraction = 0.05;       ///< perspective: points closer than this are clamped, not inverted
constexpr double kOrbitDegreesPerPixel = 0.4;
constexpr double kZoomPerWheelNotch = 1.2;
constexpr double kMinZoom = 0.05;
constexpr double kMaxZoom = 500.0;

double toRadians(double degrees)
{
    return degrees * kPi / 180.0;
}

}  // namespace

QPointF ViewTransform::operator()(const Eigen::Vector3d& position_m) const
{
    const Eigen::Vector3d q = Eigen::Vector3d(position_m.x(), position_m.y(), position_m.z() * heightFactor) - centre_m;
    double shrink = 1.0;
    if (perspective) {
        const double depth = std::max(eyeDistance_m - q.dot(toEye), kNearFraction * eyeDistance_m);
        shrink = eyeDistance_m / depth;
    }
    return origin_px + pixelsPerMetre * shrink * QPointF(q.dot(right), -q.dot(up));
}

OrbitCamera::OrbitCamera()
    : azimuth_deg_(kDefaultAzimuth_deg),
      elevation_deg_(kDefaultElevation_deg),
      fitHalfExtent_m_(kMinHalfExtent_m, kMinHalfExtent_m)
{
}

void OrbitCamera::resetOrbit()
{
    azimuth_deg_ = kDefaultAzimuth_deg;
    elevation_deg_ = kDefaultElevation_deg;
    zoom_ = 1.0;
}

void OrbitCamera::setAngles(double azimuth_deg, double elevation_deg)
{
    azimuth_deg_ = std::remainder(azimuth_deg, 360.0);
    elevation_deg_ = std::clamp(elevation_deg, -90.0, 90.0);
}

void OrbitCamera::orbitBy(const QPointF& drag_px)
{
    setAngles(azimuth_deg_ - kOrbitDegreesPerPixel * drag_px.x(), elevation_deg_ + kOrbitDegreesPerPixel * drag_px.y());
}

void OrbitCamera::setHeightFactor(double factor)
{
    heightFactor_ = std::clamp(factor, kMinHeightFactor, kMaxHeightFactor);
}

void OrbitCamera::fitTo(const Eigen::AlignedBox3d& scene_m, const std::vector<Eigen::Vector3d>& points_m)
{
    // Centre what is seen (not the box's centre, which sits off-centre once the grid is drawn).
    const ViewTransform view = screenPlane(scene_m);
    QPolygonF seenPoints;
    seenPoints.reserve(static_cast<qsizetype>(points_m.size()));
    for (const Eigen::Vector3d& point : points_m)
        seenPoints << view(point);
    const QRectF seen = seenPoints.boundingRect();
    fitHalfExtent_m_ = QPointF(std::max(0.5 * seen.width(), kMinHalfExtent_m), std::max(0.5 * seen.height(), kMinHalfExtent_m));
    pan_m_ = -seen.center();
}

ViewTransform OrbitCamera::screenPlane(const Eigen::AlignedBox3d& scene_m) const
{
    const double azimuth = toRadians(azimuth_deg_), elevation = toRadians(elevation_deg_);
    ViewTransform view;
    view.toEye = Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                                 std::sin(elevation));
    view.right = Eigen::Vector3d(-std::sin(azimuth), std::cos(azimuth), 0.0);
    view.up = view.toEye.cross(view.right);
    view.heightFactor = heightFactor_;
    view.centre_m = scene_m.center().cwiseProduct(Eigen::Vector3d(1.0, 1.0, heightFactor_));
    return view;
}

ViewTransform OrbitCamera::transform(const Eigen::AlignedBox3d& scene_m, const QRectF& area) const
{
    ViewTransform view = screenPlane(scene_m);
    view.pixelsPerMetre = pixelsPerMetre(area);
    view.perspective = perspective_;
    const double radius = (0.5 * scene_m.sizes().cwiseProduct(Eigen::Vector3d(1.0, 1.0, heightFactor_))).norm();
    view.eyeDistance_m = kEyeDistanceInRadii * std::max(radius, kMinHalfExtent_m);
    view.origin_px = area.center() + pan_m_ * view.pixelsPerMetre;
    return view;
}

double OrbitCamera::fittedScale(const QSizeF& area) const
{
    return std::min(area.width() / (2.0 * fitHalfExtent_m_.x()), area.height() / (2.0 * fitHalfExtent_m_.y()));
}

double OrbitCamera::pixelsPerMetre(const QRectF& area) const
{
    const double scale = kFitFraction * fittedScale(area.size()) * zoom_;
    // The nearest point of the scene is magnified by up to this much: it still fits.
    return perspective_ ? scale * (1.0 - 1.0 / kEyeDistanceInRadii) : scale;
}

void OrbitCamera::panBy(const QPointF& drag_px, const QRectF& area)
{
    pan_m_ += drag_px / pixelsPerMetre(area);
}

void OrbitCamera::zoomAbout(const QPointF& pointer_px, double notches, const QRectF& area)
{
    const QPointF fromCentre = pointer_px - area.center();
    const QPointF underPointer_m = fromCentre / pixelsPerMetre(area) - pan_m_;
    zoom_ = std::clamp(zoom_ * std::pow(kZoomPerWheelNotch, notches), kMinZoom, kMaxZoom);
    pan_m_ = fromCentre / pixelsPerMetre(area) - underPointer_m;
}

}  // namespace footpath
