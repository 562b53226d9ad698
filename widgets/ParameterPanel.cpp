#include "ParameterPanel.h"

#include "ParameterFieldText.h"
#include "ParameterFieldValue.h"
#include "io/ParameterIo.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QFrame>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QWheelEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace footpath {

// --- ParameterPanel: construction ---------------------------------------------------------------

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent)
{
    for (const ParameterField& field : parameterFields()) {
        FieldRow row;
        row.field = &field;
        if (field.kind == ParameterField::Kind::Real)
            row.scale = SliderScale::forField(field, parameterValue(defaults_, field));
        rows_.push_back(row);
    }
    editThrottle_.setSingleShot(true);
    editThrottle_.setInterval(kEditInterval_ms);
    connect(&editThrottle_, &QTimer::timeout, this, &ParameterPanel::flushPendingEdit);

    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(ParameterFieldRows(*this, defaults_).createSections(rows_));
    for (std::size_t index = 0; index < rows_.size(); ++index)
        connectRow(index);
    // Never narrower than the fields: the horizontal scroll bar is off, so they would be clipped.
    scroll->setMinimumWidth(scroll->widget()->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width());
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(createButtonBar());
    problems_ = new QLabel;
    problems_->setObjectName(QStringLiteral("problems"));
    problems_->setWordWrap(true);
    problems_->setStyleSheet(QStringLiteral("color: #b00020;"));
    layout->addWidget(problems_);
    layout->addWidget(scroll, 1);

    setUndoStack(nullptr);
    setParameters(defaults_);
}

ParameterPanel::~ParameterPanel()
{
    // ~QWidget closes a top-level panel, which takes the focus from a value field; its
    // editingFinished would then call into this half-destroyed panel (rows_ already gone; the
    // sanitizer build caught it). Stop listening to the children first.
    for (QObject* child : findChildren<QObject*>())
        child->disconnect(this);
}

QWidget* ParameterPanel::createButtonBar()
{
    auto* bar = new QWidget;
    auto* layout = new QGridLayout(bar);
    layout->setContentsMargins(0, 0, 0, 0);
    undoButton_ = new QToolButton;
    undoButton_->setObjectName(QStringLiteral("undo"));
    redoButton_ = new QToolButton;
    redoButton_->setObjectName(QStringLiteral("redo"));
    auto* reset = new QPushButton(tr("Reset to defaults"));
    reset->setObjectName(QStringLiteral("resetAll"));
    reset->setToolTip(tr("Set every parameter back to its default value (one undo step)"));
    auto* load = new QPushButton(tr("Load preset..."));
    load->setObjectName(QStringLiteral("loadPreset"));
    auto* save = new QPushButton(tr("Save preset..."));
    save->setObjectName(QStringLiteral("savePreset"));
    // Two rows so the panel stays usable in a narrow dock.
    layout->addWidget(undoButton_, 0, 0);
    layout->addWidget(redoButton_, 0, 1);
    layout->addWidget(reset, 0, 2, 1, 2);
    layout->addWidget(load, 1, 0, 1, 3);
    layout->addWidget(save, 1, 3);
    layout->setColumnStretch(2, 1);
    layout->setColumnStretch(3, 1);
    connect(reset, &QPushButton::clicked, this, &ParameterPanel::resetAll);
    connect(load, &QPushButton::clicked, this, &ParameterPanel::chooseAndLoadPreset);
    connect(save, &QPushButton::clicked, this, &ParameterPanel::chooseAndSavePreset);
    return bar;
}

void ParameterPanel::connectRow(std::size_t rowIndex)
{
    const FieldRow& row = rows_[rowIndex];
    connect(row.reset, &QToolButton::clicked, this, [this, rowIndex] { resetField(rowIndex); });
    if (row.slider) {
        row.slider->installEventFilter(this);  // a wheel passing over it scrolls the panel
        connect(row.slider, &QSlider::valueChanged, this, [this, rowIndex](int position) { onSliderMoved(rowIndex, position); });
        connect(row.slider, &QSlider::sliderReleased, this, &ParameterPanel::flushPendingEdit);
    }
    if (row.edit) {
        row.edit->installEventFilter(this);  // Up/Down step the value finely
        connect(row.edit, &QLineEdit::editingFinished, this, [this, rowIndex] { onValueTyped(rowIndex); });
    }
    if (row.check)
        connect(row.check, &QCheckBox::toggled, this, [this, rowIndex](bool checked) { onFlagToggled(rowIndex, checked); });
    if (row.combo) {
        row.combo->installEventFilter(this);  // a wheel passing over it scrolls the panel
        connect(row.combo, &QComboBox::activated, this, [this, rowIndex](int index) { onChoiceChosen(rowIndex, index); });
    }
}

// --- Showing values ------------------------------------------------------------------------------

void ParameterPanel::setParameters(const Parameters& params)
{
    const Parameters shown = current_;
    current_ = params;
    for (FieldRow& row : rows_) {
        if (row.slider && row.slider->isSliderDown())
            current_.*row.field->real = shown.*row.field->real;  // the user's drag wins
        showValue(row);
    }
    showProblems();
    showApplicability();
}

void ParameterPanel::showProblems()
{
    // Each field is kept in its range, but combinations (C1's lower bound above its upper one)
    // can still be invalid: say so here rather than only in the failed estimate.
    const std::vector<std::string> problems = current_.validate();
    problems_->setText(problems.empty() ? QString() : QString::fromStdString(problems.front()));
    problems_->setVisible(!problems.empty());
}

namespace {

QString chosenDetectorLabel(const Parameters& params)
{
    const ParameterField* detector = findParameterField("detector");
    const auto index = static_cast<std::size_t>(params.detector);
    return detector && index < detector->choiceLabels.size() ? fieldText(detector->choiceLabels[index]) : QString();
}

/// Why the field has no effect with the other values of params (the field conditions of core's
/// methods say when the pipeline reads each field); empty when it has one.
QString notUsedBecause(const ParameterField& field, const Parameters& params)
{
    const FieldCondition* unmet = unmetCondition(field, params);
    if (!unmet)
        return {};
    const QString reason = QCoreApplication::translate("footpath::ParameterPanel", unmet->notUsedReason);
    return reason.contains(QLatin1String("%1")) ? reason.arg(chosenDetectorLabel(params)) : reason;
}

}  // namespace

void ParameterPanel::showApplicability()
{
    for (FieldRow& row : rows_) {
        const QString reason = notUsedBecause(*row.field, current_);
        const QString toolTip = reason.isEmpty() ? row.toolTip : row.toolTip + QStringLiteral("<br><i>%1</i>").arg(reason.toHtmlEscaped());
        for (QWidget* part : row.parts) {
            part->setEnabled(reason.isEmpty());
            if (part != row.reset)  // the reset button keeps its own "back to the default"
                part->setToolTip(toolTip);
        }
    }
}

void ParameterPanel::showValue(FieldRow& row)
{
    const double value = parameterValue(current_, *row.field);
    if (row.check) {
        const QSignalBlocker blocker(row.check);
        row.check->setChecked(value != 0.0);
    }
    if (row.combo) {
        const QSignalBlocker blocker(row.combo);
        row.combo->setCurrentIndex(static_cast<int>(value));
    }
    if (row.slider && !row.slider->isSliderDown()) {
        const QSignalBlocker blocker(row.slider);
        row.slider->setValue(row.scale.toPosition(value));
    }
    const bool beingTyped = row.edit && row.edit->hasFocus() && row.edit->isModified();
    if (row.edit && !beingTyped)
        row.edit->setText(formatValue(value));
    showModified(row);
}

void ParameterPanel::showModified(FieldRow& row)
{
    const bool modified = parameterValue(current_, *row.field) != parameterValue(defaults_, *row.field);
    QWidget* nameWidget = row.check ? static_cast<QWidget*>(row.check) : row.label;
    QFont font = nameWidget->font();
    font.setBold(modified);
    nameWidget->setFont(font);
    row.reset->setVisible(modified);
}

// --- User edits ----------------------------------------------------------------------------------

void ParameterPanel::onSliderMoved(std::size_t rowIndex, int position)
{
    FieldRow& row = rows_[rowIndex];
    const double value = row.scale.toValue(position);
    storeValue(row, value);
    row.edit->setText(formatValue(value));
    showModified(row);
    emitThrottled(QString::fromUtf8(row.field->name), value);
}

void ParameterPanel::onValueTyped(std::size_t rowIndex)
{
    FieldRow& row = rows_[rowIndex];
    if (!row.edit->isModified())
        return;  // focus left without a change: nothing to report
    row.edit->setModified(false);
    bool ok = false;
    const double typed = numberLocale().toDouble(row.edit->text(), &ok);
    const double previous = parameterValue(current_, *row.field);
    // Out-of-range numbers are pulled to the nearest limit rather than sent on to fail the estimate.
    const double value = ok ? std::clamp(typed, row.field->minimum, row.field->maximum) : previous;
    storeValue(row, value);
    showValue(row);
    if (value != previous) {
        flushPendingEdit();
        emitNow(QString::fromUtf8(row.field->name), value);
    }
}

void ParameterPanel::onFlagToggled(std::size_t rowIndex, bool checked)
{
    FieldRow& row = rows_[rowIndex];
    storeValue(row, checked ? 1.0 : 0.0);
    showModified(row);
    flushPendingEdit();
    emitNow(QString::fromUtf8(row.field->name), checked ? 1.0 : 0.0);
}

void ParameterPanel::onChoiceChosen(std::size_t rowIndex, int index)
{
    FieldRow& row = rows_[rowIndex];
    const double previous = parameterValue(current_, *row.field);
    if (index < 0 || index == static_cast<int>(previous))
        return;  // the same choice again is no change
    storeValue(row, index);
    showModified(row);
    flushPendingEdit();
    emitNow(QString::fromUtf8(row.field->name), index);
}

void ParameterPanel::resetField(std::size_t rowIndex)
{
    FieldRow& row = rows_[rowIndex];
    const double value = parameterValue(defaults_, *row.field);
    storeValue(row, value);
    showValue(row);
    flushPendingEdit();
    emitNow(QString::fromUtf8(row.field->name), value);
}

void ParameterPanel::storeValue(const FieldRow& row, double value)
{
    setParameterValue(current_, *row.field, value);
    showProblems();
    showApplicability();
}

// --- Emitting: a dragged slider reports at most every kEditInterval_ms, and always its last value.

void ParameterPanel::emitThrottled(const QString& name, double value)
{
    if (hasPendingEdit_ && pendingName_ != name)
        flushPendingEdit();
    if (editThrottle_.isActive()) {
        hasPendingEdit_ = true;
        pendingName_ = name;
        pendingValue_ = value;
        return;
    }
    emitNow(name, value);
}

void ParameterPanel::flushPendingEdit()
{
    if (!hasPendingEdit_)
        return;
    hasPendingEdit_ = false;
    emitNow(pendingName_, pendingValue_);
}

void ParameterPanel::emitNow(const QString& name, double value)
{
    editThrottle_.start();
    emit parameterEdited(name, value);
}

// --- Whole sets: reset and presets ---------------------------------------------------------------

void ParameterPanel::resetAll()
{
    hasPendingEdit_ = false;  // superseded by the reset
    setParameters(defaults_);
    emit parametersReplaced(defaults_, tr("Reset parameters to defaults"));
}

bool ParameterPanel::savePreset(const QString& path)
{
    const std::string error = saveParameters(path.toStdString(), current_);
    presetError_ = QString::fromStdString(error);
    return error.empty();
}

bool ParameterPanel::loadPreset(const QString& path)
{
    Parameters loaded = current_;
    if (const std::string error = loadParameters(path.toStdString(), loaded); !error.empty()) {
        presetError_ = QString::fromStdString(error);
        return false;
    }
    if (const std::vector<std::string> problems = loaded.validate(); !problems.empty()) {
        presetError_ = tr("%1 sets values the estimate cannot use: %2")
                           .arg(path, QString::fromStdString(problems.front()));
        return false;
    }
    presetError_.clear();
    hasPendingEdit_ = false;
    setParameters(loaded);
    emit parametersReplaced(loaded, tr("Load preset %1").arg(QFileInfo(path).fileName()));
    return true;
}

void ParameterPanel::chooseAndLoadPreset()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Load parameter preset"), lastPresetDir_,
                                                      tr("Parameter presets (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    lastPresetDir_ = QFileInfo(path).absolutePath();
    if (!loadPreset(path))
        QMessageBox::warning(this, tr("Load preset"), tr("The preset was not loaded.\n\n%1").arg(presetError_));
}

void ParameterPanel::chooseAndSavePreset()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save parameter preset"), lastPresetDir_,
                                                tr("Parameter presets (*.json)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    lastPresetDir_ = QFileInfo(path).absolutePath();
    if (!savePreset(path))
        QMessageBox::warning(this, tr("Save preset"), tr("The preset was not saved.\n\n%1").arg(presetError_));
}

// --- Undo/Redo ---------------------------------------------------------------------------------

void ParameterPanel::setUndoStack(QUndoStack* stack)
{
    delete undoAction_;
    delete redoAction_;
    if (stack) {
        undoAction_ = stack->createUndoAction(this, tr("Undo"));
        redoAction_ = stack->createRedoAction(this, tr("Redo"));
    } else {
        undoAction_ = new QAction(tr("Undo"), this);
        redoAction_ = new QAction(tr("Redo"), this);
        undoAction_->setEnabled(false);
        redoAction_->setEnabled(false);
    }
    undoAction_->setIcon(QIcon::fromTheme(QStringLiteral("edit-undo"), style()->standardIcon(QStyle::SP_ArrowBack)));
    redoAction_->setIcon(QIcon::fromTheme(QStringLiteral("edit-redo"), style()->standardIcon(QStyle::SP_ArrowForward)));
    // No shortcut on the actions: the main window's Edit menu binds the same keys, and two actions
    // with one shortcut cancel each other out (Qt reports them ambiguous). event() handles the keys.
    undoButton_->setDefaultAction(undoAction_);
    redoButton_->setDefaultAction(redoAction_);
}

bool ParameterPanel::event(QEvent* event)
{
    // Claiming Undo/Redo before the shortcut map sees them makes them work while the focus is in
    // the panel, whether or not the window has its own Undo. A line edit claims them first for
    // its own text, as users expect.
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo)) {
            event->accept();
            return true;
        }
    }
    return QWidget::event(event);
}

void ParameterPanel::keyPressEvent(QKeyEvent* event)
{
    QAction* action = event->matches(QKeySequence::Undo)   ? undoAction_
                      : event->matches(QKeySequence::Redo) ? redoAction_
                                                           : nullptr;
    if (!action) {
        QWidget::keyPressEvent(event);
        return;
    }
    if (action->isEnabled())
        action->trigger();
    event->accept();
}

bool ParameterPanel::stepValueField(QObject* watched, QEvent* event)
{
    const auto row = std::find_if(rows_.begin(), rows_.end(), [watched](const FieldRow& r) { return r.edit == watched; });
    if (row == rows_.end() || !row->edit->isEnabled())
        return false;
    int positions = 0;
    if (event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        positions = key == Qt::Key_Up ? 1 : key == Qt::Key_Down ? -1 : key == Qt::Key_PageUp ? row->slider->pageStep()
                  : key == Qt::Key_PageDown ? -row->slider->pageStep() : 0;
    } else if (event->type() == QEvent::Wheel && row->edit->hasFocus()) {
        const int delta = static_cast<QWheelEvent*>(event)->angleDelta().y();
        positions = delta > 0 ? 1 : delta < 0 ? -1 : 0;
    }
    if (positions == 0)
        return false;
    // A value typed but not yet confirmed is the one to step from.
    onValueTyped(static_cast<std::size_t>(row - rows_.begin()));
    row->slider->setValue(row->slider->value() + positions);  // reports through onSliderMoved
    row->edit->selectAll();
    return true;
}

bool ParameterPanel::eventFilter(QObject* watched, QEvent* event)
{
    if (stepValueField(watched, event))
        return true;
    // A wheel over a slider or combo box the user has not clicked scrolls the panel instead:
    // otherwise scrolling through the list silently changes whichever parameter passes under the
    // pointer.
    if (event->type() == QEvent::Wheel) {
        const bool changesOnWheel = qobject_cast<QSlider*>(watched) || qobject_cast<QComboBox*>(watched);
        if (auto* widget = qobject_cast<QWidget*>(watched); changesOnWheel && !widget->hasFocus()) {
            event->ignore();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace footpath
