// The window's files: opening recordings (one or both feet, dropped, recent), exporting CSV and the PDF report.
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

}  // namespace

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
