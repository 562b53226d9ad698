#pragma once

#include "Recording.h"
#include "Result.h"
#include "metrics/ResultEvaluation.h"
#include "nav/Parameters.h"

#include <QAbstractTableModel>
#include <QString>
#include <QWidget>

#include <deque>
#include <limits>
#include <memory>
#include <optional>

class QPushButton;
class QTableView;

namespace footpath {

/// The figures a run is judged by when tuning: what the ghost row in the summary compares and the
/// history lists. NaN where there is nothing to compute (no reference, no known length).
struct RunFigures {
    static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    double pathLength_m = kNone;
    double endToStart_m = kNone;
    double armse2d_m = kNone;          ///< against the reference positions, when the recording has them
    double referenceLength_m = kNone;  ///< the walk's known length, when the recording states it
    int steps = 0;
};
RunFigures runFigures(const Result& result, const ResultEvaluation& evaluation);
/// The same, evaluating result against recording (null: no reference) first.
RunFigures runFigures(const Result& result, const Recording* recording);

/// Whether a change of a figure is an improvement: lower end-to-start and ARMSE are better, a path
/// length nearer the known length is better; steps and a path length without a reference are
/// neither.
enum class Judgement { Better, Worse, Neither };
Judgement judgePathLength(const RunFigures& before, const RunFigures& after);
Judgement judgeLowerIsBetter(double before, double after);

/// One estimate the user made while tuning: its parameters, what changed from the run before it,
/// its figures and the result itself (shared, not copied).
struct Run {
    int number = 0;  ///< 1, 2, ... in the order the runs were made
    Parameters parameters;
    QString change;  ///< "C3 bound on |ω|: 1 → 1.5"; "First run" for the first
    RunFigures figures;
    std::shared_ptr<const Result> result;
    const void* gesture = nullptr;  ///< the undo step that made it (a dragged slider is one step)
    int undoIndex = -1;
};

/// The last kMaxRuns estimates of one recording, newest last, as a table (number, change, figures).
/// A result whose parameters equal an earlier run's (undo, or going back to it) makes that run
/// current instead of adding one; the results of one undo step (a slider being dragged) update one
/// run. The previous run (the one current before the latest change) is what the views show as a
/// ghost.
class RunHistory : public QAbstractTableModel {
    Q_OBJECT
public:
    static constexpr int kMaxRuns = 20;
    enum Column { Number, Change, PathLength, EndToStart, Armse, Steps, ColumnCount };

    using QAbstractTableModel::QAbstractTableModel;

    void clear();
    /// A new result on screen. gesture and undoIndex identify the undo step that made it (the
    /// stack's top command and index), so the results of one merged step update one run.
    void record(std::shared_ptr<const Result> result, const Parameters& params, const RunFigures& figures,
                const void* gesture, int undoIndex);

    const Run* current() const;
    const Run* previous() const;  ///< the run current before the latest change; null for none
    /// What the latest change did, from previous() to current(): after an undo back to an earlier
    /// run, the undone change reversed (not the earlier run's own "First run"); empty without both.
    QString latestChange() const;
    const Run* runAt(int row) const;
    int currentRow() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

signals:
    /// current() or previous() changed.
    void currentChanged();

private:
    int rowOf(const Run* run) const;
    QString describeChange(const Parameters& from, const Parameters& to) const;
    void makeCurrent(int row);

    std::deque<Run> runs_;
    int nextNumber_ = 1;
    int currentNumber_ = 0;   ///< Run::number of the current run, 0 for none
    int previousNumber_ = 0;
};

/// The history as a list: double-click (or Go back) asks for a run's parameters again.
class RunHistoryPanel : public QWidget {
    Q_OBJECT
public:
    explicit RunHistoryPanel(RunHistory* history, QWidget* parent = nullptr);
    QTableView* table() const { return table_; }

signals:
    void runChosen(const footpath::Parameters& params, int number);

private:
    void chooseSelected();
    void showCurrent();

    RunHistory* history_;
    QTableView* table_;
    QPushButton* goBack_;
};

}  // namespace footpath
