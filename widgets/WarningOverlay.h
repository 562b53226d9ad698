#pragma once

#include "Result.h"

#include <QObject>
#include <QString>

#include <vector>

class QCPAxisRect;
class QCustomPlot;
class QMouseEvent;

namespace footpath {

class TimeBands;

/// A short name of a finding's kind for labels and lists ("missed stance").
QString warningLabel(PlausibilityWarning::Kind kind);
/// The finding's time span, "12.13-13.11 s".
QString warningSpanText(const PlausibilityWarning& warning);

/// Where the warnings lane puts a bar's label, in pixels from `start`, `width` wide: inside the bar
/// [left, right] when the text fits (or elided there when the bar holds at least minInside); else
/// beside it, after the bar or, at the lane's right end, before it. It never runs past the lane
/// [laneLeft, laneRight]: a label spilling past its span read as part of it.
struct LabelPlace {
    double start = 0.0;
    double width = 0.0;
    bool inside = true;
};
LabelPlace warningLabelPlace(double textWidth, double minInside, double left, double right, double laneLeft,
                             double laneRight);
/// Findings about the walk as a whole (the stance share, too few stances, heights drifting from the
/// barometer's): their span is the whole walk or most of it, so they are neither drawn as a band
/// over every plot nor mark every step; the summary and the labels still list them.
bool concernsWholeWalk(PlausibilityWarning::Kind kind);
/// Indices into result.warnings of the local findings whose span overlaps the stride that ends
/// with steps[step]: from the end of the previous stance to the end of this one (the first step's
/// stride reaches back to the start, the last one's on to the end), so every moment belongs to
/// exactly one row of the step table.
std::vector<std::size_t> warningsOfStep(const Result& result, std::size_t step);
/// One line per warning: "<b>label</b> (span): message", for tool tips (rich text, so it wraps).
QString warningsToolTip(const std::vector<PlausibilityWarning>& warnings, const std::vector<std::size_t>& which);

/// The plausibility warnings over the stacked rows of one QCustomPlot (SignalPlots,
/// StanceFlagsPlot): each local finding's span as a light red band the full height of every data
/// row; a lane row of its own ("Warnings") with one labelled bar per finding, stacked where they
/// overlap; and a tool tip with the messages wherever the pointer rests on a finding. The widget
/// creates the lane's axis rect and shows it (hasWarnings()) in its layout; the overlay sets it up.
class WarningOverlay : public QObject {
    Q_OBJECT
public:
    explicit WarningOverlay(QCustomPlot* plot);

    /// A data row: gets the bands.
    void addRow(QCPAxisRect* rect);
    /// The lane row: labelled bars, a fixed height for as many levels as the findings need.
    void setLane(QCPAxisRect* lane);
    void setWarnings(std::vector<PlausibilityWarning> warnings);
    const std::vector<PlausibilityWarning>& warnings() const { return warnings_; }
    bool hasWarnings() const { return !warnings_.empty(); }
    /// Whether a band (a local finding) covers time_s.
    bool isShaded(double time_s) const;
    /// The tool tip at time_s (every finding whose span holds it); empty where there is none.
    QString toolTipAt(double time_s) const;

private:
    class LaneBars;
    void onMouseMove(QMouseEvent* event);
    void fitLaneHeight();

    QCustomPlot* plot_;
    std::vector<QCPAxisRect*> rows_;  ///< the data rows and the lane
    QCPAxisRect* lane_ = nullptr;
    std::vector<TimeBands*> bands_;
    std::vector<PlausibilityWarning> warnings_;
    std::size_t neededLevels_ = 0;  ///< lane levels the findings need (overlap depth plus one)
    bool toolTipShown_ = false;
};

}  // namespace footpath
