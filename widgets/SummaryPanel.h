#pragma once

#include "SessionView.h"
#include "Recording.h"
#include "Result.h"
#include "RunHistory.h"
#include "gait/BilateralGait.h"
#include "metrics/Evaluation.h"
#include "metrics/GaitStatistics.h"
#include "metrics/ResultEvaluation.h"

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

class StepTableModel;


/// The figures of the latest result, a sortable per-step table and gait charts: stride length and
/// stance duration per step, and their histograms. Drawn with Qt Charts, without OpenGL.
///
/// The result's plausibility warnings head the figures (each with its time span, a link that asks
/// for the time cursor there), and the steps whose stride overlaps a warning's span are marked in
/// the table. The panel knows nothing of the session: MainWindow wires timeCursorRequested.
class SummaryPanel : public QWidget, public SessionView {
    Q_OBJECT
public:
    explicit SummaryPanel(QWidget* parent = nullptr);
    ~SummaryPanel() override;
    void showRecording(const AnalysisSession& session) override;
    void showEstimate(const AnalysisSession& session) override;

    /// The recording whose reference the figures are evaluated against; kept until replaced.
    void setRecording(std::shared_ptr<const Recording> recording);
    /// The recorded walk's result; null shows an empty panel. While the live session is shown it
    /// is kept for showRecorded().
    /// evaluation: the result's figures evaluated against the recording (the pipeline runner's);
    /// null evaluates them here.
    void setResult(std::shared_ptr<const Result> result, std::shared_ptr<const ResultEvaluation> evaluation = nullptr);
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

    const GaitStatistics& statistics() const { return evaluation_ ? evaluation_->statistics : noStatistics_; }

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
    std::shared_ptr<const ResultEvaluation> evaluation_;  ///< of result_: made once, shared with the window
    std::shared_ptr<const ResultEvaluation> recordedEvaluation_;
    GaitStatistics noStatistics_;  ///< what statistics() gives with no result

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
    QLabel* motionSentence_ = nullptr;     ///< Zheng et al. 2016's counts; hidden without motion classes
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
