#pragma once

#include <QFrame>

class QLabel;
class QPushButton;
class QTimer;

namespace footpath {

/// The notice a live session leaves when its port went away mid-stream (USB unplugged): what
/// happened, that everything received was kept, whether the port is back, and a Reconnect
/// button that is enabled once it is. Looks for the port once a second while shown.
class ReconnectOffer : public QFrame {
    Q_OBJECT
public:
    explicit ReconnectOffer(QWidget* parent = nullptr);

    /// Shows the offer for `port`; `why` is the session's own words, `continuation` says where
    /// a recording will continue (empty if none was running).
    void offer(const QString& port, const QString& why, const QString& continuation);
    /// Hides the offer and stops looking for the port.
    void withdraw();

    QString port() const { return port_; }
    bool portPresent() const { return portPresent_; }
    QPushButton* reconnectButton() const { return reconnect_; }

signals:
    void reconnectRequested();

private:
    void checkPort();
    void showText();

    QLabel* text_;
    QPushButton* reconnect_;
    QTimer* poll_;
    QString port_;
    QString why_;
    QString continuation_;
    bool portPresent_ = false;
};

}  // namespace footpath
