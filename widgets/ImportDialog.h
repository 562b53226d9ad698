#pragma once

#include "io/ColumnMapGuess.h"
#include "io/Import.h"

#include <QDialog>
#include <QStringList>

#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace footpath {

/// Says how to read a file that does not describe itself: a role per column (shown over a preview
/// of the first lines), units, rate, and a name to save it all as an import preset, so the next
/// file of that kind opens with one click (pick the preset) or one flag (--import-preset).
class ImportDialog : public QDialog {
    Q_OBJECT
public:
    ImportDialog(const QString& path, const QString& problem, const ImportOptions& start, QWidget* parent = nullptr);

    /// What the user chose; valid after exec() returned Accepted.
    ImportOptions options() const;
    /// The preset saved on accept, or empty.
    QString savedPresetName() const { return savedPreset_; }

    /// What the current settings read from the first part of the file, checked (shown under the
    /// preview; Open is disabled while it holds a refusal).
    const ColumnMapCheck& check() const { return check_; }

    /// A run without a user (a screenshot under xvfb): exec() then shows nothing; it accepts the
    /// settings the dialog starts with when reading the file with them looks right, and otherwise
    /// rejects and calls onNoAnswer with the reason, so the run can end instead of waiting forever.
    static void setUnattended(std::function<void(const QString& reason)> onNoAnswer);
    int exec() override;

private:
    void buildColumnEditors(int columns, const ColumnMapGuess& guess);
    void recheck();
    void showCheck(ColumnMapCheck check);
    void applyPreset(int index);
    void showUnits(AccUnit acc, GyrUnit gyr, TimeUnit time);
    void accept() override;

    QString path_;
    std::string head_;            ///< the first part of the file, which the checks read
    std::vector<TextRow> preview_;  ///< its first rows, with their line numbers in the file
    QTableWidget* table_;
    QList<QComboBox*> roleBoxes_;
    QComboBox* presets_;
    QComboBox* accUnit_;
    QComboBox* gyrUnit_;
    QComboBox* timeUnit_;
    QDoubleSpinBox* rate_;
    QCheckBox* save_;
    QLineEdit* presetName_;
    QLabel* problem_;
    QLabel* headerNote_;
    QLabel* checkText_;
    QPushButton* open_;
    ColumnMapCheck check_;
    QString savedPreset_;
    QString guessNotes_;  ///< what the values decided in the guess, as HTML lines
    QString guessDoubt_;  ///< why the starting column map may be wrong; empty when it reads well
    bool guessConfident_ = false;
};

}  // namespace footpath
