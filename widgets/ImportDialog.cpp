#include "ImportDialog.h"

#include "io/ColumnNames.h"
#include "io/ImportPresets.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>

namespace footpath {

namespace {

constexpr int kPreviewRows = 8;

QComboBox* unitBox(const QStringList& labels, const QStringList& values, QWidget* parent)
{
    auto* box = new QComboBox(parent);
    for (int i = 0; i < labels.size(); ++i)
        box->addItem(labels[i], values[i]);
    return box;
}

/// The usual layout of a headerless IMU log: time, accelerometer, gyroscope, then pressure or
/// whatever else; the user corrects what does not fit.
QString suggestedRole(int column, int columns)
{
    static const QStringList first{"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"};
    if (column < first.size())
        return first[column];
    return column == first.size() && columns > first.size() ? QStringLiteral("pressure_pa") : QStringLiteral("skip");
}

}  // namespace

QList<QStringList> ImportDialog::previewRows(const QString& path, int maxRows)
{
    QList<QStringList> rows;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return rows;
    static const QRegularExpression separators(QStringLiteral("[,;\\t ]+"));
    while (!file.atEnd() && rows.size() < maxRows) {
        const QString line = QString::fromUtf8(file.readLine(64 * 1024)).trimmed();
        if (!line.isEmpty())
            rows << line.split(separators, Qt::SkipEmptyParts);
    }
    return rows;
}

ImportDialog::ImportDialog(const QString& path, const QString& problem, const ImportOptions& start, QWidget* parent)
    : QDialog(parent), path_(path), preview_(previewRows(path, kPreviewRows))
{
    setWindowTitle(tr("How to read %1").arg(QFileInfo(path).fileName()));
    auto* layout = new QVBoxLayout(this);
    problem_ = new QLabel(problem, this);
    problem_->setWordWrap(true);
    layout->addWidget(problem_);

    auto* form = new QFormLayout;
    presets_ = new QComboBox(this);
    presets_->addItem(tr("(none)"));
    for (const ImportPreset& preset : listImportPresets())
        presets_->addItem(QString::fromStdString(preset.name));
    form->addRow(tr("Import preset:"), presets_);
    accUnit_ = unitBox({tr("detect"), tr("m/s²"), tr("g")}, {"", "mps2", "g"}, this);
    gyrUnit_ = unitBox({tr("detect"), tr("rad/s"), tr("deg/s")}, {"", "radps", "degps"}, this);
    timeUnit_ = unitBox({tr("detect"), tr("s"), tr("ms"), tr("µs")}, {"", "s", "ms", "us"}, this);
    form->addRow(tr("Accelerometer unit:"), accUnit_);
    form->addRow(tr("Gyroscope unit:"), gyrUnit_);
    form->addRow(tr("Time unit:"), timeUnit_);
    rate_ = new QDoubleSpinBox(this);
    rate_->setRange(0.0, 10000.0);
    rate_->setSuffix(tr(" Hz"));
    rate_->setSpecialValueText(tr("from the time column"));
    rate_->setValue(start.rate_hz);
    form->addRow(tr("Sample rate:"), rate_);
    layout->addLayout(form);

    table_ = new QTableWidget(this);
    layout->addWidget(new QLabel(tr("What each column holds (first lines of the file below):"), this));
    layout->addWidget(table_, 1);
    int columns = 0;
    for (const QStringList& row : preview_)
        columns = std::max(columns, int(row.size()));
    buildColumnEditors(columns);
    for (int i = 0; i < roleBoxes_.size() && i < int(start.columnMap.size()); ++i)
        roleBoxes_[i]->setCurrentText(QString::fromStdString(start.columnMap[std::size_t(i)]));

    auto* saveRow = new QHBoxLayout;
    save_ = new QCheckBox(tr("Save as import preset named"), this);
    presetName_ = new QLineEdit(this);
    presetName_->setPlaceholderText(tr("e.g. my-logger"));
    saveRow->addWidget(save_);
    saveRow->addWidget(presetName_, 1);
    layout->addLayout(saveRow);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Open"));
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &ImportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &ImportDialog::reject);
    connect(presets_, &QComboBox::currentIndexChanged, this, &ImportDialog::applyPreset);
    connect(presetName_, &QLineEdit::textEdited, this, [this] { save_->setChecked(true); });
    resize(760, 480);
}

void ImportDialog::buildColumnEditors(int columns)
{
    table_->setColumnCount(columns);
    table_->setRowCount(int(preview_.size()) + 1);
    table_->setVerticalHeaderLabels(QStringList{tr("role")});
    QStringList roles;
    for (const std::string& role : columnRoleNames())
        roles << QString::fromStdString(role);
    for (int c = 0; c < columns; ++c) {
        auto* box = new QComboBox(table_);
        box->addItems(roles);
        box->setCurrentText(suggestedRole(c, columns));
        table_->setCellWidget(0, c, box);
        roleBoxes_ << box;
        for (int r = 0; r < preview_.size(); ++r)
            if (c < preview_[r].size())
                table_->setItem(r + 1, c, new QTableWidgetItem(preview_[r][c]));
    }
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
}

void ImportDialog::applyPreset(int index)
{
    if (index <= 0)
        return;
    ImportPreset preset;
    if (std::string problem = loadImportPreset(presets_->itemText(index).toStdString(), preset); !problem.empty()) {
        problem_->setText(QString::fromStdString(problem));
        return;
    }
    for (int i = 0; i < roleBoxes_.size(); ++i)
        roleBoxes_[i]->setCurrentText(i < int(preset.columnMap.size())
                                          ? QString::fromStdString(preset.columnMap[std::size_t(i)])
                                          : QStringLiteral("skip"));
    const auto select = [](QComboBox* box, const char* name) { box->setCurrentIndex(std::max(0, box->findData(name))); };
    select(accUnit_, preset.accUnit == AccUnit::StandardGravity ? "g" : preset.accUnit == AccUnit::MetresPerSecond2 ? "mps2" : "");
    select(gyrUnit_, preset.gyrUnit == GyrUnit::DegreesPerSecond ? "degps" : preset.gyrUnit == GyrUnit::RadiansPerSecond ? "radps" : "");
    select(timeUnit_, preset.timeUnit == TimeUnit::Milliseconds ? "ms" : preset.timeUnit == TimeUnit::Microseconds ? "us"
                      : preset.timeUnit == TimeUnit::Seconds ? "s" : "");
    rate_->setValue(preset.rate_hz);
}

ImportOptions ImportDialog::options() const
{
    ImportOptions options;
    for (const QComboBox* box : roleBoxes_)
        options.columnMap.push_back(box->currentText().toStdString());
    parseAccUnit(accUnit_->currentData().toString().toStdString(), options.accUnit);
    parseGyrUnit(gyrUnit_->currentData().toString().toStdString(), options.gyrUnit);
    parseTimeUnit(timeUnit_->currentData().toString().toStdString(), options.timeUnit);
    options.rate_hz = rate_->value();
    return options;
}

void ImportDialog::accept()
{
    if (save_->isChecked()) {
        ImportPreset preset;
        preset.name = presetName_->text().trimmed().toStdString();
        const ImportOptions chosen = options();
        preset.columnMap = chosen.columnMap;
        preset.accUnit = chosen.accUnit;
        preset.gyrUnit = chosen.gyrUnit;
        preset.timeUnit = chosen.timeUnit;
        preset.rate_hz = chosen.rate_hz;
        if (std::string problem = saveImportPreset(preset); !problem.empty()) {
            QMessageBox::warning(this, windowTitle(), QString::fromStdString(problem));
            return;
        }
        savedPreset_ = QString::fromStdString(preset.name);
    }
    QDialog::accept();
}

}  // namespace footpath
