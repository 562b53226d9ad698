#pragma once

#include <QPoint>
#include <qcustomplot.h>

#include <optional>

class QPainter;

namespace footpath {

/// What SignalPlots and StanceFlagsPlot share about moving along time.

/// The time range after a navigation key (+/= zoom in, - zoom out, Left/Right pan) applied to
/// [from, to]; nothing for other keys.
std::optional<QCPRange> keyNavigatedRange(int key, double from_s, double to_s);

/// A left-button release that stayed within the platform's drag distance of its press: a click
/// that places the time cursor, not the end of a pan.
bool isClick(const QPoint& pressed, const QPoint& released, Qt::MouseButton button);

/// Draws the plot into target as vector commands: QCustomPlot paints only through its own
/// QCPPainter, so the drawing is recorded in a QPicture that the caller's painter replays.
void renderPlotTo(QCustomPlot* plot, QPainter& painter, const QRect& target);

}  // namespace footpath
