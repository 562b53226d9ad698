#pragma once

#include "io/Import.h"

#include <QDialog>
#include <QStringList>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
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

    /// The first non-empty lines of a text file, split into cells as the reader splits them.
    static QList<QStringList> previewRows(const QString& path, int maxRows);

private:
    void buildColumnEditors(int columns);
    void applyPreset(int index);
    void accept() override;

    QString path_;
    QList<QStringList> preview_;
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
    QString savedPreset_;
};

}  // namespace footpath
