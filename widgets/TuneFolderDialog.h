#pragma once

#include "Recording.h"
#include "TuneDialog.h"
#include "io/ImportPresets.h"

#include <QDialog>
#include <QFutureWatcher>
#include <QStringList>

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace footpath {

class AnalysisSession;

/// The recordings of one folder, read as the workspace reads a file: detected, or with an import
/// preset, and a headerless file with the column guess when the guess reads it well.
struct FolderRecordings {
    QStringList names;                                   ///< file names, in byte order
    std::vector<std::shared_ptr<const Recording>> recordings;  ///< one per name
    QStringList skipped;                                 ///< "name: why it could not be read"
};

/// Reads every file of the folder that can hold a recording (not hidden, not a sidecar, document
/// or picture); cancel stops between and inside files.
FolderRecordings readFolderRecordings(const QString& folder, const std::optional<ImportPreset>& preset,
                                      const std::atomic<bool>* cancel = nullptr);

/// Analysis > Tune over a folder: one parameter set for many recordings of a sensor and a way of
/// walking. Reads the folder, offers the criteria its recordings support, runs the search with
/// progress and cancel, and shows the criterion per recording before and after and what changed;
/// the result is saved as a preset or applied to the workspace (one undoable step).
class TuneFolderDialog : public QDialog {
    Q_OBJECT
public:
    TuneFolderDialog(AnalysisSession& session, const QString& startFolder, QWidget* parent = nullptr);
    ~TuneFolderDialog() override;

    /// Reads the folder off the GUI thread; folderRead() when its recordings are listed.
    void setFolder(const QString& folder);
    QString folder() const { return folder_; }
    bool isReading() const;
    const FolderRecordings& contents() const { return contents_; }

    bool isCriterionAvailable(TuneCriterion criterion) const;
    void setCriterion(TuneCriterion criterion);
    TuneCriterion criterion() const;
    void setEvaluations(int evaluations);
    void start();
    void stop();
    bool isRunning() const;
    const TuneOutcome& outcome() const;

    /// Writes the tuned parameters as a preset; an error message, or empty.
    QString savePreset(const QString& path) const;
    /// Makes the tuned parameters the workspace's (one undoable step) and closes.
    void applyToWorkspace();

    QTableWidget* recordingsTable() const { return recordingsTable_; }
    QTableWidget* changesTable() const { return changes_; }
    QProgressBar* progressBar() const { return progress_; }
    QLabel* bestLabel() const { return best_; }
    QLabel* skippedLabel() const { return skipped_; }

    void reject() override;

signals:
    void folderRead();
    void tuningFinished();

private:
    QWidget* createSettings();
    QWidget* createResultArea();
    QWidget* createButtons();
    void chooseFolder();
    void onFolderRead();
    void listRecordings();
    void updateCriteria();
    /// The recordings the chosen criterion can score (the others are not run); notes their rows.
    std::vector<std::shared_ptr<const Recording>> recordingsToTune();
    void showProgress(int evaluations, int budget, double bestScore);
    void onFinished();
    void showScores(const TuneOutcome& outcome);
    void setStage(bool busy, bool done);
    void choosePresetFile();

    AnalysisSession& session_;
    Parameters base_;
    QString folder_;
    QString browseFrom_;  ///< where choosing a folder starts
    FolderRecordings contents_;
    QFutureWatcher<FolderRecordings> reader_;
    std::shared_ptr<std::atomic<bool>> cancelRead_;
    TuneJob* job_;
    TuneCriterion runCriterion_ = TuneCriterion::ClosedLoop;
    std::vector<int> tunedRows_;  ///< the table row of each recording tuned on, in the run's order

    QLineEdit* folderEdit_ = nullptr;
    QComboBox* importPreset_ = nullptr;
    QCheckBox* allClosed_ = nullptr;
    TuneCriterionChoice* criteria_ = nullptr;
    QSpinBox* evaluations_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* best_ = nullptr;
    QLabel* message_ = nullptr;
    QLabel* skipped_ = nullptr;
    QTableWidget* recordingsTable_ = nullptr;
    QTableWidget* changes_ = nullptr;
    QPushButton* startButton_ = nullptr;
    QPushButton* stopButton_ = nullptr;
    QPushButton* saveButton_ = nullptr;
    QPushButton* applyButton_ = nullptr;
    QPushButton* closeButton_ = nullptr;
};

}  // namespace footpath
