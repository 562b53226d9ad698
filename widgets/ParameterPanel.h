#pragma once

#include "nav/Parameters.h"

#include <QString>
#include <QTimer>
#include <QWidget>

#include <vector>

class QAction;
class QCheckBox;
class QComboBox;
class QGridLayout;
class QKeyEvent;
class QLabel;
class QLineEdit;
class QSlider;
class QToolButton;
class QUndoStack;

namespace footpath {

/// Maps the integer positions of a slider to the values of one parameter field.
///
/// The rule for a logarithmic scale: a field is logarithmic when its range spans at least two
/// decades in the values people use, that is
///  - minimum > 0 and maximum / minimum >= 100 (r_*, alignment_s), or
///  - minimum == 0 and the default is below maximum / 100 (the q_* and p0_* noise values, many of
///    them 0 by default, whose useful values are orders of magnitude below the maximum).
/// A logarithmic scale from 0 keeps position 0 as an end stop meaning exactly 0; position 1 is the
/// lowest positive value, six decades below the maximum (lowered to the power of ten at or below
/// the default if the default is smaller, so the default is always on the scale). Everything else
/// (the detector thresholds, gravity, declination) is linear.
///
/// A linear field from 0 whose default is far below its maximum (the shortest stance: 0.05 of up
/// to 2 s) spans only up to the round number (1, 2, 2.5, 5 x 10^n) at or above ten times the default: over the whole
/// range a 50-pixel drag moved it from 0.02 to 0.66 s. Values beyond are typed; the slider then
/// rests at its end.
///
/// Resolution: 100 positions per decade (2.3 % per position) or 1000 over a linear range. Values
/// from a position are rounded to 3 significant digits (log) or to the power of ten at or below one
/// position (linear), so the numeric field shows tidy numbers; the rounding never moves a value to
/// another position.
class SliderScale {
public:
    static SliderScale forField(const ParameterField& field, double defaultValue);

    bool isLogarithmic() const { return logarithmic_; }
    bool hasZeroStop() const { return zeroStop_; }
    int maximumPosition() const { return firstLogPosition() + steps_; }
    int pageStep() const;
    int toPosition(double value) const;
    double toValue(int position) const;
    /// The value at the slider's far end: the field's maximum, or less where the slider spans
    /// only the useful part of a wide linear range.
    double sliderMaximum() const { return sliderMaximum_; }

private:
    int firstLogPosition() const { return zeroStop_ ? 1 : 0; }
    double linearValue(int position) const;
    double logValue(int position) const;

    double minimum_ = 0.0;
    double maximum_ = 1.0;
    double sliderMaximum_ = 1.0;
    double lowestPositive_ = 1.0;  ///< value at the first logarithmic position
    bool logarithmic_ = false;
    bool zeroStop_ = false;
    int steps_ = 1000;  ///< positions after the first (linear) or after the lowest positive (log)
};

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
    struct FieldRow {
        const ParameterField* field = nullptr;
        SliderScale scale;
        QLabel* label = nullptr;        ///< reals and choices: the name (bold when not the default)
        QSlider* slider = nullptr;      ///< reals
        QLineEdit* edit = nullptr;      ///< reals
        QCheckBox* check = nullptr;     ///< flags
        QComboBox* combo = nullptr;     ///< choices
        QToolButton* reset = nullptr;   ///< back to the default; shown when the value differs
        std::vector<QWidget*> parts;    ///< every widget of the row, enabled and disabled together
        QString toolTip;                ///< the field's own tool tip, before any "not used" note
    };

    QWidget* createButtonBar();
    QWidget* createFieldSections();
    QWidget* createSection(const QString& title, QWidget* content);
    void addRealRow(QGridLayout* grid, std::size_t rowIndex);
    void addFlagRow(QGridLayout* grid, std::size_t rowIndex);
    void addChoiceRow(QGridLayout* grid, std::size_t rowIndex);
    QToolButton* createResetButton(std::size_t rowIndex);

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
    int unitColumnWidth_ = 0;
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
