#include "SummaryPanel.h"

#include "AnalysisSession.h"
#include "StepTableModel.h"

#include "MotionLanes.h"
#include "PlotInteraction.h"
#include "WarningOverlay.h"
#include "gait/GaitEvents.h"
#include "nav/Pipeline.h"

#include <QAbstractTableModel>
#include <QApplication>
#include <QBarSeries>
#include <QBarSet>
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QGridLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QLocale>
#include <QScrollArea>
#include <QScrollBar>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QStyle>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace footpath {

namespace {


/// Decimals that show every multiple of step exactly (0.25 -> 2, 0.5 -> 1, 2 -> 0).
int decimalsFor(double step)
{
    for (int decimals = 0; decimals < 9; ++decimals) {
        const double scaled = step * std::pow(10.0, decimals);
        if (std::abs(scaled - std::round(scaled)) < 1e-6 * scaled)
            return decimals;
    }
    return 9;
}

/// In the user's locale, never "-0.00", a dash where there is no figure.
QString number(double value, int decimals)
{
    return formatFigure(value, decimals, QLocale());
}

}  // namespace

// --- Construction -------------------------------------------------------------------------------

SummaryPanel::SummaryPanel(QWidget* parent) : QWidget(parent)
{
    strideLengthChart_ = createChartView(QStringLiteral("strideLengthChart"));
    stanceDurationChart_ = createChartView(QStringLiteral("stanceDurationChart"));
    strideLengthHistogram_ = createChartView(QStringLiteral("strideLengthHistogram"));
    stanceDurationHistogram_ = createChartView(QStringLiteral("stanceDurationHistogram"));
    gaitStanceChart_ = createChartView(QStringLiteral("gaitStanceChart"));
    clearanceChart_ = createChartView(QStringLiteral("clearanceChart"));
    strideLengthHistogram_->installEventFilter(this);
    stanceDurationHistogram_->installEventFilter(this);

    auto* tabs = new QTabWidget;
    tabs_ = tabs;
    tabs->setObjectName(QStringLiteral("summaryTabs"));
    tabs->addTab(createTable(), tr("Steps"));
    tabs->addTab(createChartPair(strideLengthChart_, stanceDurationChart_), tr("Per step"));
    tabs->addTab(createChartPair(strideLengthHistogram_, stanceDurationHistogram_), tr("Distributions"));
    tabs->addTab(createChartPair(gaitStanceChart_, clearanceChart_), tr("Gait"));

    connect(tabs, &QTabWidget::currentChanged, this, [this] {
        if (chartsStale_)
            showCharts();
    });

    auto* splitter = new QSplitter(Qt::Horizontal);
    splitter->addWidget(createFigures());
    splitter->addWidget(tabs);
    splitter->setStretchFactor(0, 0);
    splitter->setStretchFactor(1, 1);
    splitter->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(splitter);
    clear();
}

SummaryPanel::~SummaryPanel() = default;

bool SummaryPanel::showTab(const QString& name)
{
    static const QStringList names{QStringLiteral("steps"), QStringLiteral("per-step"), QStringLiteral("distributions"),
                                   QStringLiteral("gait")};  // in the order of the tabs
    const qsizetype index = names.indexOf(name);
    if (index < 0)
        return false;
    tabs_->setCurrentIndex(int(index));
    return true;
}

QWidget* SummaryPanel::createFigures()
{
    auto* walk = createFigureGroup(tr("Walk"), {{"pathLength", tr("Path length")},
                                                {"strides", tr("Stance phases / strides")},
                                                {"duration", tr("Duration")},
                                                {"cadence", tr("Cadence")},
                                                {"strideLength", tr("Stride length")},
                                                {"strideDuration", tr("Stride duration")},
                                                {"stanceDuration", tr("Stance duration")},
                                                {"endToStart", tr("End to start")}});
    referenceGroup_ = createFigureGroup(tr("Against the reference"), {{"armse2d", tr("ARMSE 2D")},
                                                                      {"armse3d", tr("ARMSE 3D")},
                                                                      {"loopClosure", tr("Loop closure")},
                                                                      {"distanceError", tr("Distance error")},
                                                                      {"gaitStance", tr("Gait stance P / R / F1")},
                                                                      {"stancePhases", tr("Strides in the trial")},
                                                                      {"stancePrecision", tr("At rest (ZUPT) precision")},
                                                                      {"stanceRecall", tr("At rest (ZUPT) recall")},
                                                                      {"stanceF1", tr("At rest (ZUPT) F1")}});
    const QString gaitStanceTip = tr("The gait events' stance (heel strike to toe off) against the labelled one, "
                                     "sample by sample: precision, recall and F1. This is the figure to compare "
                                     "with a gait lab's labels.");
    const QString restTip = tr("The detector's foot at rest (the zero-velocity updates) against the labelled "
                               "stance. The foot rests only in the middle of its stance, so the recall is low by "
                               "design; the precision says no swing was taken for rest.");
    figures_.at("gaitStance").name->setToolTip(gaitStanceTip);
    figures_.at("stancePhases").name->setToolTip(tr("Strides whose swing lies inside the labelled trial, "
                                                    "against the labelled swings there"));
    for (const char* key : {"stancePrecision", "stanceRecall", "stanceF1"})
        figures_.at(key).name->setToolTip(restTip);
    gaitGroup_ = createFigureGroup(tr("Gait (heel strike to toe off)"),
                                   {{"gaitStrides", tr("Strides")},
                                    {"gaitStrideTime", tr("Stride time")},
                                    {"gaitStrideLength", tr("Stride length")},
                                    {"gaitCadence", tr("Cadence")},
                                    {"gaitStanceSwing", tr("Stance / swing")},
                                    {"gaitClearance", tr("Foot clearance")}});
    gaitGroup_->setObjectName(QStringLiteral("gaitFigures"));
    gaitGroup_->setToolTip(tr("From the gait events (heel strike, toe off) of this foot: means over the strides "
                              "that neither turn nor pause"));
    bothFeetGroup_ = createFigureGroup(tr("Both feet"), {{"doubleSupport", tr("Double support")},
                                                         {"stanceLeftRight", tr("Stance left / right")},
                                                         {"symmetryStrideTime", tr("Symmetry: stride time")},
                                                         {"symmetryStrideLength", tr("Symmetry: stride length")},
                                                         {"symmetryStance", tr("Symmetry: stance")},
                                                         {"symmetrySwing", tr("Symmetry: swing")}});
    bothFeetGroup_->setObjectName(QStringLiteral("bothFeet"));
    bothFeetGroup_->setToolTip(tr("Double support: the share of the gait cycle both feet are on the ground. "
                                  "Symmetry index: 100 (left - right) / mean, 0 symmetric, positive: the left larger."));
    bothFeetNotes_ = new QLabel;
    bothFeetNotes_->setObjectName(QStringLiteral("bothFeetNotes"));
    bothFeetNotes_->setWordWrap(true);
    bothFeetGroup_->layout()->addWidget(bothFeetNotes_);
    bothFeetGroup_->hide();

    referenceNotes_ = new QLabel;
    referenceNotes_->setObjectName(QStringLiteral("referenceNotes"));
    referenceNotes_->setWordWrap(true);
    referenceNotes_->setForegroundRole(QPalette::PlaceholderText);
    referenceGroup_->layout()->addWidget(referenceNotes_);

    liveSource_ = new QLabel(tr("<b>Live session</b>: the figures of the estimate so far. The recorded walk's "
                                "return when its views are shown again."));
    liveSource_->setObjectName(QStringLiteral("liveSource"));
    liveSource_->setWordWrap(true);
    liveSource_->hide();

    // Two columns: in a dock a quarter of the screen high, one column of every group showed the
    // first few rows of the walk's figures and nothing of the gait's.
    auto* content = new QWidget;
    auto* columns = new QHBoxLayout(content);
    columns->setContentsMargins(0, 0, 0, 0);
    auto* left = new QVBoxLayout;
    left->addWidget(liveSource_);
    left->addWidget(createChangeGroup());
    left->addWidget(createWarnings());
    left->addWidget(createMotionAndNotes());
    left->addWidget(walk);
    left->addStretch(1);
    auto* right = new QVBoxLayout;
    right->addWidget(gaitGroup_);
    right->addWidget(bothFeetGroup_);
    right->addWidget(referenceGroup_);
    right->addStretch(1);
    columns->addLayout(left, 1);
    columns->addLayout(right, 1);
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(content);
    scroll->setMinimumWidth(content->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width());
    return scroll;
}

QGroupBox* SummaryPanel::createChangeGroup()
{
    changeGroup_ = createFigureGroup(tr("Last change"), {});
    changeGroup_->setObjectName(QStringLiteral("lastChange"));
    changeText_ = new QLabel;
    changeText_->setObjectName(QStringLiteral("changeText"));
    changeText_->setWordWrap(true);
    auto* grid = new QGridLayout;
    grid->setColumnStretch(1, 1);
    grid->setHorizontalSpacing(12);
    const std::pair<const char*, QString> rows[] = {{"pathLength", tr("Path length")},
                                                    {"endToStart", tr("End to start")},
                                                    {"armse2d", tr("ARMSE 2D")},
                                                    {"steps", tr("Steps")}};
    for (const auto& [key, name] : rows) {
        FigureRow row{new QLabel(name), new QLabel};
        row.value->setObjectName(QStringLiteral("change_") + key);
        row.value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        const int gridRow = grid->rowCount();
        grid->addWidget(row.name, gridRow, 0);
        grid->addWidget(row.value, gridRow, 1);
        changeFigures_[key] = row;
    }
    auto* layout = static_cast<QVBoxLayout*>(changeGroup_->layout());
    layout->insertWidget(0, changeText_);
    layout->addLayout(grid);
    changeGroup_->setToolTip(tr("The figures before and after the last parameter change (the grey ghost path). "
                                "Green: better, red: worse. The History lists every run."));
    changeGroup_->hide();
    return changeGroup_;
}

namespace {

QColor judgementColour(Judgement judgement, const QPalette& palette)
{
    switch (judgement) {
    case Judgement::Better: return QColor(27, 127, 59);
    case Judgement::Worse: return QColor(176, 0, 32);
    case Judgement::Neither: break;
    }
    return palette.color(QPalette::WindowText);
}

}  // namespace

void SummaryPanel::showChange(const RunFigures* before, const RunFigures& after, const QString& change)
{
    changeShown_ = before != nullptr;
    changeGroup_->setVisible(changeShown_ && !live_);  // a change of the recorded walk's parameters
    if (!before)
        return;
    changeText_->setText(change);
    const auto show = [this](const char* key, const QString& text, Judgement judgement) {
        QLabel* value = changeFigures_.at(key).value;
        value->setText(text);
        value->setProperty("judgement", judgement == Judgement::Better  ? QStringLiteral("better")
                                        : judgement == Judgement::Worse ? QStringLiteral("worse")
                                                                        : QStringLiteral("neither"));
        QPalette palette = value->palette();
        palette.setColor(QPalette::WindowText, judgementColour(judgement, this->palette()));
        value->setPalette(palette);
        changeFigures_.at(key).name->setVisible(!text.isEmpty());
        value->setVisible(!text.isEmpty());
    };
    const auto metres = [](double from, double to, int decimals) {
        return tr("%1 \u2192 %2 m").arg(number(from, decimals), number(to, decimals));
    };
    show("pathLength", metres(before->pathLength_m, after.pathLength_m, 2), judgePathLength(*before, after));
    show("endToStart", metres(before->endToStart_m, after.endToStart_m, 2),
         judgeLowerIsBetter(before->endToStart_m, after.endToStart_m));
    const bool armse = std::isfinite(before->armse2d_m) && std::isfinite(after.armse2d_m);
    show("armse2d", armse ? metres(before->armse2d_m, after.armse2d_m, 3) : QString(),
         judgeLowerIsBetter(before->armse2d_m, after.armse2d_m));
    show("steps", tr("%1 \u2192 %2").arg(before->steps).arg(after.steps), Judgement::Neither);
}

QWidget* SummaryPanel::createWarnings()
{
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    noWarnings_ = new QLabel(tr("No plausibility warnings"));
    noWarnings_->setObjectName(QStringLiteral("noWarnings"));
    noWarnings_->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(noWarnings_);

    warningsGroup_ = new QGroupBox;
    warningsGroup_->setObjectName(QStringLiteral("warnings"));
    // Light red, so the findings are seen before the figures they put in doubt.
    warningsGroup_->setStyleSheet(QStringLiteral("QGroupBox#warnings { background: #fff1ec; border: 1px solid #e3a08c; "
                                                 "border-radius: 3px; } QGroupBox#warnings QLabel { color: #3a0d05; }"));
    auto* groupLayout = new QVBoxLayout(warningsGroup_);
    auto* header = new QHBoxLayout;
    auto* icon = new QLabel;
    const int iconSize = style()->pixelMetric(QStyle::PM_SmallIconSize);
    icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(iconSize, iconSize));
    warningsTitle_ = new QLabel;
    warningsTitle_->setObjectName(QStringLiteral("warningsTitle"));
    QFont bold = warningsTitle_->font();
    bold.setBold(true);
    warningsTitle_->setFont(bold);
    header->addWidget(icon);
    header->addWidget(warningsTitle_, 1);
    groupLayout->addLayout(header);
    warningList_ = new QWidget;
    auto* listLayout = new QVBoxLayout(warningList_);
    listLayout->setContentsMargins(0, 0, 0, 0);
    groupLayout->addWidget(warningList_);
    layout->addWidget(warningsGroup_);
    return box;
}

QGroupBox* SummaryPanel::createFigureGroup(const QString& title, const std::vector<std::pair<QString, QString>>& rows)
{
    auto* group = new QGroupBox(title);
    auto* outer = new QVBoxLayout(group);
    auto* grid = new QGridLayout;
    grid->setColumnStretch(1, 1);
    grid->setHorizontalSpacing(12);
    for (const auto& [key, name] : rows) {
        FigureRow row{new QLabel(name), new QLabel};
        row.value->setObjectName(QStringLiteral("figure_") + key);
        row.name->setObjectName(QStringLiteral("figureName_") + key);
        row.value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        row.value->setWordWrap(true);  // a long figure ("... (26 strides)") wraps, never cut at the edge
        row.value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        // As wide as the longest figure, so none is clipped whatever the first result shows.
        row.value->setMinimumWidth(row.value->fontMetrics().horizontalAdvance(tr("000 steps/min (00.0 strides/min)")));
        const int gridRow = grid->rowCount();
        grid->addWidget(row.name, gridRow, 0);
        grid->addWidget(row.value, gridRow, 1);
        figures_[key] = row;
    }
    outer->addLayout(grid);
    return group;
}

QWidget* SummaryPanel::createTable()
{
    stepModel_ = new StepTableModel(this);
    auto* proxy = new QSortFilterProxyModel(this);
    proxy->setSourceModel(stepModel_);
    proxy->setSortRole(StepTableModel::kSortRole);
    table_ = new QTableView;
    table_->setObjectName(QStringLiteral("stepTable"));
    table_->setModel(proxy);
    table_->setSortingEnabled(true);
    table_->sortByColumn(StepTableModel::Number, Qt::AscendingOrder);
    table_->setAlternatingRowColors(true);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->verticalHeader()->hide();
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    // Columns share the width but never shrink below their titles (then the table scrolls).
    QHeaderView* header = table_->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::Stretch);
    int widestTitle = 0;
    for (int column = 0; column < StepTableModel::ColumnCount; ++column)
        widestTitle = std::max(widestTitle, header->fontMetrics().horizontalAdvance(
                                                stepModel_->headerData(column, Qt::Horizontal).toString()));
    header->setMinimumSectionSize(widestTitle + 28);  // room for the sort arrow
    // Selecting a step, by mouse or with the arrow keys, shows its moment; a click on the step
    // already selected shows it again (the cursor may have moved away since). A click on another
    // step asks twice for the same moment, which changes nothing the second time.
    const auto showStep = [this, proxy](const QModelIndex& index) {
        if (index.isValid())
            emit timeCursorRequested(stepModel_->stanceStart(proxy->mapToSource(index).row()));
    };
    connect(table_->selectionModel(), &QItemSelectionModel::currentRowChanged, this, showStep);
    connect(table_, &QTableView::clicked, this, showStep);
    return table_;
}

QWidget* SummaryPanel::createChartPair(QChartView* left, QChartView* right)
{
    auto* pair = new QWidget;
    auto* layout = new QHBoxLayout(pair);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(left);
    layout->addWidget(right);
    // In a low dock the charts scroll rather than shrink until Qt Charts elides every label, and
    // rather than holding the whole dock (and the plots above it) at their height.
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(pair);
    scroll->setMinimumHeight(60);
    return scroll;
}

QChartView* SummaryPanel::createChartView(const QString& objectName)
{
    auto* chart = new QChart;
    chart->legend()->hide();
    chart->setMargins(QMargins(2, 2, 2, 2));
    chart->setBackgroundRoundness(0);
    QFont titleFont = chart->titleFont();
    titleFont.setBold(true);
    chart->setTitleFont(titleFont);
    auto* view = new QChartView(chart);  // no setUseOpenGL: must work offscreen and over remote desktops
    view->setObjectName(objectName);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(240, 180);
    return view;
}

// --- Showing a result ---------------------------------------------------------------------------

void SummaryPanel::setRecording(std::shared_ptr<const Recording> recording)
{
    recordedRecording_ = std::move(recording);
    recordedEvaluation_.reset();  // evaluated against the recording before
    if (live_)
        return;  // kept for showRecorded()
    recording_ = recordedRecording_;
    evaluation_.reset();
    refresh();
}

void SummaryPanel::setResult(std::shared_ptr<const Result> result, std::shared_ptr<const ResultEvaluation> evaluation)
{
    recordedResult_ = std::move(result);
    recordedEvaluation_ = std::move(evaluation);
    if (live_)
        return;
    result_ = recordedResult_;
    evaluation_ = recordedEvaluation_;
    refresh();
}

void SummaryPanel::showLive(std::shared_ptr<const Result> live)
{
    live_ = true;
    result_ = std::move(live);
    evaluation_.reset();
    recording_.reset();  // the recorded walk's reference is not this session's
    liveSource_->show();
    changeGroup_->hide();
    refresh();
}

void SummaryPanel::showRecorded()
{
    if (!live_)
        return;
    live_ = false;
    result_ = recordedResult_;
    evaluation_ = recordedEvaluation_;
    recording_ = recordedRecording_;
    liveSource_->hide();
    changeGroup_->setVisible(changeShown_);
    refresh();
}

void SummaryPanel::clear()
{
    recordedRecording_.reset();
    recordedResult_.reset();
    recordedEvaluation_.reset();
    if (!live_) {
        recording_.reset();
        result_.reset();
        evaluation_.reset();
    }
    refresh();
}

void SummaryPanel::refresh()
{
    // A result without its evaluation (the live estimate, a caller of setResult without one) is
    // evaluated here, once per refresh.
    if (result_ && !evaluation_)
        evaluation_ = std::make_shared<const ResultEvaluation>(evaluate(*result_, recording_.get()));
    if (!result_)
        evaluation_.reset();
    stepModel_->setResult(result_);
    showWalkFigures();
    showGaitFigures();
    showBothFeetFigures();
    showReferenceFigures();
    showWarnings();
    showMotionAndNotes();
    // On screen with the step table in front, the charts wait for their tab: Qt Charts take tens
    // of milliseconds for a long walk's thousand steps, on every parameter change.
    chartsStale_ = isVisible() && tabs_->currentIndex() == 0;
    if (!chartsStale_)
        showCharts();
}

void SummaryPanel::showWarnings()
{
    qDeleteAll(warningList_->findChildren<QLabel*>(QString(), Qt::FindDirectChildrenOnly));
    const std::vector<PlausibilityWarning> none;
    const std::vector<PlausibilityWarning>& warnings = result_ ? result_->warnings : none;
    noWarnings_->setVisible(result_ && warnings.empty());
    warningsGroup_->setVisible(!warnings.empty());
    warningsTitle_->setText(tr("%n plausibility warning(s)", nullptr, static_cast<int>(warnings.size())));
    for (std::size_t i = 0; i < warnings.size(); ++i) {
        const PlausibilityWarning& w = warnings[i];
        // The span is a link: following it asks for the time cursor at the start of the finding.
        auto* label = new QLabel(QStringLiteral("<a href=\"%1\">%2</a> <b>%3</b>: %4")
                                     .arg(QString::number(i), warningSpanText(w), warningLabel(w.kind).toHtmlEscaped(),
                                          QString::fromStdString(w.message).toHtmlEscaped()));
        label->setObjectName(QStringLiteral("warning_%1").arg(i));
        label->setWordWrap(true);
        label->setTextInteractionFlags(Qt::LinksAccessibleByMouse | Qt::LinksAccessibleByKeyboard);
        label->setToolTip(tr("Click the time span to move the time cursor there"));
        connect(label, &QLabel::linkActivated, this, [this, start = w.start_s] { emit timeCursorRequested(start); });
        warningList_->layout()->addWidget(label);
    }
}

QWidget* SummaryPanel::createMotionAndNotes()
{
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    motionSentence_ = new QLabel;
    motionSentence_->setObjectName(QStringLiteral("motionSentence"));
    motionSentence_->setWordWrap(true);
    motionSentence_->setToolTip(MotionLanes::tr("Counted from the barometer's height between steps (Zheng et al. 2016); a floor "
                                                "is 3 m"));
    layout->addWidget(motionSentence_);
    methodNotesGroup_ = new QGroupBox(MotionLanes::tr("Method notes"));
    methodNotesGroup_->setObjectName(QStringLiteral("methodNotes"));
    methodNotesGroup_->setToolTip(MotionLanes::tr("Where a measurement method skipped itself or did not apply, and why"));
    methodNoteList_ = new QWidget;
    auto* listLayout = new QVBoxLayout(methodNoteList_);
    listLayout->setContentsMargins(0, 0, 0, 0);
    (new QVBoxLayout(methodNotesGroup_))->addWidget(methodNoteList_);
    layout->addWidget(methodNotesGroup_);
    return box;
}

void SummaryPanel::showMotionAndNotes()
{
    const QString sentence = result_ ? motionCountsSentence(*result_) : QString();
    motionSentence_->setText(sentence.isEmpty() ? QString()
                                                : MotionLanes::tr("<b>Motion</b> (barometer): %1").arg(sentence.toHtmlEscaped()));
    motionSentence_->setVisible(!sentence.isEmpty());
    // Without pressure the two columns would only hold dashes.
    const bool barometer = result_ && (hasBarometer(*result_) || hasMotionClasses(*result_));
    table_->setColumnHidden(StepTableModel::Motion, !barometer);
    table_->setColumnHidden(StepTableModel::BaroHeight, !barometer);

    qDeleteAll(methodNoteList_->findChildren<QLabel*>(QString(), Qt::FindDirectChildrenOnly));
    const std::vector<MethodNote> none;
    const std::vector<MethodNote>& notes = result_ ? result_->methodNotes : none;
    methodNotesGroup_->setVisible(!notes.empty());
    for (std::size_t i = 0; i < notes.size(); ++i) {
        const MethodNote& note = notes[i];
        // As the warnings: the span is a link to the moment.
        auto* label = new QLabel(QStringLiteral("<b>%1</b>, <a href=\"%2\">%3</a>: %4")
                                     .arg(methodLabel(note.method).toHtmlEscaped(), QString::number(i),
                                          methodNoteSpanText(note), QString::fromStdString(note.message).toHtmlEscaped()));
        label->setObjectName(QStringLiteral("methodNote_%1").arg(i));
        label->setWordWrap(true);
        label->setTextInteractionFlags(Qt::LinksAccessibleByMouse | Qt::LinksAccessibleByKeyboard);
        connect(label, &QLabel::linkActivated, this, [this, start = note.start_s] { emit timeCursorRequested(start); });
        methodNoteList_->layout()->addWidget(label);
    }
}

void SummaryPanel::setFigure(const QString& key, const QString& text)
{
    const FigureRow& row = figures_.at(key);
    row.value->setText(text);
}

/// What the stride count left out and why, for the tooltip of the count (empty when nothing was merged).
QString SummaryPanel::mergedMovementsText(const std::vector<MergedMovement>& merged)
{
    if (merged.empty())
        return {};
    QStringList lines{tr("Movements between stances that were no stride (under %1 m, or never turning at a "
                         "swing's %2 rad/s: shifting the weight while standing), merged into one stance:")
                          .arg(number(kMinStrideDistance_m, 2), number(kMinSwingRate_radps, 1))};
    constexpr std::size_t kListed = 12;
    for (std::size_t i = 0; i < std::min(merged.size(), kListed); ++i)
        lines << tr("%1-%2 s: %3 m, at most %4 rad/s")
                     .arg(number(merged[i].start_s, 2), number(merged[i].end_s, 2), number(merged[i].displacement_m, 3),
                          number(merged[i].peakRate_radps, 2));
    if (merged.size() > kListed)
        lines << tr("... and %1 more").arg(merged.size() - kListed);
    return lines.join(QLatin1Char('\n'));
}

void SummaryPanel::showWalkFigures()
{
    const GaitStatistics& s = statistics();
    if (!result_) {
        for (auto& [key, row] : figures_)
            row.value->setText(QStringLiteral("\u2013"));
        return;
    }
    setFigure("pathLength", tr("%1 m").arg(number(s.pathLength_m, 2)));
    const std::size_t merged = result_->mergedMovements.size();
    setFigure("strides", merged == 0 ? tr("%1 / %2").arg(s.stancePhases).arg(s.strides)
                                     : tr("%1 / %2 (%3 merged: no swing)").arg(s.stancePhases).arg(s.strides).arg(merged));
    figures_.at("strides").value->setToolTip(mergedMovementsText(result_->mergedMovements));
    setFigure("duration", tr("%1 s").arg(number(s.duration_s, 1)));
    setFigure("cadence", tr("%1 steps/min (%2 strides/min)")
                             .arg(number(s.cadence_stepsPerMin, 0), number(s.strideRate_perMin, 1)));
    setFigure("strideLength", tr("%1 \u00b1 %2 m").arg(number(s.meanStrideLength_m, 3), number(s.strideLengthStd_m, 3)));
    setFigure("strideDuration", tr("%1 s (median %2 s)")
                                    .arg(number(s.meanStrideDuration_s, 3), number(s.medianStrideDuration_s, 3)));
    setFigure("stanceDuration", tr("%1 s").arg(number(s.meanStanceDuration_s, 3)));
    setFigure("endToStart", tr("%1 m (%2 % of the path)").arg(number(s.endToStart_m, 2), number(s.endToStartPct, 2)));
}

void SummaryPanel::showGaitFigures()
{
    const bool shown = result_ && result_->gait.strides > 0;
    gaitGroup_->setVisible(shown);
    if (!shown)
        return;
    const GaitSummary& g = result_->gait;
    const bool means = g.straightStrides > 0;  // else every mean is a dash, not a zero
    const auto figure = [means](double value, int decimals) { return number(means ? value : GaitStatistics::kNone, decimals); };
    setFigure("gaitStrides", tr("%1 (%2 turning)").arg(g.strides).arg(g.turningStrides));
    setFigure("gaitStrideTime", tr("%1 s").arg(figure(g.strideTime_s, 3)));
    setFigure("gaitStrideLength", tr("%1 m").arg(figure(g.strideLength_m, 3)));
    setFigure("gaitCadence", tr("%1 steps/min").arg(figure(g.cadence_spm, 1)));
    setFigure("gaitStanceSwing", tr("%1 % / %2 %").arg(figure(g.stancePct, 1), figure(g.swingPct, 1)));
    setFigure("gaitClearance", tr("%1 m").arg(figure(g.clearance_m, 3)));
}

void SummaryPanel::setBothFeet(const std::optional<BilateralGait>& walk)
{
    bothFeet_ = walk;
    showBothFeetFigures();
}

void SummaryPanel::showBothFeetFigures()
{
    const bool shown = bothFeet_.has_value() && !live_;
    bothFeetGroup_->setVisible(shown);
    if (!shown)
        return;
    const BilateralGait& walk = *bothFeet_;
    const DoubleSupportSummary& ds = walk.doubleSupport;
    setFigure("doubleSupport", tr("%1 % of the gait cycle (%2 strides)").arg(number(ds.meanPct, 1)).arg(ds.cycles));
    const auto stance = [](const GaitSummary& g) { return number(g.straightStrides > 0 ? g.stancePct : GaitStatistics::kNone, 1); };
    setFigure("stanceLeftRight", tr("%1 % / %2 %").arg(stance(walk.left), stance(walk.right)));
    const auto index = [](double value) { return tr("%1 %").arg(number(value, 1)); };
    setFigure("symmetryStrideTime", index(walk.symmetry.strideTimePct));
    setFigure("symmetryStrideLength", index(walk.symmetry.strideLengthPct));
    setFigure("symmetryStance", index(walk.symmetry.stancePct));
    setFigure("symmetrySwing", index(walk.symmetry.swingPct));
    QStringList notes;
    for (const std::string& warning : walk.warnings)
        notes.append(QString::fromStdString(warning));
    bothFeetNotes_->setText(notes.join(QLatin1Char('\n')));
    bothFeetNotes_->setVisible(!notes.isEmpty());
}

void SummaryPanel::showReferenceFigures()
{
    const GaitStatistics& s = statistics();
    const auto showRow = [this](const QString& key, bool visible) {
        figures_.at(key).name->setVisible(visible);
        figures_.at(key).value->setVisible(visible);
    };
    showRow("armse2d", s.armse.has_value());
    showRow("armse3d", s.armse.has_value());
    showRow("loopClosure", s.loopClosure.has_value());
    showRow("distanceError", s.distanceError.has_value());
    for (const char* key : {"stancePrecision", "stanceRecall", "stanceF1", "stancePhases"})
        showRow(key, s.stanceScore.has_value());
    showRow("gaitStance", s.gaitStanceScore.has_value());
    referenceGroup_->setVisible(s.armse || s.loopClosure || s.distanceError || s.stanceScore);

    if (s.armse) {
        setFigure("armse2d", tr("%1 m").arg(number(s.armse->armse2d_m, 3)));
        setFigure("armse3d", tr("%1 m").arg(number(s.armse->armse3d_m, 3)));
    }
    if (s.loopClosure)
        setFigure("loopClosure", tr("%1 m (%2 % of %3 m)")
                                     .arg(number(s.loopClosure->dbse_m, 2), number(s.loopClosure->dbsePct, 2),
                                          number(s.loopClosure->lengthUsed_m, 1)));
    if (s.distanceError)
        setFigure("distanceError", tr("%1 m (%2 % of %3 m)")
                                       .arg(number(s.distanceError->error_m, 2), number(s.distanceError->errorPct, 2),
                                            number(s.distanceError->reference_m, 1)));
    if (s.stanceScore) {
        const StanceScore& score = *s.stanceScore;
        setFigure("stancePrecision", number(score.precision, 3));
        setFigure("stanceRecall", number(score.recall, 3));
        setFigure("stanceF1", number(score.f1, 3));
    }
    if (s.strideCount)
        setFigure("stancePhases", tr("%1 detected, %2 labelled swings").arg(s.strideCount->detected).arg(s.strideCount->labelled));
    if (s.gaitStanceScore)
        setFigure("gaitStance", tr("%1 / %2 / %3")
                                    .arg(number(s.gaitStanceScore->precision, 3), number(s.gaitStanceScore->recall, 3),
                                         number(s.gaitStanceScore->f1, 3)));
    QStringList notes;
    if (recording_ && referenceGroup_->isVisibleTo(this))
        for (const std::string& note : recording_->reference.notes)
            notes.append(QString::fromStdString(note));
    referenceNotes_->setText(notes.join(QLatin1Char('\n')));
    referenceNotes_->setVisible(!notes.isEmpty());
}

// --- Charts -------------------------------------------------------------------------------------

namespace {

void removeSeriesAndAxes(QChart* chart)
{
    chart->removeAllSeries();
    for (QAbstractAxis* axis : chart->axes()) {
        chart->removeAxis(axis);
        delete axis;
    }
}

void plainTitleFont(QAbstractAxis* axis)
{
    QFont font = axis->titleFont();
    font.setBold(false);
    axis->setTitleFont(font);
}

QValueAxis* addValueAxis(QChart* chart, Qt::Alignment alignment, const QString& title)
{
    auto* axis = new QValueAxis;
    axis->setTitleText(title);
    plainTitleFont(axis);
    chart->addAxis(axis, alignment);
    return axis;
}

/// A tick interval of 1, 2 or 5 times a power of ten giving at most about maxTicks ticks.
double tickInterval(double span, int maxTicks)
{
    const double raw = span / maxTicks;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double mantissa : {1.0, 2.0, 5.0})
        if (mantissa * power >= raw)
            return mantissa * power;
    return 10.0 * power;
}

/// Integer ticks (steps, counts) from low to high.
void setIntegerTicks(QValueAxis* axis, double low, double high)
{
    const double interval = std::max(1.0, tickInterval(std::max(1.0, high - low), 8));
    axis->setRange(low, high);
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0.0);
    axis->setTickInterval(interval);
    axis->setLabelFormat(QStringLiteral("%d"));
}

/// A value range around the data with some air, never below zero (lengths and durations); at least
/// 10 % of the largest value high so that tiny variation does not look dramatic.
void setDataRange(QValueAxis* axis, const std::vector<double>& values)
{
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    const double span = std::max({*high - *low, 0.1 * std::abs(*high), 1e-3});
    const double middle = (*low + *high) / 2.0;
    axis->setRange(std::max(0.0, middle - 0.6 * span), middle + 0.6 * span);
    axis->applyNiceNumbers();
}

}  // namespace

void SummaryPanel::showCharts()
{
    chartsStale_ = false;
    const GaitStatistics& s = statistics();
    // Strides start at the second stance (step 2 in the table); stance durations at the first.
    showPerStepChart(strideLengthChart_, tr("Stride length per step"), tr("Stride length (m)"), 2, s.strideLengths_m);
    showPerStepChart(stanceDurationChart_, tr("Stance duration per step"), tr("Stance duration (s)"), 1,
                     s.stanceDurations_s);
    showHistogram(strideLengthHistogram_, tr("Stride length"), tr("Stride length (m)"),
                  evaluation_ ? evaluation_->strideLengths : Histogram());
    showHistogram(stanceDurationHistogram_, tr("Stance duration"), tr("Stance duration (s)"),
                  evaluation_ ? evaluation_->stanceDurations : Histogram());
    std::vector<double> stancePct, clearance_m;
    static const std::vector<GaitStride> none;  // both branches lvalues: the strides are not copied
    for (const GaitStride& stride : result_ ? result_->gaitStrides : none) {
        stancePct.push_back(stride.stancePct);
        clearance_m.push_back(stride.clearance_m);
    }
    showPerStepChart(gaitStanceChart_, tr("Gait stance per stride (heel strike to toe off)"), tr("Stance (% of the stride)"),
                     1, stancePct, tr("Stride"));
    showPerStepChart(clearanceChart_, tr("Foot clearance per stride"), tr("Clearance (m)"), 1, clearance_m, tr("Stride"));
}

void SummaryPanel::showPerStepChart(QChartView* view, const QString& title, const QString& yTitle,
                                    std::size_t firstStep, const std::vector<double>& values, const QString& xTitle)
{
    QChart* chart = view->chart();
    removeSeriesAndAxes(chart);
    chart->setTitle(title);
    if (values.empty())
        return;
    auto* series = new QLineSeries;
    series->setPointsVisible(true);
    QList<QPointF> points;  // handed over at once: append() signals each of a long walk's thousand steps
    points.reserve(static_cast<qsizetype>(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
        points.append(QPointF(static_cast<double>(firstStep + i), values[i]));
    series->replace(points);
    chart->addSeries(series);
    QValueAxis* x = addValueAxis(chart, Qt::AlignBottom, xTitle.isEmpty() ? tr("Step") : xTitle);
    QValueAxis* y = addValueAxis(chart, Qt::AlignLeft, yTitle);
    series->attachAxis(x);
    series->attachAxis(y);
    setIntegerTicks(x, static_cast<double>(firstStep) - 0.5, static_cast<double>(firstStep + values.size()) - 0.5);
    setDataRange(y, values);
}

void SummaryPanel::showHistogram(QChartView* view, const QString& title, const QString& xTitle,
                                 const Histogram& histogram)
{
    QChart* chart = view->chart();
    removeSeriesAndAxes(chart);
    chart->setTitle(title);
    shownHistograms_[view] = histogram;
    view->setToolTip(histogram.below + histogram.above > 0
                         ? tr("Grey bars: %1 values below and %2 above the regular bins (outliers such as "
                              "the standing still at the start and end)")
                               .arg(histogram.below)
                               .arg(histogram.above)
                         : QString());
    if (histogram.counts.empty())
        return;
    // One bar per bin; values beyond the regular bins get a grey bar at either end.
    auto* bars = new QBarSet(title);
    bars->setSelectedColor(QColor(160, 160, 160));
    if (histogram.below > 0)
        bars->append(histogram.below);
    for (int count : histogram.counts)
        bars->append(count);
    if (histogram.above > 0)
        bars->append(histogram.above);
    if (histogram.below > 0)
        bars->selectBar(0);
    if (histogram.above > 0)
        bars->selectBar(bars->count() - 1);
    auto* series = new QBarSeries;
    series->append(bars);
    series->setBarWidth(0.95);  // bins touch, as in a histogram
    chart->addSeries(series);

    // Bars sit at 0, 1, ... on this axis; its labels mark the bin edges in data units.
    auto* x = new QCategoryAxis;
    x->setTitleText(xTitle);
    x->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
    plainTitleFont(x);
    chart->addAxis(x, Qt::AlignBottom);
    series->attachAxis(x);
    QValueAxis* y = addValueAxis(chart, Qt::AlignLeft, tr("Count"));
    series->attachAxis(y);
    const int most = std::max({histogram.below, histogram.above,
                               *std::max_element(histogram.counts.begin(), histogram.counts.end())});
    // Headroom to the next tick, so the tallest bar does not touch the top.
    const double interval = std::max(1.0, tickInterval(most, 6));
    setIntegerTicks(y, 0.0, (std::floor(most / interval) + 1.0) * interval);
    labelHistogramEdges(view);
}

void SummaryPanel::labelHistogramEdges(QChartView* view)
{
    const Histogram& histogram = shownHistograms_[view];
    const QList<QAbstractAxis*> axes = view->chart()->axes(Qt::Horizontal);
    auto* axis = axes.isEmpty() ? nullptr : qobject_cast<QCategoryAxis*>(axes.first());
    if (histogram.counts.empty() || !axis)
        return;
    const int decimals = decimalsFor(histogram.binWidth);
    const auto regularEdges = static_cast<int>(histogram.counts.size());
    const int bars = regularEdges + (histogram.below > 0) + (histogram.above > 0);
    const QString widest = number(histogram.lastEdge(), decimals);
    // Qt Charts elides a label wider than its category, so label only every few edges. The plot
    // area is not laid out yet during a resize; the view less the count axis is close.
    const double perBar = std::max(1.0, (view->width() - 70.0) / bars);
    const double needed = QFontMetrics(axis->labelsFont()).horizontalAdvance(widest) + 10.0;
    const int every = std::max(1, static_cast<int>(std::ceil(needed / perBar)));
    for (const QString& label : axis->categoriesLabels())
        axis->remove(label);
    // Bar k spans k - 0.5 to k + 0.5; the first regular edge follows the grey "below" bar.
    const double firstEdgeAt = histogram.below > 0 ? 0.5 : -0.5;
    axis->setStartValue(firstEdgeAt - 1e-6);  // the first label needs a category ending at its edge
    for (int edge = 0; edge <= regularEdges; edge += every) {
        const double value = histogram.firstEdge + edge * histogram.binWidth;
        axis->append(number(value, decimals), firstEdgeAt + edge);
    }
    axis->setRange(-0.5, bars - 0.5);
}

bool SummaryPanel::eventFilter(QObject* watched, QEvent* event)
{
    // Thin the edge labels to what fits instead of letting Qt Charts elide every one to "...".
    if (event->type() == QEvent::Resize && (watched == strideLengthHistogram_ || watched == stanceDurationHistogram_))
        labelHistogramEdges(static_cast<QChartView*>(watched));
    return QWidget::eventFilter(watched, event);
}

void SummaryPanel::showRecording(const AnalysisSession& session)
{
    setRecording(session.recording());
}

void SummaryPanel::showEstimate(const AnalysisSession& session)
{
    setResult(session.result(), session.evaluation());
}

}  // namespace footpath
