#include "TuneFolderDialog.h"

#include "AnalysisSession.h"
#include "io/ColumnMapGuess.h"
#include "io/Import.h"
#include "io/ParameterIo.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QThread>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

/// Beside recordings lie their sidecars and gait events (read with them), documents and pictures.
bool mayHoldARecording(const QFileInfo& file)
{
    static const QStringList notRecordings{QStringLiteral("json"), QStringLiteral("md"), QStringLiteral("pdf"),
                                           QStringLiteral("png")};
    return !notRecordings.contains(file.suffix().toLower());
}

/// The workspace's way: the file as it describes itself (or as the preset says), and a headerless
/// file with the usual column guess when reading it so gives gravity and an IMU's rate.
ImportResult readRecording(const QString& path, const std::optional<ImportPreset>& preset,
                           const std::atomic<bool>* cancel)
{
    ImportOptions options;
    if (preset)
        applyImportPreset(*preset, options);
    options.progress = [cancel](double) { return !(cancel && cancel->load()); };
    ImportResult read = importRecording(path.toStdString(), options);
    if (read.ok() || !options.columnMap.empty())
        return read;
    const ColumnMapGuess guess = guessColumnMap(path.toStdString(), options);
    if (!guess.confident)
        return read;
    options.columnMap = guess.columnMap;
    ImportResult guessed = importRecording(path.toStdString(), options);
    return guessed.ok() ? guessed : read;
}

}  // namespace

FolderRecordings readFolderRecordings(const QString& folder, const std::optional<ImportPreset>& preset,
                                      const std::atomic<bool>* cancel)
{
    FolderRecordings contents;
    QStringList names = QDir(folder).entryList(QDir::Files, QDir::NoSort);  // hidden files are left out
    std::sort(names.begin(), names.end(), [](const QString& a, const QString& b) { return a.toUtf8() < b.toUtf8(); });
    for (const QString& name : names) {
        if (cancel && cancel->load())
            break;
        const QString path = QDir(folder).filePath(name);
        if (!mayHoldARecording(QFileInfo(path)))
            continue;
        ImportResult read = readRecording(path, preset, cancel);
        if (!read.ok()) {
            contents.skipped << QStringLiteral("%1: %2").arg(name, QString::fromStdString(read.error->text()));
            continue;
        }
        if (read.recording.samples.size() < 2) {
            contents.skipped << TuneFolderDialog::tr("%1: no samples").arg(name);
            continue;
        }
        contents.names << name;
        contents.recordings.push_back(std::make_shared<const Recording>(std::move(read.recording)));
    }
    return contents;
}

TuneFolderDialog::TuneFolderDialog(AnalysisSession& session, const QString& startFolder, QWidget* parent)
    : QDialog(parent), session_(session), base_(session.parameters()), browseFrom_(startFolder), job_(new TuneJob(this))
{
    setWindowTitle(tr("Tune over a folder"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(createSettings());
    layout->addWidget(createResultArea(), 1);
    layout->addWidget(createButtons());
    connect(&reader_, &QFutureWatcher<FolderRecordings>::finished, this, &TuneFolderDialog::onFolderRead);
    connect(job_, &TuneJob::progressed, this, &TuneFolderDialog::showProgress);
    connect(job_, &TuneJob::finished, this, &TuneFolderDialog::onFinished);
    updateCriteria();
    setStage(false, false);
    message_->setText(tr("Choose a folder of recordings of one sensor and one way of walking."));
    resize(980, 680);
}

TuneFolderDialog::~TuneFolderDialog()
{
    if (cancelRead_)
        cancelRead_->store(true);
    reader_.waitForFinished();
}

QWidget* TuneFolderDialog::createSettings()
{
    folderEdit_ = new QLineEdit(this);
    folderEdit_->setObjectName(QStringLiteral("tuneFolder"));
    folderEdit_->setReadOnly(true);
    auto* choose = new QPushButton(tr("Choose..."), this);
    choose->setObjectName(QStringLiteral("chooseTuneFolder"));
    connect(choose, &QPushButton::clicked, this, &TuneFolderDialog::chooseFolder);
    importPreset_ = new QComboBox(this);
    importPreset_->setObjectName(QStringLiteral("tuneImportPreset"));
    importPreset_->addItem(tr("Detect (headerless files: the usual columns)"));
    for (const ImportPreset& preset : listImportPresets())
        importPreset_->addItem(QString::fromStdString(preset.name));
    importPreset_->setToolTip(tr("How to read files that do not describe themselves"));
    connect(importPreset_, &QComboBox::currentIndexChanged, this, [this] {
        if (!folder_.isEmpty())
            setFolder(folder_);
    });
    allClosed_ = new QCheckBox(tr("Every walk ends where it started"), this);
    allClosed_->setObjectName(QStringLiteral("tuneAllClosed"));
    allClosed_->setToolTip(tr("Score every recording by its end-to-start distance, also those not marked closed"));
    connect(allClosed_, &QCheckBox::toggled, this, [this](bool closed) {
        updateCriteria();
        if (closed)  // said so to use it
            setCriterion(TuneCriterion::ClosedLoop);
    });

    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(new QLabel(tr("Folder:"), this));
    folderRow->addWidget(folderEdit_, 1);
    folderRow->addWidget(choose);
    folderRow->addWidget(new QLabel(tr("Read with:"), this));
    folderRow->addWidget(importPreset_);

    criteria_ = new TuneCriterionChoice(this);
    evaluations_ = new QSpinBox(this);
    evaluations_->setObjectName(QStringLiteral("tuneEvaluations"));
    evaluations_->setRange(8, 10000);
    evaluations_->setSingleStep(50);
    evaluations_->setValue(200);
    evaluations_->setToolTip(tr("Parameter sets to try, each on every recording"));
    auto* runColumn = new QVBoxLayout;
    runColumn->addWidget(allClosed_);
    auto* evaluationsRow = new QHBoxLayout;
    evaluationsRow->addWidget(new QLabel(tr("Evaluations:"), this));
    evaluationsRow->addWidget(evaluations_);
    evaluationsRow->addWidget(new QLabel(tr("on %n core(s)", nullptr, QThread::idealThreadCount()), this));
    evaluationsRow->addStretch(1);
    runColumn->addLayout(evaluationsRow);
    runColumn->addStretch(1);
    auto* choiceRow = new QHBoxLayout;
    choiceRow->addWidget(criteria_, 1);
    choiceRow->addLayout(runColumn);

    auto* settings = new QWidget(this);
    settings->setObjectName(QStringLiteral("tuneSettings"));
    auto* column = new QVBoxLayout(settings);
    column->setContentsMargins(0, 0, 0, 0);
    column->addLayout(folderRow);
    column->addLayout(choiceRow);
    return settings;
}

QWidget* TuneFolderDialog::createResultArea()
{
    progress_ = new QProgressBar(this);
    progress_->setObjectName(QStringLiteral("tuneProgress"));
    progress_->setFormat(tr("%v of %m evaluations"));
    progress_->setRange(0, evaluations_->value());
    progress_->setValue(0);
    best_ = new QLabel(this);
    best_->setObjectName(QStringLiteral("tuneBest"));
    message_ = new QLabel(this);
    message_->setObjectName(QStringLiteral("tuneMessage"));
    message_->setWordWrap(true);
    skipped_ = new QLabel(this);
    skipped_->setObjectName(QStringLiteral("tuneSkipped"));
    skipped_->setWordWrap(true);
    skipped_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    skipped_->setStyleSheet(QStringLiteral("color: #b00020;"));
    skipped_->hide();

    recordingsTable_ = makeTuneTable({tr("Recording"), tr("Before"), tr("After")}, this);
    recordingsTable_->setObjectName(QStringLiteral("tuneRecordings"));
    changes_ = makeTuneTable({tr("What changed"), tr("Before"), tr("After")}, this);
    changes_->setObjectName(QStringLiteral("tuneChanges"));
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(recordingsTable_);
    splitter->addWidget(changes_);

    auto* area = new QWidget(this);
    auto* layout = new QVBoxLayout(area);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(progress_, 1);
    progressRow->addWidget(best_);
    layout->addLayout(progressRow);
    layout->addWidget(message_);
    layout->addWidget(skipped_);
    layout->addWidget(splitter, 1);
    return area;
}

QWidget* TuneFolderDialog::createButtons()
{
    startButton_ = new QPushButton(tr("Start"), this);
    startButton_->setObjectName(QStringLiteral("tuneStart"));
    stopButton_ = new QPushButton(tr("Stop"), this);
    stopButton_->setObjectName(QStringLiteral("tuneStop"));
    stopButton_->setToolTip(tr("Stop searching and keep the best parameters found so far"));
    saveButton_ = new QPushButton(tr("Save preset..."), this);
    saveButton_->setObjectName(QStringLiteral("tuneSavePreset"));
    applyButton_ = new QPushButton(tr("Apply to the workspace"), this);
    applyButton_->setObjectName(QStringLiteral("tuneApply"));
    applyButton_->setToolTip(tr("Make them the workspace's parameters (Edit > Undo brings the current ones back)"));
    closeButton_ = new QPushButton(tr("Close"), this);
    closeButton_->setObjectName(QStringLiteral("tuneClose"));
    connect(startButton_, &QPushButton::clicked, this, &TuneFolderDialog::start);
    connect(stopButton_, &QPushButton::clicked, this, &TuneFolderDialog::stop);
    connect(saveButton_, &QPushButton::clicked, this, &TuneFolderDialog::choosePresetFile);
    connect(applyButton_, &QPushButton::clicked, this, &TuneFolderDialog::applyToWorkspace);
    connect(closeButton_, &QPushButton::clicked, this, &TuneFolderDialog::reject);
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(startButton_);
    layout->addWidget(stopButton_);
    layout->addStretch(1);
    layout->addWidget(saveButton_);
    layout->addWidget(applyButton_);
    layout->addWidget(closeButton_);
    return row;
}

void TuneFolderDialog::chooseFolder()
{
    const QString chosen = QFileDialog::getExistingDirectory(this, tr("Folder of recordings"),
                                                             folder_.isEmpty() ? browseFrom_ : folder_);
    if (!chosen.isEmpty())
        setFolder(chosen);
}

void TuneFolderDialog::setFolder(const QString& folder)
{
    if (isRunning())
        return;
    if (cancelRead_)
        cancelRead_->store(true);
    reader_.waitForFinished();
    folder_ = folder;
    folderEdit_->setText(QDir::toNativeSeparators(folder));
    contents_ = FolderRecordings();
    listRecordings();
    updateCriteria();
    std::optional<ImportPreset> preset;
    if (importPreset_->currentIndex() > 0) {
        ImportPreset loaded;
        if (loadImportPreset(importPreset_->currentText().toStdString(), loaded).empty())
            preset = loaded;
    }
    cancelRead_ = std::make_shared<std::atomic<bool>>(false);
    message_->setText(tr("Reading the recordings in %1...").arg(QDir::toNativeSeparators(folder)));
    setStage(true, false);
    reader_.setFuture(QtConcurrent::run(
        [folder, preset, cancel = cancelRead_] { return readFolderRecordings(folder, preset, cancel.get()); }));
}

bool TuneFolderDialog::isReading() const
{
    return reader_.isRunning();
}

void TuneFolderDialog::onFolderRead()
{
    if ((cancelRead_ && cancelRead_->load()) || !reader_.isFinished())
        return;  // a newer folder (or the dialog closing) superseded this read
    contents_ = reader_.result();
    listRecordings();
    updateCriteria();
    message_->setText(contents_.recordings.empty()
                          ? tr("No recording could be read in this folder.")
                          : tr("%n recording(s) read. Choose what to minimise and start.", nullptr,
                               static_cast<int>(contents_.recordings.size())));
    setStage(false, false);
    emit folderRead();
}

void TuneFolderDialog::listRecordings()
{
    recordingsTable_->setRowCount(0);
    for (const QString& name : contents_.names) {
        const int row = recordingsTable_->rowCount();
        recordingsTable_->insertRow(row);
        recordingsTable_->setItem(row, 0, new QTableWidgetItem(name));
    }
    recordingsTable_->resizeColumnsToContents();
    changes_->setRowCount(0);
    skipped_->setVisible(!contents_.skipped.isEmpty());
    skipped_->setText(tr("Not read (%n file(s)):", nullptr, static_cast<int>(contents_.skipped.size()))
                      + QStringLiteral("\n") + contents_.skipped.join(QLatin1Char('\n')));
}

void TuneFolderDialog::updateCriteria()
{
    const auto& all = contents_.recordings;
    const auto any = [&all](auto has) { return std::any_of(all.begin(), all.end(), [&](const auto& r) { return has(*r); }); };
    if (all.empty()) {
        const QString none = tr("no recordings read yet");
        criteria_->setReasons({none, none, none});
    } else {
        const bool closed = allClosed_->isChecked() || any([](const Recording& r) { return r.reference.closedLoop; });
        const bool length = any([](const Recording& r) { return r.reference.knownLength_m > 0.0; });
        const bool reference = any([](const Recording& r) { return !r.reference.positions_m.empty(); });
        criteria_->setReasons(
            {closed ? QString() : tr("no walk is marked closed: tick it if they all end where they started"),
             length ? QString() : tr("no recording has a known length (e.g. walk_72m.txt, or a sidecar)"),
             reference ? QString() : tr("no recording has reference positions")});
    }
    startButton_->setEnabled(!isRunning() && !isReading() && isCriterionAvailable(criterion()));
}

bool TuneFolderDialog::isCriterionAvailable(TuneCriterion criterion) const
{
    return criteria_->isAvailable(criterion);
}

void TuneFolderDialog::setCriterion(TuneCriterion criterion)
{
    criteria_->setCriterion(criterion);
}

TuneCriterion TuneFolderDialog::criterion() const
{
    return criteria_->criterion();
}

void TuneFolderDialog::setEvaluations(int evaluations)
{
    evaluations_->setValue(evaluations);
}

const TuneOutcome& TuneFolderDialog::outcome() const
{
    return job_->result().outcome;
}

std::vector<std::shared_ptr<const Recording>> TuneFolderDialog::recordingsToTune()
{
    const bool markClosed = allClosed_->isChecked() && criterion() == TuneCriterion::ClosedLoop;
    std::vector<std::shared_ptr<const Recording>> tuned;
    tunedRows_.clear();
    for (std::size_t i = 0; i < contents_.recordings.size(); ++i) {
        std::shared_ptr<const Recording> recording = contents_.recordings[i];
        if (markClosed && !recording->reference.closedLoop) {
            auto copy = std::make_shared<Recording>(*recording);
            copy->reference.closedLoop = true;
            recording = std::move(copy);
        }
        if (!tuneCriterionApplies(*recording, criterion()))
            continue;
        tuned.push_back(std::move(recording));
        tunedRows_.push_back(static_cast<int>(i));
    }
    return tuned;
}

void TuneFolderDialog::start()
{
    if (isRunning() || isReading() || contents_.recordings.empty() || !isCriterionAvailable(criterion()))
        return;
    std::vector<std::shared_ptr<const Recording>> recordings = recordingsToTune();
    if (recordings.empty()) {
        message_->setText(tr("None of the recordings has what this criterion needs."));
        return;
    }
    base_ = session_.parameters();
    runCriterion_ = criterion();
    TuneOptions options;
    options.criterion = runCriterion_;
    options.evaluations = evaluations_->value();
    progress_->setRange(0, options.evaluations);
    progress_->setValue(0);
    best_->clear();
    changes_->setRowCount(0);
    listRecordings();
    message_->setText(tr("Tuning on %n recording(s): the current parameters, then a spread over the whole range...",
                         nullptr, static_cast<int>(recordings.size())));
    setStage(true, false);
    job_->start(std::move(recordings), base_, options, false);
}

void TuneFolderDialog::stop()
{
    if (!isRunning())
        return;
    job_->cancel();
    message_->setText(tr("Stopping; the best parameters so far are kept..."));
    stopButton_->setEnabled(false);
}

bool TuneFolderDialog::isRunning() const
{
    return job_->isRunning();
}

void TuneFolderDialog::showProgress(int evaluations, int budget, double bestScore)
{
    progress_->setRange(0, budget);
    progress_->setValue(evaluations);
    best_->setText(tr("Best mean so far: %1").arg(formatTuneScore(runCriterion_, bestScore)));
    message_->setText(tr("Searching around the best parameters found so far..."));
}

void TuneFolderDialog::onFinished()
{
    const TuneOutcome& result = outcome();
    if (!result.error.empty()) {
        message_->setText(QString::fromStdString(result.error));
        best_->clear();
    } else {
        progress_->setValue(result.evaluations);
        best_->setText(tr("Best mean: %1").arg(formatTuneScore(runCriterion_, result.bestScore)));
        showScores(result);
        const int changed = showTuneChanges(changes_, base_, result.best, runCriterion_, result.baseScore,
                                            result.bestScore);
        const QString how = result.cancelled ? tr("Stopped after %n evaluation(s).", nullptr, result.evaluations)
                                             : tr("Done: %n evaluation(s).", nullptr, result.evaluations);
        QString text = how + QLatin1Char(' ')
                       + (changed == 0 ? tr("No better parameters were found; the current ones stay.")
                                       : tr("Save them as a preset, or apply them to the workspace."));
        if (!result.cautions.empty()) {
            QStringList cautions;
            for (const std::string& caution : result.cautions)
                cautions << QString::fromStdString(caution);
            text += QLatin1Char('\n') + tr("Beware: the tuned parameters change the strides, not only the figure: %1")
                                            .arg(cautions.join(QStringLiteral("; ")));
        }
        message_->setText(text);
    }
    setStage(false, true);
    emit tuningFinished();
}

void TuneFolderDialog::showScores(const TuneOutcome& outcome)
{
    const auto cell = [this](double score) {
        auto* item = new QTableWidgetItem(formatTuneScore(runCriterion_, score));
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (std::isnan(score))
            item->setToolTip(tr("Not scored: the recording lacks what the criterion needs"));
        return item;
    };
    for (int row = 0; row < recordingsTable_->rowCount(); ++row) {
        recordingsTable_->setItem(row, 1, cell(NAN));
        recordingsTable_->setItem(row, 2, cell(NAN));
    }
    for (std::size_t t = 0; t < tunedRows_.size(); ++t) {
        if (t < outcome.basePerRecording.size())
            recordingsTable_->setItem(tunedRows_[t], 1, cell(outcome.basePerRecording[t]));
        if (t < outcome.bestPerRecording.size())
            recordingsTable_->setItem(tunedRows_[t], 2, cell(outcome.bestPerRecording[t]));
    }
    const int mean = recordingsTable_->rowCount();
    recordingsTable_->insertRow(mean);
    recordingsTable_->setItem(mean, 0, new QTableWidgetItem(tr("Mean")));
    recordingsTable_->setItem(mean, 1, cell(outcome.baseScore));
    recordingsTable_->setItem(mean, 2, cell(outcome.bestScore));
    QFont bold = recordingsTable_->font();
    bold.setBold(true);
    for (int column = 0; column < 3; ++column)
        recordingsTable_->item(mean, column)->setFont(bold);
    recordingsTable_->resizeColumnsToContents();
}

void TuneFolderDialog::setStage(bool busy, bool done)
{
    const bool tuned = done && outcome().error.empty() && outcome().best != base_;
    findChild<QWidget*>(QStringLiteral("tuneSettings"))->setEnabled(!busy);
    startButton_->setEnabled(!busy && !contents_.recordings.empty() && isCriterionAvailable(criterion()));
    startButton_->setText(done ? tr("Start again") : tr("Start"));
    stopButton_->setEnabled(busy && isRunning());
    saveButton_->setEnabled(tuned);
    applyButton_->setEnabled(tuned);
}

QString TuneFolderDialog::savePreset(const QString& path) const
{
    return QString::fromStdString(saveParameters(path.toStdString(), outcome().best));
}

void TuneFolderDialog::choosePresetFile()
{
    const QString suggested = QDir(folder_).filePath(QFileInfo(folder_).fileName() + QStringLiteral("-tuned.json"));
    const QString path = QFileDialog::getSaveFileName(this, tr("Save preset"), suggested, tr("Presets (*.json)"));
    if (path.isEmpty())
        return;
    const QString problem = savePreset(path);
    message_->setText(problem.isEmpty() ? tr("Preset written to %1").arg(QDir::toNativeSeparators(path)) : problem);
}

void TuneFolderDialog::applyToWorkspace()
{
    if (isRunning() || !applyButton_->isEnabled())
        return;
    session_.setParameters(outcome().best, tr("Parameters tuned over %1").arg(QFileInfo(folder_).fileName()));
    QDialog::accept();
}

void TuneFolderDialog::reject()
{
    job_->cancel();
    if (cancelRead_)
        cancelRead_->store(true);
    QDialog::reject();
}

}  // namespace footpath
