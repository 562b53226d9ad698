#pragma once

#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace footpath {

/// The path views' stance dots are 5-6 px wide: closer together than this they merge into a line
/// that covers the path (half an hour seen whole puts 1500 stances a pixel or two apart).
constexpr double kMinStanceSpacing_px = 8.0;

/// Whether stance markers at these screen points, in walking order, stand apart: the median
/// distance between consecutive ones is at least kMinStanceSpacing_px. Fewer than two are apart.
inline bool stanceMarkersApart(const QPolygonF& markers_px)
{
    if (markers_px.size() < 2)
        return true;
    std::vector<double> spacing;
    spacing.reserve(static_cast<std::size_t>(markers_px.size() - 1));
    for (qsizetype i = 1; i < markers_px.size(); ++i)
        spacing.push_back(std::hypot(markers_px[i].x() - markers_px[i - 1].x(), markers_px[i].y() - markers_px[i - 1].y()));
    const auto median = spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2);
    std::nth_element(spacing.begin(), median, spacing.end());
    return *median >= kMinStanceSpacing_px;
}

}  // namespace footpath
