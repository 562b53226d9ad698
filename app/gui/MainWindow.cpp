#include "MainWindow.h"

#include "AnalysisSession.h"
#include "AppSettings.h"
#include "ComparisonPanel.h"
#include "HelpDialog.h"
#include "ImportDialog.h"
#include "LivePanel.h"
#include "LiveViews.h"
#include "OtherFootSession.h"
#include "ParameterPanel.h"
#include "RecordedInputPanel.h"
#include "RecordingLoader.h"
#include "RunHistory.h"
#include "SignalPlots.h"
#include "StanceFlagsPlot.h"
#include "StatePlots.h"
#include "SummaryPanel.h"
#include "TrajectoryView2D.h"
#include "TrajectoryView3D.h"
#include "TuneDialog.h"
#include "TuneFolderDialog.h"
#include "ReportWriter.h"
#include "io/FootPairing.h"
#include "io/NearestNames.h"
#include "io/ResultWriters.h"
#include "methods/MethodRegistry.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScreen>
#include <QSplitter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>
#include <qcustomplot.h>

#include <algorithm>
#include <iterator>

namespace footpath {

namespace {

QDockWidget* dock(QMainWindow* window, const QString& title, const QString& name, QWidget* content,
                  Qt::DockWidgetArea area)
{
    auto* widget = new QDockWidget(title, window);
    widget->setObjectName(name);  // saveState() needs stable names
    widget->setWidget(content);
    window->addDockWidget(area, widget);
    return widget;
}

}  // namespace

MainWindow::MainWindow(AppSettings& settings, QWidget* parent)
    : QMainWindow(parent), settings_(settings), session_(new AnalysisSession(this)), loader_(new RecordingLoader(this)),
      otherFoot_(new OtherFootSession(*session_, this))
{
    setWindowTitle(tr("Footpath"));
    setAcceptDrops(true);
    createViews();
    createDocks();
    createMenus();
    createComparison();
    wireSession();
    wireViews();
    wireOtherFoot();
    status_ = new QLabel(tr("Ready"), this);
    status_->setObjectName(QStringLiteral("status"));
    // A long message is cut at the window's edge rather than widening the window; the tool tip has all.
    status_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    statusBar()->addWidget(status_, 1);
    workspaceStatus_ = status_->text();
    // The status bar speaks of what is in front, as the summary does: the live session's figures
    // while its views are shown.
    connect(live_, &LivePanel::liveStatusChanged, this, &MainWindow::showLiveStatus);
    input_->setRecentFiles(settings_.recentFiles());
    parameters_->setParameters(session_->parameters());
    live_->setParameters(session_->parameters());
    restoreLayout();
}

MainWindow::~MainWindow()
{
    // The docks hide and the live panel reports as the children go: neither must reach this
    // window's members (the tab labels, the status line) once they are torn down.
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        disconnect(dock, nullptr, this, nullptr);
    disconnect(live_, nullptr, this, nullptr);
}

void MainWindow::createViews()
{
    signalPlots_ = new SignalPlots(this);
    flags_ = new StanceFlagsPlot(this);
    statePlots_ = new StatePlots(this);
    trajectory2D_ = new TrajectoryView2D(this);
    trajectory3D_ = new TrajectoryView3D(this);
    // Named, as the live panel's views of the same types share the tab widgets.
    signalPlots_->setObjectName(QStringLiteral("signalPlots"));
    flags_->setObjectName(QStringLiteral("stanceFlags"));
    statePlots_->setObjectName(QStringLiteral("statePlots"));
    trajectory2D_->setObjectName(QStringLiteral("trajectory2D"));
    trajectory3D_->setObjectName(QStringLiteral("trajectory3D"));
    // Short names while the live views' tabs are beside these (a 1280-pixel screen has no room for
    // both sets in full); the tool tip names each view in full.
    recordedTabLabels_ = {
        {signalPlots_, tr("Signals"), tr("IMU"), tr("Signals: the recorded walk's sensor signals")},
        {flags_, tr("Stance detector"), tr("Stance"), tr("Stance detector: the recorded walk's statistics, thresholds, lanes")},
        {statePlots_, tr("States"), tr("States"), tr("States: the recorded walk's attitude, velocity, biases")},
        {trajectory2D_, tr("Trajectory 2D"), tr("2D"), tr("Trajectory 2D: the recorded walk's path seen from above")},
        {trajectory3D_, tr("Trajectory 3D"), tr("3D"), tr("Trajectory 3D: the recorded walk's path in three dimensions")},
    };
    signalTabs_ = new QTabWidget(this);
    trajectoryTabs_ = new QTabWidget(this);
    for (const TabLabel& label : recordedTabLabels_) {
        QTabWidget* tabs = label.view == trajectory2D_ || label.view == trajectory3D_ ? trajectoryTabs_ : signalTabs_;
        tabs->setTabToolTip(tabs->addTab(label.view, label.full), label.toolTip);
    }
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->setObjectName(QStringLiteral("viewsSplitter"));
    splitter->addWidget(trajectoryTabs_);
    splitter->addWidget(signalTabs_);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({600, 600});  // the path deserves as much room as the signals
    setCentralWidget(splitter);
}

void MainWindow::createDocks()
{
    input_ = new RecordedInputPanel(this);
    parameters_ = new ParameterPanel(this);
    summary_ = new SummaryPanel(this);
    live_ = new LivePanel(this);
    live_->moveViewsInto(trajectoryTabs_, signalTabs_);
    live_->linkSummary(summary_);  // the live session's figures while its views are in front
    connect(live_, &LivePanel::sessionStarted, this, [this] {
        showLiveTabs(true);
        trajectoryTabs_->setCurrentWidget(live_->views()->trajectory2D());
        signalTabs_->setCurrentWidget(live_->views()->signalPlots());
    });
    connect(live_, &LivePanel::recordingFinished, this, [this](const QString& path) {
        trajectoryTabs_->setCurrentWidget(trajectory2D_);  // the recorded walk's full analysis
        signalTabs_->setCurrentWidget(signalPlots_);
        openRecording(path);
    });
    QDockWidget* inputDock = dock(this, tr("Recorded input"), "inputDock", input_, Qt::LeftDockWidgetArea);
    QDockWidget* liveDock = dock(this, tr("Live input"), "liveDock", live_, Qt::LeftDockWidgetArea);
    tabifyDockWidget(inputDock, liveDock);
    inputDock->raise();
    // The live tabs while the live input is in front or holds samples: a 1280-pixel screen has
    // room for the tabs of the recorded walk's views, not for both sets beside each other.
    connect(liveDock, &QDockWidget::visibilityChanged, this, &MainWindow::showLiveTabs);
    showLiveTabs(false);
    dock(this, tr("Parameters"), "parametersDock", parameters_, Qt::RightDockWidgetArea);
    QDockWidget* summaryDock = dock(this, tr("Summary"), "summaryDock", summary_, Qt::BottomDockWidgetArea);
    history_ = new RunHistory(this);
    historyPanel_ = new RunHistoryPanel(history_, this);
    tabifyDockWidget(summaryDock, dock(this, tr("History"), "historyDock", historyPanel_, Qt::BottomDockWidgetArea));
    summaryDock->raise();
}

void MainWindow::createComparison()
{
    comparison_ = new ComparisonPanel(this);
    comparison_->setObjectName(QStringLiteral("comparisonPanel"));
    comparison_->setBaseParameters(session_->parameters());
    comparisonDock_ = dock(this, tr("Method comparison"), QStringLiteral("comparisonDock"), comparison_,
                           Qt::BottomDockWidgetArea);
    if (auto* summaryDock = findChild<QDockWidget*>(QStringLiteral("summaryDock")))
        tabifyDockWidget(summaryDock, comparisonDock_);
    comparisonDock_->hide();
    auto* compare = new QAction(tr("&Compare methods"), this);
    compare->setObjectName(QStringLiteral("compareMethods"));
    compare->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
    compare->setToolTip(tr("Run several method sets on this recording and compare their paths and figures"));
    connect(compare, &QAction::triggered, this, [this] { showComparison(); });
    addComparisonMenu(compare);
    // In reach next to the path it changes, without a toolbar taking height from the views.
    auto* button = new QToolButton(trajectoryTabs_);
    button->setObjectName(QStringLiteral("compareButton"));
    button->setText(tr("Compare"));  // short: the tab bar beside it needs the width
    button->setToolTip(compare->toolTip());
    button->setAutoRaise(true);
    connect(button, &QToolButton::clicked, compare, &QAction::trigger);
    trajectoryTabs_->setCornerWidget(button, Qt::TopRightCorner);

    connect(session_, &AnalysisSession::recordingChanged, this,
            [this] { comparison_->setRecording(session_->recording()); });
    connect(session_, &AnalysisSession::parametersChanged, this,
            [this] { comparison_->setBaseParameters(session_->parameters()); });
    connect(comparison_, &ComparisonPanel::rowsChanged, this,
            [this] { showOverlays(); });
    connect(comparison_, &ComparisonPanel::parametersChosen, this, [this](const Parameters& params, const QString& label) {
        session_->setParameters(params, tr("Methods of the set %1").arg(label));
    });
    connect(comparisonDock_->toggleViewAction(), &QAction::toggled, this, [this] { showOverlays(); });
}

void MainWindow::showLiveTabs(bool liveInputInFront)
{
    const bool shown = liveInputInFront || live_->sampleCount() > 0;
    const QWidget* liveViews[] = {live_->views()->trajectory2D(), live_->views()->trajectory3D(),
                                  live_->views()->signalPlots(), live_->views()->stanceFlags()};
    for (QTabWidget* tabs : {trajectoryTabs_, signalTabs_})
        for (int i = 0; i < tabs->count(); ++i) {
            const QWidget* page = tabs->widget(i);
            const bool live = std::any_of(std::begin(liveViews), std::end(liveViews),
                                          [page](const QWidget* view) { return page == view || page->isAncestorOf(view); });
            if (live)
                tabs->setTabVisible(i, shown);
            for (const TabLabel& label : recordedTabLabels_)
                if (label.view == page)
                    tabs->setTabText(i, shown ? label.compact : label.full);
        }
}

void MainWindow::connectLive(const QString& port)
{
    if (auto* liveDock = findChild<QDockWidget*>(QStringLiteral("liveDock")))
        liveDock->raise();
    live_->connectTo(port);
}

void MainWindow::wireSession()
{
    connect(loader_, &RecordingLoader::progress, input_, &RecordedInputPanel::setProgress);
    connect(loader_, &RecordingLoader::loaded, this, &MainWindow::onLoaded);
    connect(loader_, &RecordingLoader::failed, this, &MainWindow::onLoadFailed);
    connect(loader_, &RecordingLoader::cancelled, this, [this] { input_->showProblem(tr("Loading cancelled.")); });
    connect(input_, &RecordedInputPanel::openRequested, this, &MainWindow::chooseRecording);
    connect(input_, &RecordedInputPanel::recentFileChosen, this, [this](const QString& path) { openRecording(path); });
    connect(input_, &RecordedInputPanel::cancelRequested, loader_, &RecordingLoader::cancel);
    connect(session_, &AnalysisSession::resultChanged, this, &MainWindow::showResult);
    connect(session_, &AnalysisSession::estimatingChanged, this, &MainWindow::showEstimating);
    connect(session_, &AnalysisSession::estimateFailed, this,
            [this](const QString& message) { showWalkStatus(tr("Estimate failed: %1").arg(message), true); });
    connect(session_, &AnalysisSession::parametersChanged, this, [this] {
        parameters_->setParameters(session_->parameters());
        live_->setParameters(session_->parameters());  // tuning works on the live estimate too
    });
    connect(parameters_, &ParameterPanel::parameterEdited, session_, &AnalysisSession::setParameter);
    // Runs of another recording are not comparable: the history and the ghost start afresh.
    connect(session_, &AnalysisSession::recordingChanged, this, [this] {
        for (SessionView* view : sessionViews())
            view->showRecording(*session_);
    });
    connect(session_, &AnalysisSession::recordingChanged, history_, &RunHistory::clear);
    connect(history_, &RunHistory::currentChanged, this, &MainWindow::showGhost);
    connect(historyPanel_, &RunHistoryPanel::runChosen, this, [this](const Parameters& params, int number) {
        session_->setParameters(params, tr("Back to run %1").arg(number));  // undoable like any change
    });
    connect(parameters_, &ParameterPanel::parametersReplaced, session_, &AnalysisSession::setParameters);
    parameters_->setUndoStack(session_->undoStack());
}

void MainWindow::wireViews()
{
    // One time cursor for every view: a click anywhere moves it everywhere.
    connect(signalPlots_, &SignalPlots::timeCursorMoved, session_, &AnalysisSession::setTimeCursor);
    connect(flags_, &StanceFlagsPlot::timeCursorMoved, session_, &AnalysisSession::setTimeCursor);
    connect(statePlots_, &StatePlots::timeCursorMoved, session_, &AnalysisSession::setTimeCursor);
    connect(trajectory2D_, &TrajectoryView2D::timeCursorMoved, session_, &AnalysisSession::setTimeCursor);
    connect(summary_, &SummaryPanel::timeCursorRequested, this, &MainWindow::showMoment);
    connect(session_, &AnalysisSession::timeCursorChanged, this, [this](double t) {
        for (SessionView* view : sessionViews())
            view->showTimeCursor(t);
    });
    // The signal and detector plots share their time axis.
    connect(signalPlots_, &SignalPlots::timeRangeChanged, flags_, &StanceFlagsPlot::setTimeRange);
    connect(flags_, &StanceFlagsPlot::timeRangeChanged, signalPlots_, &SignalPlots::setTimeRange);
    connect(signalPlots_, &SignalPlots::timeRangeChanged, statePlots_, &StatePlots::setTimeRange);
    connect(statePlots_, &StatePlots::timeRangeChanged, signalPlots_, &SignalPlots::setTimeRange);
}

std::vector<PathOverlay> MainWindow::otherFootOverlays() const
{
    if (otherFoot_->alignedPath().empty())
        return {};
    return {PathOverlay{tr("Right foot"), otherFootColour(), otherFoot_->alignedPath()}};
}

void MainWindow::showOverlays()
{
    std::vector<PathOverlay> overlays = otherFootOverlays();
    if (comparisonDock_ && !comparisonDock_->isHidden())
        for (PathOverlay& overlay : comparison_->overlays())
            overlays.push_back(std::move(overlay));
    trajectory2D_->setOverlays(overlays);
    trajectory3D_->setOverlays(overlays);
    const QString label = otherFoot_->isActive() ? tr("Left foot") : QString();
    trajectory2D_->setPathLabel(label);
    trajectory3D_->setPathLabel(label);
}

void MainWindow::wireOtherFoot()
{
    connect(otherFoot_, &OtherFootSession::changed, this, [this] {
        showOverlays();
        summary_->setBothFeet(otherFoot_->bothFeet());
    });
    connect(otherFoot_, &OtherFootSession::failed, this, [this](const QString& message) { showStatus(message, true); });
    connect(otherFoot_, &OtherFootSession::readDone, this, [this](const QString& path) {
        if (otherFoot_->read())
            input_->showOtherFoot(path, *otherFoot_->read());
    });
}

std::vector<SessionView*> MainWindow::sessionViews() const
{
    return {signalPlots_, flags_, statePlots_, summary_, trajectory2D_, trajectory3D_};
}

void MainWindow::showResult()
{
    for (SessionView* view : sessionViews())
        view->showEstimate(*session_);
    const std::shared_ptr<const Result> result = session_->result();
    if (!result) {
        ghost_.reset();  // the 3D view dropped its ghost: the next one is handed over again
        return;
    }
    recordRun(result, *session_->evaluation());
    showResultStatus(*result);
    emit resultShown();
}

void MainWindow::recordRun(const std::shared_ptr<const Result>& result, const ResultEvaluation& evaluation)
{
    // The undo step that made this result: the results of one dragged slider update one run.
    const QUndoStack* stack = session_->undoStack();
    const int index = stack->index();
    const void* gesture = index > 0 ? stack->command(index - 1) : nullptr;
    history_->record(result, session_->resultParameters(), runFigures(*result, evaluation), gesture, index);
}

void MainWindow::showGhost()
{
    const Run* before = history_->previous();
    const Run* now = history_->current();
    // While a slider is dragged the run before the drag stays the ghost: its path is not handed
    // over again on every re-estimate.
    const std::shared_ptr<const Result> ghost = before && now ? before->result : nullptr;
    if (ghost != ghost_) {
        ghost_ = ghost;
        const std::vector<Eigen::Vector3d> none;
        trajectory2D_->setGhostPath(ghost ? ghost->position_m : none);
        trajectory3D_->setGhostPath(ghost ? ghost->position_m : none);
    }
    if (before && now)
        summary_->showChange(&before->figures, now->figures, history_->latestChange());
    else
        summary_->showChange(nullptr, RunFigures(), QString());
}

void MainWindow::showResultStatus(const Result& result)
{
    if (!result.warnings.empty()) {
        const auto count = static_cast<int>(result.warnings.size());
        showWalkStatus(tr("%n plausibility warning(s): %1", nullptr, count)
                           .arg(QString::fromStdString(result.warnings.front().message)),
                       true);
        return;
    }
    const Summary& s = result.summary;
    showWalkStatus(tr("%1 samples, %2 steps, path %3 m, end to start %4 m (%5 %), estimated in %6 ms")
                       .arg(s.samples)
                       .arg(s.steps)
                       .arg(s.pathLength_m, 0, 'f', 2)
                       .arg(s.endToStart_m, 0, 'f', 2)
                       .arg(s.endToStartPct, 0, 'f', 2)
                       .arg(s.runtime_s * 1000.0, 0, 'f', 0));
}

void MainWindow::showStatus(const QString& text, bool warning)
{
    workspaceStatus_ = text;
    workspaceStatusWarns_ = warning;
    displayStatus(text, warning);
}

void MainWindow::showWalkStatus(const QString& text, bool warning)
{
    workspaceStatus_ = text;
    workspaceStatusWarns_ = warning;
    if (liveStatus_.isEmpty())
        displayStatus(text, warning);
}

void MainWindow::showLiveStatus(const QString& line)
{
    // The live panel reports at every view refresh, an empty line while its views are not in front:
    // the walk's line is already shown then, and setting it again repolishes its style 5 times a second.
    if (line.isEmpty() && liveStatus_.isEmpty())
        return;
    liveStatus_ = line;
    if (line.isEmpty())
        displayStatus(workspaceStatus_, workspaceStatusWarns_);
    else
        displayStatus(line, false);
}

void MainWindow::displayStatus(const QString& text, bool warning)
{
    status_->setText(text);
    status_->setToolTip(text);
    status_->setStyleSheet(warning ? QStringLiteral("color: #b00020; font-weight: bold;") : QString());
}

void MainWindow::showMoment(double time_s)
{
    session_->setTimeCursor(time_s);
    const QCPRange shown = flags_->timeRange();
    if (shown.contains(time_s) || shown.size() <= 0.0)
        return;
    // Keep the zoom; put the moment a tenth in from the left, where what follows it is in view.
    const double from = time_s - 0.1 * shown.size();
    flags_->setTimeRange(from, from + shown.size());  // the signal plots follow through the link
}

void MainWindow::showEstimating(bool running)
{
    if (running)
        showWalkStatus(tr("Estimating..."));
}

void MainWindow::placeOnScreen(const QRect& available)
{
    setWindowState(windowState() & ~Qt::WindowMaximized);
    // Once shown the frame is known and goes inside the area too (before, there is none yet).
    const QRect frame = frameGeometry(), client = geometry();
    const QMargins margins(client.left() - frame.left(), client.top() - frame.top(), frame.right() - client.right(),
                           frame.bottom() - client.bottom());
    setGeometry(available.marginsRemoved(margins));
}

void MainWindow::restoreLayout()
{
    // A geometry saved on a larger screen, or on one no longer attached, would hang off the screen.
    const bool restored = restoreGeometry(settings_.windowGeometry());
    const QScreen* restoredOn = restored ? QGuiApplication::screenAt(frameGeometry().center()) : nullptr;
    if (!restoredOn || !restoredOn->availableGeometry().contains(frameGeometry())) {
        const QScreen* target = screen() ? screen() : QGuiApplication::primaryScreen();
        placeOnScreen(target ? target->availableGeometry() : QRect(0, 0, 1280, 800));
        // The frame is not known before the window is shown: a window manager that maximizes fits
        // it, with its title bar, into the available area (and restores to the same area).
        setWindowState(windowState() | Qt::WindowMaximized);
    }
    if (restoreState(settings_.windowState()))
        return;
    // First start: the plots and the path get two thirds of the height and more, the summary and
    // the history under a third (the plots keep the height their rows need to stay readable).
    // Once shown, as docks are sized when the window is laid out; the user's sizes are saved with
    // the dock state.
    QTimer::singleShot(0, this, [this] {
        if (auto* summaryDock = findChild<QDockWidget*>(QStringLiteral("summaryDock"))) {
            summaryDock->raise();  // in front of the history and the comparison it shares the area with
            resizeDocks({summaryDock}, {height() * 30 / 100}, Qt::Vertical);  // with its tabs under a third
        }
        // The side panels as narrow as they stay readable, so a 1280-pixel screen leaves the path
        // and the signals more than a third of its width each.
        auto* inputDock = findChild<QDockWidget*>(QStringLiteral("inputDock"));
        auto* parametersDock = findChild<QDockWidget*>(QStringLiteral("parametersDock"));
        if (inputDock && parametersDock)
            resizeDocks({inputDock, parametersDock}, {std::max(200, width() / 7), width() / 6}, Qt::Horizontal);
    });
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!live_->mayEndSession(LivePanel::SessionEnding::Quit)) {
        event->ignore();  // the user keeps the window to save the samples another way
        return;
    }
    settings_.setWindowGeometry(saveGeometry());
    settings_.setWindowState(saveState());
    QMainWindow::closeEvent(event);
}

}  // namespace footpath
