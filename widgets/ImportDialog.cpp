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

std::function<void(const QString&)>& unattendedHandler()
{
    static std::function<void(const QString&)> handler;
    return handler;
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
    gyrUnit_ = unitBox({tr("detect"), tr("rad/s"), tr("°/s")}, {"", "radps", "degps"}, this);
    timeUnit_ = unitBox({tr("detect"), tr("s"), tr("ms"), tr("µs")}, {"", "s", "ms", "us"}, this);
    form->addRow(tr("Accelerometer unit:"), accUnit_);
    form->addRow(tr("Gyroscope unit:"), gyrUnit_);
    form->addRow(tr("Time unit:"), timeUnit_);
    rate_ = new QDoubleSpinBox(this);
    rate_->setRange(0.0, kMaxImportRate_hz);
    rate_->setSuffix(tr(" Hz"));
    rate_->setSpecialValueText(tr("from the time column"));
    rate_->setValue(start.rate_hz);
    form->addRow(tr("Sample rate:"), rate_);
    showUnits(start.accUnit, start.gyrUnit, start.timeUnit);
    layout->addLayout(form);

    table_ = new QTableWidget(this);
    layout->addWidget(new QLabel(tr("What each column holds (first lines of the file below):"), this));
    layout->addWidget(table_, 1);
    int columns = 0;
    for (const QStringList& row : preview_)
        columns = std::max(columns, int(row.size()));
    buildColumnEditors(columns);
    // The same guess footpath-cli users get told about: given roles, else the usual layout.
    const ColumnMapGuess guess = guessColumnMap(path.toStdString(), start);
    guessConfident_ = guess.confident;
    guessDoubt_ = QString::fromStdString(guess.doubt);
    for (int i = 0; i < roleBoxes_.size(); ++i)
        roleBoxes_[i]->setCurrentText(i < int(guess.columnMap.size())
                                          ? QString::fromStdString(guess.columnMap[std::size_t(i)])
                                          : QStringLiteral("skip"));

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
        table_->setCellWidget(0, c, box);
        roleBoxes_ << box;
        for (int r = 0; r < preview_.size(); ++r)
            if (c < preview_[r].size())
                table_->setItem(r + 1, c, new QTableWidgetItem(preview_[r][c]));
    }
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
}

void ImportDialog::setUnattended(std::function<void(const QString&)> onNoAnswer)
{
    unattendedHandler() = std::move(onNoAnswer);
}

int ImportDialog::exec()
{
    if (!unattendedHandler())
        return QDialog::exec();
    if (guessConfident_) {
        setResult(QDialog::Accepted);
        return QDialog::Accepted;
    }
    unattendedHandler()(tr("%1 needs import settings and no one is there to give them: %2")
                            .arg(QFileInfo(path_).fileName(), guessDoubt_.isEmpty() ? problem_->text() : guessDoubt_));
    setResult(QDialog::Rejected);
    return QDialog::Rejected;
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
    showUnits(preset.accUnit, preset.gyrUnit, preset.timeUnit);
    rate_->setValue(preset.rate_hz);
}

void ImportDialog::showUnits(AccUnit acc, GyrUnit gyr, TimeUnit time)
{
    const auto select = [](QComboBox* box, const char* name) { box->setCurrentIndex(std::max(0, box->findData(name))); };
    select(accUnit_, acc == AccUnit::StandardGravity ? "g" : acc == AccUnit::MetresPerSecond2 ? "mps2" : "");
    select(gyrUnit_, gyr == GyrUnit::DegreesPerSecond ? "degps" : gyr == GyrUnit::RadiansPerSecond ? "radps" : "");
    select(timeUnit_, time == TimeUnit::Milliseconds   ? "ms"
                      : time == TimeUnit::Microseconds ? "us"
                      : time == TimeUnit::Seconds      ? "s"
                                                       : "");
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
