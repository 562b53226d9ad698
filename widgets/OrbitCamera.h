#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QPointF>
#include <QRectF>
#include <QSizeF>

#include <vector>

namespace footpath {

/// World (metres) to target pixels for one frame: rotation into the camera basis, height
/// exaggeration, optional perspective, scale and pan.
struct ViewTransform {
    Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  ///< orbit centre, height already exaggerated
    Eigen::Vector3d right = Eigen::Vector3d::UnitY();     ///< camera basis in world coordinates (here: seen from +x)
    Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d toEye = Eigen::Vector3d::UnitX();
    double heightFactor = 1.0;
    double pixelsPerMetre = 1.0;
    QPointF origin_px;  ///< where the orbit centre lands, pan included
    bool perspective = false;
    double eyeDistance_m = 1.0;

    QPointF operator()(const Eigen::Vector3d& position_m) const;
};

/// The camera of the 3D path view, orbiting the centre of a box of the world (the scene's bounds):
/// azimuth and elevation, zoom, a pan in the screen plane, height exaggeration and the projection.
/// Pure geometry; the widget turns mouse and wheel into these calls.
class OrbitCamera {
public:
    static constexpr double kMinHeightFactor = 0.1;
    static constexpr double kMaxHeightFactor = 50.0;

    OrbitCamera();

    /// The default oblique angles and zoom 1; fitTo() then frames the scene again.
    void resetOrbit();
    /// Azimuth about z from +x, wrapped to [-180, 180]; elevation above the ground, clamped to
    /// [-90, 90]; both in degrees.
    void setAngles(double azimuth_deg, double elevation_deg);
    double azimuth_deg() const { return azimuth_deg_; }
    double elevation_deg() const { return elevation_deg_; }
    /// A drag by this many pixels: sideways turns about z, up and down tilts.
    void orbitBy(const QPointF& drag_px);
    double zoom() const { return zoom_; }
    /// Vertical scale relative to horizontal, clamped to [kMinHeightFactor, kMaxHeightFactor].
    void setHeightFactor(double factor);
    double heightFactor() const { return heightFactor_; }
    void setPerspective(bool on) { perspective_ = on; }
    bool perspective() const { return perspective_; }

    /// Frames these points (metres) as the current angles see them about the centre of scene_m:
    /// they fill any target alike at zoom 1, centred. Orbiting afterwards keeps the scale.
    void fitTo(const Eigen::AlignedBox3d& scene_m, const std::vector<Eigen::Vector3d>& points_m);
    /// The transform into area (the part of the target the scene is fitted into).
    ViewTransform transform(const Eigen::AlignedBox3d& scene_m, const QRectF& area) const;
    /// The scale at which the fitted points would just fill area, before zoom and margins; it
    /// tells which of two areas shows the scene larger.
    double fittedScale(const QSizeF& area) const;
    /// Moves the scene with a drag by this many pixels in area.
    void panBy(const QPointF& drag_px, const QRectF& area);
    /// Zooms by whole or fractional wheel notches, keeping the scene point under the pointer there.
    void zoomAbout(const QPointF& pointer_px, double notches, const QRectF& area);

private:
    /// The current angles about the centre of scene_m, one pixel per metre, orthographic, no pan:
    /// the screen plane fitTo() measures in.
    ViewTransform screenPlane(const Eigen::AlignedBox3d& scene_m) const;
    double pixelsPerMetre(const QRectF& area) const;

    double azimuth_deg_;
    double elevation_deg_;
    double zoom_ = 1.0;
    double heightFactor_ = 1.0;
    bool perspective_ = false;
    QPointF pan_m_;  ///< screen-plane shift of the scene, in metres at the orbit centre
    /// Half-size (metres) of the scene as the camera saw it when fitted; the zoom is relative to it,
    /// so orbiting does not change the scale and any target size shows the same framing.
    QPointF fitHalfExtent_m_;
};

}  // namespace footpath
