#pragma once

#include "Recording.h"
#include "Result.h"
#include "RunHistory.h"
#include "gait/BilateralGait.h"
#include "metrics/Evaluation.h"

#include <QString>
#include <QWidget>

#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

class QChartView;
class QTabWidget;
class QGroupBox;
class QLabel;
class QTableView;

namespace footpath {

/// The figures the summary panel and the PDF report show, computed once from a result (and the
/// recording's reference, when it has one). Figures that need at least one stride are NaN without.
///
/// A stride is one cycle of the instrumented foot (one stance phase to the next; Summary::steps
/// counts them). Cadence follows the clinical convention of counting both feet: two steps per
/// stride, so cadence_stepsPerMin = 2 * strideRate_perMin. Both come from the median stride
/// duration: the first stride also holds the standing still before the walk (and a pause holds
/// its wait), which would slow a mean-based cadence by 10 % on a 15-stride walk.
struct GaitStatistics {
    static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

    std::size_t stancePhases = 0;
    std::size_t strides = 0;
    double duration_s = 0.0;
    double pathLength_m = 0.0;
    double strideRate_perMin = kNone;      ///< 60 / median stride duration
    double cadence_stepsPerMin = kNone;    ///< both feet: 120 / median stride duration
    double meanStrideLength_m = kNone;
    double strideLengthStd_m = kNone;      ///< sample standard deviation (n - 1); 0 for one stride
    double meanStrideDuration_s = kNone;
    double medianStrideDuration_s = kNone;
    double meanStanceDuration_s = kNone;
    double endToStart_m = 0.0;
    double endToStartPct = 0.0;

    std::vector<double> strideLengths_m;   ///< one per stride, in step order
    std::vector<double> strideDurations_s; ///< one per stride, in step order
    std::vector<double> stanceDurations_s; ///< one per stance phase, in step order

    // Against the recording's reference; empty where it has none (evaluation.md sections 1-4).
    std::optional<ArmseResult> armse;           ///< reference position at every sample
    std::optional<LoopClosure> loopClosure;     ///< walk ends where it started
    std::optional<DistanceError> distanceError; ///< known walked length
    std::optional<StanceScore> gaitStanceScore; ///< hand-labelled gait events: heel strike to toe off
    std::optional<StanceScore> stanceScore;     ///< the same labels: the foot at rest (ZUPT flag)
    std::optional<StrideCount> strideCount;     ///< strides against the labelled swings
};

/// recording may be null; it must be the recording result was estimated from (its reference is
/// only used when its sample count matches the result's).
GaitStatistics computeGaitStatistics(const Result& result, const Recording* recording = nullptr);

/// Equal-width bins, edges on multiples of the width, plus one bin each for values below and above
/// them. The regular bins cover the values inside Tukey's far-out fences (quartiles -/+ 3 IQR), so
/// the standing still at the start and end of a walk, or a turn, does not stretch the bins over
/// the whole range and squeeze the walking strides into one. The width is a 1-2-2.5-5 number
/// giving about sqrt(n) bins (5 to 10) over that range, never narrower than minimumBinWidth (the
/// resolution worth showing: a centimetre of stride, a sample period of stance). Non-finite values
/// are left out.
struct Histogram {
    double firstEdge = 0.0;
    double binWidth = 0.0;
    std::vector<int> counts;  ///< regular bins; empty when there are no values
    int below = 0;            ///< values below firstEdge
    int above = 0;            ///< values at or above lastEdge()

    double lastEdge() const { return firstEdge + static_cast<double>(counts.size()) * binWidth; }
    double binCentre(std::size_t bin) const { return firstEdge + (static_cast<double>(bin) + 0.5) * binWidth; }
    int total() const;
};
Histogram makeHistogram(const std::vector<double>& values, double minimumBinWidth);

/// The figures of the latest result, a sortable per-step table and gait charts: stride length and
/// stance duration per step, and their histograms. Drawn with Qt Charts, without OpenGL.
///
/// The result's plausibility warnings head the figures (each with its time span, a link that asks
/// for the time cursor there), and the steps whose stride overlaps a warning's span are marked in
/// the table. The panel knows nothing of the session: MainWindow wires timeCursorRequested.
class SummaryPanel : public QWidget {
    Q_OBJECT
public:
    explicit SummaryPanel(QWidget* parent = nullptr);
    ~SummaryPanel() override;

    /// The recording whose reference the figures are evaluated against; kept until replaced.
    void setRecording(std::shared_ptr<const Recording> recording);
    /// The recorded walk's result; null shows an empty panel. While the live session is shown it
    /// is kept for showRecorded().
    void setResult(std::shared_ptr<const Result> result);
    /// Shows a live session's estimate so far (with its plausibility warnings) in place of the
    /// recorded walk, under a line saying so; call again as the estimate grows.
    void showLive(std::shared_ptr<const Result> live);
    /// Back to the recorded walk (its result, reference figures and last change).
    void showRecorded();
    bool isShowingLive() const { return live_; }
    /// Forgets the recorded walk (and shows nothing, unless the live session is shown).
    void clear();
    /// Brings one of the tabs below the figures to the front: "steps", "per-step", "distributions"
    /// or "gait". Returns false for any other name.
    bool showTab(const QString& name);

    const GaitStatistics& statistics() const { return statistics_; }

    /// Double support and left/right symmetry when both feet of the walk are open (the result
    /// shown is then the left foot's); nothing hides them.
    void setBothFeet(const std::optional<BilateralGait>& walk);

    /// The key figures before and after the last parameter change (path length, end to start,
    /// ARMSE when there is a reference, steps), green where the change helped and red where it
    /// hurt; null hides them (a new recording, the first run).
    void showChange(const RunFigures* before, const RunFigures& after, const QString& change);
    QTableView* stepTable() const { return table_; }  ///< for tests

signals:
    /// The user clicked a warning's time span or a step: show this moment.
    void timeCursorRequested(double time_s);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    class StepTableModel;
    struct FigureRow {
        QLabel* name = nullptr;
        QLabel* value = nullptr;
    };

    QWidget* createFigures();
    QGroupBox* createChangeGroup();
    QWidget* createWarnings();
    QWidget* createMotionAndNotes();
    QGroupBox* createFigureGroup(const QString& title, const std::vector<std::pair<QString, QString>>& rows);
    QWidget* createTable();
    QWidget* createChartPair(QChartView* left, QChartView* right);
    QChartView* createChartView(const QString& objectName);

    void refresh();
    void showWalkFigures();
    static QString mergedMovementsText(const std::vector<MergedMovement>& merged);
    void showGaitFigures();
    void showBothFeetFigures();
    void showReferenceFigures();
    void showWarnings();
    void showMotionAndNotes();
    void setFigure(const QString& key, const QString& text);
    void showCharts();
    /// xTitle empty: "Step".
    void showPerStepChart(QChartView* view, const QString& title, const QString& yTitle, std::size_t firstStep,
                          const std::vector<double>& values, const QString& xTitle = QString());
    void showHistogram(QChartView* view, const QString& title, const QString& xTitle, const Histogram& histogram);
    void labelHistogramEdges(QChartView* view);

    std::shared_ptr<const Recording> recording_;  ///< what is shown: null while live
    std::shared_ptr<const Result> result_;
    std::shared_ptr<const Recording> recordedRecording_;  ///< the recorded walk's, kept while live
    std::shared_ptr<const Result> recordedResult_;
    bool live_ = false;
    bool changeShown_ = false;  ///< the recorded walk has a last change to show
    GaitStatistics statistics_;

    std::map<QString, FigureRow> figures_;  ///< by key, e.g. "armse2d"
    QLabel* liveSource_ = nullptr;  ///< "Live session: ..." while the live estimate is shown
    QGroupBox* changeGroup_ = nullptr;
    QLabel* changeText_ = nullptr;
    std::map<QString, FigureRow> changeFigures_;  ///< "pathLength", "endToStart", "armse2d", "steps"
    QGroupBox* referenceGroup_ = nullptr;
    QGroupBox* gaitGroup_ = nullptr;      ///< the gait lab's stance: heel strike to toe off
    QGroupBox* bothFeetGroup_ = nullptr;  ///< shown while both feet are open
    QLabel* bothFeetNotes_ = nullptr;
    std::optional<BilateralGait> bothFeet_;
    QGroupBox* warningsGroup_ = nullptr;
    QLabel* warningsTitle_ = nullptr;
    QWidget* warningList_ = nullptr;  ///< one label per warning, remade with each result
    QLabel* noWarnings_ = nullptr;
    QLabel* motionSentence_ = nullptr;     ///< seed 004's counts; hidden without motion classes
    QGroupBox* methodNotesGroup_ = nullptr;
    QWidget* methodNoteList_ = nullptr;    ///< one label per method note, remade with each result
    QLabel* referenceNotes_ = nullptr;
    StepTableModel* stepModel_ = nullptr;
    QTableView* table_ = nullptr;
    QTabWidget* tabs_ = nullptr;  ///< the step table, then the charts' tabs
    bool chartsStale_ = false;     ///< the charts show an older result: filled when their tab comes to the front
    QChartView* strideLengthChart_ = nullptr;
    QChartView* stanceDurationChart_ = nullptr;
    QChartView* strideLengthHistogram_ = nullptr;
    QChartView* stanceDurationHistogram_ = nullptr;
    QChartView* gaitStanceChart_ = nullptr;  ///< per gait stride: heel strike to toe off, %
    QChartView* clearanceChart_ = nullptr;   ///< per gait stride: foot clearance
    std::map<QChartView*, Histogram> shownHistograms_;  ///< to relabel the edges on resize
};

}  // namespace footpath
