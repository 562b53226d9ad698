// The window's menus and the dialogs they open (comparison, tuning, help); MainWindow.cpp builds
// and wires the window.
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

}  // namespace footpath
