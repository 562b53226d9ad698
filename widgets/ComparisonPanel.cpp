#include "ComparisonPanel.h"

#include "methods/MethodRegistry.h"

#include <QFont>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <qcustomplot.h>

#include <algorithm>

namespace footpath {

namespace {

constexpr int kSpecRole = Qt::UserRole;

}  // namespace

ComparisonPanel::ComparisonPanel(QWidget* parent) : QWidget(parent)
{
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->setObjectName(QStringLiteral("comparisonSplitter"));
    splitter->addWidget(createSetColumn());
    splitter->addWidget(createResultArea());
    splitter->setStretchFactor(0, 0);
    splitter->setStretchFactor(1, 1);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(splitter);
    for (const MethodSet& set : suggestedMethodSets(base_))
        addSetItem(set, true);
    connect(&watcher_, &QFutureWatcher<std::vector<ComparisonRow>>::finished, this, &ComparisonPanel::onRunFinished);
    showBusy(false);
    updateStaleHint();
}

ComparisonPanel::~ComparisonPanel()
{
    if (cancelRun_)
        cancelRun_->store(true);
    watcher_.waitForFinished();
}

QWidget* ComparisonPanel::createSetColumn()
{
    auto* column = new QWidget(this);
    auto* layout = new QVBoxLayout(column);
    layout->setContentsMargins(0, 0, 0, 0);
    setList_ = new QListWidget(column);
    setList_->setObjectName(QStringLiteral("comparisonSets"));
    setList_->setToolTip(tr("Method sets to compare; tick the ones to run"));
    customEdit_ = new QLineEdit(column);
    customEdit_->setObjectName(QStringLiteral("customSet"));
    customEdit_->setPlaceholderText(tr("Add a set, e.g. zupt,hdr,mag"));
    customEdit_->setToolTip(tr("Methods separated by commas: %1. Enter adds the set.")
                                .arg(QString::fromStdString(methodSetTokensText())));
    customError_ = new QLabel(column);
    customError_->setObjectName(QStringLiteral("customSetError"));
    customError_->setWordWrap(true);
    customError_->setStyleSheet(QStringLiteral("color: #b00020;"));
    customError_->hide();
    connect(customEdit_, &QLineEdit::returnPressed, this, [this] {
        if (addCustomSet(customEdit_->text()).isEmpty())
            customEdit_->clear();
    });
    connect(customEdit_, &QLineEdit::textEdited, customError_, &QLabel::hide);

    runButton_ = new QPushButton(tr("Run"), column);
    runButton_->setObjectName(QStringLiteral("runComparison"));
    runButton_->setToolTip(tr("Run every ticked set on the current recording"));
    cancelButton_ = new QPushButton(tr("Cancel"), column);
    cancelButton_->setObjectName(QStringLiteral("cancelComparison"));
    busy_ = new QProgressBar(column);
    busy_->setRange(0, 0);  // the runs report no common progress: a busy indicator
    busy_->setMaximumHeight(10);
    busy_->setTextVisible(false);
    connect(runButton_, &QPushButton::clicked, this, &ComparisonPanel::run);
    connect(cancelButton_, &QPushButton::clicked, this, &ComparisonPanel::cancel);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(runButton_);
    buttons->addWidget(cancelButton_);

    hint_ = new QLabel(column);
    hint_->setObjectName(QStringLiteral("comparisonHint"));
    hint_->setWordWrap(true);

    layout->addWidget(setList_, 1);
    layout->addWidget(customEdit_);
    layout->addWidget(customError_);
    layout->addLayout(buttons);
    layout->addWidget(busy_);
    layout->addWidget(hint_);
    column->setMinimumWidth(190);
    column->setMaximumWidth(320);
    return column;
}

QWidget* ComparisonPanel::createResultArea()
{
    auto* area = new QSplitter(Qt::Horizontal, this);
    auto* tableSide = new QWidget(area);
    auto* layout = new QVBoxLayout(tableSide);
    layout->setContentsMargins(0, 0, 0, 0);
    table_ = new QTableWidget(tableSide);
    table_->setObjectName(QStringLiteral("comparisonTable"));
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->verticalHeader()->hide();
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);  // more rows in a low dock
    table_->setToolTip(tr("Click a row to make its methods the workspace's parameters (Edit > Undo goes back)"));
    connect(table_, &QTableWidget::cellClicked, this, [this](int row, int) { chooseRow(row); });
    useButton_ = new QPushButton(tr("Use as main result"), tableSide);
    useButton_->setObjectName(QStringLiteral("useComparisonRow"));
    useButton_->setToolTip(tr("Make the selected set's methods the workspace's parameters"));
    connect(useButton_, &QPushButton::clicked, this, [this] { chooseRow(table_->currentRow()); });
    layout->addWidget(table_, 1);
    layout->addWidget(useButton_, 0, Qt::AlignLeft);

    heightPlot_ = new QCustomPlot(area);
    heightPlot_->setObjectName(QStringLiteral("comparisonHeights"));
    heightPlot_->xAxis->setLabel(tr("time (s)"));
    heightPlot_->yAxis->setLabel(tr("height z (m)"));
    heightPlot_->legend->setVisible(false);  // the colours are the table's and the paths' legend
    heightPlot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    heightPlot_->setMinimumWidth(220);
    area->addWidget(tableSide);
    area->addWidget(heightPlot_);
    area->setStretchFactor(0, 3);
    area->setStretchFactor(1, 2);
    return area;
}

void ComparisonPanel::addSetItem(const MethodSet& set, bool checked)
{
    const QString spec = QString::fromStdString(set.name);
    for (int i = 0; i < setList_->count(); ++i) {
        if (setList_->item(i)->data(kSpecRole).toString() == spec) {
            setList_->item(i)->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
            return;
        }
    }
    auto* item = new QListWidgetItem(methodSetText(set.name), setList_);
    item->setData(kSpecRole, spec);
    item->setToolTip(spec);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsSelectable);
    item->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

QString ComparisonPanel::addCustomSet(const QString& spec)
{
    std::string error;
    const std::optional<MethodSet> set = parseMethodSet(spec.toStdString(), base_, error);
    if (!set) {
        customError_->setText(QString::fromStdString(error));
        customError_->show();
        return customError_->text();
    }
    customError_->hide();
    addSetItem(*set, true);
    return {};
}

QString ComparisonPanel::setCheckedSets(const QString& specs)
{
    std::string error;
    const std::vector<MethodSet> sets = parseMethodSets(specs.toStdString(), base_, error);
    if (sets.empty())
        return QString::fromStdString(error);
    for (int i = 0; i < setList_->count(); ++i)
        setList_->item(i)->setCheckState(Qt::Unchecked);
    for (const MethodSet& set : sets)
        addSetItem(set, true);
    return {};
}

QString ComparisonPanel::checkedSets() const
{
    QStringList specs;
    for (int i = 0; i < setList_->count(); ++i)
        if (setList_->item(i)->checkState() == Qt::Checked)
            specs << setList_->item(i)->data(kSpecRole).toString();
    return specs.join(QLatin1Char(';'));
}

void ComparisonPanel::setRecording(std::shared_ptr<const Recording> recording)
{
    recording_ = std::move(recording);
    if (isRunning()) {
        dropRunningResult_ = true;  // its rows belong to the old recording
        cancelRun_->store(true);
    }
    clearRows();
    if (runWhenRecordingArrives_ && recording_ && !isRunning()) {
        runWhenRecordingArrives_ = false;
        run();
    }
}

void ComparisonPanel::setBaseParameters(const Parameters& params)
{
    base_ = params;
    updateStaleHint();
}

void ComparisonPanel::run()
{
    if (!recording_ || isRunning()) {
        runWhenRecordingArrives_ = true;  // started by setRecording or when this run ends
        return;
    }
    std::string error;
    const std::vector<MethodSet> sets = parseMethodSets(checkedSets().toStdString(), base_, error);
    if (sets.empty()) {
        hint_->setText(tr("Tick at least one method set."));
        return;
    }
    runBase_ = base_;
    dropRunningResult_ = false;
    cancelRun_ = std::make_shared<std::atomic<bool>>(false);
    watcher_.setFuture(QtConcurrent::run(
        [recording = recording_, sets, cancel = cancelRun_] { return runComparison(*recording, sets, 0, cancel.get()); }));
    showBusy(true);
}

void ComparisonPanel::cancel()
{
    runWhenRecordingArrives_ = false;
    if (isRunning())
        cancelRun_->store(true);
}

bool ComparisonPanel::isRunning() const
{
    return watcher_.isRunning();
}

void ComparisonPanel::onRunFinished()
{
    showBusy(false);
    if (!dropRunningResult_) {
        rows_ = watcher_.result();
        stale_ = false;
        showRows();
        emit rowsChanged();
    }
    dropRunningResult_ = false;
    updateStaleHint();
    if (runWhenRecordingArrives_ && recording_) {
        runWhenRecordingArrives_ = false;
        run();
        return;
    }
    emit finished();
}

void ComparisonPanel::clearRows()
{
    rows_.clear();
    stale_ = false;
    showRows();
    updateStaleHint();
    emit rowsChanged();
}

void ComparisonPanel::showRows()
{
    const std::vector<ComparisonColumn> columns = comparisonColumns(rows_);
    table_->clear();
    table_->setColumnCount(static_cast<int>(columns.size()));
    table_->setRowCount(static_cast<int>(rows_.size()));
    QStringList titles;
    for (const ComparisonColumn& column : columns)
        titles << column.title;
    table_->setHorizontalHeaderLabels(titles);
    for (int r = 0; r < table_->rowCount(); ++r)
        fillTableRow(r, columns);
    for (std::size_t c = 0; c < columns.size(); ++c) {
        const int best = bestRowOfColumn(rows_, columns[c]);
        if (best < 0)
            continue;
        QTableWidgetItem* item = table_->item(best, static_cast<int>(c));
        QFont font = item->font();
        font.setBold(true);
        item->setFont(font);
        item->setText(item->text() + bestMarker());
        item->setToolTip(tr("best"));
    }
    table_->resizeColumnsToContents();
    useButton_->setEnabled(!rows_.empty());
    plotHeights();
}

void ComparisonPanel::fillTableRow(int r, const std::vector<ComparisonColumn>& columns)
{
    const ComparisonRow& row = rows_[static_cast<std::size_t>(r)];
    const QString problem = comparisonRowProblem(row);
    for (std::size_t c = 0; c < columns.size(); ++c) {
        auto* item = new QTableWidgetItem(columns[c].text(row));
        if (c > 0 && c + 1 < columns.size())
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (!problem.isEmpty())
            item->setForeground(QColor(176, 0, 32));
        table_->setItem(r, static_cast<int>(c), item);
    }
    // The set's name in its path colour: the table is the overlays' key too.
    QTableWidgetItem* name = table_->item(r, 0);
    name->setForeground(problem.isEmpty() ? comparisonColour(static_cast<std::size_t>(r)) : QColor(176, 0, 32));
    name->setToolTip(QString::fromStdString(row.set.name));
    if (!problem.isEmpty())
        table_->item(r, static_cast<int>(columns.size()) - 1)->setToolTip(problem);
    else if (!row.output.result.warnings.empty())
        table_->item(r, static_cast<int>(columns.size()) - 1)
            ->setToolTip(QString::fromStdString(row.output.result.warnings.front().message));
}

void ComparisonPanel::plotHeights()
{
    heightPlot_->clearGraphs();
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        const Result& result = rows_[i].output.result;
        if (!comparisonRowProblem(rows_[i]).isEmpty() || result.time_s.size() != result.position_m.size())
            continue;
        QVector<double> t, z;
        t.reserve(static_cast<qsizetype>(result.time_s.size()));
        z.reserve(t.capacity());
        for (std::size_t k = 0; k < result.time_s.size(); ++k) {
            t << result.time_s[k];
            z << result.position_m[k].z();
        }
        QCPGraph* graph = heightPlot_->addGraph();
        graph->setName(methodSetText(rows_[i].set.name));
        graph->setPen(QPen(comparisonColour(i), 1.2));
        graph->setData(t, z, true);
    }
    heightPlot_->rescaleAxes();
    heightPlot_->yAxis->scaleRange(1.1);
    heightPlot_->replot();
}

std::vector<PathOverlay> ComparisonPanel::overlays() const
{
    std::vector<PathOverlay> paths;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        if (comparisonRowProblem(rows_[i]).isEmpty())
            paths.push_back({methodSetText(rows_[i].set.name), comparisonColour(i), rows_[i].output.result.position_m});
    }
    return paths;
}

void ComparisonPanel::showBusy(bool busy)
{
    busy_->setVisible(busy);
    cancelButton_->setEnabled(busy);
    runButton_->setEnabled(!busy);
    if (busy)
        hint_->setText(tr("Running %n set(s)...", nullptr, static_cast<int>(checkedSets().split(';').size())));
}

void ComparisonPanel::updateStaleHint()
{
    if (isRunning())
        return;
    // Choosing a row's set makes the workspace's parameters that set's: not a reason to rerun.
    const bool baseIsARowsSet = std::any_of(rows_.cbegin(), rows_.cend(),
                                            [this](const ComparisonRow& row) { return row.set.params == base_; });
    stale_ = !rows_.empty() && !(base_ == runBase_) && !baseIsARowsSet;
    hint_->setStyleSheet(stale_ ? QStringLiteral("color: #8a5a00;") : QString());
    if (stale_)
        hint_->setText(tr("Stale: the parameters changed since this comparison. Run again to update it."));
    else if (!recording_)
        hint_->setText(tr("Open a recording to compare methods on it."));
    else if (rows_.empty())
        hint_->setText(tr("Tick the sets and press Run."));
    else
        hint_->setText(tr("Click a row to use its methods."));
}

void ComparisonPanel::chooseRow(int row)
{
    if (row < 0 || row >= static_cast<int>(rows_.size()))
        return;
    const ComparisonRow& chosen = rows_[static_cast<std::size_t>(row)];
    emit parametersChosen(chosen.set.params, methodSetText(chosen.set.name));
}

}  // namespace footpath
