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

/// Importers read files, not Qt resources: an embedded sample is copied to the cache once.
QString fileForResource(const QString& path)
{
    if (!path.startsWith(QStringLiteral(":/")))
        return path;
    const QString cache = QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + "/samples";
    QDir().mkpath(cache);
    const QString copy = cache + "/" + QFileInfo(path).fileName();
    if (!QFileInfo::exists(copy))
        QFile::copy(path, copy);
    return copy;
}

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

void MainWindow::createMenus()
{
    createFileMenu();
    createEditMenu();
    createViewMenu();
    createSettingsMenu();
    createHelpMenu();
}

void MainWindow::createHelpMenu()
{
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->setObjectName(QStringLiteral("helpMenu"));
    QAction* guide = help->addAction(tr("&User guide"), QKeySequence::HelpContents, this, [this] { showHelp(false); });
    guide->setObjectName(QStringLiteral("userGuide"));
    QAction* keys = help->addAction(tr("&Keyboard shortcuts"), this, [this] { showHelp(true); });
    keys->setObjectName(QStringLiteral("keyboardShortcuts"));
    help->addSeparator();
    help->addAction(tr("&About Footpath"), this, [this] {
        QMessageBox::about(this, tr("About Footpath"),
                           tr("<b>Footpath %1</b><p>Foot-mounted inertial navigation: stance detection, "
                              "strapdown mechanization and an error-state Kalman filter with zero-velocity "
                              "updates (Guo et al. 2015).</p><p>Sample walk: PyShoe VICON dataset, MIT licence, "
                              "Copyright (c) 2024 T\u0101-H\u0101.</p>")
                               .arg(QApplication::applicationVersion()));
    });
}

void MainWindow::showHelp(bool shortcuts)
{
    // One dialog, kept: the guide is read beside the window, not in a modal box in front of it.
    auto* dialog = findChild<HelpDialog*>();
    if (!dialog) {
        dialog = new HelpDialog(menuBar()->actions(), HelpDialog::Page::Guide, this);
        dialog->setObjectName(QStringLiteral("helpDialog"));
    }
    dialog->showPage(shortcuts ? HelpDialog::Page::Shortcuts : HelpDialog::Page::Guide);
    dialog->show();
    dialog->raise();
}

void MainWindow::createFileMenu()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open recording..."), QKeySequence::Open, this, &MainWindow::chooseRecording);
    file->addAction(tr("Open with &import settings..."), this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Open recording"), settings_.lastFolder());
        if (path.isEmpty())
            return;
        ImportDialog dialog(path, tr("Say how to read this file."), ImportOptions(), this);
        if (dialog.exec() == QDialog::Accepted)
            openRecording(path, dialog.options());
    });
    file->addSeparator();
    file->addAction(tr("Export &report (PDF)..."), QKeySequence(Qt::CTRL | Qt::Key_P), this, &MainWindow::exportReport);
    file->addAction(tr("Export &CSV..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E), this, &MainWindow::exportCsv);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
}

void MainWindow::createEditMenu()
{
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = session_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setProperty("helpText", tr("Undo the last change"));  // the action's own text names the change
    QAction* redo = session_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    redo->setProperty("helpText", tr("Redo"));
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    edit->addAction(tr("Reset parameters to &defaults"), this,
                    [this] { session_->setParameters(Parameters(), tr("Reset to defaults")); });
}

void MainWindow::createViewMenu()
{
    viewMenu_ = menuBar()->addMenu(tr("&View"));
    viewMenu_->setObjectName(QStringLiteral("viewMenu"));
    viewMenu_->addAction(tr("&Trajectory 2D"), QKeySequence(Qt::CTRL | Qt::Key_1), this,
                         [this] { trajectoryTabs_->setCurrentWidget(trajectory2D_); });
    viewMenu_->addAction(tr("Trajectory &3D"), QKeySequence(Qt::CTRL | Qt::Key_2), this,
                         [this] { trajectoryTabs_->setCurrentWidget(trajectory3D_); });
    viewMenu_->addAction(tr("&Signals"), QKeySequence(Qt::CTRL | Qt::Key_3), this,
                         [this] { signalTabs_->setCurrentWidget(signalPlots_); });
    viewMenu_->addAction(tr("Stance &detector"), QKeySequence(Qt::CTRL | Qt::Key_4), this,
                         [this] { signalTabs_->setCurrentWidget(flags_); });
    // Numbered in the menu's order: the recorded walk's views, then the live ones.
    viewMenu_->addAction(tr("S&tates"), QKeySequence(Qt::CTRL | Qt::Key_5), this,
                         [this] { signalTabs_->setCurrentWidget(statePlots_); });
    viewMenu_->addAction(tr("&Live path"), QKeySequence(Qt::CTRL | Qt::Key_6), this,
                         [this] { trajectoryTabs_->setCurrentWidget(live_->views()->trajectory2D()); });
    viewMenu_->addAction(tr("Live si&gnals"), QKeySequence(Qt::CTRL | Qt::Key_7), this,
                         [this] { signalTabs_->setCurrentWidget(live_->views()->signalPlots()); });
    addPathColouringMenu();
    viewMenu_->addSeparator();
    for (QDockWidget* widget : findChildren<QDockWidget*>())
        viewMenu_->addAction(widget->toggleViewAction());
}

const QStringList& MainWindow::viewNames()
{
    static const QStringList names{"signals", "detector", "states", "trajectory2d", "trajectory3d",
                                   "motion",  "summary",  "steps",  "gait"};
    return names;
}

QString MainWindow::showView(const QString& name)
{
    if (name == QLatin1String("signals"))
        signalTabs_->setCurrentWidget(signalPlots_);
    else if (name == QLatin1String("detector"))
        signalTabs_->setCurrentWidget(flags_);
    else if (name == QLatin1String("states"))
        signalTabs_->setCurrentWidget(statePlots_);
    else if (name == QLatin1String("trajectory2d"))
        trajectoryTabs_->setCurrentWidget(trajectory2D_);
    else if (name == QLatin1String("trajectory3d"))
        trajectoryTabs_->setCurrentWidget(trajectory3D_);
    else if (name == QLatin1String("motion")) {
        signalTabs_->setCurrentWidget(flags_);
        trajectoryTabs_->setCurrentWidget(trajectory2D_);
        setPathColouring(name);
    } else if (name == QLatin1String("summary") || summary_->showTab(name)) {
        if (auto* summaryDock = findChild<QDockWidget*>(QStringLiteral("summaryDock")))
            summaryDock->raise();
    } else {
        std::vector<std::string> candidates;
        for (const QString& view : viewNames())
            candidates.push_back(view.toStdString());
        return tr("unknown view '%1'%2; the views are %3")
            .arg(name, QString::fromStdString(didYouMean(name.toStdString(), candidates)), viewNames().join(QStringLiteral(", ")));
    }
    return {};
}

void MainWindow::addPathColouringMenu()
{
    QMenu* menu = viewMenu_->addMenu(tr("Path &colours"));
    menu->setObjectName(QStringLiteral("pathColouringMenu"));
    auto* group = new QActionGroup(menu);
    const QList<QPair<QString, QString>> choices{{"none", tr("One colour")},
                                                 {"time", tr("By time")},
                                                 {"speed", tr("By foot speed")},
                                                 {"motion", tr("By motion (stairs, elevator)")}};
    for (const auto& [name, label] : choices) {
        QAction* action = menu->addAction(label, this, [this, name = name] { setPathColouring(name); });
        action->setObjectName(QStringLiteral("pathColouring_") + name);
        action->setCheckable(true);
        action->setChecked(name == QLatin1String("none"));
        group->addAction(action);
    }
}

void MainWindow::setPathColouring(const QString& name)
{
    using Colouring = TrajectoryView2D::Colouring;
    const Colouring colouring = name == QLatin1String("time")    ? Colouring::Time
                                : name == QLatin1String("speed")  ? Colouring::Speed
                                : name == QLatin1String("motion") ? Colouring::Motion
                                                                  : Colouring::None;
    trajectory2D_->setColouring(colouring);
    trajectory3D_->setMotionColouring(colouring == Colouring::Motion);
    if (auto* action = findChild<QAction*>(QStringLiteral("pathColouring_") + name))
        action->setChecked(true);
}

void MainWindow::createSettingsMenu()
{
    QMenu* settings = menuBar()->addMenu(tr("&Settings"));
    QMenu* language = settings->addMenu(tr("&Language"));
    auto* group = new QActionGroup(this);
    const QList<QPair<QString, QString>> languages{
        {QString(), tr("System default")}, {"en", QStringLiteral("English")}, {"de", QStringLiteral("Deutsch")},
        {"zh_CN", QStringLiteral("\u7b80\u4f53\u4e2d\u6587")}};
    for (const auto& [code, name] : languages) {
        QAction* action = language->addAction(name, this, [this, code = code] { chooseLanguage(code); });
        action->setCheckable(true);
        action->setChecked(settings_.language() == code);
        group->addAction(action);
    }
}

void MainWindow::chooseLanguage(const QString& language)
{
    settings_.setLanguage(language);
    QMessageBox::information(this, tr("Language"), tr("The new language is used from the next start of Footpath."));
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
        trajectory3D_->setTimeCursor(t);
    });
    // The signal and detector plots share their time axis.
    connect(signalPlots_, &SignalPlots::timeRangeChanged, flags_, &StanceFlagsPlot::setTimeRange);
    connect(flags_, &StanceFlagsPlot::timeRangeChanged, signalPlots_, &SignalPlots::setTimeRange);
    connect(signalPlots_, &SignalPlots::timeRangeChanged, statePlots_, &StatePlots::setTimeRange);
    connect(statePlots_, &StatePlots::timeRangeChanged, signalPlots_, &SignalPlots::setTimeRange);
}

ReportContent MainWindow::reportContent() const
{
    ReportContent content;
    content.recordingPath = session_->recordingPath();
    content.info = session_->recordingInfo();
    content.recording = session_->recording();
    content.result = session_->result();
    content.evaluation = session_->evaluation();
    content.parameters = session_->parameters();
    content.parameterSource = content.parameters == Parameters() ? tr("defaults") : tr("adjusted in the window");
    if (comparisonDock_ && !comparisonDock_->isHidden()) {
        content.comparison = comparison_->rows();
        content.comparisonStale = comparison_->isStale();
    }
    if (otherFoot_->isActive()) {
        content.pathLabel = tr("Left foot");
        content.otherPaths = otherFootOverlays();
        content.bothFeet = otherFoot_->bothFeet();
        content.recordingPath += QStringLiteral(" + ") + QFileInfo(otherFoot_->path()).fileName();
    }
    return content;
}

void MainWindow::exportReport()
{
    if (!session_->result()) {
        QMessageBox::information(this, tr("Export report"), tr("There is no estimate to report yet."));
        return;
    }
    const QString suggested = QFileInfo(session_->recordingPath()).completeBaseName() + QStringLiteral("-report.pdf");
    const QString path = QFileDialog::getSaveFileName(this, tr("Export report"),
                                                      QDir(settings_.lastFolder()).filePath(suggested),
                                                      tr("PDF (*.pdf)"));
    if (path.isEmpty())
        return;
    const bool letter = QLocale().measurementSystem() == QLocale::ImperialUSSystem;
    if (const QString problem = writePdfReport(reportContent(), path, letter ? QPageSize::Letter : QPageSize::A4);
        !problem.isEmpty())
        QMessageBox::warning(this, tr("Export report"), problem);
    else
        showStatus(tr("Report written to %1").arg(path));
}

QString MainWindow::writeReport(const QString& path, QPageSize::PageSizeId pageSize) const
{
    return writePdfReport(reportContent(), path, pageSize);
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

void MainWindow::addComparisonMenu(QAction* compare)
{
    auto* analysis = new QMenu(tr("&Analysis"), this);
    analysis->addAction(compare);
    analysis->addSeparator();
    QAction* tune = analysis->addAction(tr("&Tune for this recording..."), this, [this] { tuneForRecording(); });
    tune->setObjectName(QStringLiteral("tuneRecording"));
    tune->setToolTip(tr("Search the detector settings and the filter noise that fit this recording best"));
    QAction* tuneFolder = analysis->addAction(tr("Tune over a &folder..."), this, [this] { tuneOverFolder(); });
    tuneFolder->setObjectName(QStringLiteral("tuneFolder"));
    tuneFolder->setToolTip(tr("One parameter set for many recordings of a sensor and a way of walking"));
    // After View, before Settings and Help.
    const QList<QAction*> menus = menuBar()->actions();
    const qsizetype view = menus.indexOf(viewMenu_->menuAction());
    menuBar()->insertMenu(view >= 0 && view + 1 < menus.size() ? menus[view + 1] : nullptr, analysis);
    viewMenu_->addAction(comparisonDock_->toggleViewAction());
}

QString MainWindow::showComparison(const QString& sets)
{
    comparisonDock_->show();
    comparisonDock_->raise();
    if (sets.isEmpty())
        return {};
    if (const QString error = comparison_->setCheckedSets(sets); !error.isEmpty()) {
        showStatus(error, true);
        return error;
    }
    comparison_->run();
    return {};
}

TuneDialog* MainWindow::tuneForRecording()
{
    if (!session_->recording()) {
        QMessageBox::information(this, tr("Tune for this recording"), tr("Open a recording first."));
        return nullptr;
    }
    // Accepting applies the parameters through the session: one undo step, and the history's
    // ghost path shows the path before them.
    auto* dialog = new TuneDialog(*session_, this);
    dialog->setObjectName(QStringLiteral("tuneDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
}

TuneFolderDialog* MainWindow::tuneOverFolder()
{
    auto* dialog = new TuneFolderDialog(*session_, settings_.lastFolder(), this);
    dialog->setObjectName(QStringLiteral("tuneFolderDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
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

void MainWindow::exportCsv()
{
    if (!session_->result()) {
        QMessageBox::information(this, tr("Export CSV"), tr("There is no estimate to export yet."));
        return;
    }
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Export CSV into folder"), settings_.lastFolder());
    if (folder.isEmpty())
        return;
    if (const QString problem = exportCsvInto(folder); !problem.isEmpty()) {
        QMessageBox::warning(this, tr("Export CSV"), problem);
        return;
    }
    showStatus(otherFoot_->isActive() ? tr("Trajectory, steps and summary of both feet, and the parameters, written to %1").arg(folder)
                                      : tr("Trajectory, steps, summary and parameters written to %1").arg(folder));
}

QString MainWindow::exportCsvInto(const QString& folder) const
{
    const std::shared_ptr<const Result> result = session_->result();
    if (!result)
        return tr("There is no estimate to export yet.");
    const auto baseOf = [&folder](const QString& recording) {
        return QDir(folder).filePath(QFileInfo(recording).completeBaseName());
    };
    const Parameters params = session_->parameters();
    std::vector<std::pair<QString, std::function<void(std::ostream&)>>> files;
    // Both feet open: each foot's own files (named after its recording), the parameters once.
    std::vector<std::pair<QString, std::shared_ptr<const Result>>> feet{{baseOf(session_->recordingPath()), result}};
    if (otherFoot_->isActive() && otherFoot_->result())
        feet.emplace_back(baseOf(otherFoot_->path()), otherFoot_->result());
    for (const auto& [base, foot] : feet) {
        files.emplace_back(base + "-trajectory.csv", [foot = foot](std::ostream& out) { writeTrajectoryCsv(out, *foot); });
        files.emplace_back(base + "-steps.csv", [foot = foot](std::ostream& out) { writeStepsCsv(out, *foot); });
        files.emplace_back(base + "-summary.csv", [foot = foot](std::ostream& out) { writeSummaryCsv(out, *foot); });
    }
    files.emplace_back(feet.front().first + "-parameters.csv", [&params](std::ostream& out) { writeParametersCsv(out, params); });
    for (const auto& [path, write] : files)
        if (const std::string problem = writeFileAtomically(path.toStdString(), write); !problem.empty())
            return QString::fromStdString(problem);
    return {};
}

void MainWindow::chooseRecording()
{
    // Two files at once: the left and the right foot of one walk.
    const QStringList paths = QFileDialog::getOpenFileNames(
        this, tr("Open recording (two files: both feet)"), settings_.lastFolder(),
        tr("Recordings (%1);;All files (*)").arg(QString::fromStdString(importerFilePatterns())));
    if (!paths.isEmpty())
        openRecordings(paths);
}

QString MainWindow::openRecordings(const QStringList& paths)
{
    std::string problem;
    std::optional<FootPair> pair;
    if (paths.size() == 1 && QFileInfo(paths.first()).isDir()) {
        std::vector<std::string> files;
        for (const QFileInfo& file : QDir(paths.first()).entryInfoList(QDir::Files, QDir::Name))
            files.push_back(file.filePath().toStdString());
        pair = footPairInFolder(files, problem);
    } else if (paths.size() == 1) {
        openRecording(paths.first());
        return {};
    } else if (paths.size() == 2) {
        pair = pairFeet(paths[0].toStdString(), paths[1].toStdString(), problem);
    } else {
        problem = tr("%1 files: open one recording, or the left and the right file of one walk").arg(paths.size()).toStdString();
    }
    if (!pair) {
        const QString message = QString::fromStdString(problem);
        showStatus(message, true);
        return message;
    }
    QStringList notes;
    for (const std::string& note : pair->notes)
        notes << QString::fromStdString(note);
    openFootPair(QString::fromStdString(pair->left), QString::fromStdString(pair->right), notes);
    return {};
}

void MainWindow::openFootPair(const QString& left, const QString& right, const QStringList& notes)
{
    startLoading(left, ImportOptions());
    otherFoot_->load(right, notes);
    if (!notes.isEmpty())
        showStatus(notes.join(QStringLiteral("; ")));
}

void MainWindow::openRecording(const QString& path, const ImportOptions& options)
{
    otherFoot_->clear();  // one file: one foot
    startLoading(path, options);
}

void MainWindow::startLoading(const QString& path, const ImportOptions& options)
{
    const QString file = fileForResource(path);
    input_->showLoading(file);
    showWalkStatus(tr("Reading %1...").arg(QFileInfo(file).fileName()));
    loader_->load(file, options);
}

void MainWindow::onLoaded(const QString& path, const std::shared_ptr<const ImportResult>& result)
{
    input_->showInfo(path, *result);
    if (!path.startsWith(QStandardPaths::writableLocation(QStandardPaths::CacheLocation))) {
        settings_.addRecentFile(path);
        settings_.setLastFolder(QFileInfo(path).absolutePath());
        input_->setRecentFiles(settings_.recentFiles());
    }
    // Shares the read's ownership instead of copying it: a copy of a ten-hour recording is 315 MB
    // and a third of a second on the GUI thread.
    const std::shared_ptr<const Recording> recording(result, &result->recording);
    setWindowTitle(otherFoot_->isActive() ? tr("Footpath - %1 + %2")
                                                .arg(QFileInfo(path).fileName(), QFileInfo(otherFoot_->path()).fileName())
                                          : tr("Footpath - %1").arg(QFileInfo(path).fileName()));
    session_->setRecording(recording, result->info, path);
}

void MainWindow::onLoadFailed(const QString& path, const QString& message, const ImportOptions& options)
{
    otherFoot_->clear();  // no left foot: the right alone is no pair
    input_->showProblem(message);
    showStatus(message, true);
    // A file that does not describe itself gets the import dialog instead of a dead end.
    const bool needsColumnMap = message.contains(QStringLiteral("no header row"))
                                || message.contains(QStringLiteral("missing column"))
                                || message.contains(QStringLiteral("column map"));
    if (!needsColumnMap)
        return;
    ImportDialog dialog(path, message, options, this);
    if (dialog.exec() == QDialog::Accepted)
        openRecording(path, dialog.options());
}

std::vector<SessionView*> MainWindow::sessionViews() const
{
    return {signalPlots_, flags_, statePlots_, summary_, trajectory2D_};
}

void MainWindow::showResult()
{
    for (SessionView* view : sessionViews())
        view->showEstimate(*session_);
    const std::shared_ptr<const Result> result = session_->result();
    if (!result) {
        trajectory3D_->clear();
        ghost_.reset();  // the 3D view dropped its ghost: the next one is handed over again
        return;
    }
    trajectory3D_->setResult(result);
    trajectory3D_->setReference(session_->evaluation()->alignedReference);
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

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (event->mimeData()->hasUrls() && event->mimeData()->urls().first().isLocalFile())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    QStringList paths;
    for (const QUrl& url : event->mimeData()->urls())
        if (url.isLocalFile())
            paths << url.toLocalFile();
    openRecordings(paths);  // two files or a folder: both feet
    event->acceptProposedAction();
}

}  // namespace footpath
