#pragma once

#include "PathOverlay.h"
#include "Result.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QCoreApplication>
#include <QString>

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace footpath {

/// What the 3D path view draws, in world coordinates (metres, navigation frame): the foot path with
/// its stances and time cursor, the reference, the overlays and the ghost, the ground grid and the
/// bounds. Nothing here paints. The thinned-out lines, the bounds and the motion classes are built
/// when first asked for after a change (any const reader), so a view nobody looks at builds nothing.
class PathScene3D {
    // The texts keep the 3D view's translation context, where they were translated.
    Q_DECLARE_TR_FUNCTIONS(footpath::TrajectoryView3D)

public:
    /// The ground grid: lines every step_m at the lowest height of the scene.
    struct Grid {
        double step_m = 1.0;
        double xMin = 0.0, xMax = 0.0, yMin = 0.0, yMax = 0.0;
        double z_m = 0.0;
        /// How far outside the grid the metre labels sit.
        double labelOffset_m() const;
    };
    /// Points and the indices of those drawn: every one up to a few thousand, then thinned out.
    struct Line {
        const std::vector<Eigen::Vector3d>& points_m;
        const std::vector<std::size_t>& drawn;
    };

    void setResult(std::shared_ptr<const Result> result);
    /// Positions already in the estimate's frame; empty: none.
    void setReference(const std::vector<Eigen::Vector3d>& positions_m);
    void setOverlays(const std::vector<PathOverlay>& overlays);
    /// The path before the last change; it is not part of the bounds.
    void setGhost(const std::vector<Eigen::Vector3d>& positions_m);
    void clear();  ///< removes path, reference and ghost; the overlays stay
    /// NaN: no cursor.
    void setTimeCursor(double time_s) { timeCursor_s_ = time_s; }
    /// The main path's key entry; empty: "Foot path".
    void setPathLabel(const QString& label) { pathLabel_ = label; }
    void setMotionColouring(bool on) { motionColouring_ = on; }

    const std::vector<Eigen::Vector3d>& path() const;
    const std::vector<Eigen::Vector3d>& reference() const { return reference_m_; }
    const std::vector<PathOverlay>& overlays() const { return overlays_; }
    const std::vector<Eigen::Vector3d>& ghost() const { return ghost_m_; }
    double timeCursor() const { return timeCursor_s_; }
    QString pathLabel() const { return pathLabel_.isEmpty() ? tr("Foot path") : pathLabel_; }
    bool motionColouring() const { return motionColouring_; }

    /// Neither a path nor a reference: the view says so instead of drawing a grid.
    bool isEmpty() const { return path().empty() && reference_m_.empty(); }
    /// A path to mark start, end, stances and the cursor on.
    bool hasPath() const { return result_ && !path().empty(); }
    /// The steps' positions in walking order (none without a path).
    const std::vector<Step>& stances() const;
    /// The path sample nearest the time cursor; none without cursor or path.
    std::optional<Eigen::Vector3d> cursorPosition() const;
    /// Whether the path is drawn in the motion classes' colours: asked for and the result has them.
    bool showsMotionColours() const;
    /// Per path sample (motionOfSamples).
    const std::vector<MotionClass>& sampleMotion() const;

    Line drawnPath() const;
    Line drawnReference() const;
    Line drawnOverlay(std::size_t index) const;
    Line drawnGhost() const;
    /// Path, reference and overlays; a point at the origin when there are none.
    const Eigen::AlignedBox3d& bounds() const;
    Grid grid() const;
    /// What a fitted camera keeps in view: the grid with its labels and every drawn point.
    std::vector<Eigen::Vector3d> framedPoints() const;

    /// Builds what changed since the last build; every reader above calls it.
    void ensureBuilt() const;
    /// How often the lines, bounds and classes were built (not the ghost, which is cheap; for tests).
    int builds() const { return builds_; }

private:
    /// What is derived from the inputs; a cache, so filling it from a const reader is no visible change.
    struct Built {
        std::vector<std::size_t> path;  ///< keeping every stance change
        std::vector<std::size_t> reference;
        std::vector<std::vector<std::size_t>> overlays;
        std::vector<std::size_t> ghost;
        std::vector<MotionClass> sampleMotion;
        Eigen::AlignedBox3d bounds{Eigen::Vector3d::Zero()};
    };
    void rebuild() const;
    Eigen::AlignedBox3d boundsOfLines() const;

    std::shared_ptr<const Result> result_;
    std::vector<Eigen::Vector3d> reference_m_;
    std::vector<PathOverlay> overlays_;
    std::vector<Eigen::Vector3d> ghost_m_;
    double timeCursor_s_ = std::numeric_limits<double>::quiet_NaN();
    QString pathLabel_;
    bool motionColouring_ = false;

    mutable Built built_;
    mutable bool stale_ = false;  ///< path, reference or overlays changed since built_
    mutable bool ghostStale_ = false;
    mutable int builds_ = 0;
};

}  // namespace footpath
