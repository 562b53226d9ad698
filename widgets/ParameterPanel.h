#pragma once

#include "ParameterFieldRows.h"
#include "nav/Parameters.h"

#include <QString>
#include <QTimer>
#include <QWidget>

#include <vector>

class QAction;
class QKeyEvent;
class QLabel;
class QToolButton;
class QUndoStack;

namespace footpath {

/// Every parameter of parameterFields() as a slider with a numeric field (reals), a check box
/// (flags) or a combo box (choices), grouped by ParameterField::group in collapsible sections.
/// Built from the field list alone, so a new field appears without changes here. A field that has
/// no effect with the other values (the C1/C2/C3 bounds while a statistic detector is chosen, the
/// adaptive threshold's settings while it is off, ...) is disabled, not hidden, and its tool tip
/// says why.
///
/// The panel does not own the parameters: it reports what the user does (parameterEdited,
/// parametersReplaced) and shows what it is given (setParameters). A slider the user is dragging is
/// never moved from outside.
class ParameterPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParameterPanel(QWidget* parent = nullptr);
    ~ParameterPanel() override;

    /// Shows params without emitting anything.
    void setParameters(const Parameters& params);
    /// What the panel shows, including edits not yet echoed back through setParameters.
    const Parameters& parameters() const { return current_; }

    /// Binds the Undo/Redo buttons and their shortcuts to stack (nullptr: disabled). Not owned.
    void setUndoStack(QUndoStack* stack);

    /// Writes the shown parameters as a JSON preset; false with presetError() set on failure.
    bool savePreset(const QString& path);
    /// Reads a JSON preset over the shown parameters and emits parametersReplaced; false with
    /// presetError() set on failure (nothing emitted). Neither function shows a dialog.
    bool loadPreset(const QString& path);
    QString presetError() const { return presetError_; }

signals:
    /// The user changed one field (flags as 0/1). While a slider is dragged this arrives
    /// continuously, at most every kEditInterval_ms, and always with the final value.
    void parameterEdited(const QString& name, double value);  // choices as their index
    /// The user replaced the whole set (reset to defaults, preset loaded).
    void parametersReplaced(const footpath::Parameters& params, const QString& description);

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    using FieldRow = ParameterFieldRow;

    QWidget* createButtonBar();
    /// Listens to the row's widgets: their edits, and the keys and wheel eventFilter() handles.
    void connectRow(std::size_t rowIndex);

    void showValue(FieldRow& row);
    void showModified(FieldRow& row);
    void showProblems();
    void showApplicability();
    void onSliderMoved(std::size_t rowIndex, int position);
    /// Up/Down (one slider position), Page Up/Down and the wheel in a value field; true if handled.
    bool stepValueField(QObject* watched, QEvent* event);
    void onValueTyped(std::size_t rowIndex);
    void onFlagToggled(std::size_t rowIndex, bool checked);
    void onChoiceChosen(std::size_t rowIndex, int index);
    void resetField(std::size_t rowIndex);
    void storeValue(const FieldRow& row, double value);

    void emitThrottled(const QString& name, double value);
    void flushPendingEdit();
    void emitNow(const QString& name, double value);

    void resetAll();
    void chooseAndLoadPreset();
    void chooseAndSavePreset();

    static constexpr int kEditInterval_ms = 30;

    std::vector<FieldRow> rows_;
    Parameters current_;
    const Parameters defaults_;
    QString presetError_;
    QString lastPresetDir_;

    QTimer editThrottle_;
    bool hasPendingEdit_ = false;
    QString pendingName_;
    double pendingValue_ = 0.0;

    QLabel* problems_ = nullptr;  ///< what validate() finds in the shown set
    QToolButton* undoButton_ = nullptr;
    QToolButton* redoButton_ = nullptr;
    QAction* undoAction_ = nullptr;
    QAction* redoAction_ = nullptr;
};

}  // namespace footpath
