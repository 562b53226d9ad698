#include "ParameterFieldRows.h"

#include "ParameterFieldText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleValidator>
#include <QFrame>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMap>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace footpath {

namespace {

QString unitText(const ParameterField& field)
{
    return QString::fromStdString(displayUnit(field));
}

/// "C2 bound on the std of |a| (m/s²)": the label translated, the unit as written everywhere.
QString fieldLabel(const ParameterField& field)
{
    const QString unit = unitText(field);
    const QString label = fieldText(field.label);
    return unit.isEmpty() ? label : QStringLiteral("%1 (%2)").arg(label, unit);
}

/// A name label above its controls; it wraps rather than widening the panel.
QLabel* createNameLabel(const ParameterField& field)
{
    auto* label = new QLabel(fieldLabel(field));
    label->setObjectName(QStringLiteral("label_") + QString::fromUtf8(field.name));
    label->setWordWrap(true);
    return label;
}

QString choiceNames(const ParameterField& field)
{
    QStringList names;
    for (const char* name : field.choiceNames)
        names << QString::fromUtf8(name);
    return names.join(QStringLiteral(", "));
}

}  // namespace

ParameterFieldRows::ParameterFieldRows(const QWidget& panel, const Parameters& defaults) : panel_(panel), defaults_(defaults)
{
}

QWidget* ParameterFieldRows::createSections(std::vector<ParameterFieldRow>& rows)
{
    for (const ParameterFieldRow& row : rows)
        unitColumnWidth_ = std::max(unitColumnWidth_, panel_.fontMetrics().horizontalAdvance(unitText(*row.field)));
    // Groups appear in the order of their first field; each gets one grid.
    QStringList groupOrder;
    QMap<QString, QGridLayout*> grids;
    for (ParameterFieldRow& row : rows) {
        const QString group = QString::fromUtf8(row.field->group);
        if (!grids.contains(group)) {
            groupOrder.append(group);
            auto* grid = new QGridLayout;
            grid->setColumnStretch(0, 1);
            grid->setVerticalSpacing(2);
            grids.insert(group, grid);
        }
        addRow(grids.value(group), row);
    }
    auto* container = new QWidget;
    auto* layout = new QVBoxLayout(container);
    layout->setContentsMargins(0, 0, 0, 0);
    for (const QString& group : groupOrder) {
        auto* content = new QWidget;
        content->setLayout(grids.value(group));
        layout->addWidget(createSection(fieldText(group.toUtf8().constData()), content));
    }
    layout->addStretch(1);
    return container;
}

QWidget* ParameterFieldRows::createSection(const QString& title, QWidget* content)
{
    auto* header = new QToolButton;
    header->setObjectName(QStringLiteral("section_") + title);
    header->setText(title);
    header->setCheckable(true);
    header->setChecked(true);
    header->setAutoRaise(true);
    header->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    header->setArrowType(Qt::DownArrow);
    header->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    QFont bold = header->font();
    bold.setBold(true);
    header->setFont(bold);

    auto* frame = new QFrame;
    frame->setFrameShape(QFrame::StyledPanel);
    auto* frameLayout = new QVBoxLayout(frame);
    frameLayout->setContentsMargins(6, 4, 6, 6);
    frameLayout->addWidget(content);
    QObject::connect(header, &QToolButton::toggled, frame, [header, frame](bool open) {
        frame->setVisible(open);
        header->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    });

    auto* section = new QWidget;
    auto* layout = new QVBoxLayout(section);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(header);
    layout->addWidget(frame);
    return section;
}

void ParameterFieldRows::addRow(QGridLayout* grid, ParameterFieldRow& row) const
{
    switch (row.field->kind) {
    case ParameterField::Kind::Real: addRealRow(grid, row); break;
    case ParameterField::Kind::Flag: addFlagRow(grid, row); break;
    case ParameterField::Kind::Choice: addChoiceRow(grid, row); break;
    }
}

/// The label, then the identifier presets and the command line use, then what the field does.
QString ParameterFieldRows::toolTipOf(const ParameterField& field) const
{
    const double defaultValue = parameterValue(defaults_, field);
    const QString head = QStringLiteral("<b>%1</b><br><code>%2</code><br>%3")
                             .arg(fieldLabel(field).toHtmlEscaped(), QString::fromUtf8(field.name),
                                  fieldText(field.description).toHtmlEscaped());
    if (field.kind == ParameterField::Kind::Flag)
        return head;
    if (field.kind == ParameterField::Kind::Choice)
        return tr("%1<br>Choices in presets: %2<br>Default: %3")
            .arg(head, choiceNames(field), QString::fromUtf8(field.choiceNames.at(static_cast<std::size_t>(defaultValue))));
    const double sliderEnd = SliderScale::forField(field, defaultValue).sliderMaximum();
    const QString span = sliderEnd < field.maximum
                             ? tr(" (the slider up to %1; type a larger value)").arg(formatValue(sliderEnd))
                             : QString();
    return tr("%1<br>Range: %2 to %3 %4%6<br>Default: %5 %4<br>Up/Down in the value field: one slider "
              "step; Page Up/Down: ten")
        .arg(head, formatValue(field.minimum), formatValue(field.maximum), unitText(field), formatValue(defaultValue), span);
}

void ParameterFieldRows::addRealRow(QGridLayout* grid, ParameterFieldRow& row) const
{
    const ParameterField& field = *row.field;
    const QString name = QString::fromUtf8(field.name);
    const QString toolTip = toolTipOf(field);

    row.label = createNameLabel(field);
    row.label->setToolTip(toolTip);
    row.edit = new QLineEdit;
    row.edit->setObjectName(QStringLiteral("value_") + name);
    row.edit->setToolTip(toolTip);
    row.edit->setAlignment(Qt::AlignRight);
    auto* validator = new QDoubleValidator(row.edit);
    validator->setNotation(QDoubleValidator::ScientificNotation);
    validator->setLocale(numberLocale());
    row.edit->setValidator(validator);
    row.edit->setFixedWidth(row.edit->fontMetrics().horizontalAdvance(QStringLiteral("-0.000000e-00")));
    auto* unit = new QLabel(unitText(field));
    unit->setMinimumWidth(unitColumnWidth_);  // the same in every section, so the fields line up
    row.slider = new QSlider(Qt::Horizontal);
    row.slider->setObjectName(QStringLiteral("slider_") + name);
    row.slider->setToolTip(toolTip);
    row.slider->setRange(0, row.scale.maximumPosition());
    row.slider->setPageStep(row.scale.pageStep());
    row.slider->setFocusPolicy(Qt::StrongFocus);
    row.reset = createResetButton(field);
    row.toolTip = toolTip;
    row.parts = {row.label, row.edit, unit, row.slider, row.reset};

    // The label on a line of its own: a readable label beside the value would widen the panel.
    const int gridRow = grid->rowCount();
    grid->addWidget(row.label, gridRow, 0, 1, 3);
    grid->addWidget(row.reset, gridRow, 3);
    grid->addWidget(row.slider, gridRow + 1, 0);
    grid->addWidget(row.edit, gridRow + 1, 1);
    grid->addWidget(unit, gridRow + 1, 2);
    grid->setRowMinimumHeight(gridRow + 2, 6);  // air between fields
}

void ParameterFieldRows::addFlagRow(QGridLayout* grid, ParameterFieldRow& row) const
{
    const ParameterField& field = *row.field;
    const QString name = QString::fromUtf8(field.name);
    row.check = new QCheckBox(fieldLabel(field));
    row.check->setObjectName(QStringLiteral("check_") + name);
    row.toolTip = toolTipOf(field);
    row.check->setToolTip(row.toolTip);
    // The description on its own wrapped line: beside the name it would widen the whole panel.
    auto* description = new QLabel(fieldText(field.description));
    description->setWordWrap(true);
    description->setForegroundRole(QPalette::PlaceholderText);
    description->setIndent(row.check->style()->pixelMetric(QStyle::PM_IndicatorWidth) + 6);
    row.reset = createResetButton(field);
    row.parts = {row.check, description, row.reset};
    const int gridRow = grid->rowCount();
    grid->addWidget(row.check, gridRow, 0, 1, 3);
    grid->addWidget(row.reset, gridRow, 3);
    grid->addWidget(description, gridRow + 1, 0, 1, 3);
    grid->setRowMinimumHeight(gridRow + 2, 6);
}

void ParameterFieldRows::addChoiceRow(QGridLayout* grid, ParameterFieldRow& row) const
{
    const ParameterField& field = *row.field;
    const QString name = QString::fromUtf8(field.name);
    row.toolTip = toolTipOf(field);
    row.label = createNameLabel(field);
    row.label->setToolTip(row.toolTip);
    row.combo = new QComboBox;
    row.combo->setObjectName(QStringLiteral("choice_") + name);
    row.combo->setToolTip(row.toolTip);
    row.combo->setFocusPolicy(Qt::StrongFocus);
    for (std::size_t i = 0; i < field.choiceNames.size(); ++i) {
        const char* label = i < field.choiceLabels.size() ? field.choiceLabels[i] : field.choiceNames[i];
        row.combo->addItem(fieldText(label));
        // What a preset or --set calls this choice.
        row.combo->setItemData(static_cast<int>(i), QString::fromUtf8(field.choiceNames[i]), Qt::ToolTipRole);
    }
    row.reset = createResetButton(field);
    row.parts = {row.label, row.combo, row.reset};
    const int gridRow = grid->rowCount();
    grid->addWidget(row.label, gridRow, 0, 1, 3);
    grid->addWidget(row.combo, gridRow + 1, 0, 1, 3);
    grid->addWidget(row.reset, gridRow, 3);
    grid->setRowMinimumHeight(gridRow + 2, 6);
}

QToolButton* ParameterFieldRows::createResetButton(const ParameterField& field) const
{
    auto* button = new QToolButton;
    button->setObjectName(QStringLiteral("reset_") + QString::fromUtf8(field.name));
    button->setIcon(panel_.style()->standardIcon(QStyle::SP_DialogResetButton));
    button->setAutoRaise(true);
    button->setToolTip(tr("Back to the default (%1)").arg(formatValue(parameterValue(defaults_, field))));
    // Hidden while the value is the default, but its space is kept so the rows do not jump.
    QSizePolicy policy = button->sizePolicy();
    policy.setRetainSizeWhenHidden(true);
    button->setSizePolicy(policy);
    return button;
}

}  // namespace footpath
