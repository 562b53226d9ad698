#include "RecordedInputPanel.h"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QTextBrowser>
#include <QToolButton>
#include <QVBoxLayout>

namespace footpath {

RecordedInputPanel::RecordedInputPanel(QWidget* parent)
    : QWidget(parent),
      open_(new QPushButton(tr("Open recording..."), this)),
      recent_(new QToolButton(this)),
      progress_(new QProgressBar(this)),
      cancel_(new QPushButton(tr("Cancel"), this)),
      info_(new QTextBrowser(this))
{
    recent_->setText(tr("Recent"));
    recent_->setPopupMode(QToolButton::InstantPopup);
    recent_->setMenu(new QMenu(recent_));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(open_, 1);
    buttons->addWidget(recent_);
    auto* loading = new QHBoxLayout;
    loading->addWidget(progress_, 1);
    loading->addWidget(cancel_);
    progress_->setRange(0, 1000);
    progress_->setVisible(false);
    cancel_->setVisible(false);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(buttons);
    layout->addLayout(loading);
    layout->addWidget(info_, 1);
    info_->setPlaceholderText(tr("Open a recording: Xsens text export or .mtb log, pyshoe CSV, or any delimited "
                                 "text with time, acceleration and angular rate. You can also drop a file here."));
    connect(open_, &QPushButton::clicked, this, &RecordedInputPanel::openRequested);
    connect(cancel_, &QPushButton::clicked, this, &RecordedInputPanel::cancelRequested);
}

void RecordedInputPanel::setRecentFiles(const QStringList& paths)
{
    QMenu* menu = recent_->menu();
    menu->clear();
    for (const QString& path : paths)
        menu->addAction(QFileInfo(path).fileName(), this, [this, path] { emit recentFileChosen(path); })
            ->setToolTip(path);
    recent_->setEnabled(!paths.isEmpty());
}

void RecordedInputPanel::showLoading(const QString& path)
{
    progress_->setValue(0);
    progress_->setFormat(tr("Reading %1: %p%").arg(QFileInfo(path).fileName()));
    progress_->setVisible(true);
    cancel_->setVisible(true);
    open_->setEnabled(false);
    mainHtml_.clear();  // a new recording: the last one's feet go
    otherHtml_.clear();
}

void RecordedInputPanel::setProgress(double fraction)
{
    progress_->setValue(int(fraction * 1000.0));
}

void RecordedInputPanel::showInfo(const QString& path, const ImportResult& result)
{
    progress_->setVisible(false);
    cancel_->setVisible(false);
    open_->setEnabled(true);
    mainHtml_ = describe(path, result);
    showBoth();
}

void RecordedInputPanel::showOtherFoot(const QString& path, const ImportResult& result)
{
    otherHtml_ = describe(path, result);  // whichever of the two files is read first
    showBoth();
}

void RecordedInputPanel::showBoth()
{
    info_->setHtml(otherHtml_.isEmpty() ? mainHtml_
                                        : tr("<p><b>Left foot</b></p>%1<hr><p><b>Right foot</b></p>%2").arg(mainHtml_, otherHtml_));
}

void RecordedInputPanel::showProblem(const QString& message)
{
    progress_->setVisible(false);
    cancel_->setVisible(false);
    open_->setEnabled(true);
    info_->setHtml(QStringLiteral("<p style='color:#a00'>%1</p>").arg(message.toHtmlEscaped()));
}

QString RecordedInputPanel::describe(const QString& path, const ImportResult& result)
{
    const RecordingInfo& info = result.info;
    const Recording& recording = result.recording;
    QStringList channels;
    for (const std::string& channel : info.channels)
        channels << QString::fromStdString(channel);
    QString html = QStringLiteral("<b>%1</b><table>").arg(QFileInfo(path).fileName().toHtmlEscaped());
    const auto row = [&html](const QString& label, const QString& value) {
        html += QStringLiteral("<tr><td>%1&nbsp;</td><td>%2</td></tr>").arg(label, value.toHtmlEscaped());
    };
    row(tr("Format"), QString::fromStdString(info.format));
    row(tr("Samples"), QString::number(recording.samples.size()));
    row(tr("Rate"), tr("%1 Hz").arg(info.rate_hz, 0, 'g', 4));
    row(tr("Duration"), tr("%1 s").arg(recording.duration_s(), 0, 'f', 1));
    row(tr("Time"), QString::fromStdString(info.timeSource));
    row(tr("Channels"), channels.join(QStringLiteral(", ")));
    // core names units in ASCII for the command line; the window writes them as everywhere else in it.
    const auto shownUnit = [](const char* name) {
        return QString::fromUtf8(name).replace(QStringLiteral("m/s^2"), QStringLiteral("m/s²")).replace(QStringLiteral("deg/s"), QStringLiteral("°/s"));
    };
    row(tr("Units in file"), QStringLiteral("%1, %2").arg(shownUnit(unitName(info.accUnitAsRead)), shownUnit(unitName(info.gyrUnitAsRead))));
    row(tr("Gaps"), info.gaps.count == 0 ? tr("none")
                                         : tr("%1 (about %2 samples lost), longest %3 s")
                                               .arg(info.gaps.count)
                                               .arg(info.gaps.missingSamples)
                                               .arg(info.gaps.longest_s, 0, 'g', 3));
    html += QStringLiteral("</table>");
    for (const std::string& note : recording.reference.notes)
        html += QStringLiteral("<p>%1</p>").arg(QString::fromStdString(note).toHtmlEscaped());
    for (const std::string& warning : recording.warnings)
        html += QStringLiteral("<p style='color:#a60'>%1 %2</p>")
                    .arg(tr("Warning:"), QString::fromStdString(warning).toHtmlEscaped());
    return html;
}

}  // namespace footpath
