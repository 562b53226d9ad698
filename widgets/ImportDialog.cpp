#include "ImportDialog.h"

#include "io/ColumnMapGuess.h"
#include "io/ColumnNames.h"
#include "io/ImportPresets.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace footpath {

namespace {

constexpr std::size_t kPreviewRows = 12;

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

ImportDialog::ImportDialog(const QString& path, const QString& problem, const ImportOptions& start, QWidget* parent)
    : QDialog(parent)
    , path_(path)
    , head_(headOfFile(path.toStdString(), kColumnGuessBytes))
    , preview_(splitTextRows(head_, kPreviewRows))
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
    layout->addWidget(new QLabel(tr("What each column holds (the first lines of the file below, numbered as in the file):"), this));
    headerNote_ = new QLabel(this);
    headerNote_->setObjectName(QStringLiteral("importHeaderNote"));
    headerNote_->setWordWrap(true);
    layout->addWidget(headerNote_);
    layout->addWidget(table_, 1);
    // The same guess footpath-cli users get told about: given roles, else the header's names, else
    // the usual layout, with the time unit and the pressure column decided by the values.
    const ColumnMapGuess guess = guessColumnMapFromHead(head_, path.toStdString(), start);
    guessConfident_ = guess.confident;
    guessDoubt_ = QString::fromStdString(guess.doubt);
    int columns = int(guess.headerNames.size());
    for (const TextRow& row : preview_)
        columns = std::max(columns, int(row.cells.size()));
    buildColumnEditors(columns, guess);
    checkText_ = new QLabel(this);
    checkText_->setObjectName(QStringLiteral("importCheck"));
    checkText_->setWordWrap(true);
    checkText_->setTextFormat(Qt::RichText);
    layout->addWidget(checkText_);

    auto* saveRow = new QHBoxLayout;
    save_ = new QCheckBox(tr("Save as import preset named"), this);
    presetName_ = new QLineEdit(this);
    presetName_->setPlaceholderText(tr("e.g. my-logger"));
    saveRow->addWidget(save_);
    saveRow->addWidget(presetName_, 1);
    layout->addLayout(saveRow);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    open_ = buttons->button(QDialogButtonBox::Ok);
    open_->setText(tr("Open"));
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &ImportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &ImportDialog::reject);
    connect(presets_, &QComboBox::currentIndexChanged, this, &ImportDialog::applyPreset);
    connect(presetName_, &QLineEdit::textEdited, this, [this] { save_->setChecked(true); });
    // A preset changes every box at once: one check after them, not one per box.
    auto* recheckSoon = new QTimer(this);
    recheckSoon->setSingleShot(true);
    recheckSoon->setInterval(0);
    connect(recheckSoon, &QTimer::timeout, this, &ImportDialog::recheck);
    for (QComboBox* box : roleBoxes_ + QList<QComboBox*>{accUnit_, gyrUnit_, timeUnit_})
        connect(box, &QComboBox::currentIndexChanged, recheckSoon, qOverload<>(&QTimer::start));
    connect(rate_, &QDoubleSpinBox::valueChanged, recheckSoon, qOverload<>(&QTimer::start));
    showCheck(guess.check);  // the boxes hold the guess: its check is theirs
    resize(820, 560);
}

/// One role box per column over the preview; the header row, when the file has one, titles the
/// columns instead of posing as data, and every row is labelled with its line in the file.
void ImportDialog::buildColumnEditors(int columns, const ColumnMapGuess& guess)
{
    std::vector<TextRow> rows = preview_;
    if (guess.headerLine > 0 && !rows.empty() && rows.front().line == guess.headerLine)
        rows.erase(rows.begin());
    table_->setColumnCount(columns);
    table_->setRowCount(int(rows.size()) + 1);
    QStringList titles;
    for (int c = 0; c < columns; ++c) {
        const QString name = c < int(guess.headerNames.size()) ? QString::fromStdString(guess.headerNames[std::size_t(c)])
                                                                : QString();
        titles << (name.isEmpty() ? tr("column %1").arg(c + 1) : tr("%1: %2").arg(c + 1).arg(name));
    }
    table_->setHorizontalHeaderLabels(titles);
    QStringList lineLabels{tr("role")};
    for (const TextRow& row : rows)
        lineLabels << tr("line %1").arg(row.line);
    table_->setVerticalHeaderLabels(lineLabels);
    headerNote_->setText(guess.headerLine > 0
                             ? tr("Line %1 is the file's header: its names title the columns, and the roles below "
                                  "replace it.")
                                   .arg(guess.headerLine)
                             : tr("The file has no header row: say what each column holds."));
    QStringList roles;
    for (const std::string& role : columnRoleNames())
        roles << QString::fromStdString(role);
    for (int c = 0; c < columns; ++c) {
        auto* box = new QComboBox(table_);
        box->addItems(roles);
        box->setCurrentText(c < int(guess.columnMap.size()) ? QString::fromStdString(guess.columnMap[std::size_t(c)])
                                                             : QStringLiteral("skip"));
        table_->setCellWidget(0, c, box);
        roleBoxes_ << box;
        for (int r = 0; r < int(rows.size()); ++r)
            if (c < int(rows[std::size_t(r)].cells.size()))
                table_->setItem(r + 1, c, new QTableWidgetItem(QString::fromStdString(rows[std::size_t(r)].cells[std::size_t(c)])));
    }
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    QStringList notes;
    for (const std::string& note : guess.notes)
        notes << QString::fromStdString(note).toHtmlEscaped();
    guessNotes_ = notes.join(QStringLiteral("<br>"));
}

/// The file's first part read with the settings as they are now: what it gives, what cannot be
/// right (Open waits until it is mended) and what is unusual.
void ImportDialog::recheck()
{
    showCheck(checkColumnMap(head_, path_.toStdString(), options()));
}

void ImportDialog::showCheck(ColumnMapCheck check)
{
    check_ = std::move(check);
    QStringList lines;
    for (const std::string& refusal : check_.refusals)
        lines << QStringLiteral("<span style='color:#b00020'>%1</span>")
                     .arg(tr("Cannot be right: %1").arg(QString::fromStdString(refusal).toHtmlEscaped()));
    for (const std::string& doubt : check_.doubts)
        lines << QStringLiteral("<span style='color:#a05a00'>%1</span>")
                     .arg(tr("Check: %1").arg(QString::fromStdString(doubt).toHtmlEscaped()));
    if (!check_.reading.empty())
        lines << tr("Read so, the first lines give: %1").arg(QString::fromStdString(check_.reading).toHtmlEscaped());
    if (!guessNotes_.isEmpty())
        lines << tr("From the values: %1").arg(guessNotes_);
    checkText_->setText(lines.join(QStringLiteral("<br>")));
    open_->setEnabled(check_.refusals.empty());
    open_->setToolTip(check_.refusals.empty() ? QString() : tr("Mend the roles or units first: the file cannot be read right so"));
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
