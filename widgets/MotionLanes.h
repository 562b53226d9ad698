#pragma once

#include "Result.h"

#include <QColor>
#include <QObject>
#include <QString>

#include <vector>

class QCPAxisRect;
class QCustomPlot;
class QMouseEvent;

namespace footpath {

// --- Zheng et al. 2016's motion classes and the methods' notes, worded and coloured for every view -------

/// "Level", "Stairs up", ...; "Unclassified" for Unknown.
QString motionClassLabel(MotionClass motion);
/// One colour per class, the same in the lane, the paths and the table: up red-violet, down blue,
/// elevators darker than stairs, level a muted green so the classes that matter stand out.
QColor motionClassColour(MotionClass motion);
/// Whether any step has a class other than Unknown (a barometer was there and the classifier ran).
bool hasMotionClasses(const Result& result);
/// Whether any step has a barometric height (the recording had pressure).
bool hasBarometer(const Result& result);

/// The stretch of time a step's class describes: the stride that leads to it, from the end of the
/// previous stance to the end of its own (the first from the start of the result), so every moment
/// of the walk belongs to exactly one step, as in the step table's warning marks.
struct MotionSpan {
    MotionClass motion = MotionClass::Unknown;
    double start_s = 0.0;
    double end_s = 0.0;
    std::size_t firstStep = 0;  ///< consecutive steps of one class are one span
    std::size_t lastStep = 0;
};
/// The classified spans in time order, consecutive steps of the same class merged; Unknown left out.
std::vector<MotionSpan> motionSpans(const Result& result);
/// Per result sample, the class of the step whose stride holds it (Unknown after the last stance).
std::vector<MotionClass> motionOfSamples(const Result& result);
/// The classes that occur in classes, in the enum's order (for legends).
std::vector<MotionClass> motionClassesIn(const std::vector<MotionClass>& classes);

/// "3 floors up by stairs (9.1 m), 1 elevator ride"; "Level walking only: no stairs or elevator";
/// empty when no step is classified. A floor is 3 m of stairs climbed or descended.
QString motionCountsSentence(const Result& result);

/// "Magnetometer", "Heading drift reduction (HDR)", ... for a MethodNote's short name.
QString methodLabel(const std::string& method);
/// "12.0–15.5 s"
QString methodNoteSpanText(const MethodNote& note);
/// "Magnetometer, 12.0–15.5 s: <message>"
QString methodNoteText(const MethodNote& note);

/// One bar in a lane: its span, colour, the label drawn in it when it fits, and its tool tip.
struct LaneBar {
    double start_s = 0.0;
    double end_s = 0.0;
    QColor colour;
    QString label;
    QString toolTip;
};

/// Two lanes over the stacked rows of one QCustomPlot (StanceFlagsPlot): the steps' motion classes
/// as coloured, labelled spans ("Motion"; greyed with "not classified" when the recording had
/// pressure but no step is classified, left out without a barometer, so it costs no height then),
/// and the spans where a method skipped itself or did not apply ("Method notes"; stacked where
/// they overlap), each with its message as tool tip. The widget creates the lanes' axis rects and
/// shows them (hasMotionLane(), hasNotes()) in its layout; this object sets them up and draws them.
class MotionLanes : public QObject {
    Q_OBJECT
public:
    explicit MotionLanes(QCustomPlot* plot);

    void setMotionLane(QCPAxisRect* lane);
    void setNotesLane(QCPAxisRect* lane);
    /// nullptr clears both lanes.
    void setResult(const Result* result);

    /// Whether the motion lane has something to show (classes, or a barometer without them).
    bool hasMotionLane() const { return hasResult_ && (!motionBars_.empty() || barometer_); }
    bool hasNotes() const { return !noteBars_.empty(); }
    /// True when the result has barometric heights but no step is classified: the lane is grey
    /// with placeholder().
    bool isMotionGreyed() const { return hasMotionLane() && motionBars_.empty(); }
    /// Why the lane is grey (classification off, or the result predates it).
    const QString& placeholder() const { return placeholder_; }
    const std::vector<LaneBar>& motionBars() const { return motionBars_; }
    const std::vector<LaneBar>& noteBars() const { return noteBars_; }
    /// The tool tip of the bars in lane at time_s; empty where there is none.
    QString toolTipAt(const QCPAxisRect* lane, double time_s) const;

private:
    class Bars;
    void setUpLane(QCPAxisRect* lane, const QString& name, std::vector<LaneBar>* bars, bool greyable);
    void onMouseMove(QMouseEvent* event);
    void fitLaneHeights();

    QCustomPlot* plot_;
    QCPAxisRect* motionLane_ = nullptr;
    QCPAxisRect* notesLane_ = nullptr;
    std::vector<LaneBar> motionBars_;
    std::vector<LaneBar> noteBars_;
    QString placeholder_;
    bool hasResult_ = false;
    bool barometer_ = false;  ///< some step has a barometric height
    QString shownToolTip_;  ///< the tool tip we showed last, so we hide only our own
};

}  // namespace footpath
