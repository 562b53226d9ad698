#pragma once

#include "PathOverlay.h"
#include "ReportWriter.h"
#include "io/Import.h"

#include <QMainWindow>

#include <memory>
#include <vector>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QTabWidget;

namespace footpath {

class AnalysisSession;
class AppSettings;
class ComparisonPanel;
class LivePanel;
class OtherFootSession;
class ParameterPanel;
class RecordedInputPanel;
class RecordingLoader;
class RunHistory;
class RunHistoryPanel;
class SessionView;
class SignalPlots;
class StanceFlagsPlot;
class StatePlots;
class SummaryPanel;
class TrajectoryView2D;
class TrajectoryView3D;
class TuneDialog;
class TuneFolderDialog;

/// Assembles the panels, docks and menus and wires them to the session; holds no algorithm.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(AppSettings& settings, QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Starts loading a recording (a file path or a ":/" resource) in the background.
    /// Raises the Live input dock and connects it to `port` (a device or the emulator's link).
    void connectLive(const QString& port);
    void openRecording(const QString& path, const ImportOptions& options = {});
    /// The left and the right foot of one walk: the left in the session, the right beside it; both
    /// paths drawn, double support and symmetry in the summary and the report.
    void openFootPair(const QString& left, const QString& right, const QStringList& notes = {});
    /// What the user chose or dropped: one file opens as before; two files (or a folder holding one
    /// left/right pair) open as both feet. Returns the problem shown in the status bar, or empty.
    QString openRecordings(const QStringList& paths);
    OtherFootSession* otherFoot() const { return otherFoot_; }
    AnalysisSession* session() const { return session_; }
    /// Brings a view to the front: "signals", "detector", "states", "trajectory2d" or "trajectory3d";
    /// "motion" shows the detector (with the motion lane) and colours the paths by motion class;
    /// "summary", "steps" and "gait" raise the summary with its figures, step table or gait charts.
    /// Returns an error naming the views (and the nearest one) for any other name, else empty.
    QString showView(const QString& name);
    static const QStringList& viewNames();
    /// Colours the 2D and 3D paths: "none", "time", "speed" or "motion" (the 3D view knows motion only).
    void setPathColouring(const QString& name);
    /// Opens the method comparison; given sets ("zupt;zupt,zaru;feliz") are ticked and run (once a
    /// recording is there). Returns the sets' parse error, empty on success.
    QString showComparison(const QString& sets = QString());
    ComparisonPanel* comparisonPanel() const { return comparison_; }
    /// Writes the CSV files into folder: trajectory, steps and summary of each open foot (named
    /// after its recording) and the parameters. An error message, or empty.
    QString exportCsvInto(const QString& folder) const;
    /// Writes the PDF report (with the comparison while its panel is open); an error message or empty.
    QString writeReport(const QString& path, QPageSize::PageSizeId pageSize = QPageSize::A4) const;
    /// Fills the available area of a screen; the constructor calls it (and maximizes) with the
    /// window's screen when no saved geometry fits there.
    void placeOnScreen(const QRect& available);
    RunHistory* runHistory() const { return history_; }
    /// Help > User guide (false) or Keyboard shortcuts (true), not modal.
    void showHelp(bool shortcuts);
    /// Analysis > Tune for this recording / Tune over a folder: the dialog, opened (window-modal,
    /// deleted on close); null when there is no recording to tune.
    TuneDialog* tuneForRecording();
    TuneFolderDialog* tuneOverFolder();

signals:
    /// A result is on screen (after each estimate); screenshots and tests wait for it.
    void resultShown();

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createViews();
    void createDocks();
    /// Shows the live views' tabs while the live input dock is in front or a session has samples.
    void showLiveTabs(bool liveInputInFront);
    void createMenus();
    void createFileMenu();
    void createEditMenu();
    void createViewMenu();
    void addPathColouringMenu();
    void createSettingsMenu();
    void createHelpMenu();
    /// Adds the result on screen to the history and shows the run before the last change as the
    /// ghost path and the summary's before -> after.
    /// The views that follow the session: each gets every estimate and time cursor alike.
    std::vector<SessionView*> sessionViews() const;
    void recordRun(const std::shared_ptr<const Result>& result, const ResultEvaluation& evaluation);
    void showGhost();
    void wireSession();
    void wireViews();
    void chooseRecording();
    void exportReport();
    void exportCsv();
    ReportContent reportContent() const;
    void onLoaded(const QString& path, const std::shared_ptr<const ImportResult>& result);
    void onLoadFailed(const QString& path, const QString& message, const ImportOptions& options);
    void showResult();
    void showResultStatus(const Result& result);
    /// Sets the status bar text; a warning stands out in colour.
    /// The answer to something the user did: shown at once, and kept as the workspace's line.
    void showStatus(const QString& text, bool warning = false);
    /// The recorded walk's line: kept, and shown unless the live views are in front.
    void showWalkStatus(const QString& text, bool warning = false);
    /// The live session's line while its views are in front; empty gives the bar back to the walk.
    void showLiveStatus(const QString& line);
    void displayStatus(const QString& text, bool warning);
    /// Moves the time cursor to time_s and brings it into view in the time plots.
    void showMoment(double time_s);
    void showEstimating(bool running);
    void chooseLanguage(const QString& language);
    void restoreLayout();
    void createComparison();
    void addComparisonMenu(QAction* compare);
    /// The comparison's paths (while its panel is open) and the right foot's (while both feet are
    /// open) in the trajectory views; the main path named after its foot when both are.
    void showOverlays();
    std::vector<PathOverlay> otherFootOverlays() const;
    void startLoading(const QString& path, const ImportOptions& options);
    void wireOtherFoot();

    AppSettings& settings_;
    AnalysisSession* session_;
    RecordingLoader* loader_;
    RecordedInputPanel* input_ = nullptr;
    ParameterPanel* parameters_ = nullptr;
    SummaryPanel* summary_ = nullptr;
    SignalPlots* signalPlots_ = nullptr;
    StanceFlagsPlot* flags_ = nullptr;
    StatePlots* statePlots_ = nullptr;
    TrajectoryView2D* trajectory2D_ = nullptr;
    TrajectoryView3D* trajectory3D_ = nullptr;
    QTabWidget* signalTabs_ = nullptr;
    QTabWidget* trajectoryTabs_ = nullptr;
    /// A recorded walk's view's tab: its label alone, and beside the live views' tabs.
    struct TabLabel {
        QWidget* view;
        QString full;
        QString compact;
        QString toolTip;
    };
    std::vector<TabLabel> recordedTabLabels_;
    LivePanel* live_ = nullptr;
    QLabel* status_ = nullptr;
    QString workspaceStatus_;         ///< the recorded walk's (or the last action's) line
    bool workspaceStatusWarns_ = false;
    QString liveStatus_;              ///< the live session's, while its views are in front
    QMenu* viewMenu_ = nullptr;
    ComparisonPanel* comparison_ = nullptr;
    QDockWidget* comparisonDock_ = nullptr;
    RunHistory* history_ = nullptr;
    RunHistoryPanel* historyPanel_ = nullptr;
    OtherFootSession* otherFoot_ = nullptr;
    std::shared_ptr<const Result> ghost_;  ///< whose path the trajectory views show as the ghost
};

}  // namespace footpath
