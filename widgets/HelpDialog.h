#pragma once

#include <QDialog>
#include <QList>

class QAction;
class QTabWidget;
class QTableWidget;
class QTextBrowser;

namespace footpath {

/// Help > User guide and Help > Keyboard shortcuts: a short guide to the workspace (opening files,
/// what the views and lanes show, tuning, live input) and every shortcut. The shortcut list is
/// read from the menus' actions, so it cannot disagree with them, plus the mouse and keys the
/// views handle themselves.
class HelpDialog : public QDialog {
    Q_OBJECT
public:
    enum class Page { Guide, Shortcuts };

    /// menus: the menu bar's actions (their menus are walked for shortcuts).
    HelpDialog(const QList<QAction*>& menus, Page page, QWidget* parent = nullptr);

    void showPage(Page page);
    QTextBrowser* guide() const { return guide_; }
    QTableWidget* shortcuts() const { return shortcuts_; }

    /// The guide as rich text (translatable).
    static QString guideText();

private:
    void fillShortcuts(const QList<QAction*>& menus);

    QTabWidget* tabs_;
    QTextBrowser* guide_;
    QTableWidget* shortcuts_;
};

}  // namespace footpath
