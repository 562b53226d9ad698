#pragma once

#include "SliderScale.h"
#include "nav/Parameters.h"

#include <QCoreApplication>
#include <QString>

#include <vector>

class QCheckBox;
class QComboBox;
class QGridLayout;
class QLabel;
class QLineEdit;
class QSlider;
class QToolButton;
class QWidget;

namespace footpath {

/// One field's row in the parameter panel: the widgets the panel shows the value in and reads the
/// user's edits from. Only the widgets of the field's kind are set.
struct ParameterFieldRow {
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

/// Builds the parameter panel's rows, grouped by ParameterField::group in collapsible sections.
/// It only lays the widgets out: the panel connects them and shows the values.
class ParameterFieldRows {
    // The texts keep the panel's translation context, where they were translated.
    Q_DECLARE_TR_FUNCTIONS(footpath::ParameterPanel)

public:
    /// panel: whose font and style the rows are measured and drawn with; defaults: what the tool
    /// tips and reset buttons name. Both must outlive the builder.
    ParameterFieldRows(const QWidget& panel, const Parameters& defaults);

    /// Creates the widgets of every row (each with its field and, for reals, its scale set), in one
    /// section per group; the returned widget holds them all.
    QWidget* createSections(std::vector<ParameterFieldRow>& rows);

private:
    static QWidget* createSection(const QString& title, QWidget* content);
    void addRow(QGridLayout* grid, ParameterFieldRow& row) const;
    void addRealRow(QGridLayout* grid, ParameterFieldRow& row) const;
    void addFlagRow(QGridLayout* grid, ParameterFieldRow& row) const;
    void addChoiceRow(QGridLayout* grid, ParameterFieldRow& row) const;
    QToolButton* createResetButton(const ParameterField& field) const;
    QString toolTipOf(const ParameterField& field) const;

    const QWidget& panel_;
    const Parameters& defaults_;
    int unitColumnWidth_ = 0;  ///< the widest unit, so the value fields line up across sections
};

}  // namespace footpath
