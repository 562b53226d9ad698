#pragma once

#include "io/Import.h"

#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;
class QToolButton;
class QTextBrowser;

namespace footpath {

/// The recorded-input panel: open a file (button, recent files), loading progress with cancel,
/// and what the importer found (format, rate, duration, channels, units, gaps, reference,
/// warnings).
class RecordedInputPanel : public QWidget {
    Q_OBJECT
public:
    explicit RecordedInputPanel(QWidget* parent = nullptr);

    void setRecentFiles(const QStringList& paths);
    void showLoading(const QString& path);
    void setProgress(double fraction);
    void showInfo(const QString& path, const ImportResult& result);
    /// Both feet open: the right foot's file below the left's, with its own gaps and warnings.
    void showOtherFoot(const QString& path, const ImportResult& result);
    void showProblem(const QString& message);

    /// The text shown for a result; also used by tests and the report's header.
    static QString describe(const QString& path, const ImportResult& result);

signals:
    void openRequested();                     ///< "Open..." pressed: the window shows a file dialog
    void recentFileChosen(const QString& path);
    void cancelRequested();

private:
    QPushButton* open_;
    QToolButton* recent_;
    QProgressBar* progress_;
    QPushButton* cancel_;
    QTextBrowser* info_;
    void showBoth();

    QString mainHtml_;   ///< the (left) recording's part, which the other foot's follows
    QString otherHtml_;  ///< the right foot's, when both feet are open
};

}  // namespace footpath
