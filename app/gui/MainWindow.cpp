#include "MainWindow.h"

#include "PipelineRunner.h"
#include "TrajectoryView2D.h"
#include "io/Import.h"

#include <QApplication>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

#include <sstream>

namespace footpath {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      trajectory_(new TrajectoryView2D(this)),
      summary_(new QLabel(this)),
      runner_(new PipelineRunner(this))
{
    setWindowTitle(tr("Footpath"));
    setCentralWidget(trajectory_);
    statusBar()->addWidget(summary_, 1);
    createMenus();
    connect(runner_, &PipelineRunner::finished, this, &MainWindow::showResult);
    connect(runner_, &PipelineRunner::failed, this, &MainWindow::showError);
    resize(1000, 720);
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open recording..."), QKeySequence::Open, this, &MainWindow::chooseRecording);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, qApp, &QApplication::quit);
}

void MainWindow::chooseRecording()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open recording"), QString(),
                                                      tr("Delimited text (*.csv *.txt);;All files (*)"));
    if (!path.isEmpty())
        openRecording(path);
}

bool MainWindow::openRecording(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        showError(tr("%1: cannot open the file: %2").arg(path, file.errorString()));
        return false;
    }
    // Through a stream so embedded samples (":/...") open like files.
    const QByteArray bytes = file.readAll();
    std::istringstream text(bytes.toStdString());
    ImportResult read = importStream(text, static_cast<std::size_t>(bytes.size()), path.toStdString());
    if (!read.ok()) {
        showError(QString::fromStdString(read.error->text()));
        return false;
    }
    recording_ = std::make_shared<const Recording>(std::move(read.recording));
    setWindowTitle(tr("Footpath - %1").arg(QString::fromStdString(recording_->source)));
    summary_->setText(tr("Estimating %1 samples...").arg(recording_->samples.size()));
    trajectory_->clear();
    runner_->run(recording_, params_);
    return true;
}

void MainWindow::showResult(const std::shared_ptr<const Result>& result)
{
    trajectory_->showResult(*result);
    const Summary& s = result->summary;
    summary_->setText(tr("%1 samples, %2 s, %3 steps, path %4 m, end to start %5 m (%6 %), estimated in %7 ms")
                          .arg(s.samples)
                          .arg(s.duration_s, 0, 'f', 1)
                          .arg(s.steps)
                          .arg(s.pathLength_m, 0, 'f', 2)
                          .arg(s.endToStart_m, 0, 'f', 2)
                          .arg(s.endToStartPct, 0, 'f', 2)
                          .arg(s.runtime_s * 1000.0, 0, 'f', 1));
}

void MainWindow::showError(const QString& message)
{
    summary_->setText(message);
    QMessageBox::warning(this, tr("Footpath"), message);
}

}  // namespace footpath
