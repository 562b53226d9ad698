#pragma once

#include "ComparisonTable.h"
#include "PathOverlay.h"
#include "Recording.h"
#include "nav/MethodSets.h"
#include "nav/Parameters.h"

#include <QFutureWatcher>
#include <QWidget>

#include <atomic>
#include <memory>
#include <vector>

class QCustomPlot;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace footpath {

/// The comparison mode: method sets to tick (the suggested ones and the user's own), a run of all
/// of them on the current recording off the GUI thread, a table of their figures with the best
/// value per column marked, and their heights over time. The paths go to the trajectory views as
/// overlays (MainWindow wires them). A changed recording clears the table; changed parameters
/// only mark it stale: a comparison reruns when asked, never on its own.
class ComparisonPanel : public QWidget {
    Q_OBJECT
public:
    explicit ComparisonPanel(QWidget* parent = nullptr);
    ~ComparisonPanel() override;

    void setRecording(std::shared_ptr<const Recording> recording);
    /// The workspace's parameters: the base every set is built on (detector, noises, thresholds).
    void setBaseParameters(const Parameters& params);
    /// Ticks exactly these sets ("zupt;zupt,zaru;feliz"), adding those not in the list; returns
    /// the parse error, empty on success (nothing changes then).
    QString setCheckedSets(const QString& specs);
    /// The ticked sets as a spec, in list order.
    QString checkedSets() const;
    /// Adds one set from the custom line's syntax ("zupt,hdr,mag"), ticked; returns the error.
    QString addCustomSet(const QString& spec);

    /// Runs the ticked sets now, or as soon as a recording arrives.
    void run();
    void cancel();
    bool isRunning() const;
    bool isStale() const { return stale_; }
    /// Drops the rows (and with them the overlays).
    void clearRows();

    const std::vector<ComparisonRow>& rows() const { return rows_; }
    std::vector<PathOverlay> overlays() const;
    QTableWidget* table() const { return table_; }
    QCustomPlot* heightPlot() const { return heightPlot_; }

signals:
    /// The rows (and so the overlays) changed: a run ended or the rows were cleared.
    void rowsChanged();
    /// A run ended (finished or cancelled) and its rows are shown.
    void finished();
    /// The user chose a set's parameters for the workspace (row clicked, or "Use as main result").
    void parametersChosen(const footpath::Parameters& params, const QString& setLabel);

private:
    QWidget* createSetColumn();
    QWidget* createResultArea();
    void addSetItem(const MethodSet& set, bool checked);
    void onRunFinished();
    void showRows();
    void fillTableRow(int r, const std::vector<ComparisonColumn>& columns);
    void plotHeights();
    void showBusy(bool busy);
    void updateStaleHint();
    void chooseRow(int row);

    QListWidget* setList_;
    QLineEdit* customEdit_;
    QLabel* customError_;
    QPushButton* runButton_;
    QPushButton* cancelButton_;
    QPushButton* useButton_;
    QProgressBar* busy_;
    QLabel* hint_;
    QTableWidget* table_;
    QCustomPlot* heightPlot_;

    std::shared_ptr<const Recording> recording_;
    Parameters base_;
    Parameters runBase_;  ///< the base of the rows shown
    std::vector<ComparisonRow> rows_;
    QFutureWatcher<std::vector<ComparisonRow>> watcher_;
    std::shared_ptr<std::atomic<bool>> cancelRun_;
    bool runWhenRecordingArrives_ = false;
    bool stale_ = false;
    bool dropRunningResult_ = false;  ///< the recording changed under the run
};

}  // namespace footpath
