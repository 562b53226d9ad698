#include "TuneDialog.h"

#include "AnalysisSession.h"
#include "TrajectoryView2D.h"
#include "metrics/Evaluation.h"
#include "nav/Pipeline.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QThread>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <cmath>

namespace footpath {

namespace {

/// A tuned path this much longer or shorter than the current one is pointed out: the end-to-start
/// distance and the ARMSE shrink with the path itself.
constexpr double kSuspectLengthChange = 0.1;

constexpr TuneCriterion kCriteria[] = {TuneCriterion::ClosedLoop, TuneCriterion::KnownLength, TuneCriterion::Reference};

std::size_t indexOf(TuneCriterion criterion)
{
    return static_cast<std::size_t>(criterion);
}

QString valueText(const Parameters& params, const ParameterField& field)
{
    switch (field.kind) {
    case ParameterField::Kind::Choice:
        return QString::fromStdString(choiceName(params, field));
    case ParameterField::Kind::Flag:
        return parameterValue(params, field) != 0.0 ? TuneDialog::tr("on") : TuneDialog::tr("off");
    case ParameterField::Kind::Real:
        break;
    }
    return QLocale().toString(parameterValue(params, field), 'g', 4);
}

/// "C2 bound on the std of |a| (m/s²)", the label translated as the parameter panel shows it.
QString fieldLabel(const ParameterField& field)
{
    const QString label = QCoreApplication::translate("footpath::ParameterFields", field.label);
    const QString unit = QString::fromStdString(displayUnit(field));
    return unit.isEmpty() ? label : QStringLiteral("%1 (%2)").arg(label, unit);
}

void addChangeRow(QTableWidget* table, const QString& name, const QString& before, const QString& after,
                  const QString& toolTip, int row = -1)
{
    row = row < 0 ? table->rowCount() : row;
    table->insertRow(row);
    auto* nameItem = new QTableWidgetItem(name);
    nameItem->setToolTip(toolTip);
    table->setItem(row, 0, nameItem);
    table->setItem(row, 1, new QTableWidgetItem(before));
    table->setItem(row, 2, new QTableWidgetItem(after));
    for (int column = 1; column < 3; ++column)
        table->item(row, column)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
}

}  // namespace

QString tuneCriterionText(TuneCriterion criterion)
{
    switch (criterion) {
    case TuneCriterion::ClosedLoop:
        return TuneDialog::tr("End-to-start distance of a closed walk (%)");
    case TuneCriterion::KnownLength:
        return TuneDialog::tr("Error of the path length (%)");
    case TuneCriterion::Reference:
        return TuneDialog::tr("Position error against the reference (ARMSE, m)");
    }
    return {};
}

QString formatTuneScore(TuneCriterion criterion, double score)
{
    if (!std::isfinite(score))
        return QStringLiteral("\u2013");
    if (criterion == TuneCriterion::Reference)
        return TuneDialog::tr("%1 m").arg(QLocale().toString(score, 'f', 3));
    return TuneDialog::tr("%1 %").arg(QLocale().toString(score, 'f', 2));
}

QTableWidget* makeTuneTable(const QStringList& headers, QWidget* parent)
{
    auto* table = new QTableWidget(0, static_cast<int>(headers.size()), parent);
    table->setHorizontalHeaderLabels(headers);
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->horizontalHeader()->setStretchLastSection(true);
    return table;
}

int showTuneChanges(QTableWidget* table, const Parameters& before, const Parameters& after, TuneCriterion criterion,
                    double scoreBefore, double scoreAfter)
{
    table->setRowCount(0);
    if (!std::isnan(scoreBefore)) {
        addChangeRow(table, tuneCriterionText(criterion), formatTuneScore(criterion, scoreBefore),
                     formatTuneScore(criterion, scoreAfter), TuneDialog::tr("The criterion the search minimised"));
        QFont bold = table->item(0, 0)->font();
        bold.setBold(true);
        for (int column = 0; column < 3; ++column)
            table->item(0, column)->setFont(bold);
    }
    int changed = 0;
    for (const ParameterField& field : parameterFields()) {
        if (parameterValue(before, field) == parameterValue(after, field))
            continue;
        addChangeRow(table, fieldLabel(field), valueText(before, field), valueText(after, field),
                     QString::fromUtf8(field.name));
        ++changed;
    }
    table->resizeColumnsToContents();
    return changed;
}

// --- TuneCriterionChoice ----------------------------------------------------------------------

TuneCriterionChoice::TuneCriterionChoice(QWidget* parent) : QGroupBox(tr("Minimise"), parent)
{
    auto* grid = new QGridLayout(this);
    for (const TuneCriterion c : kCriteria) {
        const std::size_t i = indexOf(c);
        buttons_[i] = new QRadioButton(tuneCriterionText(c), this);
        buttons_[i]->setObjectName(QStringLiteral("criterion_") + QString::fromUtf8(tuneCriterionName(c)));
        reasons_[i] = new QLabel(this);
        reasons_[i]->setObjectName(QStringLiteral("whyNot_") + QString::fromUtf8(tuneCriterionName(c)));
        reasons_[i]->setStyleSheet(QStringLiteral("color: palette(mid);"));
        reasons_[i]->setWordWrap(true);
        grid->addWidget(buttons_[i], static_cast<int>(i), 0);
        grid->addWidget(reasons_[i], static_cast<int>(i), 1);
    }
    grid->setColumnStretch(1, 1);
}

void TuneCriterionChoice::setReasons(const std::array<QString, 3>& whyNot)
{
    for (std::size_t i = 0; i < buttons_.size(); ++i) {
        available_[i] = whyNot[i].isEmpty();
        buttons_[i]->setEnabled(available_[i]);
        buttons_[i]->setToolTip(whyNot[i]);
        reasons_[i]->setText(whyNot[i]);
    }
    if (isAvailable(criterion()) && buttons_[indexOf(criterion())]->isChecked())
        return;
    for (const TuneCriterion c : {TuneCriterion::Reference, TuneCriterion::ClosedLoop, TuneCriterion::KnownLength})
        if (isAvailable(c)) {
            setCriterion(c);
            return;
        }
}

bool TuneCriterionChoice::isAvailable(TuneCriterion criterion) const
{
    return available_[indexOf(criterion)];
}

TuneCriterion TuneCriterionChoice::criterion() const
{
    for (const TuneCriterion c : kCriteria)
        if (buttons_[indexOf(c)]->isChecked())
            return c;
    return TuneCriterion::ClosedLoop;
}

void TuneCriterionChoice::setCriterion(TuneCriterion criterion)
{
    buttons_[indexOf(criterion)]->setChecked(true);
}

// --- TuneJob -----------------------------------------------------------------------------------

TuneJob::TuneJob(QObject* parent) : QObject(parent)
{
    connect(&watcher_, &QFutureWatcher<TuneJobResult>::finished, this, [this] {
        result_ = watcher_.result();
        emit finished();
    });
}

TuneJob::~TuneJob()
{
    cancel();
    watcher_.waitForFinished();
}

void TuneJob::start(std::vector<std::shared_ptr<const Recording>> recordings, const Parameters& base,
                    const TuneOptions& options, bool withPaths)
{
    cancel();
    watcher_.waitForFinished();
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    // The worker emits progressed() from its thread; the receivers live in the GUI thread, so
    // Qt queues the calls there. The destructor waits for the worker, so `this` outlives it.
    watcher_.setFuture(QtConcurrent::run([this, recordings = std::move(recordings), base, options, withPaths,
                                          cancel = cancel_] {
        std::vector<const Recording*> pointers;
        for (const std::shared_ptr<const Recording>& recording : recordings)
            pointers.push_back(recording.get());
        TuneJobResult result;
        result.outcome = tuneParameters(
            pointers, base, options,
            [this](const TuneProgress& p) { emit progressed(p.evaluations, p.budget, p.bestScore); }, cancel.get());
        if (withPaths && !recordings.empty() && result.outcome.error.empty()) {
            // Drawn as two paths with their figures: no standard deviations.
            const auto pathOf = [&](const Parameters& params) {
                PipelineOutput run = runPipeline(*recordings.front(), params, {}, RtsSmoother::Threads::Two, {},
                                                 RtsSmoother::Variances::Skip);
                return std::make_shared<const Result>(std::move(run.result));
            };
            result.before = pathOf(base);
            result.after = pathOf(result.outcome.best);
        }
        return result;
    }));
}

void TuneJob::cancel()
{
    if (cancel_)
        cancel_->store(true);
}

bool TuneJob::isRunning() const
{
    return watcher_.isRunning();
}

// --- TuneDialog --------------------------------------------------------------------------------

TuneDialog::TuneDialog(AnalysisSession& session, QWidget* parent)
    : QDialog(parent), session_(session), base_(session.parameters()), job_(new TuneJob(this))
{
    setWindowTitle(tr("Tune for %1").arg(QFileInfo(session.recordingPath()).fileName()));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(createSettings());
    layout->addWidget(createResultArea(), 1);
    layout->addWidget(createButtons());
    connect(job_, &TuneJob::progressed, this, &TuneDialog::showProgress);
    connect(job_, &TuneJob::finished, this, &TuneDialog::onFinished);
    updateCriteria();
    setStage(false, false);
    resize(960, 680);
}

TuneDialog::~TuneDialog() = default;

QWidget* TuneDialog::createSettings()
{
    const std::shared_ptr<const Recording> recording = session_.recording();
    const Reference noReference;
    const Reference& reference = recording ? recording->reference : noReference;

    auto* walk = new QGroupBox(tr("What is known about the walk"), this);
    auto* walkForm = new QFormLayout(walk);
    closed_ = new QCheckBox(tr("The walk ends where it started"), walk);
    closed_->setObjectName(QStringLiteral("tuneClosed"));
    closed_->setChecked(reference.closedLoop);
    closed_->setToolTip(tr("Then the distance from its end to its start is the error to minimise"));
    length_ = new QDoubleSpinBox(walk);
    length_->setObjectName(QStringLiteral("tuneLength"));
    length_->setRange(0.0, 100000.0);
    length_->setDecimals(1);
    length_->setSuffix(tr(" m"));
    length_->setSpecialValueText(tr("unknown"));
    length_->setValue(reference.knownLength_m);
    length_->setToolTip(tr("The length of the walked path, if measured; then the error of the estimated length "
                           "is the error to minimise"));
    walkForm->addRow(closed_);
    walkForm->addRow(tr("Path length:"), length_);
    connect(closed_, &QCheckBox::toggled, this, [this](bool closed) {
        updateCriteria();
        if (closed)  // said so to use it
            setCriterion(TuneCriterion::ClosedLoop);
    });
    connect(length_, &QDoubleSpinBox::valueChanged, this, &TuneDialog::updateCriteria);

    criteria_ = new TuneCriterionChoice(this);

    evaluations_ = new QSpinBox(this);
    evaluations_->setObjectName(QStringLiteral("tuneEvaluations"));
    evaluations_->setRange(8, 10000);
    evaluations_->setSingleStep(50);
    evaluations_->setValue(200);
    evaluations_->setToolTip(tr("Parameter sets to try, the current one included; more finds better settings "
                                "but takes longer"));
    auto* cores = new QLabel(tr("on %n core(s)", nullptr, QThread::idealThreadCount()), this);

    auto* runRow = new QHBoxLayout;
    runRow->addWidget(new QLabel(tr("Evaluations:"), this));
    runRow->addWidget(evaluations_);
    runRow->addWidget(cores);
    runRow->addStretch(1);

    auto* settings = new QWidget(this);
    settings->setObjectName(QStringLiteral("tuneSettings"));
    auto* top = new QHBoxLayout;
    top->setContentsMargins(0, 0, 0, 0);
    top->addWidget(walk);
    top->addWidget(criteria_, 1);
    auto* column = new QVBoxLayout(settings);
    column->setContentsMargins(0, 0, 0, 0);
    column->addLayout(top);
    column->addLayout(runRow);
    return settings;
}

QWidget* TuneDialog::createResultArea()
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
    warning_ = new QLabel(this);
    warning_->setObjectName(QStringLiteral("tuneWarning"));
    warning_->setWordWrap(true);
    warning_->setStyleSheet(QStringLiteral("color: #b00020; font-weight: bold;"));
    warning_->hide();

    view_ = new TrajectoryView2D(this);
    view_->setObjectName(QStringLiteral("tunePath"));
    view_->setMinimumSize(360, 260);
    if (session_.result())
        view_->setResult(session_.result());
    changes_ = makeTuneTable({tr("What changed"), tr("Before"), tr("After")}, this);
    changes_->setObjectName(QStringLiteral("tuneChanges"));
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(view_);
    splitter->addWidget(changes_);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);

    auto* area = new QWidget(this);
    auto* layout = new QVBoxLayout(area);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(progress_, 1);
    progressRow->addWidget(best_);
    layout->addLayout(progressRow);
    layout->addWidget(message_);
    layout->addWidget(warning_);
    layout->addWidget(splitter, 1);
    return area;
}

QWidget* TuneDialog::createButtons()
{
    startButton_ = new QPushButton(tr("Start"), this);
    startButton_->setObjectName(QStringLiteral("tuneStart"));
    stopButton_ = new QPushButton(tr("Stop"), this);
    stopButton_->setObjectName(QStringLiteral("tuneStop"));
    stopButton_->setToolTip(tr("Stop searching and keep the best parameters found so far"));
    acceptButton_ = new QPushButton(tr("Use the tuned parameters"), this);
    acceptButton_->setObjectName(QStringLiteral("tuneAccept"));
    acceptButton_->setToolTip(tr("Make them the workspace's parameters (Edit > Undo brings the current ones back)"));
    rejectButton_ = new QPushButton(tr("Close"), this);
    rejectButton_->setObjectName(QStringLiteral("tuneReject"));
    startButton_->setDefault(true);
    connect(startButton_, &QPushButton::clicked, this, &TuneDialog::start);
    connect(stopButton_, &QPushButton::clicked, this, &TuneDialog::stop);
    connect(acceptButton_, &QPushButton::clicked, this, &TuneDialog::accept);
    connect(rejectButton_, &QPushButton::clicked, this, &TuneDialog::reject);
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(startButton_);
    layout->addWidget(stopButton_);
    layout->addStretch(1);
    layout->addWidget(acceptButton_);
    layout->addWidget(rejectButton_);
    return row;
}

std::shared_ptr<const Recording> TuneDialog::recordingToTune() const
{
    const std::shared_ptr<const Recording> recording = session_.recording();
    if (!recording || (recording->reference.closedLoop == closed_->isChecked()
                       && recording->reference.knownLength_m == length_->value()))
        return recording;
    auto said = std::make_shared<Recording>(*recording);
    said->reference.closedLoop = closed_->isChecked();
    said->reference.knownLength_m = length_->value();
    return said;
}

bool TuneDialog::isCriterionAvailable(TuneCriterion criterion) const
{
    return criteria_->isAvailable(criterion);
}

void TuneDialog::setCriterion(TuneCriterion criterion)
{
    criteria_->setCriterion(criterion);
}

TuneCriterion TuneDialog::criterion() const
{
    return criteria_->criterion();
}

void TuneDialog::setEvaluations(int evaluations)
{
    evaluations_->setValue(evaluations);
}

const TuneOutcome& TuneDialog::outcome() const
{
    return job_->result().outcome;
}

void TuneDialog::updateCriteria()
{
    const std::shared_ptr<const Recording> recording = session_.recording();
    if (!recording || recording->samples.size() < 2) {
        const QString none = tr("no recording is open");
        criteria_->setReasons({none, none, none});
    } else {
        criteria_->setReasons(
            {closed_->isChecked() ? QString() : tr("needs a walk that ends where it started: tick it if yours does"),
             length_->value() > 0.0 ? QString() : tr("needs the path length: enter it"),
             !recording->reference.positions_m.empty() ? QString()
                                                        : tr("needs reference positions: this recording has none")});
    }
    if (startButton_)
        startButton_->setEnabled(!isRunning() && isCriterionAvailable(criterion()));
}

void TuneDialog::start()
{
    if (isRunning() || !isCriterionAvailable(criterion()))
        return;
    base_ = session_.parameters();
    runCriterion_ = criterion();
    TuneOptions options;
    options.criterion = runCriterion_;
    options.evaluations = evaluations_->value();
    progress_->setRange(0, options.evaluations);
    progress_->setValue(0);
    best_->clear();
    warning_->hide();
    view_->setOverlays({});  // a previous run's paths give way to the current one
    if (session_.result())
        view_->setResult(session_.result());
    message_->setText(tr("Trying the current parameters, then a spread over the whole range..."));
    changes_->setRowCount(0);
    setStage(true, false);
    job_->start({recordingToTune()}, base_, options, true);
}

void TuneDialog::stop()
{
    if (!isRunning())
        return;
    job_->cancel();
    message_->setText(tr("Stopping; the best parameters so far are kept..."));
    stopButton_->setEnabled(false);
}

bool TuneDialog::isRunning() const
{
    return job_->isRunning();
}

void TuneDialog::showProgress(int evaluations, int budget, double bestScore)
{
    progress_->setRange(0, budget);
    progress_->setValue(evaluations);
    best_->setText(tr("Best so far: %1").arg(formatTuneScore(runCriterion_, bestScore)));
    message_->setText(tr("Searching around the best parameters found so far..."));
}

void TuneDialog::onFinished()
{
    showOutcome(job_->result());
    setStage(false, true);
    if (warning_->isVisibleTo(this))  // Enter should not take a suspect result
        rejectButton_->setDefault(true);
    emit tuningFinished();
}

void TuneDialog::showOutcome(const TuneJobResult& result)
{
    const TuneOutcome& outcome = result.outcome;
    if (!outcome.error.empty()) {
        message_->setText(QString::fromStdString(outcome.error));
        best_->clear();
        return;
    }
    progress_->setValue(outcome.evaluations);
    best_->setText(tr("Best: %1").arg(formatTuneScore(runCriterion_, outcome.bestScore)));
    const int changed = showTuneChanges(changes_, base_, outcome.best, runCriterion_, outcome.baseScore,
                                        outcome.bestScore);
    const QString how = outcome.cancelled ? tr("Stopped after %n evaluation(s).", nullptr, outcome.evaluations)
                                          : tr("Done: %n evaluation(s).", nullptr, outcome.evaluations);
    message_->setText(changed == 0 ? how + QLatin1Char(' ') + tr("No better parameters were found; the current ones stay.")
                                   : how + QLatin1Char(' ') + tr("The path with the tuned parameters, over the current one "
                                                                 "(orange). Use them, or keep the current ones."));
    if (changed > 0 && result.before && result.after) {
        showPathFigures(result.before->summary, result.after->summary);
        showPaths(result.before, result.after);
    }
    showCautions(outcome.cautions);
}

/// What tuning changed beyond the figure (strides split or lost), said before the parameters are
/// used, after the path-length warning when there is one.
void TuneDialog::showCautions(const std::vector<std::string>& cautions)
{
    if (cautions.empty())
        return;
    QStringList lines;
    if (warning_->isVisible() && !warning_->text().isEmpty())
        lines << warning_->text();
    lines << tr("Beware: the tuned parameters change the strides, not only the figure (a swing split in two or a "
                "stance lost looks like this):");
    for (const std::string& caution : cautions)
        lines << QString::fromStdString(caution);
    warning_->setText(lines.join(QLatin1Char('\n')));
    warning_->setVisible(true);
}

void TuneDialog::showPathFigures(const Summary& before, const Summary& after)
{
    // What the criterion does not say: a path that shrank also ends nearer its start.
    const auto metres = [](double value) { return tr("%1 m").arg(QLocale().toString(value, 'f', 2)); };
    addChangeRow(changes_, tr("Path length"), metres(before.pathLength_m), metres(after.pathLength_m),
                 tr("The estimated path's length, for comparison"), 1);
    addChangeRow(changes_, tr("End to start"), metres(before.endToStart_m), metres(after.endToStart_m),
                 tr("The distance from the path's end to its start, for comparison"), 2);
    changes_->resizeColumnsToContents();
    const double lengthChange = after.pathLength_m / before.pathLength_m - 1.0;
    const QString percent = QLocale().toString(std::abs(lengthChange) * 100.0, 'f', 0);
    warning_->setText(lengthChange < 0.0 ? tr("Beware: the tuned path is %1 % shorter than the current one; a smaller "
                                              "error may come from a path that shrank rather than from a better one.")
                                               .arg(percent)
                                         : tr("Beware: the tuned path is %1 % longer than the current one.").arg(percent));
    warning_->setVisible(runCriterion_ != TuneCriterion::KnownLength && std::abs(lengthChange) > kSuspectLengthChange);
}

void TuneDialog::showPaths(const std::shared_ptr<const Result>& before, const std::shared_ptr<const Result>& after)
{
    if (after->position_m.empty())
        return;
    view_->setResult(after);
    const std::shared_ptr<const Recording> recording = session_.recording();
    if (recording && !recording->reference.positions_m.empty())
        view_->setReference(alignReferenceToEstimate(recording->reference.positions_m, after->position_m));
    view_->setOverlays({{tr("Current parameters"), QColor(230, 120, 0), before->position_m}});
}

void TuneDialog::setStage(bool running, bool done)
{
    const bool better = done && outcome().error.empty() && outcome().best != base_;
    findChild<QWidget*>(QStringLiteral("tuneSettings"))->setEnabled(!running);
    startButton_->setEnabled(!running && isCriterionAvailable(criterion()));
    startButton_->setText(done ? tr("Start again") : tr("Start"));
    stopButton_->setEnabled(running);
    acceptButton_->setEnabled(better);
    acceptButton_->setDefault(better);
    rejectButton_->setText(better ? tr("Keep the current ones") : tr("Close"));
}

void TuneDialog::accept()
{
    if (isRunning() || !acceptButton_->isEnabled())
        return;
    session_.setParameters(outcome().best, tr("Tuned parameters"));
    QDialog::accept();
}

void TuneDialog::reject()
{
    job_->cancel();  // the destructor waits for the worker; nothing of the run is applied
    QDialog::reject();
}

}  // namespace footpath
