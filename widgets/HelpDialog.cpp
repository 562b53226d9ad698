#include "HelpDialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QMenu>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace footpath {

namespace {

/// "&Open recording..." -> "Open recording"
QString plainActionText(QString text)
{
    text.remove(QLatin1Char('&'));
    if (text.endsWith(QStringLiteral("...")))
        text.chop(3);
    return text;
}

void collectShortcuts(const QList<QAction*>& actions, const QString& menu, QList<QPair<QString, QString>>& rows)
{
    for (QAction* action : actions) {
        if (action->menu()) {
            const QString title = plainActionText(action->text());
            collectShortcuts(action->menu()->actions(), menu.isEmpty() ? title : menu + QStringLiteral(" > ") + title, rows);
            continue;
        }
        if (action->shortcut().isEmpty())
            continue;
        // An action whose text follows the state (Undo names the change) gives its plain name.
        const QString name = action->property("helpText").toString();
        rows.append({action->shortcut().toString(QKeySequence::NativeText),
                     menu + QStringLiteral(" > ") + plainActionText(name.isEmpty() ? action->text() : name)});
    }
}

}  // namespace

HelpDialog::HelpDialog(const QList<QAction*>& menus, Page page, QWidget* parent)
    : QDialog(parent), tabs_(new QTabWidget), guide_(new QTextBrowser), shortcuts_(new QTableWidget)
{
    setWindowTitle(tr("Footpath help"));
    guide_->setObjectName(QStringLiteral("userGuide"));
    guide_->setOpenExternalLinks(true);
    guide_->setHtml(guideText());
    shortcuts_->setObjectName(QStringLiteral("shortcutList"));
    fillShortcuts(menus);
    tabs_->addTab(guide_, tr("User guide"));
    tabs_->addTab(shortcuts_, tr("Keyboard shortcuts"));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(tabs_, 1);
    layout->addWidget(buttons);
    resize(720, 640);
    showPage(page);
}

void HelpDialog::showPage(Page page)
{
    tabs_->setCurrentWidget(page == Page::Guide ? static_cast<QWidget*>(guide_) : shortcuts_);
}

void HelpDialog::fillShortcuts(const QList<QAction*>& menus)
{
    QList<QPair<QString, QString>> rows;
    collectShortcuts(menus, QString(), rows);
    // What the views and panels handle themselves, not through a menu.
    rows.append({tr("Click"), tr("Plots and 2D path: move the time cursor there")});
    rows.append({tr("Wheel"), tr("Plots: zoom the time axis; 3D: zoom about the pointer")});
    rows.append({tr("Drag"), tr("Plots and 2D path: pan; 3D: orbit (right or middle button: pan)")});
    rows.append({tr("Ctrl+Wheel"), tr("Plots: zoom the value axis of the row under the pointer")});
    rows.append({tr("Wheel or drag on a value axis"), tr("Plots: zoom or pan that row's values")});
    rows.append({tr("Pointer over a plot"), tr("Plots and 2D path: read the time and the values there")});
    rows.append({tr("Shift+Click"), tr("Plots and 2D path: set a marker; the readout then gives \u0394t and \u0394y from it")});
    rows.append({tr("Right-click"), tr("Plots: reset the view, export as PNG, SVG or PDF, or the visible data as CSV")});
    rows.append({tr("Double-click"), tr("Plots and paths: show everything again")});
    rows.append({tr("Up / Down"), tr("Parameter value field: one slider step")});
    rows.append({tr("Page Up / Page Down"), tr("Parameter value field: ten slider steps")});
    rows.append({tr("Up / Down"), tr("Step table: the next step, with the time cursor")});
    shortcuts_->setColumnCount(2);
    shortcuts_->setRowCount(static_cast<int>(rows.size()));
    shortcuts_->setHorizontalHeaderLabels({tr("Keys or mouse"), tr("Does")});
    for (int row = 0; row < rows.size(); ++row) {
        shortcuts_->setItem(row, 0, new QTableWidgetItem(rows[row].first));
        shortcuts_->setItem(row, 1, new QTableWidgetItem(rows[row].second));
    }
    shortcuts_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    shortcuts_->verticalHeader()->hide();
    shortcuts_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    shortcuts_->horizontalHeader()->setStretchLastSection(true);
}

QString HelpDialog::guideText()
{
    return tr(
        "<h2>Footpath in five minutes</h2>"
        "<p>Footpath turns the recording of an inertial sensor on a shoe into the path walked: it finds the "
        "moments the foot rests on the ground (stance), integrates the motion in between, and corrects the "
        "drift with zero-velocity updates in a Kalman filter.</p>"
        "<h3>Opening a recording</h3>"
        "<ul><li><b>File &gt; Open recording</b>, the Recorded input panel, or drag a file onto the window. "
        "Xsens text exports, MT binary logs (.mtb), PyShoe CSV files and plain CSV/text with one sample per "
        "row are read.</li>"
        "<li>A file that does not name its columns opens the import dialog: say which column holds what and "
        "in which unit; the dialog shows the first rows as they will be read.</li>"
        "<li>The recording should start with about a second of standing still: the sensor's attitude is "
        "found from it.</li></ul>"
        "<h3>What the views show</h3>"
        "<ul><li><b>Trajectory 2D / 3D</b>: the path from above and in space. Orange dots are the stances, "
        "the green square is the start and the red cross the end, the yellow dot the time cursor; a dashed "
        "line is the reference when the file has one. After a parameter change the path before it stays as "
        "a faint grey ghost until the next change.</li>"
        "<li><b>Signals</b>: accelerometer, gyroscope and the other channels over time. The coloured lanes "
        "under them mark the stance phases (the foot at rest), plausibility warnings (red spans: a stride "
        "too long, a stance missed) and, with a barometer, the motion class of each step (level, stairs, "
        "elevator).</li>"
        "<li><b>Stance detector</b>: the statistic the detector thresholds and the threshold itself; where "
        "the curve is below the threshold the foot is taken to be at rest. A <i>Reference stance</i> lane "
        "shows the stances the file's own labels give (gait events, motion capture), to compare with.</li>"
        "<li><b>States</b>: the filter's attitude, velocity, height and sensor biases over time, with a band "
        "of one standard deviation where the filter estimates it.</li>"
        "<li><b>Summary</b>: the walk's figures (path length, strides, cadence, end-to-start distance), the "
        "figures against the reference when there is one, and a table of the steps. Selecting a step moves "
        "the time cursor to it in every view.</li></ul>"
        "<p>One time cursor links every view: click a plot or the path and all views show that moment. "
        "Hold the pointer over a plot to read the values; Shift+click sets a marker to measure time and "
        "value differences from; right-click a plot to export it. <b>Help &gt; Keyboard shortcuts</b> "
        "lists every key.</p>"
        "<h3>Tuning</h3>"
        "<ul><li>The <b>Parameters</b> panel lists every setting with its unit; the tool tip names the "
        "identifier used in presets and on the command line. A setting that has no effect with the others "
        "is greyed out, and its tool tip says why.</li>"
        "<li>Every change re-estimates at once. The summary then shows the key figures before and after the "
        "change, green where the change helped and red where it hurt, and the <b>History</b> lists the last "
        "runs: double-click one to go back to it. Undo (Ctrl+Z) goes back one change.</li>"
        "<li>Presets save and load the whole set; <b>Analysis &gt; Compare methods</b> runs several method "
        "sets on the same recording side by side.</li></ul>"
        "<h3>Live input</h3>"
        "<ul><li>In the <b>Live input</b> panel choose the sensor's serial port (or the emulator) and "
        "connect: the live path and signals appear in their own tabs while you walk.</li>"
        "<li>Record writes the samples to a file (the name offered is the device's and the time's, in the "
        "folder of the last recording); when recording stops, the file opens for the full "
        "analysis. A session you did not record can still be saved after Disconnect.</li>"
        "<li>A recording that starts while walking is still read: the path then starts at the first stance, "
        "and a warning says so.</li></ul>"
        "<h3>Exporting</h3>"
        "<p><b>File &gt; Export report</b> writes a PDF with the figures, plots and parameters; <b>Export "
        "CSV</b> writes the trajectory, steps, summary and parameters as CSV files.</p>");
}

}  // namespace footpath
