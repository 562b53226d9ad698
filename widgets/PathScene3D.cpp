#include "PathScene3D.h"

#include "MotionLanes.h"
#include "TrajectoryView2D.h"  // nearestSampleAtTime, shared so both views mark the same sample

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <utility>

namespace footpath {

namespace {

/// A 30-minute 100 Hz walk has 180k samples; this many points draw in a few milliseconds and
/// still follow every stride.
constexpr std::size_t kMaxDrawnPoints = 20000;
constexpr double kLabelOffsetInSteps = 0.45;  ///< metre labels sit this far outside the grid

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
std::vector<std::size_t> decimatedIndices(std::size_t count, const std::vector<std::uint8_t>& stance = {})
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

/// Lines at least two steps wide: a straight walk still gets a floor that reads as one.
void widenToTwoSteps(double& from, double& to, double step)
{
    if (to - from < 2.0 * step) {
        from -= step;
        to += step;
    }
}

}  // namespace

double PathScene3D::Grid::labelOffset_m() const
{
    return kLabelOffsetInSteps * step_m;
}

void PathScene3D::setResult(std::shared_ptr<const Result> result)
{
    result_ = std::move(result);
    stale_ = true;
}

void PathScene3D::setReference(const std::vector<Eigen::Vector3d>& positions_m)
{
    reference_m_ = positions_m;
    stale_ = true;
}

void PathScene3D::setOverlays(const std::vector<PathOverlay>& overlays)
{
    overlays_ = overlays;
    stale_ = true;
}

void PathScene3D::setGhost(const std::vector<Eigen::Vector3d>& positions_m)
{
    ghost_m_ = positions_m;
    ghostStale_ = true;
}

void PathScene3D::clear()
{
    result_.reset();
    reference_m_.clear();
    ghost_m_.clear();
    stale_ = ghostStale_ = true;
}

const std::vector<Eigen::Vector3d>& PathScene3D::path() const
{
    static const std::vector<Eigen::Vector3d> none;
    return result_ ? result_->position_m : none;
}

const std::vector<Step>& PathScene3D::stances() const
{
    static const std::vector<Step> none;
    return hasPath() ? result_->steps : none;
}

std::optional<Eigen::Vector3d> PathScene3D::cursorPosition() const
{
    if (!hasPath() || std::isnan(timeCursor_s_) || result_->time_s.empty())
        return std::nullopt;
    return path()[std::min(nearestSampleAtTime(result_->time_s, timeCursor_s_), path().size() - 1)];
}

bool PathScene3D::showsMotionColours() const
{
    return motionColouring_ && result_ && hasMotionClasses(*result_) && sampleMotion().size() == path().size();
}

const std::vector<MotionClass>& PathScene3D::sampleMotion() const
{
    ensureBuilt();
    return built_.sampleMotion;
}

PathScene3D::Line PathScene3D::drawnPath() const
{
    ensureBuilt();
    return {path(), built_.path};
}

PathScene3D::Line PathScene3D::drawnReference() const
{
    ensureBuilt();
    return {reference_m_, built_.reference};
}

PathScene3D::Line PathScene3D::drawnOverlay(std::size_t index) const
{
    ensureBuilt();
    return {overlays_[index].positions_m, built_.overlays[index]};
}

PathScene3D::Line PathScene3D::drawnGhost() const
{
    ensureBuilt();
    return {ghost_m_, built_.ghost};
}

const Eigen::AlignedBox3d& PathScene3D::bounds() const
{
    ensureBuilt();
    return built_.bounds;
}

PathScene3D::Grid PathScene3D::grid() const
{
    const Eigen::Vector3d& min = bounds().min();
    const Eigen::Vector3d& max = bounds().max();
    Grid grid;
    grid.step_m = niceStep(std::max({max.x() - min.x(), max.y() - min.y(), 1.0}) / 6.0);
    // A walk that starts at 0 and wobbles to -1 cm should not earn a whole extra row of cells.
    const double slack = 0.1 * grid.step_m;
    const auto down = [&grid, slack](double v) { return std::floor((v + slack) / grid.step_m) * grid.step_m; };
    const auto up = [&grid, slack](double v) { return std::ceil((v - slack) / grid.step_m) * grid.step_m; };
    grid.xMin = down(min.x());
    grid.xMax = up(max.x());
    grid.yMin = down(min.y());
    grid.yMax = up(max.y());
    widenToTwoSteps(grid.xMin, grid.xMax, grid.step_m);
    widenToTwoSteps(grid.yMin, grid.yMax, grid.step_m);
    grid.z_m = min.z();
    return grid;
}

std::vector<Eigen::Vector3d> PathScene3D::framedPoints() const
{
    const Grid floorGrid = grid();
    const double labelRoom = floorGrid.labelOffset_m();
    std::vector<Eigen::Vector3d> points;
    for (double x : {floorGrid.xMin - labelRoom, floorGrid.xMax + labelRoom})
        for (double y : {floorGrid.yMin - labelRoom, floorGrid.yMax + labelRoom})
            points.emplace_back(x, y, floorGrid.z_m);
    const auto addDrawn = [&points](const Line& line) {
        for (std::size_t index : line.drawn)
            points.push_back(line.points_m[index]);
    };
    addDrawn(drawnPath());
    addDrawn(drawnReference());
    for (std::size_t i = 0; i < overlays_.size(); ++i)
        addDrawn(drawnOverlay(i));
    return points;
}

void PathScene3D::ensureBuilt() const
{
    if (stale_) {
        stale_ = false;
        rebuild();
    }
    if (ghostStale_) {
        ghostStale_ = false;
        built_.ghost = decimatedIndices(ghost_m_.size());
    }
}

void PathScene3D::rebuild() const
{
    ++builds_;
    built_.path = decimatedIndices(path().size(), result_ ? result_->flags.stance : std::vector<std::uint8_t>());
    built_.sampleMotion = result_ ? motionOfSamples(*result_) : std::vector<MotionClass>();
    built_.reference = decimatedIndices(reference_m_.size());
    built_.overlays.clear();
    for (const PathOverlay& overlay : overlays_)
        built_.overlays.push_back(decimatedIndices(overlay.positions_m.size()));
    built_.bounds = boundsOfLines();
}

Eigen::AlignedBox3d PathScene3D::boundsOfLines() const
{
    std::vector<const std::vector<Eigen::Vector3d>*> sources{&path(), &reference_m_};
    for (const PathOverlay& overlay : overlays_)
        sources.push_back(&overlay.positions_m);
    // Started at the first point rather than empty: no points leave a box at the origin, which the
    // grid and the camera can still work with.
    Eigen::AlignedBox3d box(Eigen::Vector3d::Zero());
    bool first = true;
    for (const std::vector<Eigen::Vector3d>* points : sources) {
        for (const Eigen::Vector3d& p : *points) {
            if (first)
                box = Eigen::AlignedBox3d(p);
            else
                box.extend(p);
            first = false;
        }
    }
    return box;
}

}  // namespace footpath
