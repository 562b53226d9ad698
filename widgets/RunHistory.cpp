#include "RunHistory.h"

#include "metrics/Evaluation.h"

#include <QFont>
#include <QHeaderView>
#include <QHBoxLayout>
#include <QLocale>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace footpath {

RunFigures runFigures(const Result& result, const ResultEvaluation& evaluation)
{
    RunFigures figures;
    figures.pathLength_m = result.summary.pathLength_m;
    figures.endToStart_m = result.summary.endToStart_m;
    figures.steps = static_cast<int>(result.summary.steps);
    const GaitStatistics& statistics = evaluation.statistics;
    if (statistics.armse)
        figures.armse2d_m = statistics.armse->armse2d_m;
    if (statistics.distanceError)
        figures.referenceLength_m = statistics.distanceError->reference_m;
    return figures;
}

RunFigures runFigures(const Result& result, const Recording* recording)
{
    return runFigures(result, evaluate(result, recording));
}

Judgement judgeLowerIsBetter(double before, double after)
{
    if (!std::isfinite(before) || !std::isfinite(after) || before == after)
        return Judgement::Neither;
    return after < before ? Judgement::Better : Judgement::Worse;
}

Judgement judgePathLength(const RunFigures& before, const RunFigures& after)
{
    if (!std::isfinite(after.referenceLength_m))
        return Judgement::Neither;  // longer or shorter says nothing without the true length
    return judgeLowerIsBetter(std::abs(before.pathLength_m - after.referenceLength_m),
                              std::abs(after.pathLength_m - after.referenceLength_m));
}

// --- RunHistory -----------------------------------------------------------------------------------

void RunHistory::clear()
{
    beginResetModel();
    runs_.clear();
    nextNumber_ = 1;
    currentNumber_ = previousNumber_ = 0;
    endResetModel();
    emit currentChanged();
}

void RunHistory::record(std::shared_ptr<const Result> result, const Parameters& params, const RunFigures& figures,
                        const void* gesture, int undoIndex)
{
    const Run* now = current();
    // A slider still being dragged (one merged undo step): the run it started is updated.
    if (now && now == &runs_.back() && gesture && now->gesture == gesture && now->undoIndex == undoIndex) {
        Run& run = runs_.back();
        const Run* base = previous();
        run.parameters = params;
        run.change = base ? describeChange(base->parameters, params) : tr("First run");
        run.figures = figures;
        run.result = std::move(result);
        emit dataChanged(index(rowCount() - 1, 0), index(rowCount() - 1, ColumnCount - 1));
        emit currentChanged();
        return;
    }
    // Undo, redo or going back to a run: the run with these parameters again.
    const auto same = std::find_if(runs_.begin(), runs_.end(), [&params](const Run& run) { return run.parameters == params; });
    if (same != runs_.end()) {
        same->result = std::move(result);
        same->figures = figures;
        same->gesture = gesture;
        same->undoIndex = undoIndex;
        makeCurrent(static_cast<int>(same - runs_.begin()));
        return;
    }
    if (static_cast<int>(runs_.size()) >= kMaxRuns) {
        beginRemoveRows({}, 0, 0);
        runs_.pop_front();
        endRemoveRows();
    }
    Run run;
    run.number = nextNumber_++;
    run.parameters = params;
    run.change = now ? describeChange(now->parameters, params) : tr("First run");
    run.figures = figures;
    run.result = std::move(result);
    run.gesture = gesture;
    run.undoIndex = undoIndex;
    beginInsertRows({}, rowCount(), rowCount());
    runs_.push_back(std::move(run));
    endInsertRows();
    makeCurrent(rowCount() - 1);
}

void RunHistory::makeCurrent(int row)
{
    const int number = runs_[static_cast<std::size_t>(row)].number;
    if (number != currentNumber_) {
        previousNumber_ = currentNumber_;
        currentNumber_ = number;
    }
    emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1), {Qt::FontRole});
    emit currentChanged();
}

QString RunHistory::latestChange() const
{
    const Run* before = previous();
    const Run* now = current();
    if (!before || !now)
        return {};
    return now->number < before->number ? tr("Back to run %1: %2").arg(now->number).arg(describeChange(before->parameters, now->parameters))
                                        : describeChange(before->parameters, now->parameters);
}

const Run* RunHistory::runAt(int row) const
{
    return row >= 0 && row < rowCount() ? &runs_[static_cast<std::size_t>(row)] : nullptr;
}

int RunHistory::currentRow() const
{
    for (int row = 0; row < rowCount(); ++row)
        if (runs_[static_cast<std::size_t>(row)].number == currentNumber_)
            return row;
    return -1;
}

const Run* RunHistory::current() const
{
    return runAt(currentRow());
}

const Run* RunHistory::previous() const
{
    const auto run = std::find_if(runs_.begin(), runs_.end(), [this](const Run& r) { return r.number == previousNumber_; });
    return run == runs_.end() ? nullptr : &*run;
}

QString RunHistory::describeChange(const Parameters& from, const Parameters& to) const
{
    QStringList changes;
    for (const ParameterField& field : parameterFields()) {
        const double before = parameterValue(from, field), after = parameterValue(to, field);
        if (before == after)
            continue;
        const auto text = [&field](const Parameters& params, double value) {
            if (field.kind == ParameterField::Kind::Choice)
                return QString::fromStdString(choiceName(params, field));
            if (field.kind == ParameterField::Kind::Flag)
                return value != 0.0 ? tr("on") : tr("off");
            return QLocale().toString(value, 'g', 4);
        };
        changes << QStringLiteral("%1: %2 \u2192 %3")
                       .arg(QString::fromStdString(labelWithUnit(field)), text(from, before), text(to, after));
    }
    if (changes.size() > 2)
        return tr("%1; %2 and %n more", nullptr, static_cast<int>(changes.size() - 2)).arg(changes[0], changes[1]);
    return changes.isEmpty() ? tr("No change") : changes.join(QStringLiteral("; "));
}

int RunHistory::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(runs_.size());
}

int RunHistory::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

namespace {

QString metres(double value, int decimals)
{
    return std::isfinite(value) ? QLocale().toString(value, 'f', decimals) : QStringLiteral("\u2013");
}

}  // namespace

QVariant RunHistory::data(const QModelIndex& index, int role) const
{
    const Run* run = runAt(index.row());
    if (!run)
        return {};
    if (role == Qt::FontRole && run->number == currentNumber_) {
        QFont bold;
        bold.setBold(true);
        return bold;
    }
    if (role == Qt::ToolTipRole && index.column() == Change)
        return run->change;
    if (role == Qt::TextAlignmentRole && index.column() != Change)
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case Number: return run->number;
    case Change: return run->change;
    case PathLength: return metres(run->figures.pathLength_m, 2);
    case EndToStart: return metres(run->figures.endToStart_m, 2);
    case Armse: return metres(run->figures.armse2d_m, 3);
    case Steps: return run->figures.steps;
    default: return {};
    }
}

QVariant RunHistory::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Number: return tr("Run");
    case Change: return tr("Change");
    case PathLength: return tr("Path (m)");
    case EndToStart: return tr("End to start (m)");
    case Armse: return tr("ARMSE 2D (m)");
    case Steps: return tr("Steps");
    default: return {};
    }
}

// --- RunHistoryPanel ------------------------------------------------------------------------------

RunHistoryPanel::RunHistoryPanel(RunHistory* history, QWidget* parent)
    : QWidget(parent), history_(history), table_(new QTableView), goBack_(new QPushButton(tr("Go back to this run")))
{
    table_->setObjectName(QStringLiteral("runHistoryTable"));
    table_->setModel(history_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setSectionResizeMode(RunHistory::Change, QHeaderView::Stretch);
    table_->setToolTip(tr("The last %1 estimates of this recording (bold: the one shown). Double-click one to go "
                          "back to its parameters; Undo goes back too.")
                           .arg(RunHistory::kMaxRuns));
    goBack_->setObjectName(QStringLiteral("goBackToRun"));
    goBack_->setEnabled(false);
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(goBack_);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(table_, 1);
    layout->addLayout(buttons);
    connect(table_, &QTableView::activated, this, &RunHistoryPanel::chooseSelected);
    connect(goBack_, &QPushButton::clicked, this, &RunHistoryPanel::chooseSelected);
    connect(table_->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        const QModelIndexList rows = table_->selectionModel()->selectedRows();
        goBack_->setEnabled(!rows.isEmpty() && rows.first().row() != history_->currentRow());
    });
    connect(history_, &RunHistory::currentChanged, this, &RunHistoryPanel::showCurrent);
}

void RunHistoryPanel::showCurrent()
{
    if (const int row = history_->currentRow(); row >= 0)
        table_->scrollTo(history_->index(row, 0));
    const QModelIndexList rows = table_->selectionModel()->selectedRows();
    goBack_->setEnabled(!rows.isEmpty() && rows.first().row() != history_->currentRow());
}

void RunHistoryPanel::chooseSelected()
{
    const QModelIndexList rows = table_->selectionModel()->selectedRows();
    if (rows.isEmpty())
        return;
    if (const Run* run = history_->runAt(rows.first().row()); run && rows.first().row() != history_->currentRow())
        emit runChosen(run->parameters, run->number);
}

}  // namespace footpath
