#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <QMainWindow>

#include <memory>

class QLabel;

namespace footpath {

class PipelineRunner;
class TrajectoryView2D;

/// Assembles the panels and menus; holds no algorithm.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    /// Opens a delimited text recording (a file path or a ":/" resource); errors are shown in words.
    bool openRecording(const QString& path);

private:
    void createMenus();
    void chooseRecording();
    void showResult(const std::shared_ptr<const Result>& result);
    void showError(const QString& message);

    TrajectoryView2D* trajectory_;
    QLabel* summary_;
    PipelineRunner* runner_;
    std::shared_ptr<const Recording> recording_;
    Parameters params_;
};

}  // namespace footpath
