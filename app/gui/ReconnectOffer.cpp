#include "ReconnectOffer.h"

#include "PortDiscovery.h"

#include <QDir>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

namespace footpath {

namespace {

constexpr int kPollInterval_ms = 1000;

}  // namespace

ReconnectOffer::ReconnectOffer(QWidget* parent)
    : QFrame(parent), text_(new QLabel(this)), reconnect_(new QPushButton(tr("Reconnect"), this)), poll_(new QTimer(this))
{
    setObjectName(QStringLiteral("reconnectOffer"));
    setFrameShape(QFrame::StyledPanel);
    setAutoFillBackground(true);
    QPalette tinted = palette();
    tinted.setColor(QPalette::Window, QColor(255, 243, 205));  // a warning, not an error
    setPalette(tinted);
    text_->setWordWrap(true);
    reconnect_->setObjectName(QStringLiteral("liveReconnect"));
    auto* dismiss = new QPushButton(tr("Dismiss"), this);

    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(reconnect_);
    buttons->addWidget(dismiss);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(text_);
    layout->addLayout(buttons);

    poll_->setInterval(kPollInterval_ms);
    connect(poll_, &QTimer::timeout, this, &ReconnectOffer::checkPort);
    // Withdrawn by the panel once the new session starts: the user may still keep the old
    // samples (Cancel in the panel's question), and then the offer stays.
    connect(reconnect_, &QPushButton::clicked, this, &ReconnectOffer::reconnectRequested);
    connect(dismiss, &QPushButton::clicked, this, &ReconnectOffer::withdraw);
    hide();
}

void ReconnectOffer::offer(const QString& port, const QString& why, const QString& continuation)
{
    port_ = port;
    why_ = why;
    continuation_ = continuation;
    checkPort();
    poll_->start();
    show();
}

void ReconnectOffer::withdraw()
{
    poll_->stop();
    hide();
}

void ReconnectOffer::checkPort()
{
    portPresent_ = serialPortPresent(port_);
    reconnect_->setEnabled(portPresent_);
    showText();
}

void ReconnectOffer::showText()
{
    // The session's own words say what was kept.
    QString text = tr("<b>The device went away:</b> %1").arg(why_.toHtmlEscaped());
    if (!continuation_.isEmpty())
        text += QStringLiteral("<br>") + tr("Reconnecting continues the recording in %1.").arg(continuation_.toHtmlEscaped());
    text += QStringLiteral("<br>")
            + (portPresent_ ? tr("%1 is back: reconnect?").arg(QDir::toNativeSeparators(port_).toHtmlEscaped())
                            : tr("Waiting for %1 to come back (plug the sensor in again)...")
                                  .arg(QDir::toNativeSeparators(port_).toHtmlEscaped()));
    text_->setText(text);
}

}  // namespace footpath
