#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"
#include "tune/AutoTune.h"

#include <QDialog>
#include <QFutureWatcher>
#include <QGroupBox>

#include <array>
#include <atomic>
#include <memory>
#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QRadioButton;
class QSpinBox;
class QTableWidget;

namespace footpath {

class AnalysisSession;
class TrajectoryView2D;

/// "End-to-start distance of a closed walk", ...: what the criterion measures, for people.
QString tuneCriterionText(TuneCriterion criterion);
/// "2.31 %" or "0.412 m"; a dash for a recording the criterion could not score (NaN).
QString formatTuneScore(TuneCriterion criterion, double score);
/// A read-only table with these column headers, the last column stretched: the dialogs' result tables.
QTableWidget* makeTuneTable(const QStringList& headers, QWidget* parent);
/// Fills the table with one row per parameter that differs (label with unit, before, after), the
/// criterion's mean first when given (not NaN). Returns the number of changed parameters.
int showTuneChanges(QTableWidget* table, const Parameters& before, const Parameters& after, TuneCriterion criterion,
                    double scoreBefore, double scoreAfter);

/// The criteria as radio buttons; one the recordings do not support is disabled with the reason
/// beside it.
class TuneCriterionChoice : public QGroupBox {
    Q_OBJECT
public:
    explicit TuneCriterionChoice(QWidget* parent = nullptr);

    /// Why each criterion (in TuneCriterion order) cannot be used; empty: it can. A choice that is
    /// no longer possible moves to the first one that is (the reference first: it says the most).
    void setReasons(const std::array<QString, 3>& whyNot);
    bool isAvailable(TuneCriterion criterion) const;
    TuneCriterion criterion() const;
    void setCriterion(TuneCriterion criterion);

private:
    std::array<QRadioButton*, 3> buttons_{};
    std::array<QLabel*, 3> reasons_{};
    std::array<bool, 3> available_{};  ///< not the buttons' isEnabled(): a disabled parent disables them too
};

/// What a tuning run hands back: the search's outcome and, when asked for, the first recording's
/// path with the starting and with the best parameters (the search keeps no paths).
struct TuneJobResult {
    TuneOutcome outcome;
    std::shared_ptr<const Result> before;
    std::shared_ptr<const Result> after;
};

/// One tuneParameters run off the GUI thread, on every core, with its progress delivered to the
/// GUI thread and a cancel that keeps the best found so far.
class TuneJob : public QObject {
    Q_OBJECT
public:
    explicit TuneJob(QObject* parent = nullptr);
    ~TuneJob() override;  ///< cancels and waits: the worker reads the recordings this job holds

    /// withPaths: also estimate the first recording's path with the base and the best parameters.
    void start(std::vector<std::shared_ptr<const Recording>> recordings, const Parameters& base,
               const TuneOptions& options, bool withPaths);
    void cancel();
    bool isRunning() const;
    /// Valid once finished() was emitted.
    const TuneJobResult& result() const { return result_; }

signals:
    /// After each generation of the search; bestScore is the mean criterion of the best so far.
    void progressed(int evaluations, int budget, double bestScore);
    void finished();

private:
    QFutureWatcher<TuneJobResult> watcher_;
    std::shared_ptr<std::atomic<bool>> cancel_;
    TuneJobResult result_;
};

/// Analysis > Tune for this recording: picks a criterion the open recording supports (the walk
/// can be said to end where it started, and its length given, here), the number of evaluations,
/// runs the search with progress and cancel, then shows the path before and after and what
/// changed. Accept makes the tuned parameters the workspace's in one undoable step; Reject (or
/// closing) changes nothing.
class TuneDialog : public QDialog {
    Q_OBJECT
public:
    explicit TuneDialog(AnalysisSession& session, QWidget* parent = nullptr);
    ~TuneDialog() override;

    /// Starts the search with the settings shown (what the Start button does).
    void start();
    /// Stops the search; the best found so far is shown (what the Stop button does while running).
    void stop();
    bool isRunning() const;
    bool isCriterionAvailable(TuneCriterion criterion) const;
    void setCriterion(TuneCriterion criterion);
    TuneCriterion criterion() const;
    void setEvaluations(int evaluations);

    /// The finished run's outcome (for tests and the caller).
    const TuneOutcome& outcome() const;
    QProgressBar* progressBar() const { return progress_; }
    QLabel* bestLabel() const { return best_; }
    QTableWidget* changesTable() const { return changes_; }
    TrajectoryView2D* pathView() const { return view_; }

    void accept() override;
    void reject() override;

signals:
    /// A run ended (finished or stopped) and its outcome is shown.
    void tuningFinished();

private:
    QWidget* createSettings();
    QWidget* createResultArea();
    QWidget* createButtons();
    /// The recording as tuned: the session's, with what the user said about the walk.
    std::shared_ptr<const Recording> recordingToTune() const;
    void updateCriteria();
    void showProgress(int evaluations, int budget, double bestScore);
    void onFinished();
    void showOutcome(const TuneJobResult& result);
    /// The path's length and end-to-start distance before and after, and a warning when it changed much.
    void showCautions(const std::vector<std::string>& cautions);
    void showPathFigures(const Summary& before, const Summary& after);
    void showPaths(const std::shared_ptr<const Result>& before, const std::shared_ptr<const Result>& after);
    void setStage(bool running, bool done);

    AnalysisSession& session_;
    Parameters base_;
    TuneJob* job_;
    QCheckBox* closed_;
    QDoubleSpinBox* length_;
    TuneCriterionChoice* criteria_;
    QSpinBox* evaluations_;
    QProgressBar* progress_;
    QLabel* best_;
    QLabel* message_;
    QLabel* warning_;  ///< a tuned path much longer or shorter than the current one
    TrajectoryView2D* view_;
    QTableWidget* changes_;
    QPushButton* startButton_ = nullptr;
    QPushButton* stopButton_ = nullptr;
    QPushButton* acceptButton_ = nullptr;
    QPushButton* rejectButton_ = nullptr;
    TuneCriterion runCriterion_ = TuneCriterion::ClosedLoop;
};

}  // namespace footpath
