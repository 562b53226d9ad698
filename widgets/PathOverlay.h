#pragma once

#include <Eigen/Core>

#include <QColor>
#include <QString>

#include <vector>

namespace footpath {

/// A further path drawn over the main one in the trajectory views (the comparison mode's method
/// sets), with its own colour and legend entry.
struct PathOverlay {
    QString label;
    QColor colour;
    std::vector<Eigen::Vector3d> positions_m;  ///< navigation frame, as Result::position_m
};

/// The right foot's path beside the left's, in the window and the report alike.
inline QColor otherFootColour()
{
    return QColor(214, 96, 24);
}

}  // namespace footpath
