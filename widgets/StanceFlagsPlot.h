#pragma once

#include "SessionView.h"
#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <QWidget>

#include <array>
#include <memory>
#include <vector>

class QAction;
class QCPAxisRect;
class QCPLegend;
class QCPGraph;
class QCPItemStraightLine;
class QCPRange;
class QCustomPlot;
class QMouseEvent;
class QPainter;
class QToolBar;

namespace footpath {

class DetectorInputRows;
class DetectorStatisticRow;

class DeferredReplot;

class LegendStrip;
class LinkedTimeRows;
class MotionLanes;
class PlotInteraction;
class ReferenceStanceLane;
class TimeBands;
class WarningOverlay;

/// The stance detector at work, following the chosen detector (Parameters::detector):
///  - its flags as 0/1 lanes: C1, C2, C3, C and the median-filtered stance for the paper's
///    C1/C2/C3 detector; C (statistic below threshold) and stance for the statistic detectors
///    (SHOE, ARED, AMVD, MBGTD), which have one condition, so C1-C3 would only repeat C;
///  - its test statistic (StanceFlags::logStatistic) on a logarithmic axis with the threshold it
///    was compared with at each sample (a moving line for the adaptive threshold) and the stance
///    shaded, so a user sees how far from stance each moment was;
///  - for C1/C2/C3, on demand, its inputs (|a|, the centred std of |a|, |w|) with their thresholds,
///    so a user sees which condition failed where;
///  - the result's plausibility warnings as bands with labels and tool tips (a missed stance names
///    what blocked the detector).
///
/// Navigation is the same as in SignalPlots (wheel/drag on time, +/-, Left/Right, Home, click for
/// the cursor); setTimeRange/timeRangeChanged let MainWindow link the two time axes. Setters
/// schedule one replot for the next event-loop pass, so several in a row draw once.
class StanceFlagsPlot : public QWidget, public SessionView {
    Q_OBJECT
public:
    enum class Lane { C1, C2, C3, C, Stance };  ///< top to bottom
    Q_ENUM(Lane)
    enum class Input { AccNorm, AccStdDev, GyrNorm };  ///< one row each, below the lanes
    Q_ENUM(Input)
    enum class Threshold { AccMin, AccMax, AccStdMax, GyrMax };
    Q_ENUM(Threshold)
    static constexpr int kLaneCount = 5;
    static constexpr int kInputCount = 3;
    static constexpr int kThresholdCount = 4;

    explicit StanceFlagsPlot(QWidget* parent = nullptr);
    ~StanceFlagsPlot() override;
    void showRecording(const AnalysisSession& session) override;
    void showEstimate(const AnalysisSession& session) override;
    void showTimeCursor(double time_s) override { setTimeCursor(time_s); }

    /// Plots the detector inputs (copied: the recording is not kept); the lanes are cleared, since
    /// they belonged to the old recording.
    void setRecording(std::shared_ptr<const Recording> recording);
    /// Draws result->flags as lanes and statistic, and result->warnings; nullptr clears them.
    void setResult(std::shared_ptr<const Result> result);
    /// Moves the threshold lines, recomputes the std of |a| for the new window, and shows the lanes
    /// and rows of the chosen detector.
    void setParameters(const Parameters& params);
    void setTimeCursor(double time_s);
    /// Shows [from_s, to_s]; emits timeRangeChanged if that is a change.
    void setTimeRange(double from_s, double to_s);
    void setInputsVisible(bool visible);
    /// Time range of the whole recording (what Home shows).
    void showAll();

    /// Whether the user asked for the inputs; they are shown only for the C1/C2/C3 detector.
    bool inputsVisible() const { return inputsVisible_; }
    bool isLaneShown(Lane lane) const;
    bool isInputRowShown(Input input) const;
    double timeCursor() const { return timeCursor_s_; }
    QCPRange timeRange() const;
    /// The plotted height of a lane for a flag; lanes are step curves between these two levels.
    static double laneLevel(Lane lane, bool flag);

    /// For the PDF report (QCustomPlot::toPainter, savePdf) and for tests.
    QCustomPlot* plot() const
    {
        ensureCurvesPlotted();  // for a report or a test that replots it while hidden
        return plot_;
    }
    /// The legend above the rows: the threshold(s) and the stance shading.
    QCPLegend* legend() const;
    QCPAxisRect* lanesRect() const;
    QCPAxisRect* inputRect(Input input) const;
    QCPGraph* laneGraph(Lane lane) const;
    QCPGraph* inputGraph(Input input) const;
    QCPGraph* thresholdGraph(Threshold threshold) const;
    QCPAxisRect* statisticRect() const;
    /// The lane of labelled warning bars above the rows; in the layout while there are warnings.
    QCPAxisRect* warningLane() const;
    /// 10^logStatistic per sample (the log axis shows the logarithm).
    QCPGraph* statisticGraph() const;
    /// 10^logThreshold where it changes, as a step curve.
    QCPGraph* statisticThresholdGraph() const;
    bool isStatisticStanceShaded(double time_s) const;
    const WarningOverlay& warningOverlay() const { return *warnings_; }
    /// The steps' motion classes (Zheng et al. 2016) under the detector lanes; in the layout with a result.
    QCPAxisRect* motionLane() const;
    /// Spans where a method skipped itself; in the layout while the result has method notes.
    QCPAxisRect* methodNotesLane() const;
    const MotionLanes& motionLanes() const { return *motion_; }
    /// The recording's reference stance (IPOL gait events, pyshoe's zv_vicon_opt) as a lane under
    /// the detector's; in the layout when the recording has one.
    QCPAxisRect* referenceLane() const;
    bool isReferenceStance(double time_s) const;
    /// Where the reference stance comes from, for the lane's tool tip; empty without one.
    const QString& referenceSource() const;
    /// Hover readout, marker, Y zoom, context menu and export.
    PlotInteraction* interaction() const { return interaction_; }
    /// Draws the plots (without the toolbar) into target as vector commands.
    void renderTo(QPainter& painter, const QRect& target);

signals:
    /// The user clicked in a plot at this time.
    void timeCursorMoved(double time_s);
    /// The visible time range changed (user zoom or pan, Home, or setTimeRange).
    void timeRangeChanged(double from_s, double to_s);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    /// warnings, method notes, lanes, reference stance, motion, statistic, one per input
    static constexpr std::size_t kRowCount = 6 + kInputCount;
    struct RowParts {
        QCPAxisRect* rect = nullptr;
        QCPItemStraightLine* cursor = nullptr;
    };

    void createLanesRow();
    void createPlotInteraction();
    void labelLanes();
    void wireInteractions();
    bool usesPaperDetector() const;
    /// The warnings and motion lanes of result_ now, its lanes and statistic when seen.
    void showResultLanes();
    void ensureCurvesPlotted() const;
    void plotLanes();
    void arrangeRows();

    QCustomPlot* plot_;
    DeferredReplot* replot_;  ///< one replot per event-loop pass for the setters, none while hidden
    QToolBar* toolBar_;
    QAction* inputsAction_;
    std::array<RowParts, kRowCount> rows_;
    std::array<QCPGraph*, kLaneCount> lanes_{};
    std::array<TimeBands*, kLaneCount> laneFills_{};  ///< under each lane's outline while its flag is set
    std::unique_ptr<DetectorInputRows> inputRows_;  ///< also holds the recording's sample times
    std::unique_ptr<DetectorStatisticRow> statisticRow_;
    WarningOverlay* warnings_ = nullptr;
    MotionLanes* motion_ = nullptr;
    PlotInteraction* interaction_ = nullptr;
    std::unique_ptr<ReferenceStanceLane> reference_;
    std::shared_ptr<const Result> result_;
    Parameters params_;
    bool inputsVisible_ = false;
    bool curvesStale_ = false;  ///< the lanes and the statistic do not show result_ yet
    double timeCursor_s_ = 0.0;
    bool cursorPlaced_ = false;  ///< the cursor stays hidden until someone places it
    LinkedTimeRows* timeRows_ = nullptr;  ///< made with the rows
    LegendStrip* legend_ = nullptr;       ///< one for all rows, above them
};

}  // namespace footpath
